//! Area lights with linearly transformed cosines (Heitz, Dupuy, Hill and
//! Neubelt 2016, "Real-Time Polygonal-Light Shading with Linearly
//! Transformed Cosines": §3 linearly transformed distributions, §4 the GGX
//! fit, §5 polygonal-light shading; the shader `LTC_Evaluate` of its code,
//! selfshadow/ltc_code).
//!
//! A rectangle of uniform radiance L_e lights a surface by the integral of
//! its BRDF times the cosine over the solid angle the rectangle covers.
//! The paper's steps, per fragment and light:
//!
//! ```text
//! 1. M^-1 from the table at (sqrt(alpha), sqrt(1 - N.V)): the linear map
//!    that turns the BRDF's lobe into a clamped cosine
//! 2. the corners into the frame (T1, T2, N), through M^-1
//! 3. ClipQuadToHorizon: clipped to z >= 0
//! 4. Lambert's formula: the form factor, a sum over the edges
//! 5. times the BRDF's magnitude and Fresnel (the second table)
//! ```
//!
//! The diffuse term is step 2 to 4 with M^-1 the identity: the exact
//! polygon integral (src/lighting/area_light.rs), no table. gloss clips to
//! the surface's horizon before M^-1 as well, so a light behind the surface
//! gives nothing (src/lighting/ltc.rs says why). The forward pass does the
//! shading (glsl/lighting/ltc_area_lights.glsl, included by
//! lighting/forward.frag; src/frame/ltc_area_lights.rs binds the two tables
//! on units 25 and 26 as RGBA32F textures). This pass then draws each
//! light's rectangle with its radiance, so that the light is seen, as the
//! paper's demo does: after the world is shaded, into its target, with its
//! depth (after the composite or the combine on the G-buffer paths, whose
//! own pass, deferred/ltc_area_lights_deferred.rs, shades from the
//! G-buffer). Every path but forward's Gouraud and flat shading; the
//! scene's warnings name what else leaves the lights out.
//!
//! GL state: glDepthFunc(GL_LESS) with depth writes on, no culling
//! (gl_FrontFacing tells the lit side), glFrontFace for a reflected view,
//! the stencil test and clip distances as forward's pass sets them; restores
//! no depth test, GL_CCW, no stencil test, no clip distance, no program,
//! no vertex array.

use crate::frame::lights::FrameLights;
use crate::frame::ltc_area_lights::wanted;
use crate::frame::plan::Pass;
use crate::frame::post::world_target;
use crate::frame::targets::TargetDesc;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::geometry::{MeshData, Vertex};
use crate::gl::mesh::Mesh;
use crate::gl::program::Program;
use crate::scene::area_lights::AreaLightReference;
use crate::scene::{RenderPath, Scene, knobs};
use anyhow::Result;
use glow::HasContext;

pub const LTC_AREA_LIGHTS: Technique = Technique {
    name: "ltc_area_lights",
    notes: "beyond the notes: Heitz, Dupuy, Hill and Neubelt 2016, Real-Time Polygonal-Light Shading with Linearly Transformed Cosines",
    file: file!(),
    shaders: &[
        "lighting/ltc_area_lights.glsl",
        "lighting/area_light_reference.glsl",
        "lighting/ltc_area_lights.vert",
        "lighting/ltc_area_lights.frag",
    ],
    scene: "scenes/area-lights.toml",
    docs: "docs/lighting/ltc_area_lights.md",
    knobs: &[
        &knobs::AREA_LIGHTS,
        &knobs::AREA_LIGHT_REFERENCE,
        &knobs::AREA_LIGHT_POINTS,
    ],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::PerView,
};

fn passes(scene: &Scene, _: &FrameLights) -> Vec<Pass> {
    if !wanted(scene) {
        return vec![];
    }
    let n = scene.area_lights.len();
    let r = &scene.render;
    let shaded = match (r.path, r.area_light_reference) {
        (RenderPath::Forward, AreaLightReference::Off) => {
            "the forward pass shaded the world with them by LTC".to_string()
        }
        (RenderPath::Forward, reference) => {
            let points = r.area_light_points;
            format!(
                "the forward pass shaded the world with them by the {reference} reference: gloss's BRDF at {points} x {points} points a triangle of each light"
            )
        }
        _ => "the area lights (LTC) pass shaded the world with them by LTC".to_string(),
    };
    let draws = format!("{n} area lights x 2 triangles, each its radiance ({shaded})");
    vec![Pass::new(
        "area lights",
        world_target(scene),
        draws,
        file!(),
    )]
}

fn targets(_: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    vec![]
}

struct LtcAreaLights {
    program: Program,
    /// The unit square (s, t) in 0..=1, two triangles.
    square: Mesh,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    let program = p.build(&[
        (glow::VERTEX_SHADER, "lighting/ltc_area_lights.vert"),
        (glow::FRAGMENT_SHADER, "lighting/ltc_area_lights.frag"),
    ])?;
    let vertices = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]].map(|[s, t]| Vertex {
        position: [s, t, 0.0],
        normal: [0.0, 0.0, 1.0],
        uv: [s, t],
        tangent: [1.0, 0.0, 0.0, 1.0],
    });
    let square = MeshData {
        vertices: vertices.to_vec(),
        indices: vec![0, 1, 2, 0, 2, 3],
        colors: Vec::new(),
    };
    let square = Mesh::upload(p.gl, &square)?;
    Ok(Box::new(LtcAreaLights { program, square }))
}

impl RunPasses for LtcAreaLights {
    fn run(&self, _: &Pass, f: &Frame) {
        let (gl, u, p) = (f.gl, f.uniforms, &self.program);
        let target = f.targets.get(world_target(f.scene));
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(target.id));
            let (x, y, w, h) = f.view.rect(target.width, target.height);
            gl.viewport(x, y, w, h);
            gl.enable(glow::DEPTH_TEST);
            gl.depth_func(glow::LESS);
            gl.depth_mask(true);
            // Both faces drawn: the back of a one-sided light is black.
            gl.front_face(f.view.front_face(false));
            if let Some(region) = f.view.stencil {
                gl.enable(glow::STENCIL_TEST);
                gl.stencil_func(glow::EQUAL, region.into(), 0xff);
                gl.stencil_op(glow::KEEP, glow::KEEP, glow::KEEP);
            }
            if f.view.clips() {
                gl.enable(glow::CLIP_DISTANCE0);
            }
            for i in 0..f.scene.clip_planes.len() as u32 {
                gl.enable(glow::CLIP_DISTANCE1 + i);
            }
            p.use_program();
            p.set_mat4("u_view_projection", &u.view_projection);
            p.set_bool("u_output_srgb", u.output_srgb);
            f.view.set_uniforms(p, u.eye, &f.scene.clip_planes);
            for light in &f.scene.area_lights {
                for (k, c) in light.corners().iter().enumerate() {
                    p.set_vec3(&format!("u_corners[{k}]"), *c);
                }
                p.set_vec3("u_radiance", light.radiance());
                p.set_bool("u_two_sided", light.two_sided);
                self.square.draw();
            }

            // Restore the state this pass changed.
            gl.disable(glow::CLIP_DISTANCE0);
            for i in 0..f.scene.clip_planes.len() as u32 {
                gl.disable(glow::CLIP_DISTANCE1 + i);
            }
            gl.stencil_func(glow::ALWAYS, 0, 0xff);
            gl.disable(glow::STENCIL_TEST);
            gl.front_face(glow::CCW);
            gl.use_program(None);
            gl.disable(glow::DEPTH_TEST);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }
}
