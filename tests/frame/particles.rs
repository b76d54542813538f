//! src/techniques/vertex_geometry/particles.rs: the geometry shader's quads
//! and the CPU's quads draw the same image; a mapped buffer and
//! glBufferSubData upload the same bytes; the frame plan counts the living
//! particles; nothing raises a GL error (debug output on).

use crate::common;
use gloss::image_compare::{Tolerance, compare_rgba8};
use gloss::renderer::Output;
use gloss::scene::Scene;

fn scene(edit: impl Fn(&mut gloss::scene::particles::Particles)) -> Scene {
    let mut s = common::scene("particles.toml");
    s.render.size = (320, 180);
    edit(s.particles.as_mut().unwrap());
    s
}

#[test]
fn the_geometry_shader_draws_what_the_cpu_quads_draw() {
    let gs = common::render(&scene(|_| {}), Output::Srgb8).image;
    let cpu = common::render(&scene(|p| p.geometry_shader = false), Output::Srgb8).image;
    // The corners are the same sums in f32, on the GPU and on the CPU: at
    // most a pixel in 1000 one 8-bit step apart where a quad's edge falls.
    let tol = Tolerance {
        threshold: 1.0 / 255.0,
        max_frac_over: 0.001,
        max_abs: Some(2.0 / 255.0),
    };
    let m = common::assert_close("particles-gs-vs-cpu", &gs, &cpu, &tol);
    eprintln!("geometry shader vs CPU quads: {m}");
    // The particles are there at all: without them the image differs.
    let mut none = scene(|_| {});
    none.particles = None;
    let bare = common::render(&none, Output::Srgb8).image;
    let d = compare_rgba8(&gs, &bare, 1.0 / 255.0).unwrap();
    assert!(d.frac_over > 0.01, "the fountain shows: {d}");
}

#[test]
fn mapped_and_subdata_streams_give_the_same_image() {
    for gs in [true, false] {
        let map = common::render(&scene(|p| p.geometry_shader = gs), Output::Srgb8).image;
        let sub = common::render(
            &scene(|p| {
                p.geometry_shader = gs;
                p.map = false;
            }),
            Output::Srgb8,
        )
        .image;
        assert!(map == sub, "geometry shader {gs}: the streams differ");
    }
}

#[test]
fn alpha_tested_particles_hide_what_is_behind_them() {
    use gloss::scene::particles::ParticleBlend;
    let additive = common::render(&scene(|_| {}), Output::Srgb8).image;
    let tested = common::render(
        &scene(|p| p.blend = ParticleBlend::AlphaTest),
        Output::Srgb8,
    )
    .image;
    let d = compare_rgba8(&additive, &tested, 1.0 / 255.0).unwrap();
    assert!(
        d.frac_over > 0.005,
        "alpha test draws discs, not glows: {d}"
    );
}

#[test]
fn the_plan_counts_the_living_particles() {
    let mut s = common::scene("particles.toml");
    let text = gloss::techniques::plan(&s).to_string();
    let n = gloss::frame::particles::alive(s.particles.as_ref().unwrap(), 2.0).len();
    assert!(
        text.contains(&format!(
            "{n} particles, points made quads by the geometry shader"
        )),
        "{text}"
    );
    s.set_time(0.0).unwrap();
    assert!(
        gloss::techniques::plan(&s)
            .to_string()
            .contains("1 particles")
    );
}
