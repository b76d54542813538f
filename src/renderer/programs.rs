//! Building the techniques' programs for the plan, specialised ones per
//! lighting variant (src/frame/variant.rs), with a cache of the variants
//! built before.

use super::Renderer;
use crate::frame::Programs;
use crate::frame::variant::LightingVariant;
use crate::techniques;
use anyhow::Result;

impl Renderer {
    /// Build the programs of every technique the plan uses that has none
    /// yet, the specialised ones for lighting `variant` (src/frame/variant.rs):
    /// when it changes, their instances for the old one go to the cache and
    /// those for the new one come from it, or are built.
    pub(super) fn build_planned_techniques(&mut self, variant: LightingVariant) -> Result<()> {
        if variant != self.variant {
            for (i, t) in self.techniques.iter_mut().enumerate() {
                if self.specialised[i]
                    && let Some(t) = t.take()
                {
                    self.variant_cache.insert((i, self.variant), t);
                }
            }
            self.variant = variant;
        }
        let defines = [("MAX_LIGHTS", self.max_lights.to_string())];
        let variant_defines = variant.defines();
        let used = std::cell::Cell::new(false);
        let programs = Programs {
            gl: &self.gl,
            sources: &self.sources,
            defines: &defines,
            variant: &variant_defines,
            variant_used: &used,
        };
        self.draws.shadow_cull.set(Default::default());
        for pass in &self.plan.passes {
            let i = pass.technique;
            if self.techniques[i].is_none() {
                if let Some(t) = self.variant_cache.remove(&(i, variant)) {
                    self.techniques[i] = Some(t);
                    continue;
                }
                used.set(false);
                self.techniques[i] = Some((techniques::ALL[i].create)(&programs)?);
                self.specialised[i] = used.get();
            }
        }
        Ok(())
    }

    /// The lighting variant the specialised passes run (src/frame/variant.rs).
    pub fn variant(&self) -> LightingVariant {
        self.variant
    }
}
