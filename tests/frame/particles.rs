//! src/techniques/vertex_geometry/particles.rs: the geometry shader's quads
//! and the CPU's quads draw the same image; a mapped buffer and
//! glBufferSubData upload the same bytes, and a frame asked to map did map
//! (src/gl/stream.rs counts each way); the frame plan counts the living
//! particles; nothing raises a GL error (debug output on).

use crate::common;
use gloss::gl::stream::{StreamBuffer, Upload, UploadCounts, uploads_on_this_thread};
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

/// Render `s` and count the stream writes the frame made on this thread.
fn render_counting(s: &Scene) -> (image::RgbaImage, UploadCounts) {
    let before = uploads_on_this_thread();
    let image = common::render(s, Output::Srgb8).image;
    let after = uploads_on_this_thread();
    let counts = UploadCounts {
        mapped: after.mapped - before.mapped,
        subdata: after.subdata - before.subdata,
        map_refused: after.map_refused - before.map_refused,
    };
    (image, counts)
}

#[test]
fn mapped_and_subdata_streams_give_the_same_image() {
    // The same image both ways, and each frame wrote its particles the way
    // it was asked: particles.map = true really mapped (a refused map would
    // fall back to glBufferSubData, draw the same image, and count as
    // map_refused here).
    for gs in [true, false] {
        let (map, m) = render_counting(&scene(|p| p.geometry_shader = gs));
        let (sub, s) = render_counting(&scene(|p| {
            p.geometry_shader = gs;
            p.map = false;
        }));
        assert_eq!(
            m,
            UploadCounts {
                mapped: 1,
                subdata: 0,
                map_refused: 0
            },
            "geometry shader {gs}, map = true"
        );
        assert_eq!(
            s,
            UploadCounts {
                mapped: 0,
                subdata: 1,
                map_refused: 0
            },
            "geometry shader {gs}, map = false"
        );
        assert!(map == sub, "geometry shader {gs}: the streams differ");
    }
}

#[test]
fn a_mapped_write_puts_its_bytes_in_the_buffer() {
    // Read back with glGetBufferSubData: what went through the mapped
    // pointer is in the buffer, also after it grew, and a glBufferSubData
    // write after it replaces it.
    let ctx = common::context(common::backend());
    let buffer = StreamBuffer::new(&ctx.gl, &[(0, 4, 0)], 16).unwrap();
    for len in [64usize, 10_000] {
        let bytes: Vec<u8> = (0..len).map(|i| (i * 7 + len) as u8).collect();
        assert_eq!(buffer.write(&bytes, true), Upload::Mapped, "{len} bytes");
        assert!(
            buffer.read_back(len) == bytes,
            "{len} bytes through the map"
        );
        let other: Vec<u8> = bytes.iter().map(|b| b ^ 0x5a).collect();
        assert_eq!(buffer.write(&other, false), Upload::SubData);
        assert!(
            buffer.read_back(len) == other,
            "{len} bytes with glBufferSubData"
        );
    }
    ctx.debug.check(&ctx.gl, "the stream writes").unwrap();
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
