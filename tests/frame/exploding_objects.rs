//! Exploding objects (LearnOpenGL, Geometry Shader;
//! src/techniques/vertex_geometry/exploding_objects.rs): every triangle the
//! geometry shader emits, captured by transform feedback
//! (glBeginTransformFeedback(GL_TRIANGLES) with the rasterizer off), against
//! the mesh on the CPU: triangle t's vertex j is model x position moved by
//! magnitude x (sin(time) + 1) / 2 along the triangle's outward face normal,
//! normalize((p1 - p0) x (p2 - p0)), for a smooth torus, a faceted cube and
//! a rock, under a model matrix that turns, scales unevenly and moves, and
//! one that mirrors. At magnitude 0 every corner is forward.vert's own,
//! bit for bit, and the shipped scene's image the whole one (llvmpipe's
//! other vertex pipeline for a geometry shader: at most 4 pixels off by 1/255).

use crate::common;
use glam::{Mat4, Vec3};
use gloss::geometry::MeshData;
use gloss::gl::mesh::Mesh;
use gloss::gl::program::{Program, Sources};
use gloss::renderer::Output;
use gloss::techniques::vertex_geometry::exploding_objects::{STAGES, offset};
use glow::HasContext;

/// The triangles' corners (world space) the geometry shader emits for
/// `mesh` under `model`, read back from a transform feedback buffer.
fn captured(
    ctx: &gloss::gl::Headless,
    mesh: &MeshData,
    model: Mat4,
    magnitude: f32,
    time: f32,
) -> Vec<Vec3> {
    // The vertex and geometry stages: the rasterizer is off, no fragment runs.
    capture(ctx, &[STAGES[0], STAGES[1]], mesh, model, magnitude, time)
}

/// `v_position` of every corner that `stages` hand to the rasterizer.
fn capture(
    ctx: &gloss::gl::Headless,
    stages: &[(u32, &str)],
    mesh: &MeshData,
    model: Mat4,
    magnitude: f32,
    time: f32,
) -> Vec<Vec3> {
    let gl = &ctx.gl;
    let p = Program::with_feedback(gl, &Sources::Embedded, stages, &[], &["v_position"]).unwrap();
    let m = Mesh::upload(gl, mesh).unwrap();
    let bytes = mesh.indices.len() * 12;
    let set = |p: &Program| {
        p.set_mat4("u_model", &model);
        p.set_mat3(
            "u_normal_matrix",
            &gloss::frame::draw_list::normal_matrix(&model),
        );
        let mirrored = model.determinant() < 0.0;
        p.set_f32("u_mirror", if mirrored { -1.0 } else { 1.0 });
        p.set_vec4("u_uv_transform", glam::Vec4::new(1.0, 1.0, 0.0, 0.0));
        p.set_mat4("u_view_projection", &Mat4::IDENTITY);
        p.set_f32("u_time", time);
        p.set_f32("u_magnitude", magnitude);
    };
    let floats = common::capture_feedback(gl, &p, glow::TRIANGLES, bytes, set, |gl| unsafe {
        gl.bind_vertex_array(Some(m.vao));
        gl.draw_elements(glow::TRIANGLES, m.index_count, glow::UNSIGNED_INT, 0);
        gl.bind_vertex_array(None);
    });
    floats.chunks_exact(3).map(Vec3::from_slice).collect()
}

#[test]
fn every_exploded_triangle_is_the_meshs_triangle_moved_along_its_face_normal() {
    let ctx = common::context(common::backend());
    let turn = Mat4::from_translation(Vec3::new(0.5, -1.0, 2.0))
        * Mat4::from_axis_angle(Vec3::new(1.0, 2.0, 0.5).normalize(), 0.7)
        * Mat4::from_scale(Vec3::new(1.5, 0.5, 2.0));
    let mirror = turn * Mat4::from_scale(Vec3::new(-1.0, 1.0, 1.0));
    let (magnitude, time) = (0.8, 0.9);
    let distance = offset(magnitude, time);
    // The lesson's (sin(t) + 1) / 2, worked by hand: sin(0.9) = 0.783327.
    assert!((distance - 0.8 * 0.891_663_5).abs() < 1e-6);
    for (name, mesh) in [
        ("torus", gloss::geometry::torus(1.0, 0.3, 24, 12)),
        ("cube", gloss::geometry::cube()),
        ("rock", gloss::geometry::rock()),
    ] {
        for (how, model) in [("turned", turn), ("mirrored", mirror)] {
            let corners = captured(&ctx, &mesh, model, magnitude, time);
            assert_eq!(corners.len(), mesh.indices.len(), "{name}: corners");
            let sign: f32 = if model.determinant() < 0.0 { -1.0 } else { 1.0 };
            let mut worst = 0.0f32;
            for (t, tri) in mesh.indices.chunks_exact(3).enumerate() {
                let p: [Vec3; 3] = std::array::from_fn(|j| {
                    model.transform_point3(Vec3::from(mesh.vertices[tri[j] as usize].position))
                });
                let n = ((p[1] - p[0]).cross(p[2] - p[0]) * sign).normalize_or_zero();
                for j in 0..3 {
                    let expected = p[j] + distance * n;
                    let got = corners[3 * t + j];
                    let err = (got - expected).length();
                    worst = worst.max(err);
                    assert!(
                        err < 1e-4,
                        "{name} ({how}): triangle {t} corner {j} at {got}, expected {expected} ({} + {distance} x {n})",
                        p[j]
                    );
                }
                // Outward: the moved triangle's centre is further from the
                // mesh's centre than the triangle's own for a convex mesh.
                if name == "cube" {
                    let c = model.transform_point3(Vec3::ZERO);
                    let centre = (p[0] + p[1] + p[2]) / 3.0;
                    assert!((centre + distance * n - c).length() > (centre - c).length());
                }
            }
            eprintln!(
                "{name} ({how}): {} triangles, each moved {distance}, worst corner off by {worst:e}",
                mesh.indices.len() / 3
            );
        }
    }
}

#[test]
fn at_magnitude_zero_every_corner_is_forwards_own_bit_for_bit() {
    // The other path: forward.vert's v_position, captured the same way.
    let ctx = common::context(common::backend());
    let model = Mat4::from_translation(Vec3::new(0.5, -1.0, 2.0))
        * Mat4::from_axis_angle(Vec3::new(1.0, 2.0, 0.5).normalize(), 0.7)
        * Mat4::from_scale(Vec3::new(1.5, 0.5, 2.0));
    let mesh = gloss::geometry::torus(1.0, 0.3, 24, 12);
    let forward = [(glow::VERTEX_SHADER, "lighting/forward.vert")];
    let whole = capture(&ctx, &forward, &mesh, model, 0.0, 0.0);
    let zero = captured(&ctx, &mesh, model, 0.0, 1.3);
    assert_eq!(whole.len(), zero.len());
    for (k, (a, b)) in whole.iter().zip(&zero).enumerate() {
        assert_eq!(
            a, b,
            "corner {k}: forward.vert {a}, exploded at magnitude 0 {b}"
        );
    }
}

#[test]
fn magnitude_zero_is_the_unexploded_image() {
    let ctx = common::context(common::backend());
    let scene = common::scene("explode.toml");
    assert!(scene.render.explode && scene.render.explode_magnitude > 0.0);
    let mut whole = scene.clone();
    whole.render.explode = false;
    let mut zero = scene.clone();
    zero.render.explode_magnitude = 0.0;
    assert!(gloss::techniques::plan(&zero).has_pass("explode"));
    assert!(!gloss::techniques::plan(&whole).has_pass("explode"));
    let a = common::render_with(&ctx, &whole, Output::Srgb8).image;
    let b = common::render_with(&ctx, &zero, Output::Srgb8).image;
    // The corners are forward's bit for bit (the test above); llvmpipe
    // runs a draw with a geometry shader through another vertex pipeline
    // (its viewport transform outside the vertex shader's code), and a
    // pixel in ~200 000 rounds its shading the other way by 1/255.
    let mut differ = 0;
    let mut worst = 0u8;
    for (x, y) in a.pixels().zip(b.pixels()) {
        if x != y {
            differ += 1;
            worst = worst.max((0..4).map(|c| x[c].abs_diff(y[c])).max().unwrap());
        }
    }
    eprintln!("magnitude 0: {differ} pixels differ from the whole image, by at most {worst}/255");
    assert!(
        worst <= 1 && differ <= 4,
        "{differ} pixels differ, by up to {worst}/255"
    );
    // Exploded, the pieces have moved: the image is not the whole one.
    let c = common::render_with(&ctx, &scene, Output::Srgb8).image;
    let moved = a.pixels().zip(c.pixels()).filter(|(x, y)| x != y).count();
    eprintln!("magnitude 0.5 at t = 0.6: {moved} pixels differ");
    assert!(moved > 2000, "only {moved} pixels changed when exploded");
}
