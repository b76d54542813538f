//! Planar mirrors with the stencil buffer (notes 05, "Planar Reflections"
//! to "Normal First Addendum").
//!
//! Rendering reflected first (one mirror; the slides' order):
//! ```text
//! 1. the reflected scene without the mirror, depth test on     World(reflected view)
//! 2. colour off, stencil always/replace: draw the mirror;      step STENCIL_AND_CLEAR
//!    stencil "outside the mirror": clear the colour there
//! 3. colour on, stencil off: the scene without the mirror      World(camera)
//! ```
//! Rendering normal first (several mirrors, and mirrors in mirrors):
//! ```text
//! 1. the scene without the mirror                              World(camera)
//! 2. clear the stencil, draw the mirror setting the stencil    step MARK
//!    where the depth test passes
//! 3. clear the depth inside the stencil only,                  step CLEAR_DEPTH
//!    reflect the world and draw it with the stencil test       World(reflected view)
//! ```
//! then, for either order, the mirror's tint and roughening texture
//! multiply the reflection (step SURFACE). Each mirror has its own stencil
//! value; a mirror seen in a mirror is marked by incrementing its parent's
//! value and unmarked by decrementing it again (step UNMARK), so nested
//! reflections stay inside their parent's region.
//!
//! The reflection itself (R, the clip plane, glFrontFace(GL_CW)) is a view
//! (src/frame/views.rs): the world passes of every lighting path draw it.
//!
//! GL state: each step sets the stencil, depth, colour-mask, culling and
//! blend state it needs, and restores the defaults (all off, GL_LESS, masks
//! on, GL_CCW) before returning.

use super::mirror_order::{CLEAR_DEPTH, MARK, STENCIL_AND_CLEAR, SURFACE, SURFACE_TESTED, UNMARK};
use crate::frame::lights::FrameLights;
use crate::frame::plan::Pass;
use crate::frame::post::world_target;
use crate::frame::targets::TargetDesc;
use crate::frame::uniforms::unit;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::program::Program;
use crate::scene::Scene;
use crate::scene::knobs;
use anyhow::Result;
use glam::Mat4;
use glow::HasContext;

pub const MIRROR: Technique = Technique {
    name: "mirror",
    notes: "notes 05, Planar Reflections to Normal First Addendum",
    file: file!(),
    shaders: &[
        "stencil/mirror.vert",
        "stencil/mirror.frag",
        "common/fullscreen.vert",
        "stencil/mirror_clear.frag",
    ],
    scene: "scenes/mirror-normal-first.toml",
    docs: "docs/stencil/mirror.md",
    knobs: &[
        &knobs::MIRROR_ORDER,
        &knobs::MIRROR_DEPTH,
        &knobs::MIRROR_CLIP,
        &knobs::MIRROR_WINDING,
    ],
    // Every pass of this technique comes through `order`.
    passes: |_, _| vec![],
    targets,
    create,
    order: Some(super::mirror_order::order),
    runs: Runs::PerView,
};

fn targets(_: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    vec![]
}

struct Mirror {
    polygon: Program,
    clear: Program,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    Ok(Box::new(Mirror {
        polygon: p.build(&[
            (glow::VERTEX_SHADER, "stencil/mirror.vert"),
            (glow::FRAGMENT_SHADER, "stencil/mirror.frag"),
        ])?,
        clear: p.build(&[
            (glow::VERTEX_SHADER, "common/fullscreen.vert"),
            (glow::FRAGMENT_SHADER, "stencil/mirror_clear.frag"),
        ])?,
    }))
}

impl RunPasses for Mirror {
    fn run(&self, pass: &Pass, f: &Frame) {
        let gl = f.gl;
        let target = f.targets.get(world_target(f.scene));
        let value = pass.value as i32;
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(target.id));
            let (x, y, w, h) = f.view.rect(target.width, target.height);
            gl.viewport(x, y, w, h);
            gl.enable(glow::STENCIL_TEST);
            gl.enable(glow::DEPTH_TEST);
            match pass.step {
                MARK => {
                    // Normal first, pass 2: "clear the stencil, render the
                    // mirror, setting the stencil if the depth test passes".
                    if f.view.stencil.is_none() {
                        if f.scene.mirrors().first() == Some(&pass.item) {
                            gl.clear_stencil(0);
                            gl.clear(glow::STENCIL_BUFFER_BIT);
                        }
                        gl.stencil_func(glow::ALWAYS, value, 0xff);
                        gl.stencil_op(glow::KEEP, glow::KEEP, glow::REPLACE);
                    } else {
                        // Inside its parent's region only, one level deeper.
                        gl.stencil_func(glow::EQUAL, value - 1, 0xff);
                        gl.stencil_op(glow::KEEP, glow::KEEP, glow::INCR);
                    }
                    gl.depth_func(glow::LEQUAL);
                    gl.depth_mask(false);
                    // Painted in the clear colour: where the reflection shows
                    // nothing, the mirror shows what reflected first shows.
                    self.draw_polygon(f, pass.item, f.scene.render.background, false);
                }
                CLEAR_DEPTH => {
                    // Pass 3: "clear the depth buffer with the stencil active,
                    // passing things inside the mirror only".
                    gl.stencil_func(glow::EQUAL, value, 0xff);
                    gl.stencil_op(glow::KEEP, glow::KEEP, glow::KEEP);
                    gl.color_mask(false, false, false, false);
                    gl.depth_func(glow::ALWAYS);
                    self.draw_clear(f);
                }
                STENCIL_AND_CLEAR => {
                    // Reflected first, pass 2: "disable the colour buffer,
                    // enable the stencil buffer to always pass but set the
                    // buffer, render the mirror polygon".
                    gl.clear_stencil(0);
                    gl.clear(glow::STENCIL_BUFFER_BIT);
                    gl.color_mask(false, false, false, false);
                    gl.stencil_func(glow::ALWAYS, value, 0xff);
                    gl.stencil_op(glow::KEEP, glow::KEEP, glow::REPLACE);
                    // The mirror's own depth: what lies behind it must not
                    // show through it in pass 3.
                    gl.depth_func(glow::ALWAYS);
                    self.draw_polygon(f, pass.item, glam::Vec3::ZERO, false);
                    // "Now set the stencil test to only pass points outside
                    // the mirror; clear the colour buffer."
                    gl.color_mask(true, true, true, true);
                    gl.stencil_func(glow::NOTEQUAL, value, 0xff);
                    gl.stencil_op(glow::KEEP, glow::KEEP, glow::KEEP);
                    self.draw_clear(f);
                }
                SURFACE | SURFACE_TESTED => {
                    if value == 0 {
                        gl.disable(glow::STENCIL_TEST);
                    }
                    gl.stencil_func(glow::EQUAL, value, 0xff);
                    gl.stencil_op(glow::KEEP, glow::KEEP, glow::KEEP);
                    // Reflected first marked the whole polygon: what stands
                    // in front of it must fail the depth test.
                    let test = if pass.step == SURFACE {
                        glow::ALWAYS
                    } else {
                        glow::LEQUAL
                    };
                    gl.depth_func(test);
                    gl.enable(glow::BLEND);
                    gl.blend_func(glow::ZERO, glow::SRC_COLOR);
                    let m = f.scene.objects[pass.item].mirror.as_ref();
                    let tint = m.map_or(glam::Vec3::ONE, |m| m.tint * m.reflectance);
                    self.draw_polygon(f, pass.item, tint, true);
                    gl.disable(glow::BLEND);
                    gl.blend_func(glow::ONE, glow::ZERO);
                }
                UNMARK => {
                    gl.stencil_func(glow::EQUAL, value, 0xff);
                    gl.stencil_op(glow::KEEP, glow::KEEP, glow::DECR);
                    gl.color_mask(false, false, false, false);
                    gl.depth_func(glow::ALWAYS);
                    gl.depth_mask(false);
                    self.draw_polygon(f, pass.item, glam::Vec3::ZERO, false);
                }
                other => unreachable!("mirror has no step {other}"),
            }
            // Restore the state this pass changed.
            gl.color_mask(true, true, true, true);
            gl.depth_mask(true);
            gl.depth_func(glow::LESS);
            gl.disable(glow::DEPTH_TEST);
            gl.stencil_func(glow::ALWAYS, 0, 0xff);
            gl.stencil_op(glow::KEEP, glow::KEEP, glow::KEEP);
            gl.disable(glow::STENCIL_TEST);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }
}

impl Mirror {
    /// Draw mirror `item`'s polygon in this pass's view in linear `color`
    /// (times its roughening texture when `roughen`), back faces culled: a
    /// mirror seen from behind is no mirror.
    fn draw_polygon(&self, f: &Frame, item: usize, color: glam::Vec3, roughen: bool) {
        let (gl, p, u) = (f.gl, &self.polygon, f.uniforms);
        let d = &f.draws.items[item];
        let texture = d.roughness.filter(|_| roughen);
        unsafe {
            gl.enable(glow::CULL_FACE);
            gl.cull_face(glow::BACK);
            gl.front_face(f.view.front_face(d.mirrored));
            if f.view.clips() {
                gl.enable(glow::CLIP_DISTANCE0);
            }
            p.use_program();
            p.set_mat4("u_model", &d.model);
            p.set_mat4("u_view_projection", &u.view_projection);
            f.view.set_uniforms(p, f.uniforms.eye, &f.scene.clip_planes);
            p.set_vec3("u_color", color);
            p.set_bool("u_output_srgb", u.output_srgb);
            p.set_bool("u_has_roughness", texture.is_some());
            p.set_i32("u_roughness", unit::MIRROR_ROUGHNESS as i32);
            gl.active_texture(glow::TEXTURE0 + unit::MIRROR_ROUGHNESS);
            gl.bind_texture(glow::TEXTURE_2D, texture.map(|t| f.draws.textures[t].id));
            f.draws.mesh(d).draw();
            gl.bind_texture(glow::TEXTURE_2D, None);
            gl.use_program(None);
            gl.disable(glow::CLIP_DISTANCE0);
            gl.front_face(glow::CCW);
            gl.disable(glow::CULL_FACE);
        }
    }

    /// A full-screen triangle in the clear colour at the far depth.
    fn draw_clear(&self, f: &Frame) {
        let p = &self.clear;
        p.use_program();
        p.set_mat4("u_mvp", &Mat4::IDENTITY);
        p.set_vec3("u_clear_color", f.uniforms.clear_color);
        f.meshes.fullscreen.draw();
        unsafe { f.gl.use_program(None) };
    }
}
