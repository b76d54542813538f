//! Drawing the casters into a shadow map (notes 01 §8.5, first pass), for
//! shadow_map.rs and cascaded_shadow_maps.rs, with two programs: an opaque
//! caster needs depth alone (the fragment shader of 8922fc1: empty for a 2D
//! map, the distance for a cube), an alpha-tested caster (notes 05 "Alpha
//! Test": an OBJ's cut-out leaves) its material's alpha test
//! (glsl/shadows/shadow_alpha.glsl). A software rasteriser pays for the
//! test's code even where `u_alpha_test` says "always", so with
//! `render.specialize` the opaque casters are drawn with the program built
//! with `DEPTH_ONLY` and the alpha-tested ones, after them, with the general
//! one; a frame without alpha-tested casters never uses the general program.
//! With `render.specialize = false` every caster is drawn with the general
//! program, in the scene's order. Either way the map holds the same depths
//! (GL_LESS keeps the nearest, whatever the order).

use crate::frame::Frame;
use crate::frame::Programs;
use crate::frame::draw_list::DrawItem;
use crate::frame::uniforms::unit;
use crate::gl::program::Program;
use crate::scene::{AlphaTest, Cull};
use anyhow::Result;
use glow::HasContext;

/// The general program (the alpha test behind `u_alpha_test`) and the
/// depth-only one, built from the same stages.
pub(super) struct CasterPrograms {
    pub general: Program,
    pub depth_only: Program,
}

impl CasterPrograms {
    /// `stages` with `defines`, and again with `DEPTH_ONLY` besides.
    pub fn build(p: &Programs, stages: &[(u32, &str)], defines: &[(&str, String)]) -> Result<Self> {
        let general = p.build_with(stages, defines)?;
        let mut only = defines.to_vec();
        only.push(("DEPTH_ONLY", "1".into()));
        let depth_only = p.build_with(stages, &only)?;
        Ok(CasterPrograms {
            general,
            depth_only,
        })
    }
}

fn tested(d: &DrawItem) -> bool {
    d.alpha_test != AlphaTest::Always.code()
}

/// Every opaque object (mirrors too: they are solid); transparent ones cast
/// no shadow here. With `render.frustum_culling`, only the casters inside
/// the frustum of one of `faces` (the light's view-projections this draw
/// reaches; notes 01 §6.3), counted in `DrawList::shadow_cull`.
/// With `cull_front`, a two-sided material (`cull = "none"`: a leaf's
/// quad) is drawn without culling, so that it casts from either side.
/// `setup` sets the pass's uniforms on each program as it is put in use.
pub(super) fn draw_casters(
    gl: &glow::Context,
    programs: &CasterPrograms,
    f: &Frame,
    faces: &[glam::Mat4],
    cull_front: bool,
    setup: &dyn Fn(&Program),
) {
    let mut keep = vec![true; f.draws.items.len()];
    if f.scene.render.frustum_culling {
        let mut any = vec![false; keep.len()];
        let mut total = f.draws.shadow_cull.get();
        for vp in faces {
            let (seen, stats) = f.draws.casters_in(vp);
            for (a, s) in any.iter_mut().zip(seen) {
                *a |= s;
            }
            total.objects += stats.objects;
            total.drawn += stats.drawn;
            total.culled += stats.culled;
            total.tests += stats.tests;
        }
        f.draws.shadow_cull.set(total);
        keep = any;
    }
    let casters: Vec<&DrawItem> = (f.draws.items.iter().zip(keep))
        .filter(|(d, k)| *k && !d.transparent)
        .map(|(d, _)| d)
        .collect();
    if !f.scene.render.specialize {
        draw(gl, &programs.general, true, f, &casters, cull_front, setup);
        return;
    }
    // 1. The opaque casters: depth only.
    let (alpha, opaque): (Vec<&DrawItem>, Vec<&DrawItem>) =
        casters.into_iter().partition(|d| tested(d));
    if !opaque.is_empty() {
        draw(
            gl,
            &programs.depth_only,
            false,
            f,
            &opaque,
            cull_front,
            setup,
        );
    }
    // 2. The alpha-tested casters: the test, then depth.
    if !alpha.is_empty() {
        draw(gl, &programs.general, true, f, &alpha, cull_front, setup);
    }
}

/// `casters` with `p`; `general`: `p` has the alpha test (its uniforms are set).
fn draw(
    gl: &glow::Context,
    p: &Program,
    general: bool,
    f: &Frame,
    casters: &[&DrawItem],
    cull_front: bool,
    setup: &dyn Fn(&Program),
) {
    p.use_program();
    setup(p);
    let mut bound = false;
    for d in casters {
        unsafe { gl.front_face(if d.mirrored { glow::CW } else { glow::CCW }) };
        if cull_front {
            match d.cull {
                Cull::None => unsafe { gl.disable(glow::CULL_FACE) },
                _ => unsafe { gl.enable(glow::CULL_FACE) },
            }
        }
        p.set_mat4("u_model", &d.model);
        if !general {
            f.draws.mesh(d).draw();
            continue;
        }
        // 2. An alpha-tested caster runs its material's alpha test on its
        // diffuse texture (glsl/shadows/shadow_alpha.glsl): a leaf casts a
        // leaf, not its quad.
        p.set_i32("u_alpha_test", d.alpha_test);
        if tested(d) {
            let texture = d.texture.map(|t| f.draws.textures[t].id);
            p.set_f32("u_alpha_ref", d.alpha_ref);
            p.set_bool("u_has_diffuse_texture", texture.is_some());
            let (scale, offset) = (d.texturing.uv_scale, d.texturing.uv_offset);
            p.set_vec4(
                "u_uv_transform",
                glam::Vec4::new(scale[0], scale[1], offset[0], offset[1]),
            );
            unsafe {
                gl.active_texture(glow::TEXTURE0 + unit::DIFFUSE_TEXTURE);
                gl.bind_texture(glow::TEXTURE_2D, texture);
                gl.bind_sampler(unit::DIFFUSE_TEXTURE, f.draws.sampler(d, &f.scene.render));
            }
            bound = true;
        }
        f.draws.mesh(d).draw();
    }
    if bound {
        unsafe {
            gl.bind_texture(glow::TEXTURE_2D, None);
            gl.bind_sampler(unit::DIFFUSE_TEXTURE, None);
            gl.active_texture(glow::TEXTURE0);
        }
    }
}
