//! Cascaded shadow maps (Engel 2006, "Cascaded Shadow Maps", ShaderX5;
//! Dimitrov 2007, "Cascaded Shadow Maps", NVIDIA; Zhang et al. 2006,
//! "Parallel-Split Shadow Maps" for the split scheme; Valient 2008, "Stable
//! Rendering of Cascaded Shadow Maps", ShaderX6, for the stable fit;
//! LearnOpenGL's "CSM" guest article for the layout in GL):
//!
//! ```text
//! 1. Divide the view frustum into m slices along its depth (the split scheme).
//! 2. For each slice, fit the light's orthographic projection around it.
//! 3. Render one shadow map per slice (a layer of one texture array).
//! 4. When shading, pick the slice that holds the fragment's view depth and
//!    compare against its map; blend into the next map near a split.
//! ```
//!
//! Steps 1-2 are src/math/cascades.rs (called each frame from
//! src/frame/shadows.rs, which also writes the `Cascades` block); step 3
//! is this file: one pass per cascade, before the views, each binding the
//! framebuffer that has its layer of the GL_TEXTURE_2D_ARRAY attached
//! (glFramebufferTextureLayer: GL 3.3 needs no geometry shader for it) and
//! drawing the casters with the flat shadow pass's shaders. Step 4 is
//! glsl/shadows/cascaded_shadow_maps.glsl, in every lighting shader.
//!
//! It runs only for a directional light with `shadow.cascades > 1`; the
//! light's other knobs (biases, PCF, front-face culling) are shadow_map.rs's.
//!
//! GL state: as shadow_map.rs; sets the viewport to the map, depth test
//! and writes, GL_DEPTH_CLAMP, glPolygonOffset, with `cull_front`
//! glCullFace(GL_FRONT); restores no depth test, GL_LESS, no depth clamp,
//! no polygon offset, no culling, GL_BACK, GL_CCW.

use super::casters::{CasterPrograms, draw_casters, plan_programs};
use super::depth_pass;
use super::shadow_map::transparent;
use crate::frame::lights::FrameLights;
use crate::frame::plan::Pass;
use crate::frame::shadows::casters;
use crate::frame::targets::{TargetDesc, format_name};
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::depth_map;
use crate::scene::Scene;
use anyhow::Result;
use glow::HasContext;

pub const CASCADED_SHADOW_MAPS: Technique = Technique {
    name: "cascaded_shadow_maps",
    notes: "Engel 2006, Cascaded Shadow Maps; Zhang et al. 2006, Parallel-Split Shadow Maps (beyond the notes; notes 01 §8.5 has one map)",
    file: file!(),
    shaders: &[
        "shadows/shadow_map.vert",
        "shadows/shadow_map.frag",
        "shadows/cascaded_shadow_maps.glsl",
    ],
    scene: "scenes/cascaded-shadows.toml",
    docs: "docs/shadows/cascaded_shadow_maps.md",
    knobs: &[],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::BeforeViews,
};

/// One pass per cascade of the cascaded light; none without one.
fn passes(scene: &Scene, _: &FrameLights) -> Vec<Pass> {
    let casting = scene.objects.len() - transparent(scene);
    let Some(c) = casters(scene).into_iter().find(|c| c.cascaded()) else {
        return vec![];
    };
    let s = c.shadow;
    let n = s.resolution;
    let format = format_name(depth_map::FORMAT);
    let fit = if s.stable { "stable" } else { "tight" };
    (0..s.cascades)
        .map(|k| {
            let draws = format!(
                "light {} (directional): cascade {} of {}, layer {k} of a {n} x {n} x {} {format} array ({} split, {fit} fit), {casting} objects",
                c.light,
                k + 1,
                s.cascades,
                s.cascades,
                s.split.name(),
            );
            Pass::new("cascaded shadow map", "shadow map", draws, file!())
                .about(c.light, k)
                .step(k + 1)
                .with_programs(plan_programs(scene, &[]))
        })
        .collect()
}

fn targets(_: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    vec![]
}

struct CascadedShadowMaps {
    flat: CasterPrograms,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    let stages = [
        (glow::VERTEX_SHADER, "shadows/shadow_map.vert"),
        (glow::FRAGMENT_SHADER, "shadows/shadow_map.frag"),
    ];
    let flat = CasterPrograms::new(p, &stages, &[]);
    Ok(Box::new(CascadedShadowMaps { flat }))
}

impl RunPasses for CascadedShadowMaps {
    fn prepare(&self, _: &Pass, f: &Frame) -> Result<()> {
        self.flat.prepare(f.scene)
    }

    fn run(&self, pass: &Pass, f: &Frame) {
        let gl = f.gl;
        let index = (f.shadows.maps.iter()).position(|(c, _)| c.cascaded() && c.light == pass.item);
        let Some(index) = index else { return };
        let (caster, map) = &f.shadows.maps[index];
        let Some(view) = &f.shadows.views[index] else {
            return;
        };
        let k = pass.value as usize;
        let (Some(vp), Some(&fb)) = (view.view_projections.get(k), map.framebuffers.get(k)) else {
            return;
        };
        let s = caster.shadow;
        unsafe {
            // 3. Render cascade k's depth from the light into layer k.
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(fb));
            gl.viewport(0, 0, map.size, map.size);
            gl.clear(glow::DEPTH_BUFFER_BIT);
            // shadow_map.rs's depth-pass state: what lies nearer the light
            // than the box still casts (clamped).
            depth_pass::set(gl, &s);
            // The opaque casters' program, then the alpha-tested ones'
            // (casters.rs).
            let setup = |p: &crate::gl::program::Program| p.set_mat4("u_light_view_projection", vp);
            let faces = std::slice::from_ref(vp);
            draw_casters(gl, &self.flat, f, faces, s.cull_front, &setup);

            // Restore the state this pass changed.
            gl.use_program(None);
            depth_pass::restore(gl);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }
}
