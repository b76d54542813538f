//! The frame plan: from a scene, which passes run, in which order, and which
//! render targets they use, decided before any GL work. It is put together
//! from the techniques' own lists (`Technique::passes` and `targets`, in the
//! registry's frame order), `gloss plan SCENE` prints it, and the renderer
//! allocates exactly its targets and runs exactly its passes, one line each.
//!
//! A frame runs only what its scene needs: a technique whose scene does not
//! need it adds no pass (no light pass for a scene with no lights, no stencil
//! work unless the stencil light-volume test is on).

use crate::frame::lights::FrameLights;
use crate::frame::targets::TargetDesc;
use crate::frame::technique::Technique;
use crate::scene::{RenderPath, Scene};

#[derive(Clone, Debug, PartialEq)]
pub struct Pass {
    pub name: &'static str,
    /// Which of its technique's passes this is (a technique with one pass: 0).
    pub step: u32,
    /// Where the pass writes.
    pub target: &'static str,
    /// What the pass draws, in words (e.g. "12 objects", "256 spheres").
    pub draws: String,
    /// Source file that implements it (`file!()`).
    pub code: &'static str,
    /// Index of its technique in the registry the plan was made from.
    pub technique: usize,
}

impl Pass {
    /// A pass of the technique in file `code` (step 0).
    pub fn new(
        name: &'static str,
        target: &'static str,
        draws: String,
        code: &'static str,
    ) -> Pass {
        Pass {
            name,
            step: 0,
            target,
            draws,
            code,
            technique: 0,
        }
    }

    /// The same pass, as step `step` of its technique.
    pub fn step(self, step: u32) -> Pass {
        Pass { step, ..self }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct FramePlan {
    pub path: RenderPath,
    pub targets: Vec<TargetDesc>,
    pub passes: Vec<Pass>,
}

impl FramePlan {
    /// Ask every technique of `registry`, in order, for its passes and targets.
    /// Two techniques may name the same target only if they describe it alike.
    pub fn new(scene: &Scene, lights: &FrameLights, registry: &[&Technique]) -> FramePlan {
        let mut targets: Vec<TargetDesc> = Vec::new();
        let mut passes = Vec::new();
        for (index, t) in registry.iter().enumerate() {
            for target in (t.targets)(scene, lights) {
                match targets.iter().find(|d| d.name == target.name) {
                    Some(same) => assert_eq!(
                        same, &target,
                        "{} describes target {} unlike an earlier technique",
                        t.name, target.name
                    ),
                    None => targets.push(target),
                }
            }
            passes.extend((t.passes)(scene, lights).into_iter().map(|p| Pass {
                technique: index,
                ..p
            }));
        }
        targets.push(TargetDesc::output());
        FramePlan {
            path: scene.render.path,
            targets,
            passes,
        }
    }

    pub fn has_pass(&self, name: &str) -> bool {
        self.passes.iter().any(|p| p.name == name)
    }

    pub fn target(&self, name: &str) -> Option<&TargetDesc> {
        self.targets.iter().find(|t| t.name == name)
    }
}

impl std::fmt::Display for FramePlan {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        writeln!(f, "path: {}", self.path.name())?;
        writeln!(f, "render targets:")?;
        for t in &self.targets {
            writeln!(f, "  {:<20} {}", t.name, t.attachments().join(", "))?;
        }
        writeln!(f, "passes:")?;
        for (i, p) in self.passes.iter().enumerate() {
            writeln!(
                f,
                "  {}. {:<16} -> {:<20} {}  [{}]",
                i + 1,
                p.name,
                p.target,
                p.draws,
                p.code
            )?;
        }
        Ok(())
    }
}
