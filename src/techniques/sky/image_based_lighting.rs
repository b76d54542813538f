//! Image-based lighting (Karis 2013, "Real Shading in Unreal Engine 4",
//! Image-Based Lighting): the environment cube map (the `[sky]` rendered by
//! sky_cube_map.rs, or the `[skybox]` faces) as the ambient light of
//! gloss's materials, precomputed into three textures
//! (src/frame/image_based_lighting.rs) when the scene loads and again when
//! the sky changes, with `render.ibl` on. The forward pass, the composite
//! and the light pre-pass's combine read them
//! (glsl/common/image_based_lighting.glsl).
//!
//! 1. The irradiance map: E(N) / pi for the Lambertian k_d, a convolution
//!    of the environment's 16-texel mip level into a 32-texel cube map
//!    (glsl/sky/irradiance_map.frag).
//! 2. PrefilterEnvMap: for each mip level, one GGX roughness, the
//!    environment averaged over the lobe about R with N = V = R
//!    (glsl/sky/prefilter_env_map.frag).
//! 3. IntegrateBRDF: the split sum's table of (A, B), F0 A + B the specular
//!    directional albedo of gloss's microfacet BRDF with Schlick's Fresnel
//!    (glsl/sky/integrate_brdf.frag).
//!
//! Each face of each level is drawn through one framebuffer, the face
//! attached with glFramebufferTexture2D, one full-screen triangle each.
//!
//! GL state: the viewport (the face's size; the passes after it set their
//! own), GL_TEXTURE_CUBE_MAP_SEAMLESS on while sampling the environment,
//! the environment on unit 0; no depth test, no blending (the defaults).
//! Restores no seamless filtering, no texture, the default framebuffer and
//! no program.

use crate::frame::image_based_lighting::{IblMaps, wanted};
use crate::frame::lights::FrameLights;
use crate::frame::plan::Pass;
use crate::frame::targets::TargetDesc;
use crate::frame::uniforms::unit;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::cube_map::CubeMap;
use crate::gl::program::Program;
use crate::lighting::image_based_lighting::{
    BRDF_SAMPLES, BRDF_SIZE, IRRADIANCE_SIZE, IRRADIANCE_SOURCE, PREFILTER_SAMPLES, level_alpha,
};
use crate::scene::{Scene, knobs};
use anyhow::Result;
use glam::Mat4;
use glow::HasContext;

pub const IMAGE_BASED_LIGHTING: Technique = Technique {
    name: "image_based_lighting",
    notes: "beyond the notes: Karis 2013, Real Shading in Unreal Engine 4, Image-Based Lighting",
    file: file!(),
    shaders: &[
        "common/fullscreen.vert",
        "sky/irradiance_map.frag",
        "sky/prefilter_env_map.frag",
        "sky/integrate_brdf.frag",
        "common/image_based_lighting.glsl",
    ],
    scene: "scenes/ibl.toml",
    docs: "docs/sky/image_based_lighting.md",
    knobs: &[&knobs::IBL],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::BeforeViews,
};

fn passes(scene: &Scene, _: &FrameLights) -> Vec<Pass> {
    if !wanted(scene) {
        return vec![];
    }
    let when = "when the scene loads or the sky changes";
    let irradiance = format!(
        "6 faces x 1 full-screen triangle: E(N) / pi, the environment's {IRRADIANCE_SOURCE}-texel level convolved into a {IRRADIANCE_SIZE}x{IRRADIANCE_SIZE} RGBA16F cube map, {when}"
    );
    let prefilter = format!(
        "6 faces x 1 full-screen triangle per mip level: the environment over GGX's lobe, one roughness a level ({PREFILTER_SAMPLES} samples a texel), {when}"
    );
    let brdf = format!(
        "1 full-screen triangle: the split-sum table (A, B) of the microfacet BRDF, {BRDF_SIZE}x{BRDF_SIZE} RG16F, {BRDF_SAMPLES} samples a texel, {when}"
    );
    vec![
        Pass::new("irradiance map", "ibl irradiance", irradiance, file!())
            .without_depth()
            .reading(&["environment"])
            .step(1),
        Pass::new("prefilter env map", "ibl prefiltered", prefilter, file!())
            .without_depth()
            .reading(&["environment"])
            .step(2),
        Pass::new("integrate brdf", "ibl brdf", brdf, file!())
            .without_depth()
            .step(3),
    ]
}

fn targets(_: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    vec![]
}

struct ImageBasedLighting {
    irradiance: Program,
    prefilter: Program,
    brdf: Program,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    let with = |frag: &'static str| {
        p.build(&[
            (glow::VERTEX_SHADER, "common/fullscreen.vert"),
            (glow::FRAGMENT_SHADER, frag),
        ])
    };
    Ok(Box::new(ImageBasedLighting {
        irradiance: with("sky/irradiance_map.frag")?,
        prefilter: with("sky/prefilter_env_map.frag")?,
        brdf: with("sky/integrate_brdf.frag")?,
    }))
}

impl RunPasses for ImageBasedLighting {
    fn run(&self, pass: &Pass, f: &Frame) {
        let environment = &f.draws.environment;
        let (Some(maps), Some(cube)) = (&environment.ibl, &environment.cube) else {
            return;
        };
        // Made already from this environment: nothing to do. The last
        // step records it.
        let source = environment.drawn_for.borrow().clone();
        if maps.made_for.borrow().as_ref() == Some(&source) {
            return;
        }
        match pass.step {
            1 => self.irradiance_map(f, maps, cube),
            2 => self.prefilter_env_map(f, maps, cube),
            _ => {
                self.integrate_brdf(f, maps);
                *maps.made_for.borrow_mut() = Some(source);
            }
        }
    }
}

/// Attach `face` (0..6; None: the 2D table) of `texture` at `level` to the
/// maps' framebuffer, bound.
unsafe fn attach(
    gl: &glow::Context,
    maps: &IblMaps,
    texture: glow::Texture,
    face: Option<u32>,
    level: i32,
) {
    let target = face.map_or(glow::TEXTURE_2D, |i| glow::TEXTURE_CUBE_MAP_POSITIVE_X + i);
    unsafe {
        gl.bind_framebuffer(glow::FRAMEBUFFER, Some(maps.framebuffer));
        gl.framebuffer_texture_2d(
            glow::FRAMEBUFFER,
            glow::COLOR_ATTACHMENT0,
            target,
            Some(texture),
            level,
        );
    }
}

/// The environment on unit::IBL_SOURCE for `p` (in use), filtered across faces.
unsafe fn bind_environment(gl: &glow::Context, p: &Program, cube: &CubeMap) {
    p.set_i32("u_environment", unit::IBL_SOURCE as i32);
    p.set_mat4("u_mvp", &Mat4::IDENTITY);
    unsafe {
        gl.enable(glow::TEXTURE_CUBE_MAP_SEAMLESS);
        gl.active_texture(glow::TEXTURE0 + unit::IBL_SOURCE);
        gl.bind_texture(glow::TEXTURE_CUBE_MAP, Some(cube.id));
    }
}

/// Undo `bind_environment` and the attachment; no program.
unsafe fn restore(gl: &glow::Context) {
    unsafe {
        gl.bind_texture(glow::TEXTURE_CUBE_MAP, None);
        gl.disable(glow::TEXTURE_CUBE_MAP_SEAMLESS);
        gl.framebuffer_texture_2d(
            glow::FRAMEBUFFER,
            glow::COLOR_ATTACHMENT0,
            glow::TEXTURE_2D,
            None,
            0,
        );
        gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        gl.use_program(None);
    }
}

impl ImageBasedLighting {
    /// 1. The diffuse convolution into each face of the irradiance map.
    fn irradiance_map(&self, f: &Frame, maps: &IblMaps, cube: &CubeMap) {
        let (gl, p) = (f.gl, &self.irradiance);
        // The environment's level whose faces are IRRADIANCE_SOURCE texels a side (or level 0).
        let level = (cube.size / IRRADIANCE_SOURCE).max(1).ilog2() as i32;
        unsafe {
            p.use_program();
            bind_environment(gl, p, cube);
            p.set_i32("u_source_level", level);
            p.set_i32("u_source_size", (cube.size >> level).max(1));
            p.set_f32("u_size", IRRADIANCE_SIZE as f32);
            gl.viewport(0, 0, IRRADIANCE_SIZE, IRRADIANCE_SIZE);
            for face in 0..6 {
                attach(gl, maps, maps.irradiance.id, Some(face), 0);
                p.set_i32("u_face", face as i32);
                f.meshes.fullscreen.draw();
            }
            restore(gl);
        }
    }

    /// 2. PrefilterEnvMap into each face of each mip level, one roughness a level.
    fn prefilter_env_map(&self, f: &Frame, maps: &IblMaps, cube: &CubeMap) {
        let (gl, p) = (f.gl, &self.prefilter);
        unsafe {
            p.use_program();
            bind_environment(gl, p, cube);
            p.set_f32("u_source_size", cube.size as f32);
            for level in 0..maps.levels() {
                let size = (maps.prefiltered.size >> level).max(1);
                // Level 0 is the mirror: every GGX sample is R itself.
                let samples = if level == 0 { 1 } else { PREFILTER_SAMPLES };
                p.set_f32("u_alpha", level_alpha(level) as f32);
                p.set_i32("u_samples", samples as i32);
                p.set_f32("u_size", size as f32);
                gl.viewport(0, 0, size, size);
                for face in 0..6 {
                    attach(gl, maps, maps.prefiltered.id, Some(face), level);
                    p.set_i32("u_face", face as i32);
                    f.meshes.fullscreen.draw();
                }
            }
            restore(gl);
        }
    }

    /// 3. IntegrateBRDF into the table.
    fn integrate_brdf(&self, f: &Frame, maps: &IblMaps) {
        let (gl, p) = (f.gl, &self.brdf);
        unsafe {
            p.use_program();
            p.set_mat4("u_mvp", &Mat4::IDENTITY);
            p.set_f32("u_size", BRDF_SIZE as f32);
            p.set_i32("u_samples", BRDF_SAMPLES as i32);
            gl.viewport(0, 0, BRDF_SIZE, BRDF_SIZE);
            attach(gl, maps, maps.brdf.id, None, 0);
            f.meshes.fullscreen.draw();
            restore(gl);
        }
    }
}
