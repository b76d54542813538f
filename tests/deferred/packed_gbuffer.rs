//! The packed G-buffer (`render.gbuffer = "octahedral"`, src/frame/gbuffer.rs):
//! the octahedral normal (Cigolle et al. 2014) in 12 + 12 bits and the
//! shininess as an index into the scene's table, in one RGBA8 attachment.
//!
//! * glsl/common/octahedral.glsl against its CPU twin (src/math/octahedral.rs),
//!   run on the GPU by transform feedback: the bytes it packs equal the CPU's,
//!   what it unpacks from the CPU's bytes equals the CPU's decode, and the
//!   round trip stays within the 12-bit bound, on a sphere of directions and
//!   the hard cases (the poles, (0, 0, -1), the octahedron's seams).
//! * every G-buffer path draws the shipped scenes with it as forward does
//!   (the deferred bound), no further from it than with the RGBA16F normal
//!   but for one step;
//! * `gloss plan` says which encoding and the bytes a pixel; a scene with
//!   more shininess values than the table, or tiled shading's far field,
//!   keeps RGBA16F and says why.

use crate::common;
use glam::Vec3;
use gloss::frame::lights::FrameLights;
use gloss::frame::plan::FramePlan;
use gloss::image_compare::compare_rgba8;
use gloss::math::octahedral::{self, angle, hard_cases};
use gloss::renderer::Output;
use gloss::scene::material::GBufferNormals;
use gloss::scene::{RenderPath, Scene};
use glow::HasContext;

const VERT: &str = "#version 330 core
#include \"common/octahedral.glsl\"
layout(location = 0) in vec3 a_normal;
layout(location = 1) in vec3 a_cpu_bytes;   // the CPU's three bytes / 255
out vec3 t_packed;
out vec3 t_round_trip;
out vec3 t_from_cpu;
void main() {
    t_packed = oct_pack(a_normal);
    t_round_trip = oct_unpack(t_packed);
    t_from_cpu = oct_unpack(a_cpu_bytes);
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}
";

/// Run glsl/common/octahedral.glsl on `normals`: (packed, round trip,
/// unpacked from the CPU's bytes) for each, by transform feedback.
fn on_the_gpu(ctx: &gloss::gl::Headless, normals: &[Vec3]) -> Vec<[Vec3; 3]> {
    let gl = &ctx.gl;
    let varyings = ["t_packed", "t_round_trip", "t_from_cpu"];
    let p = common::feedback_program(gl, "octahedral.glsl", VERT, &varyings);
    let input: Vec<f32> = (normals.iter())
        .flat_map(|&n| {
            let b = octahedral::pack(n).map(|x| f32::from(x) / 255.0);
            [n.x, n.y, n.z, b[0], b[1], b[2]]
        })
        .collect();
    let bytes = normals.len() * 9 * 4;
    let f = unsafe {
        let vao = gl.create_vertex_array().unwrap();
        gl.bind_vertex_array(Some(vao));
        let vbo = gl.create_buffer().unwrap();
        gl.bind_buffer(glow::ARRAY_BUFFER, Some(vbo));
        let raw: Vec<u8> = input.iter().flat_map(|f| f.to_le_bytes()).collect();
        gl.buffer_data_u8_slice(glow::ARRAY_BUFFER, &raw, glow::STATIC_DRAW);
        gl.enable_vertex_attrib_array(0);
        gl.vertex_attrib_pointer_f32(0, 3, glow::FLOAT, false, 24, 0);
        gl.enable_vertex_attrib_array(1);
        gl.vertex_attrib_pointer_f32(1, 3, glow::FLOAT, false, 24, 12);
        let f = common::capture_feedback(
            gl,
            &p,
            glow::POINTS,
            bytes,
            |_| {},
            |gl| gl.draw_arrays(glow::POINTS, 0, normals.len() as i32),
        );
        gl.bind_buffer(glow::ARRAY_BUFFER, None);
        gl.bind_vertex_array(None);
        gl.delete_buffer(vbo);
        gl.delete_vertex_array(vao);
        f
    };
    let v = |k: usize| Vec3::new(f[k], f[k + 1], f[k + 2]);
    (0..normals.len())
        .map(|i| [v(9 * i), v(9 * i + 3), v(9 * i + 6)])
        .collect()
}

/// Directions spread over the sphere (Fibonacci), then the hard cases.
fn directions() -> Vec<Vec3> {
    sphere(20_000).into_iter().chain(hard_cases()).collect()
}

#[test]
fn the_glsl_packs_and_unpacks_as_the_cpu_twin() {
    let ctx = common::context(common::backend());
    let normals = directions();
    let got = on_the_gpu(&ctx, &normals);
    let (mut worst_trip, mut worst_twin, mut byte_mismatches) = (0.0f32, 0.0f32, 0);
    for (&n, [packed, trip, from_cpu]) in normals.iter().zip(&got) {
        // The stored bytes: what the GPU writes (x 255) against the CPU's.
        let gpu = packed.to_array().map(|c| (c * 255.0).round() as u8);
        let cpu = octahedral::pack(n);
        if gpu != cpu {
            byte_mismatches += 1;
            // Only a 12-bit number off by one, where the two round a tie apart.
            let twelve = |b: [u8; 3]| {
                let u = (i32::from(b[0]) << 4) | (i32::from(b[2]) >> 4);
                let v = (i32::from(b[1]) << 4) | (i32::from(b[2]) & 15);
                (u, v)
            };
            let (g, c) = (twelve(gpu), twelve(cpu));
            assert!(
                (g.0 - c.0).abs() <= 1 && (g.1 - c.1).abs() <= 1,
                "{n}: GLSL packs {gpu:?}, the CPU {cpu:?}"
            );
        }
        // The GLSL's decode of the CPU's bytes is the CPU's decode.
        let twin = octahedral::unpack(cpu);
        worst_twin = worst_twin.max((*from_cpu - twin).length());
        // The round trip in GLSL stays within the 12-bit bound, on its side
        // of every seam.
        worst_trip = worst_trip.max(angle(n, *trip));
        assert!(trip.z * n.z >= -1e-3, "{n} came back as {trip}");
    }
    eprintln!(
        "octahedral GLSL vs CPU: {} directions, {byte_mismatches} packed differently (a tie), \
         decode differs by {worst_twin:e}, round trip worst {worst_trip:e} rad",
        normals.len()
    );
    assert!(worst_twin < 2e-6, "GLSL unpack vs CPU: {worst_twin}");
    assert!(worst_trip < BOUND, "round trip: {worst_trip} rad");
    assert!(
        byte_mismatches * 100 < normals.len(),
        "{byte_mismatches} mismatches"
    );
    // (0, 0, -1), the point the whole lower edge folds to, comes back exactly.
    let south = normals.iter().position(|&n| n == Vec3::NEG_Z).unwrap();
    assert!(
        (got[south][1] - Vec3::NEG_Z).length() < 1e-6,
        "{}",
        got[south][1]
    );
}

/// The largest angle the 12-bit grid is off by: half a step (1 / 4095) on
/// each coordinate of the square, stretched where the octahedron's faces
/// meet the sphere at their steepest (about 3x near the equator's
/// diagonals). The RGBA16F normal's is about 4e-4.
const BOUND: f32 = 1.2e-3;

fn sphere(n: usize) -> Vec<Vec3> {
    let golden = std::f32::consts::PI * (3.0 - 5f32.sqrt());
    (0..n)
        .map(|i| {
            let z = 1.0 - 2.0 * (i as f32 + 0.5) / n as f32;
            let r = (1.0 - z * z).sqrt();
            let a = golden * i as f32;
            Vec3::new(r * a.cos(), r * a.sin(), z)
        })
        .collect()
}

#[test]
fn the_cpu_twin_round_trips_within_the_twelve_bit_bound() {
    let all: Vec<Vec3> = sphere(200_000).into_iter().chain(hard_cases()).collect();
    for &n in &all {
        // Unquantised, the mapping is exact to float.
        let back = octahedral::decode(octahedral::encode(n));
        assert!((n - back).length() < 2e-6, "{n} -> {back}");
    }
    let worst = (all.iter())
        .map(|&n| angle(n, octahedral::unpack(octahedral::pack(n))))
        .fold(0.0f32, f32::max);
    eprintln!(
        "octahedral 12 + 12 bits on the CPU: worst {worst:e} rad over {} directions",
        all.len()
    );
    // Not a loose bound: the grid's worst comes within 25% of it.
    assert!(worst < BOUND && worst > 0.75 * BOUND, "worst {worst} rad");
    // (0, 0, -1) folds to the square's corner (1, 1) and comes back exactly;
    // each side of a seam stays on its side.
    assert_eq!(octahedral::encode(Vec3::NEG_Z), glam::Vec2::ONE);
    assert_eq!(
        octahedral::unpack(octahedral::pack(Vec3::NEG_Z)),
        Vec3::NEG_Z
    );
    for n in hard_cases() {
        let back = octahedral::unpack(octahedral::pack(n));
        assert!(
            angle(n, back) < BOUND && back.z * n.z >= -1e-3,
            "{n} -> {back}"
        );
    }
}

fn on(scene: &Scene, path: RenderPath, normals: GBufferNormals) -> Scene {
    let mut s = crate::with_path(scene, path);
    s.render.gbuffer = normals;
    s.render.size = (320, 180);
    s
}

#[test]
fn every_gbuffer_path_draws_as_forward_with_the_packed_normal() {
    let ctx = common::context(common::backend());
    for name in ["deferred-shading", "microfacet", "bump-mapping"] {
        let scene = common::scene(&format!("{name}.toml"));
        let forward = on(&scene, RenderPath::Forward, GBufferNormals::Rgba16f);
        let forward = common::render_with(&ctx, &forward, Output::Srgb8).image;
        for path in [RenderPath::Deferred, RenderPath::Tiled, RenderPath::Prepass] {
            let packed = on(&scene, path, GBufferNormals::Octahedral);
            let image = common::render_with(&ctx, &packed, Output::Srgb8).image;
            let f16 = on(&scene, path, GBufferNormals::Rgba16f);
            let f16 = common::render_with(&ctx, &f16, Output::Srgb8).image;
            let m = compare_rgba8(&image, &forward, 1.0 / 255.0).unwrap();
            let n = compare_rgba8(&f16, &forward, 1.0 / 255.0).unwrap();
            eprintln!(
                "{name} {path} vs forward: octahedral max {:.0}/255 ({:.3}% > 1/255, RMSE {:.3}), \
                 RGBA16F max {:.0}/255 ({:.3}%, RMSE {:.3})",
                m.max_abs * 255.0,
                m.frac_over * 100.0,
                m.rmse * 255.0,
                n.max_abs * 255.0,
                n.frac_over * 100.0,
                n.rmse * 255.0
            );
            let tag = format!("packed_gbuffer_{name}_{path}");
            common::assert_close(&tag, &image, &forward, &crate::DEFERRED_BOUND);
            // No further from forward than the RGBA16F normal, but for one step.
            assert!(
                m.max_abs <= n.max_abs + 1.0 / 255.0 && m.frac_over <= n.frac_over + 1e-3,
                "{tag}: octahedral {m:?} against RGBA16F {n:?}"
            );
        }
    }
}

#[test]
fn the_plan_names_the_encoding_and_its_bytes_per_pixel() {
    let gbuffer_pass = |s: &Scene| {
        let plan = FramePlan::new(s, &FrameLights::new(s), gloss::techniques::ALL);
        let p = plan.passes.iter().find(|p| p.name == "gbuffer").unwrap();
        let t = plan.targets.iter().find(|t| t.name == "gbuffer").unwrap();
        (p.draws.clone(), t.colors[0])
    };
    let scene = common::scene("deferred-shading.toml");
    let packed = on(&scene, RenderPath::Deferred, GBufferNormals::Octahedral);
    let (what, normal) = gbuffer_pass(&packed);
    // RGBA8 normal, two SRGB8_ALPHA8, 24-bit depth (padded to 4): 16 bytes.
    assert_eq!(normal, ("normal_octahedral", glow::RGBA8));
    assert!(
        what.contains("octahedral normal RGBA8") && what.contains("16 bytes/px"),
        "{what}"
    );
    let (what, normal) = gbuffer_pass(&on(&scene, RenderPath::Deferred, GBufferNormals::Rgba16f));
    assert_eq!(normal, ("normal_shininess", glow::RGBA16F));
    assert!(
        what.contains("normal RGBA16F") && what.contains("20 bytes/px"),
        "{what}"
    );

    // 65 shininess values: more than the table holds, so RGBA16F, said.
    let mut text = String::from(
        "name = \"t\"\n[camera]\neye = [0.0, 2.0, 5.0]\ntarget = [0.0, 0.0, 0.0]\n\
         [render]\npath = \"deferred\"\ngbuffer = \"octahedral\"\n",
    );
    for i in 0..65 {
        text.push_str(&format!("[materials.m{i}]\nshininess = {}.0\n", i + 2));
    }
    for i in 0..65 {
        text.push_str(&format!(
            "[[objects]]\nmesh = \"cube\"\nmaterial = \"m{i}\"\n"
        ));
    }
    let many = Scene::parse(&text, &common::root().join("scenes/t.toml")).unwrap();
    let (what, normal) = gbuffer_pass(&many);
    assert_eq!(normal.1, glow::RGBA16F);
    assert!(what.contains("more than the packed table's 64"), "{what}");

    // Tiled shading's far field compares normals finer than the 12-bit grid:
    // RGBA16F, said.
    let mut far = on(&scene, RenderPath::Tiled, GBufferNormals::Octahedral);
    far.render.far_field = 4;
    let (what, normal) = gbuffer_pass(&far);
    assert_eq!(normal, ("normal_shininess", glow::RGBA16F));
    assert!(what.contains("far field"), "{what}");
}
