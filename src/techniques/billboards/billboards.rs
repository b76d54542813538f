//! Billboards (notes 05, "Billboards"; "Alpha Test"; "Alpha Test and
//! Billboards").
//!
//! A billboard replaces complex geometry (a tree) with an image on a quad
//! that turns to the camera; the image's alpha is 1 where the tree is and 0
//! where it is not. The quad is built in glsl/billboards/billboards.vert
//! from its centre and size (one instanced quad, corners from gl_VertexID):
//! spherical billboards lie in the camera's image plane, cylindrical ones
//! turn only about the world's up axis and stay upright.
//!
//! Three ways to draw them (`render.billboards`):
//!
//! - `blend`: glEnable(GL_BLEND), glBlendFunc(GL_SRC_ALPHA,
//!   GL_ONE_MINUS_SRC_ALPHA), in scene order with depth writes on: the
//!   notes' "big problem". A near billboard drawn first writes depth over
//!   its transparent texels too, and a billboard behind it drawn later is
//!   depth-rejected there: a hole.
//! - `blend_sorted`: the same blending, the billboards sorted back to front
//!   by view depth on the CPU every frame (`back_to_front`).
//! - `alpha_test` (the default): "Do not let alpha < 0.5 pass through",
//!   `discard` in glsl/common/alpha_test.glsl (the reference is
//!   `render.billboard_alpha_ref`, 0.5 by default); no blending, no sorting.
//!   "Depth buffer is never set for fragments that are see through."
//!
//! Lighting is simple: sprite colour x (ambient + each directional light on
//! an up-facing normal), `billboard_light`; point and spot lights do not
//! light billboards.
//!
//! In the deferred paths the composite (and the light pre-pass's combine)
//! leaves the G-buffer's depth in the output, so this pass draws forward
//! against it in every path. In a mirror's reflected view (stencil/mirror.rs)
//! it draws only inside the mirror's stencil region, cut by its clip plane,
//! the quads turned to the reflected viewer.
//!
//! GL state: depth test with render.depth_func, glColorMask with alpha off
//! (the output stays opaque), blending in the blend modes; restores no
//! depth test, GL_LESS, all colour channels, no blending, GL_ONE/GL_ZERO.

use crate::frame::billboards::instance_data;
use crate::frame::lights::FrameLights;
use crate::frame::plan::Pass;
use crate::frame::post::world_target;
use crate::frame::targets::TargetDesc;
use crate::frame::uniforms::unit;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::debug::check_feedback_before_draw;
use crate::gl::program::Program;
use crate::scene::knobs;
use crate::scene::{AlphaTest, BILLBOARD_ALPHA_TEST, Billboard, BillboardMode, LightKind, Scene};
use anyhow::Result;
use glam::{Mat4, Vec3};
use glow::HasContext;

pub const BILLBOARDS: Technique = Technique {
    name: "billboards",
    notes: "notes 05, Billboards; Alpha Test; Alpha Test and Billboards",
    file: file!(),
    shaders: &["billboards/billboards.vert", "billboards/billboards.frag"],
    scene: "scenes/billboards-forest.toml",
    docs: "docs/billboards/billboards.md",
    knobs: &[
        &knobs::BILLBOARDS,
        &knobs::BILLBOARD_ALPHA_REF,
        &knobs::DEPTH_FUNC,
        &knobs::AMBIENT,
    ],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::PerView,
};

fn passes(scene: &Scene, _: &FrameLights) -> Vec<Pass> {
    if scene.billboards.is_empty() {
        return vec![];
    }
    let mode = match scene.render.billboards {
        BillboardMode::AlphaTest => format!(
            "alpha test: discard alpha < {}, no blending",
            scene.render.billboard_alpha_ref
        ),
        BillboardMode::Blend => "alpha blending in scene order, depth writes on".into(),
        BillboardMode::BlendSorted => "alpha blending, sorted back to front".into(),
    };
    let draws = format!(
        "{} billboards, 1 instanced quad ({mode})",
        scene.billboards.len()
    );
    vec![Pass::new("billboards", world_target(scene), draws, file!())]
}

fn targets(_: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    vec![]
}

struct Billboards {
    program: Program,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    Ok(Box::new(Billboards {
        program: p.build(&[
            (glow::VERTEX_SHADER, "billboards/billboards.vert"),
            (glow::FRAGMENT_SHADER, "billboards/billboards.frag"),
        ])?,
    }))
}

/// The order to draw `billboards` in, back to front: view space looks down
/// -z, so the most negative view-space z (the farthest centre) comes first.
/// Ties keep the scene's order.
pub fn back_to_front(billboards: &[Billboard], view: &Mat4) -> Vec<usize> {
    let z: Vec<f32> = billboards
        .iter()
        .map(|b| view.transform_point3(b.center).z)
        .collect();
    let mut order: Vec<usize> = (0..billboards.len()).collect();
    order.sort_by(|&a, &b| z[a].total_cmp(&z[b]));
    order
}

/// The light a billboard gets: ambient plus each directional light as if
/// the billboard's normal pointed up (world +y).
pub fn billboard_light(scene: &Scene) -> Vec3 {
    let mut c = scene.render.ambient;
    for l in &scene.lights {
        if l.kind == LightKind::Directional {
            c += l.radiance() * (-l.direction).dot(Vec3::Y).max(0.0);
        }
    }
    c
}

impl RunPasses for Billboards {
    fn run(&self, _: &Pass, f: &Frame) {
        let Some(b) = &f.draws.billboards.gpu else {
            return;
        };
        let (gl, scene, u, p) = (f.gl, f.scene, f.uniforms, &self.program);
        let output = f.targets.get(world_target(f.scene));
        // 1. The view: the camera's, or a mirror's reflected one (R: the
        // quads turn to the reflected viewer, and sort for it).
        let view = u.view * f.view.reflection;
        // 2. The draw order: sorted back to front, or as the scene lists them.
        let mode = scene.render.billboards;
        let mut order = match mode {
            BillboardMode::BlendSorted => back_to_front(&scene.billboards, &view),
            BillboardMode::Blend | BillboardMode::AlphaTest => {
                (0..scene.billboards.len()).collect()
            }
        };
        // The instance buffer holds the billboards it was made for.
        order.truncate(b.count);
        let data = instance_data(&scene.billboards, &order);
        b.instances.write(floats_as_bytes(&data)); // glBufferSubData
        // 3. The alpha test only in its mode: blending needs the soft texels.
        let (test, reference) = match mode {
            BillboardMode::AlphaTest => (BILLBOARD_ALPHA_TEST, scene.render.billboard_alpha_ref),
            BillboardMode::Blend | BillboardMode::BlendSorted => (AlphaTest::Always, 0.5),
        };
        let blend = mode != BillboardMode::AlphaTest;
        // 4. Over the opaque image, depth tested; blended in the blend modes.
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(output.id));
            let (x, y, w, h) = f.view.rect(output.width, output.height);
            gl.viewport(x, y, w, h);
            gl.enable(glow::DEPTH_TEST);
            gl.depth_func(scene.render.depth_func.gl());
            gl.depth_mask(true);
            // Blend the colour; the output's alpha stays 1.
            gl.color_mask(true, true, true, false);
            if blend {
                gl.enable(glow::BLEND);
                gl.blend_func(glow::SRC_ALPHA, glow::ONE_MINUS_SRC_ALPHA);
            }
            // A mirror's reflected view: inside its stencil region, cut by its plane.
            if let Some(region) = f.view.stencil {
                gl.enable(glow::STENCIL_TEST);
                gl.stencil_func(glow::EQUAL, region.into(), 0xff);
                gl.stencil_op(glow::KEEP, glow::KEEP, glow::KEEP);
            }
            if f.view.clips() {
                gl.enable(glow::CLIP_DISTANCE0);
            }
            // The scene's clip planes (notes 01 §3.3), GL_CLIP_DISTANCE1 on.
            for i in 0..f.scene.clip_planes.len() as u32 {
                gl.enable(glow::CLIP_DISTANCE1 + i);
            }

            // 5. One instanced quad per billboard, corners from gl_VertexID.
            p.use_program();
            p.set_mat4("u_view", &view);
            f.view.set_uniforms(p, f.uniforms.eye, &f.scene.clip_planes);
            p.set_mat4("u_view_projection", &u.view_projection);
            p.set_f32("u_sprite_count", b.sprite_count as f32);
            p.set_vec3("u_light", billboard_light(scene));
            p.set_bool("u_output_srgb", u.output_srgb);
            p.set_i32("u_alpha_test", test.code());
            p.set_f32("u_alpha_ref", reference);
            p.set_i32("u_sprites", unit::DIFFUSE_TEXTURE as i32);
            gl.active_texture(glow::TEXTURE0 + unit::DIFFUSE_TEXTURE);
            gl.bind_texture(glow::TEXTURE_2D, Some(b.sheet.id));
            check_feedback_before_draw(gl);
            gl.bind_vertex_array(Some(b.vao));
            gl.draw_arrays_instanced(glow::TRIANGLE_STRIP, 0, 4, order.len() as i32);

            // Restore the state this pass changed.
            gl.bind_vertex_array(None);
            gl.bind_texture(glow::TEXTURE_2D, None);
            gl.active_texture(glow::TEXTURE0);
            gl.use_program(None);
            if blend {
                gl.blend_func(glow::ONE, glow::ZERO);
                gl.disable(glow::BLEND);
            }
            gl.disable(glow::CLIP_DISTANCE0);
            for i in 0..f.scene.clip_planes.len() as u32 {
                gl.disable(glow::CLIP_DISTANCE1 + i);
            }
            gl.stencil_func(glow::ALWAYS, 0, 0xff);
            gl.disable(glow::STENCIL_TEST);
            gl.color_mask(true, true, true, true);
            gl.depth_func(glow::LESS);
            gl.disable(glow::DEPTH_TEST);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }
}

fn floats_as_bytes(v: &[f32]) -> &[u8] {
    // f32 is plain old data with no padding.
    unsafe { std::slice::from_raw_parts(v.as_ptr() as *const u8, std::mem::size_of_val(v)) }
}
