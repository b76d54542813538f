//! Visualizing normal vectors (LearnOpenGL, Geometry Shader;
//! src/techniques/vertex_geometry/visualizing_normals.rs): every line the
//! geometry shader emits, captured by transform feedback
//! (glBeginTransformFeedback(GL_LINES) with the rasterizer off), against the
//! mesh on the CPU: triangle t's vertex j gives the line from
//! model x position to that + length x normalize(normal matrix x normal),
//! in that order, for a smooth torus, a faceted cube and a rock, under a
//! model matrix that turns, scales unevenly and moves. And the shipped
//! scene draws yellow lines only with the switch on.

use crate::common;
use glam::{Mat3, Mat4, Vec3};
use gloss::geometry::MeshData;
use gloss::gl::mesh::Mesh;
use gloss::gl::program::{Program, Sources};
use gloss::renderer::Output;
use gloss::techniques::vertex_geometry::visualizing_normals::STAGES;
use glow::HasContext;

/// The line ends the geometry shader emits for `mesh` under `model`, read
/// back from a transform feedback buffer (vec3 each, two per line).
fn captured(ctx: &gloss::gl::Headless, mesh: &MeshData, model: Mat4, length: f32) -> Vec<Vec3> {
    let gl = &ctx.gl;
    let p = Program::with_feedback(gl, &Sources::Embedded, &STAGES, &[], &["g_world"]).unwrap();
    let m = Mesh::upload(gl, mesh).unwrap();
    let lines = mesh.indices.len(); // one line per vertex of each triangle
    let bytes = lines * 2 * 12;
    let set = |p: &Program| {
        p.set_mat4("u_model", &model);
        p.set_mat3(
            "u_normal_matrix",
            &gloss::frame::draw_list::normal_matrix(&model),
        );
        p.set_mat4("u_view_projection", &Mat4::IDENTITY);
        p.set_f32("u_length", length);
    };
    let floats = common::capture_feedback(gl, &p, glow::LINES, bytes, set, |gl| unsafe {
        gl.bind_vertex_array(Some(m.vao));
        gl.draw_elements(glow::TRIANGLES, m.index_count, glow::UNSIGNED_INT, 0);
        gl.bind_vertex_array(None);
    });
    floats.chunks_exact(3).map(Vec3::from_slice).collect()
}

#[test]
fn every_drawn_normal_is_the_meshs_normal_at_its_vertex() {
    let ctx = common::context(common::backend());
    let model = Mat4::from_translation(Vec3::new(0.5, -1.0, 2.0))
        * Mat4::from_axis_angle(Vec3::new(1.0, 2.0, 0.5).normalize(), 0.7)
        * Mat4::from_scale(Vec3::new(1.5, 0.5, 2.0));
    let normal_matrix = Mat3::from_mat4(model).inverse().transpose();
    let length = 0.3;
    for (name, mesh) in [
        ("torus", gloss::geometry::torus(1.0, 0.3, 24, 12)),
        ("cube", gloss::geometry::cube()),
        ("rock", gloss::geometry::rock()),
    ] {
        let ends = captured(&ctx, &mesh, model, length);
        assert_eq!(ends.len(), mesh.indices.len() * 2, "{name}: line ends");
        let mut worst = 0.0f32;
        for (k, &i) in mesh.indices.iter().enumerate() {
            let v = &mesh.vertices[i as usize];
            let p = model.transform_point3(Vec3::from(v.position));
            let n = (normal_matrix * Vec3::from(v.normal)).normalize();
            let (a, b) = (ends[2 * k], ends[2 * k + 1]);
            let err = (a - p).length().max((b - (p + length * n)).length());
            worst = worst.max(err);
            assert!(
                err < 1e-4,
                "{name}: line {k} (vertex {i}) runs {a} -> {b}, expected {p} -> {}",
                p + length * n
            );
        }
        eprintln!(
            "{name}: {} lines, worst end off by {worst:e}",
            mesh.indices.len()
        );
    }
}

#[test]
fn the_normals_scene_draws_yellow_lines_only_when_switched_on() {
    let ctx = common::context(common::backend());
    let yellow = |img: &image::RgbaImage| {
        img.pixels()
            .filter(|p| p[0] >= 250 && p[1] >= 250 && p[2] <= 5)
            .count()
    };
    let on = common::scene("normals.toml");
    assert!(on.render.show_normals);
    let mut off = on.clone();
    off.render.show_normals = false;
    let a = common::render_with(&ctx, &on, Output::Srgb8).image;
    let b = common::render_with(&ctx, &off, Output::Srgb8).image;
    assert!(yellow(&a) > 2000, "only {} line pixels", yellow(&a));
    assert_eq!(yellow(&b), 0);
    assert!(!gloss::techniques::plan(&off).has_pass("normals"));
}
