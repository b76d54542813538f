//! Object outlines (LearnOpenGL, 4.advanced_opengl "Stencil testing",
//! "Object outlining"; beyond the notes, whose stencil chapter is notes 05's
//! mirrors). The lesson's steps:
//!
//! 1. Enable the stencil test; glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE).
//! 2. Draw the objects to outline with glStencilFunc(GL_ALWAYS, 1, 0xFF)
//!    and glStencilMask(0xFF): each of their fragments writes 1.
//! 3. glStencilFunc(GL_NOTEQUAL, 1, 0xFF), glStencilMask(0x00), depth test
//!    off; draw the objects again, a little larger, in one flat colour:
//!    only the band around each object passes.
//! 4. glStencilMask(0xFF), glStencilFunc(GL_ALWAYS, 0, 0xFF), depth test on.
//!
//! gloss differs in three places, each for a reason:
//!
//! - The objects are already lit by the path's own passes (forward, the
//!   G-buffer's), so step 2 draws them again with colour writes off. It runs
//!   after the opaque world, its composite and the sky, in every path: the
//!   world target holds the frame's depth and stencil in each.
//! - The stencil bits are shared with the mirrors (stencil/mirror.rs), whose
//!   regions count up from 1. The outline takes the top bit alone: reference
//!   0x80, write mask glStencilMask(0x80) and value mask 0x80 in
//!   glStencilFunc(GL_NOTEQUAL, 0x80, 0x80), and clears only that bit
//!   (glClear obeys the stencil write mask) before and after, so the
//!   mirrors' values are never touched. In a mirror's reflected view the
//!   test is glStencilFunc(GL_EQUAL, region, 0xFF): inside the region and
//!   not marked.
//! - Step 2 writes the stencil whether the depth test passes or not
//!   (glStencilOp(GL_KEEP, GL_REPLACE, GL_REPLACE)): with the lesson's
//!   GL_KEEP on depth fail, the part of an object hidden behind another
//!   stays unmarked and step 3 paints it over in the outline's colour. Here
//!   the whole silhouette is marked and the outline surrounds it, drawn over
//!   whatever hides it, as an editor shows a selection.
//! - "A little larger" is not a scale about the object's origin (uneven for
//!   shapes not centred on it) but each vertex moved along its normal as the
//!   screen sees it, `render.outline_width` pixels (glsl/stencil/object_outlines.vert,
//!   `extrude` its CPU twin): the band is as wide near and far.
//!
//! GL state: stencil test, function, operations and masks; colour writes;
//! the depth test; clip distances. Restores them all, and leaves the stencil
//! bit it used cleared.

use crate::frame::lights::FrameLights;
use crate::frame::plan::Pass;
use crate::frame::post::world_target;
use crate::frame::targets::TargetDesc;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::program::Program;
use crate::scene::{Scene, knobs};
use anyhow::Result;
use glam::{Mat4, Vec2, Vec3, Vec4};
use glow::HasContext;

pub const OBJECT_OUTLINES: Technique = Technique {
    name: "object_outlines",
    notes: "LearnOpenGL, 4.advanced_opengl, Stencil testing: Object outlining (beyond the notes; notes 05 has the stencil buffer)",
    file: file!(),
    shaders: &[
        "stencil/object_outlines.vert",
        "stencil/object_outlines.frag",
    ],
    scene: "scenes/outlines.toml",
    docs: "docs/stencil/object_outlines.md",
    knobs: &[&knobs::OUTLINES, &knobs::OUTLINE_WIDTH],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::PerView,
};

/// The stencil bit the outline marks: the top one (the mirrors' regions
/// count up from 1 and stay below it: at most 255 values, and a scene with
/// outlines and mirrors is checked to need fewer than 128).
pub const OUTLINE_BIT: u8 = 0x80;

fn passes(scene: &Scene, _: &FrameLights) -> Vec<Pass> {
    let Some(o) = scene.outlines.as_ref().filter(|_| scene.render.outlines) else {
        return vec![];
    };
    let n = o.objects.len();
    let world = world_target(scene);
    vec![
        Pass::new(
            "outline_mark",
            world,
            format!("{n} objects, colour off, GL_ALWAYS 0x80 / GL_REPLACE into stencil bit 0x80"),
            file!(),
        ),
        Pass::new(
            "outline_draw",
            world,
            format!(
                "{n} objects moved {} px along their normals, GL_NOTEQUAL 0x80 & 0x80, depth test off",
                scene.render.outline_width
            ),
            file!(),
        )
        .step(1),
    ]
}

fn targets(_: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    vec![]
}

struct ObjectOutlines {
    program: Program,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    let program = p.build(&[
        (glow::VERTEX_SHADER, "stencil/object_outlines.vert"),
        (glow::FRAGMENT_SHADER, "stencil/object_outlines.frag"),
    ])?;
    Ok(Box::new(ObjectOutlines { program }))
}

impl RunPasses for ObjectOutlines {
    fn run(&self, pass: &Pass, f: &Frame) {
        let Some(outlines) = f.scene.outlines.as_ref() else {
            return;
        };
        let (gl, p, u) = (f.gl, &self.program, f.uniforms);
        let target = f.targets.get(world_target(f.scene));
        let bit = u32::from(OUTLINE_BIT);
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(target.id));
            let (x, y, w, h) = f.view.rect(target.width, target.height);
            gl.viewport(x, y, w, h);
            gl.enable(glow::STENCIL_TEST);
            if pass.step == 0 {
                // Clear the outline's bit only (glClear writes through the
                // stencil write mask); then 1.-2.: every fragment of the
                // outlined objects sets it, in front of others or behind.
                gl.stencil_mask(bit);
                gl.clear_stencil(0);
                gl.clear(glow::STENCIL_BUFFER_BIT);
                gl.stencil_op(glow::KEEP, glow::REPLACE, glow::REPLACE);
                gl.stencil_func(glow::ALWAYS, bit as i32, bit);
                gl.color_mask(false, false, false, false);
                gl.enable(glow::DEPTH_TEST);
                gl.depth_mask(false);
            } else {
                // 3. Where the bit is not set (in a reflected view: where
                // the stencil holds the region's value, bit clear), depth
                // test off, stencil writes off.
                gl.stencil_mask(0x00);
                match f.view.stencil {
                    Some(region) => gl.stencil_func(glow::EQUAL, region.into(), 0xff),
                    None => gl.stencil_func(glow::NOTEQUAL, bit as i32, bit),
                }
                gl.stencil_op(glow::KEEP, glow::KEEP, glow::KEEP);
                gl.disable(glow::DEPTH_TEST);
            }
            if f.view.clips() {
                gl.enable(glow::CLIP_DISTANCE0);
            }
            for i in 0..f.scene.clip_planes.len() as u32 {
                gl.enable(glow::CLIP_DISTANCE1 + i);
            }
            p.use_program();
            f.view.set_uniforms(p, u.eye, &f.scene.clip_planes);
            p.set_mat4("u_view_projection", &u.view_projection);
            p.set_vec2("u_viewport", Vec2::new(w as f32, h as f32));
            let width = if pass.step == 0 {
                0.0
            } else {
                f.scene.render.outline_width as f32
            };
            p.set_f32("u_width", width);
            p.set_vec3("u_color", outlines.color);
            p.set_bool("u_output_srgb", u.output_srgb);
            for &i in &outlines.objects {
                let d = &f.draws.items[i];
                p.set_mat4("u_model", &d.model);
                p.set_mat3("u_normal_matrix", &d.normal_matrix);
                f.draws.mesh(d).draw();
            }

            // 4. Restore, and leave the outline's bit cleared for the
            // mirrors' later steps.
            gl.use_program(None);
            gl.disable(glow::CLIP_DISTANCE0);
            for i in 0..f.scene.clip_planes.len() as u32 {
                gl.disable(glow::CLIP_DISTANCE1 + i);
            }
            if pass.step == 0 {
                gl.color_mask(true, true, true, true);
                gl.depth_mask(true);
                gl.disable(glow::DEPTH_TEST);
            } else {
                gl.stencil_mask(bit);
                gl.clear(glow::STENCIL_BUFFER_BIT);
            }
            gl.stencil_mask(0xff);
            gl.stencil_op(glow::KEEP, glow::KEEP, glow::KEEP);
            gl.stencil_func(glow::ALWAYS, 0, 0xff);
            gl.disable(glow::STENCIL_TEST);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }
}

/// The CPU twin of glsl/stencil/object_outlines.vert: where a vertex at
/// `world` with world normal `normal` lands in pixels (window coordinates,
/// origin bottom left of a `viewport`-sized view), moved `width` pixels
/// along its normal's direction on screen.
pub fn extrude(vp: &Mat4, world: Vec3, normal: Vec3, viewport: Vec2, width: f32) -> Vec2 {
    let mut c = *vp * world.extend(1.0);
    let n = *vp * Vec4::new(normal.x, normal.y, normal.z, 0.0);
    let d = (n.truncate().truncate() * c.w - c.truncate().truncate() * n.w) * viewport;
    if width > 0.0 && d.length() > 0.0 {
        let o = d.normalize() * (2.0 * width / viewport) * c.w;
        c.x += o.x;
        c.y += o.y;
    }
    (Vec2::new(c.x, c.y) / c.w * 0.5 + 0.5) * viewport
}
