//! Tiled and clustered deferred shading: beyond the notes, where notes 04
//! ends ("Deferred lighting is famous for LOTS OF LIGHTS") and notes 01
//! §8.6.1 asks to shade only the pixels a light reaches. Light volumes do
//! that by rasterising one mesh per light, and pay for it in blending: each
//! pixel reads and writes the accumulation target once per light over it.
//! Tiled shading (Olsson and Assarsson 2011) moves the "which lights reach
//! here" question to a coarse grid, answered once per frame; clustered
//! shading (Olsson et al. 2012; Persson, "Practical Clustered Shading",
//! 2015) cuts the grid along depth too. GL 3.3 has no compute shaders, so
//! the binning runs on the CPU, as Persson's does:
//!
//! 1. Bin: each light's bounding sphere at its cutoff radius (a spot
//!    light's: the sphere around its cone) goes into every screen tile and
//!    depth slice it may touch (src/frame/clusters.rs). Lights with no
//!    finite radius (directional; Kl = Kq = 0) go in a global list that
//!    every pixel shades; the lights with a shadow map (at most eight) are
//!    shaded everywhere too, in a loop of their own, the only one that
//!    samples shadow maps (the shader says why).
//! 2. Upload, through a buffer texture (src/gl/texture_buffer.rs), each
//!    cluster's (offset, count) followed by the light numbers, in one R32UI
//!    buffer. Every light is in the renderer's own buffer texture (four
//!    RGBA32F texels each, the std140 `Light`; `FrameUniforms::
//!    lights_texture`), written with the uniform block when the lights change.
//!    A uniform block would stop at 256 lights on the smallest GL 3.3; a
//!    buffer texture holds 16384 even there.
//! 3. One full-screen triangle: each pixel finds its tile from
//!    gl_FragCoord, its slice from its depth, and loops over the global
//!    lights and its cluster's list (glsl/deferred/tiled_shading.frag),
//!    summing in f32 and writing once. No blending, no depth test.
//!
//! Each listed light is still tested against its radius, as the light-volume
//! shader does, so the image equals the light volumes' at the same cutoff:
//! the binning decides only what it costs.
//!
//! GL state: no depth test, depth writes off; restores depth writes.

use crate::frame::clusters::{self, Bins, Bound, Grid};
use crate::frame::gbuffer;
use crate::frame::lights::FrameLights;
use crate::frame::plan::Pass;
use crate::frame::shadows;
use crate::frame::targets::{Depth, LIGHT_ACCUMULATION, TargetDesc};
use crate::frame::uniforms::{LIGHTS_BINDING, unit};
use crate::frame::variant::LightingVariant;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::program::Program;
use crate::gl::texture_buffer::{TextureBuffer, max_texels};
use crate::scene::knobs;
use crate::scene::{Light, LightKind, RenderPath, Scene};
use crate::techniques::deferred::deferred_shading::accumulation_target;
use crate::techniques::deferred::{far_field, far_lists};
use anyhow::Result;
use glam::{Mat4, Vec3};
use glow::HasContext;

pub const TILED_SHADING: Technique = Technique {
    name: "tiled_shading",
    notes: "beyond the notes: notes 01 §8.6.1 and notes 04's many lights, binned per tile and depth slice (Persson 2015)",
    file: file!(),
    shaders: &["common/fullscreen.vert", "deferred/tiled_shading.frag"],
    scene: "scenes/tiled-shading.toml",
    docs: "docs/deferred/tiled_shading.md",
    knobs: &[
        &knobs::CUTOFF,
        &knobs::TILE_SIZE,
        &knobs::DEPTH_SLICES,
        &knobs::FAR_FIELD,
        &knobs::LIGHT_BLOCK,
        &knobs::LIGHT_DATA,
        &knobs::ACCUMULATION,
    ],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::PerView,
};

fn runs(scene: &Scene, lights: &FrameLights) -> bool {
    scene.render.path == RenderPath::Tiled && !lights.is_empty()
}

fn passes(scene: &Scene, lights: &FrameLights) -> Vec<Pass> {
    if !runs(scene, lights) {
        return vec![];
    }
    let r = &scene.render;
    let (w, h) = r.size;
    let c = &scene.camera;
    let grid = Grid::new(w, h, r.tile_size, r.depth_slices, c.near, c.far);
    let global = (lights.lights.iter())
        .filter(|l| l.radius.is_none())
        .count();
    let draws = format!(
        "1 full-screen triangle; {} lights binned on the CPU into {} x {} tiles ({} px) x {} depth slices = {} clusters{}",
        lights.len() - global,
        grid.tiles.0,
        grid.tiles.1,
        grid.tile_size,
        grid.slices,
        grid.clusters(),
        if global > 0 {
            format!(", {global} with no finite radius shade every pixel")
        } else {
            String::new()
        }
    );
    let variant = LightingVariant::of(scene, lights).describe();
    vec![Pass::new("lighting", LIGHT_ACCUMULATION, draws, file!()).with_variant(variant)]
}

fn targets(scene: &Scene, lights: &FrameLights) -> Vec<TargetDesc> {
    if !runs(scene, lights) {
        return vec![];
    }
    vec![accumulation_target(scene, Depth::None)]
}

/// The sphere that bounds light `l`'s reach at `radius`: a point light's
/// own; for a spot light, the smaller of that and the sphere around the
/// sector of the cone (apex, axis, half-angle theta, length radius), whose
/// centre is radius / (2 cos theta) along the axis for theta <= 45 degrees,
/// and radius cos theta along it (radius sin theta) beyond.
pub fn bounding_sphere(l: &Light, radius: f32) -> (Vec3, f32) {
    let theta = l.outer_angle.to_radians();
    if l.kind != LightKind::Spot || theta >= std::f32::consts::FRAC_PI_2 {
        return (l.position, radius);
    }
    let (s, c) = theta.sin_cos();
    let (along, r) = if theta <= std::f32::consts::FRAC_PI_4 {
        (radius / (2.0 * c), radius / (2.0 * c))
    } else {
        (radius * c, radius * s)
    };
    if r >= radius {
        return (l.position, radius);
    }
    (l.position + l.direction * along, r)
}

/// Each light's bound for the binning: its sphere; the global list (every
/// pixel) without a radius; apart for the lights in `casting` (those with a
/// shadow map this frame), which the shader shades in a loop of their own
/// (`caster(k)`, glsl/common/shadow.glsl).
/// With the far field, the sphere is the near part's: `render.near_radius`
/// times the cutoff radius.
pub fn light_bounds(scene: &Scene, lights: &FrameLights, casting: &[usize]) -> Vec<Bound> {
    let near = if far_field::runs(scene, lights) {
        scene.render.near_radius
    } else {
        1.0
    };
    (scene.lights.iter().zip(&lights.lights).enumerate())
        .map(|(i, (l, f))| match (casting.contains(&i), f.radius) {
            (true, _) => Bound::Apart,
            (false, Some(r)) => {
                let (c, r) = bounding_sphere(l, near * r);
                Bound::Sphere(c, r)
            }
            (false, None) => Bound::Everywhere,
        })
        .collect()
}

struct TiledShading {
    program: Program,
    /// With `far_field.rs`'s far part added (`render.far_field` > 0).
    with_far_field: Program,
    /// Drawing the far field's error bound instead of the light
    /// (`render.far_field_bound`, set by `gloss bench`).
    far_field_bound: Program,
    /// The same two with the far field's diffuse part as harmonics
    /// (`render.far_field_sh`, glsl/common/far_field_sh.glsl).
    with_harmonics: Program,
    harmonics_bound: Program,
    /// Each cluster's (offset, count), then the light numbers.
    clusters: TextureBuffer,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    let stages = [
        (glow::VERTEX_SHADER, "common/fullscreen.vert"),
        (glow::FRAGMENT_SHADER, "deferred/tiled_shading.frag"),
    ];
    // Specialised to the frame's lighting variant (src/frame/variant.rs).
    let program = p.build_variant(&stages)?;
    let with_far_field = p.build_variant_with(&stages, &[("FAR_FIELD", "1".into())])?;
    let far_field_bound = p.build_variant_with(
        &stages,
        &[("FAR_FIELD", "1".into()), ("FAR_FIELD_BOUND", "1".into())],
    )?;
    let with_harmonics = p.build_variant_with(
        &stages,
        &[("FAR_FIELD", "1".into()), ("FAR_FIELD_SH", "1".into())],
    )?;
    let harmonics_bound = p.build_variant_with(
        &stages,
        &[
            ("FAR_FIELD", "1".into()),
            ("FAR_FIELD_SH", "1".into()),
            ("FAR_FIELD_BOUND", "1".into()),
        ],
    )?;
    for program in [
        &program,
        &with_far_field,
        &far_field_bound,
        &with_harmonics,
        &harmonics_bound,
    ] {
        // shadow_visibility reads the caster from the Lights block (the
        // casters are among the lights the block holds: check_lights_fit).
        program.bind_uniform_block("Lights", LIGHTS_BINDING);
        shadows::setup_program(program);
    }
    Ok(Box::new(TiledShading {
        program,
        with_far_field,
        far_field_bound,
        with_harmonics,
        harmonics_bound,
        clusters: TextureBuffer::new(p.gl, glow::R32UI)?,
    }))
}

/// Step 1 for this view: the grid over its rectangle and the lights binned
/// into it (every light global in a curved mirror's view, whose pixels do
/// not lie on straight rays from one eye).
pub fn bin_view(f: &Frame, size: (u32, u32), max_texels: usize) -> (Grid, Bins) {
    let r = &f.scene.render;
    let u = f.uniforms;
    let grid = Grid::new(size.0, size.1, r.tile_size, r.depth_slices, u.near, u.far);
    let mut bounds = light_bounds(f.scene, f.lights, &f.shadows.casting_lights());
    if f.view.curved.is_some() {
        for b in bounds.iter_mut().filter(|b| **b != Bound::Apart) {
            *b = Bound::Everywhere;
        }
    }
    let view = u.view * f.view.reflection;
    clusters::bin_within(&grid, view, u.projection, size, &bounds, max_texels)
}

impl RunPasses for TiledShading {
    fn run(&self, _: &Pass, f: &Frame) {
        let (gl, u) = (f.gl, f.uniforms);
        let target = f.targets.get(LIGHT_ACCUMULATION);
        let (x, y, w, h) = f.view.rect(target.width, target.height);

        // 1. Bin the lights for this view.
        let (grid, bins) = bin_view(f, (w as u32, h as u32), max_texels(gl));

        // 2. Upload the lists (the lights are the frame's buffer texture,
        // written when the scene's lights change: FrameUniforms::lights_texture).
        // With far lists (far_lists.rs), each cluster's far list after them.
        let far_bins = far_field::lists_on(f.scene, f.lights).then(|| {
            let casting = f.shadows.casting_lights();
            let bounds = far_lists::far_bounds(f.scene, f.lights, &casting, bounding_sphere);
            let view = u.view * f.view.reflection;
            far_lists::bin(&grid, view, u.projection, (w as u32, h as u32), &bounds)
        });
        let far_bins = far_bins.filter(|b| far_lists::texel_count(&bins, b) <= max_texels(gl));
        let (texels, index_base, far_index_base) = far_lists::texels(&bins, far_bins.as_ref());
        let lists: Vec<u8> = texels.iter().flat_map(|v| v.to_ne_bytes()).collect();
        self.clusters.write(&lists);
        if f.view.name == "camera" {
            // Kept for the pixel probe (src/renderer/probe.rs).
            *f.draws.tiled_lists.borrow_mut() = Some((grid, bins.clone()));
        }

        // 3. One full-screen pass over the G-buffer.
        let far = far_field::runs(f.scene, f.lights);
        let r = &f.scene.render;
        let p = match (far, r.far_field_sh, r.far_field_bound) {
            (true, false, true) => &self.far_field_bound,
            (true, false, false) => &self.with_far_field,
            (true, true, true) => &self.harmonics_bound,
            (true, true, false) => &self.with_harmonics,
            (false, _, _) => &self.program,
        };
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(target.id));
            gl.viewport(x, y, w, h);
            gl.clear_color(0.0, 0.0, 0.0, 0.0);
            gl.clear(glow::COLOR_BUFFER_BIT);
            gl.disable(glow::DEPTH_TEST);
            gl.depth_mask(false);

            p.use_program();
            gbuffer::bind_for_reading(gl, p, f.targets.get(gbuffer::NAME), u);
            for (name, unit, texture) in [
                ("u_light_data", unit::TILED_LIGHTS, u.lights_texture),
                ("u_clusters", unit::TILED_CLUSTERS, self.clusters.texture),
            ] {
                gl.active_texture(glow::TEXTURE0 + unit);
                gl.bind_texture(glow::TEXTURE_BUFFER, Some(texture));
                p.set_i32(name, unit as i32);
            }
            p.set_mat4("u_mvp", &Mat4::IDENTITY);
            p.set_mat4("u_view", &(u.view * f.view.reflection));
            p.set_i32("u_index_base", index_base);
            p.set_i32("u_global_count", bins.global as i32);
            if far {
                far_field::bind_for_reading(f, p);
                // 0: no far lists; else the far table's first texel.
                let table = far_bins
                    .as_ref()
                    .map_or(0, |_| 2 * bins.clusters.len() as i32);
                p.set_i32("u_far_table", table);
                p.set_i32("u_far_index_base", far_index_base);
            }
            p.set_ivec3(
                "u_grid",
                glam::IVec3::new(grid.tiles.0 as i32, grid.tiles.1 as i32, grid.slices as i32),
            );
            p.set_i32("u_tile_size", grid.tile_size as i32);
            let (scale, bias) = grid.slice_scale_bias();
            p.set_vec2("u_slice_scale_bias", glam::Vec2::new(scale, bias));
            gl.bind_buffer_base(glow::UNIFORM_BUFFER, LIGHTS_BINDING, Some(u.lights_ubo));
            f.shadows.bind(gl);
            f.meshes.fullscreen.draw();

            f.shadows.unbind(gl);
            if far {
                far_field::unbind_textures(f);
            }
            gl.bind_buffer_base(glow::UNIFORM_BUFFER, LIGHTS_BINDING, None);
            for unit in [unit::TILED_LIGHTS, unit::TILED_CLUSTERS] {
                gl.active_texture(glow::TEXTURE0 + unit);
                gl.bind_texture(glow::TEXTURE_BUFFER, None);
            }
            gl.active_texture(glow::TEXTURE0);
            gbuffer::unbind(gl);
            gl.use_program(None);
            gl.depth_mask(true);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spot(outer: f32) -> Light {
        Light {
            range: None,
            kind: LightKind::Spot,
            position: Vec3::new(1.0, 2.0, 3.0),
            direction: Vec3::new(0.0, -0.6, -0.8),
            color: Vec3::ONE,
            intensity: 1.0,
            kc: 1.0,
            kl: 0.09,
            kq: 0.032,
            inner_angle: outer * 0.5,
            outer_angle: outer,
            shadow: None,
        }
    }

    /// The sphere holds the cone's sector: the apex, points along the rim
    /// and over the cap, for narrow and wide cones.
    #[test]
    fn a_spot_lights_sphere_holds_its_cone() {
        for outer in [1.0, 10.0, 30.0, 45.0, 46.0, 60.0, 89.0, 90.0, 120.0] {
            let l = spot(outer);
            let (c, r) = bounding_sphere(&l, 5.0);
            assert!(r <= 5.0 + 1e-5);
            let axis = l.direction;
            let side = axis.any_orthonormal_vector();
            let theta = outer.min(90.0).to_radians();
            for k in 0..=16 {
                let phi = theta * k as f32 / 16.0;
                for turn in 0..8 {
                    let q = glam::Quat::from_axis_angle(axis, turn as f32 * 0.785);
                    let dir = axis * phi.cos() + q * side * phi.sin();
                    for t in [0.0, 0.5, 1.0] {
                        let p = l.position + dir * 5.0 * t;
                        assert!(
                            (p - c).length() <= r * (1.0 + 1e-5),
                            "outer {outer}: {p} is {} from the centre, radius {r}",
                            (p - c).length()
                        );
                    }
                }
            }
            if outer < 60.0 {
                assert!(
                    r < 5.0,
                    "a narrow cone gets a smaller sphere ({outer}: {r})"
                );
            }
        }
    }
}
