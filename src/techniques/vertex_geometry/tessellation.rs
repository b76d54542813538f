//! Amplification with the tessellation shaders (notes 01 §3.1, "Amplification
//! (Tessellation Shader)"): a terrain sent as a grid of four-corner patches.
//! The tessellator runs after the vertex shader and divides each patch:
//!
//! - the control shader (glsl/vertex_geometry/tessellation.tesc) sets the
//!   outer level of each edge and the inner levels, from the distance to
//!   the eye (finer near, coarser far);
//! - the evaluation shader (tessellation.tese) places each vertex the
//!   tessellator makes: bilinear across the patch, then raised by the
//!   displacement map.
//!
//! The notes' rule: "edges that are shared between two tessellated areas
//! must share the same outer tessellation level and vertex calculation".
//! With `edges = "shared"` each edge's level comes from its own middle, so
//! both patches that share it compute the same level, and the evaluation
//! shader's vertex depends on the edge alone. With `"per_patch"` each patch
//! takes one level from its centre: neighbours then split a shared edge
//! differently and the terrain cracks (tests/frame/tessellation.rs shows
//! both).
//!
//! Tessellation shaders are GL 4.0. gloss targets 3.3 core: on a context
//! below 4.0 this pass draws nothing, says so once on stderr (and `gloss
//! plan` says it needs 4.0), and the rest of the frame renders. Forward
//! path only.
//!
//! GL state: depth test on (the frame's function), no culling, patches of
//! 4 (glPatchParameteri(GL_PATCH_VERTICES, 4)), glPolygonMode(GL_LINE) for
//! the wireframe; restores GL_FILL, culling off as found, no depth test.

use crate::frame::lights::FrameLights;
use crate::frame::plan::Pass;
use crate::frame::post::world_target;
use crate::frame::targets::TargetDesc;
use crate::frame::uniforms::{LIGHTS_BINDING, unit};
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::Gl;
use crate::gl::program::Program;
use crate::gl::stream::StreamBuffer;
use crate::gl::texture::{Sampling, Texture};
use crate::scene::{RenderPath, Scene};
use anyhow::Result;
use glow::HasContext;
use std::cell::{Cell, RefCell};

pub const TESSELLATION: Technique = Technique {
    name: "tessellation",
    notes: "notes 01 §3.1, Amplification (Tessellation Shader)",
    file: file!(),
    shaders: &[
        "vertex_geometry/tessellation.vert",
        "vertex_geometry/tessellation.tesc",
        "vertex_geometry/tessellation.tese",
        "vertex_geometry/tessellation.frag",
    ],
    scene: "scenes/tessellated-terrain.toml",
    docs: "docs/vertex_geometry/tessellation.md",
    knobs: &[],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::PerView,
};

fn passes(scene: &Scene, _: &FrameLights) -> Vec<Pass> {
    let Some(t) = &scene.tessellation else {
        return vec![];
    };
    if scene.render.path != RenderPath::Forward {
        return vec![];
    }
    let n = t.patches;
    let draws = format!(
        "{} patches ({n} x {n}) of 4 corners, levels {} to {}, {} (needs OpenGL 4.0)",
        n * n,
        t.levels[0],
        t.levels[1],
        if t.shared_edges {
            "a level per edge"
        } else {
            "a level per patch: cracks"
        }
    );
    vec![Pass::new(
        "tessellation",
        world_target(scene),
        draws,
        file!(),
    )]
}

fn targets(_: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    vec![]
}

/// The patch corners of an `n` x `n` grid over a square of side `size` on
/// y = 0: per patch (u0, v0), (u1, v0), (u1, v1), (u0, v1), u along x and v
/// along z. Neighbours share their corners exactly.
pub fn grid(size: f32, n: u32) -> Vec<[f32; 3]> {
    let at = |i: u32| -size * 0.5 + size * i as f32 / n as f32;
    let mut out = Vec::with_capacity((n * n * 4) as usize);
    for j in 0..n {
        for i in 0..n {
            let (x0, x1, z0, z1) = (at(i), at(i + 1), at(j), at(j + 1));
            out.extend([[x0, 0.0, z0], [x1, 0.0, z0], [x1, 0.0, z1], [x0, 0.0, z1]]);
        }
    }
    out
}

struct Tessellation {
    gl: Gl,
    /// None below GL 4.0.
    program: Option<Program>,
    /// The grid's corners (and how many) and the displacement map, made at
    /// the first frame (they depend on the scene) and again when it changes.
    made: RefCell<
        Option<(
            crate::scene::tessellation::Tessellation,
            StreamBuffer,
            i32,
            Texture,
        )>,
    >,
    warned: Cell<bool>,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    let v = p.gl.version();
    let program = if v.major >= 4 {
        let program = p.build(&[
            (glow::VERTEX_SHADER, "vertex_geometry/tessellation.vert"),
            (
                glow::TESS_CONTROL_SHADER,
                "vertex_geometry/tessellation.tesc",
            ),
            (
                glow::TESS_EVALUATION_SHADER,
                "vertex_geometry/tessellation.tese",
            ),
            (glow::FRAGMENT_SHADER, "vertex_geometry/tessellation.frag"),
        ])?;
        program.bind_uniform_block("Lights", LIGHTS_BINDING);
        Some(program)
    } else {
        None
    };
    Ok(Box::new(Tessellation {
        gl: p.gl.clone(),
        program,
        made: RefCell::new(None),
        warned: Cell::new(false),
    }))
}

impl RunPasses for Tessellation {
    fn run(&self, _: &Pass, f: &Frame) {
        let Some(t) = &f.scene.tessellation else {
            return;
        };
        let Some(p) = &self.program else {
            if !self.warned.replace(true) {
                let v = f.gl.version();
                eprintln!(
                    "gloss: the tessellated terrain needs OpenGL 4.0 (tessellation shaders); this context is {}.{}: the rest of the scene is drawn without it",
                    v.major, v.minor
                );
            }
            return;
        };
        let mut made = self.made.borrow_mut();
        if made.as_ref().is_none_or(|(had, ..)| had != t) {
            let gl = &self.gl;
            // The corners at location 0, written once.
            let built = StreamBuffer::new(gl, &[(0, 3, 0)], 12).and_then(|corners| {
                let g = grid(t.size, t.patches);
                let bytes: Vec<u8> = g.iter().flatten().flat_map(|x| x.to_ne_bytes()).collect();
                corners.write_subdata(&bytes);
                let map = Texture::load(gl, &t.displacement, false, Sampling::TRILINEAR_REPEAT)?;
                Ok((t.clone(), corners, g.len() as i32, map))
            });
            match built {
                Ok(m) => *made = Some(m),
                Err(e) => {
                    eprintln!("gloss: tessellation: {e:#}");
                    return;
                }
            }
        }
        let (_, corners, count, map) = made.as_ref().expect("made above");
        let (gl, u) = (f.gl, f.uniforms);
        let target = f.targets.get(world_target(f.scene));
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(target.id));
            let (x, y, w, h) = f.view.rect(target.width, target.height);
            gl.viewport(x, y, w, h);
            gl.enable(glow::DEPTH_TEST);
            gl.depth_func(f.scene.render.depth_func.gl());
            gl.depth_mask(true);
            gl.disable(glow::CULL_FACE);
            if t.wireframe {
                gl.polygon_mode(glow::FRONT_AND_BACK, glow::LINE);
            }
            gl.patch_parameter_i32(glow::PATCH_VERTICES, 4);

            p.use_program();
            p.set_mat4("u_view_projection", &u.view_projection);
            p.set_vec3("u_eye", u.eye);
            p.set_vec2("u_levels", glam::Vec2::from(t.levels));
            p.set_vec2("u_distances", glam::Vec2::from(t.distances));
            p.set_bool("u_shared_edges", t.shared_edges);
            p.set_f32("u_size", t.size);
            p.set_f32("u_height_scale", t.height);
            p.set_vec3("u_color", t.color);
            p.set_vec3("u_ambient", f.scene.render.ambient);
            p.set_i32("u_light_count", u.light_count);
            p.set_bool("u_output_srgb", u.output_srgb);
            gl.active_texture(glow::TEXTURE0 + unit::TERRAIN_HEIGHT);
            gl.bind_texture(glow::TEXTURE_2D, Some(map.id));
            p.set_i32("u_height", unit::TERRAIN_HEIGHT as i32);
            gl.bind_buffer_base(glow::UNIFORM_BUFFER, LIGHTS_BINDING, Some(u.lights_ubo));
            corners.draw(glow::PATCHES, *count);

            gl.bind_buffer_base(glow::UNIFORM_BUFFER, LIGHTS_BINDING, None);
            gl.bind_texture(glow::TEXTURE_2D, None);
            gl.use_program(None);
            gl.polygon_mode(glow::FRONT_AND_BACK, glow::FILL);
            gl.disable(glow::DEPTH_TEST);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn neighbouring_patches_share_their_corners_exactly() {
        let n = 5;
        let g = grid(10.0, n);
        assert_eq!(g.len(), (n * n * 4) as usize);
        let patch = |i: u32, j: u32| &g[((j * n + i) * 4) as usize..((j * n + i) * 4 + 4) as usize];
        for j in 0..n {
            for i in 0..n - 1 {
                let (a, b) = (patch(i, j), patch(i + 1, j));
                // a's u = 1 edge is b's u = 0 edge, bit for bit.
                assert_eq!((a[1], a[2]), (b[0], b[3]));
            }
        }
        for j in 0..n - 1 {
            let (a, b) = (patch(2, j), patch(2, j + 1));
            assert_eq!((a[3], a[2]), (b[0], b[1]));
        }
        assert_eq!(g[0], [-5.0, 0.0, -5.0]);
        assert_eq!(*g.last().unwrap(), [-5.0 + 10.0 * 4.0 / 5.0, 0.0, 5.0]);
    }
}
