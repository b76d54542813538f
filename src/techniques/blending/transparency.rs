//! Transparent objects (notes 01 §4.5 "Blending"; §6.1 "Handling Transparent
//! Objects"; §8.6: deferred rendering "still does not help with issue of
//! lighting transparent objects", so every path draws them forward).
//!
//! Notes 01 §6.1, step by step:
//!
//! 1. Build a list of opaque objects and a list of transparent ones: a
//!    material with `opacity` < 1 is transparent (`DrawItem::transparent`);
//!    the opaque passes (forward, G-buffer, the light pre-pass's combine)
//!    skip it.
//! 2. Render all the opaque objects: the paths' own passes, before this one.
//!    In the deferred paths the composite (gl_FragDepth) or the light
//!    pre-pass's combine (glBlitFramebuffer) leaves the G-buffer's depth in
//!    the output, so the depth test below works in every path.
//! 3. Sort the transparent objects by their z position: the view depth of
//!    each object's centre (`back_to_front`). One point per object: two
//!    objects that intersect, or a large one whose centre is behind a small
//!    one it partly covers, are in no correct order (docs/blending/transparency.md).
//! 4. Render them from furthest away to closest, lit by the same Phong code
//!    as the forward pass, with the blend equation of §4.5:
//!    glEnable(GL_BLEND); glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA),
//!    C = C_source x alpha + C_dest x (1 - alpha). The depth test stays on
//!    (opaque objects in front hide glass), depth writes go off
//!    (glDepthMask(GL_FALSE)), so glass never hides glass drawn after it.
//!    Each object is drawn twice: back faces (glCullFace(GL_FRONT)), then
//!    front faces (glCullFace(GL_BACK)), so a glass sphere's far wall lies
//!    under its near wall.
//!
//! The blend happens on the values in the output: sRGB-encoded for the
//! 8-bit image, linear for the float output.
//!
//! GL state: depth test (render.depth_func, or the material's), depth writes off, blending, culling, glFrontFace
//! per object, alpha writes off (the image stays opaque); restores all.

use crate::frame::draw_list::DrawList;
use crate::frame::lights::FrameLights;
use crate::frame::plan::Pass;
use crate::frame::post::world_target;
use crate::frame::shadows;
use crate::frame::targets::TargetDesc;
use crate::frame::uniforms::LIGHTS_BINDING;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::program::Program;
use crate::scene::Scene;
use crate::scene::knobs;
use anyhow::Result;
use glam::{Mat4, Vec3};
use glow::HasContext;

pub const TRANSPARENCY: Technique = Technique {
    name: "transparency",
    notes: "notes 01 §4.5, Blending; §6.1, Handling Transparent Objects",
    file: file!(),
    shaders: &["blending/transparency.vert", "blending/transparency.frag"],
    scene: "scenes/transparency.toml",
    docs: "docs/blending/transparency.md",
    knobs: &[
        &knobs::SORT_TRANSPARENT,
        &knobs::TRANSPARENCY,
        &knobs::AMBIENT,
    ],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::PerView,
};

fn passes(scene: &Scene, _: &FrameLights) -> Vec<Pass> {
    let n = scene.objects.len() - scene.opaque_objects();
    // render.transparency chose an order-independent technique instead.
    if n == 0 || scene.render.transparency != crate::scene::Transparency::Sorted {
        return vec![];
    }
    let order = if scene.render.sort_transparent {
        "back to front"
    } else {
        "unsorted (scene order)"
    };
    let draws = format!(
        "{n} transparent objects {order}, GL_SRC_ALPHA / GL_ONE_MINUS_SRC_ALPHA, depth writes off"
    );
    vec![Pass::new(
        "transparency",
        world_target(scene),
        draws,
        file!(),
    )]
}

fn targets(_: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    vec![]
}

/// Step 3: the order to draw `centres` (world space) in, furthest first, by
/// view depth (the distance in front of the eye along the view direction,
/// -z in eye space, `view` the view matrix). Ties keep the given order (a
/// stable sort); a centre behind the eye has a negative depth and comes last.
pub fn back_to_front(view: &Mat4, centres: &[Vec3]) -> Vec<usize> {
    let depth: Vec<f32> = centres
        .iter()
        .map(|c| -view.transform_point3(*c).z)
        .collect();
    let mut order: Vec<usize> = (0..centres.len()).collect();
    order.sort_by(|&a, &b| depth[b].total_cmp(&depth[a]));
    order
}

struct Transparency {
    program: Program,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    let program = p.build(&[
        (glow::VERTEX_SHADER, "blending/transparency.vert"),
        (glow::FRAGMENT_SHADER, "blending/transparency.frag"),
    ])?;
    program.bind_uniform_block("Lights", LIGHTS_BINDING);
    shadows::setup_program(&program);
    Ok(Box::new(Transparency { program }))
}

impl RunPasses for Transparency {
    fn run(&self, _: &Pass, f: &Frame) {
        let (gl, p, u) = (f.gl, &self.program, f.uniforms);
        let output = f.targets.get(world_target(f.scene));
        // 1. The transparent list (those in the view's frustum, notes 01
        // §6.3), 3. sorted (or not, to show why it must be).
        let seen = f.in_view();
        let items: Vec<usize> = (0..f.draws.items.len())
            .filter(|&i| f.draws.items[i].transparent && seen.as_ref().is_none_or(|s| s[i]))
            .collect();
        let order: Vec<usize> = if f.scene.render.sort_transparent {
            let centres: Vec<Vec3> = items
                .iter()
                .map(|&i| {
                    let d = &f.draws.items[i];
                    d.model.transform_point3(d.centre)
                })
                .collect();
            // For the viewer of this view (a mirror's reflection: reflected).
            back_to_front(&(u.view * f.view.reflection), &centres)
                .into_iter()
                .map(|k| items[k])
                .collect()
        } else {
            items
        };
        unsafe {
            // 4. Blend over the opaque image, furthest first.
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(output.id));
            let (x, y, w, h) = f.view.rect(output.width, output.height);
            gl.viewport(x, y, w, h);
            gl.enable(glow::DEPTH_TEST);
            let mut depth_func = f.scene.render.depth_func;
            gl.depth_func(depth_func.gl());
            gl.depth_mask(false);
            gl.enable(glow::BLEND);
            gl.blend_func(glow::SRC_ALPHA, glow::ONE_MINUS_SRC_ALPHA);
            // The output stays opaque: blend colour only.
            gl.color_mask(true, true, true, false);
            gl.enable(glow::CULL_FACE);
            // A mirror's reflected view: inside its stencil region, cut by its plane.
            if let Some(region) = f.view.stencil {
                gl.enable(glow::STENCIL_TEST);
                gl.stencil_func(glow::EQUAL, region.into(), 0xff);
                gl.stencil_op(glow::KEEP, glow::KEEP, glow::KEEP);
            }
            // The clip planes, the program and what every transparent
            // fragment reads, as the order-independent passes set them.
            super::transparent_draws::set_up(f, p);
            for i in order {
                let d = &f.draws.items[i];
                let func = d.depth_func.unwrap_or(f.scene.render.depth_func);
                if func != depth_func {
                    gl.depth_func(func.gl());
                    depth_func = func;
                }
                // A mirroring model matrix, or a reflected view, turns
                // counter-clockwise triangles clockwise.
                gl.front_face(f.view.front_face(d.mirrored));
                // Its texture and normal map, with the sampler that says how
                // to read them (notes 01 §5: wrap rules, filter; §8.4).
                f.draws.bind_textures(gl, p, d, &f.scene.render);
                f.draws.set_object_uniforms(p, d);
                p.set_f32("u_opacity", d.opacity);
                // Back faces first (the far side), then front faces.
                for cull in [glow::FRONT, glow::BACK] {
                    gl.cull_face(cull);
                    f.draws.mesh(d).draw();
                }
            }

            // Restore the state this pass changed.
            gl.disable(glow::CLIP_DISTANCE0);
            for i in 0..f.scene.clip_planes.len() as u32 {
                gl.disable(glow::CLIP_DISTANCE1 + i);
            }
            gl.stencil_func(glow::ALWAYS, 0, 0xff);
            gl.disable(glow::STENCIL_TEST);
            gl.front_face(glow::CCW);
            DrawList::unbind_textures(gl);
            gl.bind_texture(glow::TEXTURE_2D, None);
            gl.active_texture(glow::TEXTURE0);
            gl.bind_buffer_base(glow::UNIFORM_BUFFER, LIGHTS_BINDING, None);
            f.shadows.unbind(gl);
            gl.use_program(None);
            gl.cull_face(glow::BACK);
            gl.disable(glow::CULL_FACE);
            gl.color_mask(true, true, true, true);
            gl.blend_func(glow::ONE, glow::ZERO);
            gl.disable(glow::BLEND);
            gl.depth_mask(true);
            gl.depth_func(glow::LESS);
            gl.disable(glow::DEPTH_TEST);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }
}
