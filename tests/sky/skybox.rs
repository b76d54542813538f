//! The skybox (notes 03, Implementation): the cube map made of six PNG
//! faces (src/gl/cube_map.rs); the skybox pass at z = w with GL_LEQUAL
//! draws nothing over objects and the background is the cube map sampled
//! on the CPU (src/math/cube_map.rs) along each pixel's view ray; seamless
//! filtering is continuous across a face edge, and the same check fails with
//! GL_TEXTURE_CUBE_MAP_SEAMLESS off; drawn first (render.sky_first) the
//! image is the same; bad faces are refused, naming the faces and sizes.

use crate::common;
use crate::environment_reflection::{magnified, pixel_ray};
use glam::{DVec3, Vec3};
use gloss::gl::cube_map::CubeMap;
use gloss::gl::framebuffer::Framebuffer;
use gloss::gl::mesh::Mesh;
use gloss::gl::program::{Program, Sources};
use gloss::math::cube_map::{CubeImage, direction};
use gloss::renderer::Output;
use gloss::scene::Scene;
use glow::HasContext;
use std::path::PathBuf;

const FACES: [&str; 6] = ["px", "nx", "py", "ny", "pz", "nz"];

fn scene(objects: &str, extra: &str) -> Scene {
    let faces: Vec<String> = (FACES.iter())
        .map(|f| format!("\"assets/skybox-{f}.png\""))
        .collect();
    let text = format!(
        "name = \"t\"\n[camera]\neye = [0.0, 1.0, 0.0]\ntarget = [3.0, 1.4, -4.0]\nfov_y = 60.0\n\
         [render]\nsize = [320, 240]\nambient = [1.0, 1.0, 1.0]\n{extra}\n[skybox]\nfaces = [{}]\n{objects}",
        faces.join(", ")
    );
    Scene::parse(&text, &common::root().join("scenes/t.toml")).unwrap()
}

/// The shipped faces decoded on the CPU: sRGB to linear, as the GPU does
/// before it filters.
fn shipped_faces() -> CubeImage {
    let decode = |v: u8| srgb_decode(f32::from(v) / 255.0);
    let faces = std::array::from_fn(|f| {
        let p = common::root().join(format!("scenes/assets/skybox-{}.png", FACES[f]));
        let img = image::open(&p).unwrap().to_rgba8();
        img.pixels()
            .map(|p| [decode(p[0]), decode(p[1]), decode(p[2]), 1.0])
            .collect()
    });
    CubeImage { size: 128, faces }
}

#[test]
fn the_background_is_the_cube_map_along_each_view_ray_and_objects_are_untouched() {
    let cube = "[[objects]]\nmesh = \"cube\"\nposition = [3.0, 1.2, -4.0]\n";
    let ctx = common::context(common::backend());
    let s = scene(cube, "");
    let with = common::render_with(&ctx, &s, Output::Linear32F);
    let mut bare = s.clone();
    bare.skybox = None;
    let without = common::render_with(&ctx, &bare, Output::Linear32F);
    let faces = shipped_faces();
    let (w, h) = (320usize, 240usize);
    let (mut object, mut background, mut worst) = (0, 0, 0.0f64);
    for y in 1..h - 1 {
        for x in 1..w - 1 {
            let i = (y * w + x) * 4;
            if without.linear[i..i + 3] != [0.0, 0.0, 0.0] {
                // Covered by the cube: the skybox changed nothing.
                object += 1;
                assert_eq!(
                    with.linear[i..i + 4],
                    without.linear[i..i + 4],
                    "({x}, {y})"
                );
                continue;
            }
            let d = pixel_ray(&s, x, y).1;
            let around: Vec<DVec3> = [(x + 1, y), (x - 1, y), (x, y + 1), (x, y - 1)]
                .iter()
                .map(|&(a, b)| pixel_ray(&s, a, b).1)
                .collect();
            if !magnified(&faces, d, &around) {
                continue;
            }
            background += 1;
            let want = faces.sample(d, true);
            for (c, want) in want.iter().take(3).enumerate() {
                let got = with.linear[i + c];
                let err = (f64::from(got) - want).abs();
                worst = worst.max(err);
                assert!(err < 4e-3, "({x}, {y}) channel {c}: {got} against {want}");
            }
        }
    }
    println!(
        "{object} object pixels unchanged; {background} background pixels, worst difference {worst:.2e}"
    );
    assert!(object > 2000 && background > 30000, "{object} {background}");
}

#[test]
fn drawn_first_the_sky_gives_the_same_image() {
    let cube = "[[objects]]\nmesh = \"cube\"\nposition = [3.0, 1.2, -4.0]\n";
    let last = common::render(&scene(cube, ""), Output::Srgb8).image;
    let first_scene = scene(cube, "sky_first = true");
    let names: Vec<_> = gloss::techniques::plan(&first_scene)
        .passes
        .iter()
        .map(|p| p.name)
        .collect();
    assert!(
        names.contains(&"sky first") && !names.contains(&"skybox"),
        "{names:?}"
    );
    let first = common::render(&first_scene, Output::Srgb8).image;
    assert!(last == first, "the sky drawn first changed the image");
    // On a deferred path the knob is a warning, and the skybox is drawn last.
    let mut deferred = first_scene.clone();
    deferred.render.path = gloss::scene::RenderPath::Deferred;
    assert!(
        deferred
            .warnings()
            .iter()
            .any(|w| w.starts_with("render.sky_first"))
    );
    let names: Vec<_> = gloss::techniques::plan(&deferred)
        .passes
        .iter()
        .map(|p| p.name)
        .collect();
    assert!(
        names.contains(&"skybox") && !names.contains(&"sky first"),
        "{names:?}"
    );
}

/// Six 8 x 8 faces, each one flat colour, written as PNGs.
fn flat_faces(dir: &std::path::Path) -> Vec<PathBuf> {
    std::fs::create_dir_all(dir).unwrap();
    (0..6)
        .map(|f| {
            let v = [0u8, 255, 60, 200, 120, 30][f];
            let img = image::RgbaImage::from_pixel(8, 8, image::Rgba([v, 255 - v, 128, 255]));
            let p = dir.join(format!("{f}.png"));
            img.save(&p).unwrap();
            p
        })
        .collect()
}

/// The cube map sampled by the skybox's shaders across the edge between
/// +x and +z (a 256-pixel row spanning three texels), seamless or not.
fn across_the_edge(seamless: bool) -> (Vec<f32>, Vec<DVec3>, CubeImage) {
    let ctx = common::context(common::backend());
    let gl = &ctx.gl;
    let dir = common::out_dir().join("skybox-flat-faces");
    let cube = CubeMap::from_faces(gl, &flat_faces(&dir)).unwrap();
    let (w, h) = (256, 4);
    let fb = Framebuffer::new(gl, "edge", w, h, &[glow::RGBA32F], None).unwrap();
    let p = Program::new(
        gl,
        &Sources::Embedded,
        &[
            (glow::VERTEX_SHADER, "sky/skybox.vert"),
            (glow::FRAGMENT_SHADER, "sky/skybox.frag"),
        ],
        &[],
    )
    .unwrap();
    let mesh = Mesh::upload(gl, &gloss::geometry::fullscreen_triangle()).unwrap();
    // Looking along (1, 0, 1), 10 degrees either side.
    let aspect = w as f32 / h as f32;
    let fov_y = 2.0 * (10f32.to_radians().tan() / aspect).atan();
    let view = gloss::math::look_at(Vec3::ZERO, Vec3::new(1.0, 0.0, 1.0), Vec3::Y);
    let vp = gloss::math::perspective(fov_y, aspect, 0.1, 10.0) * view;
    unsafe {
        gl.bind_framebuffer(glow::FRAMEBUFFER, Some(fb.id));
        gl.viewport(0, 0, w, h);
        if seamless {
            gl.enable(glow::TEXTURE_CUBE_MAP_SEAMLESS);
        }
        p.use_program();
        p.set_mat4("u_inverse_view_projection", &vp.inverse());
        p.set_bool("u_output_srgb", false);
        p.set_i32("u_environment", 3);
        gl.active_texture(glow::TEXTURE3);
        gl.bind_texture(glow::TEXTURE_CUBE_MAP, Some(cube.id));
        mesh.draw();
        gl.bind_texture(glow::TEXTURE_CUBE_MAP, None);
        gl.active_texture(glow::TEXTURE0);
        gl.disable(glow::TEXTURE_CUBE_MAP_SEAMLESS);
        gl.use_program(None);
        gl.bind_framebuffer(glow::FRAMEBUFFER, None);
    }
    ctx.debug.check(gl, "sampling across the edge").unwrap();
    let row: Vec<f32> = fb.read_rgba_f32(0)[(2 * w * 4) as usize..(3 * w * 4) as usize]
        .chunks(4)
        .map(|c| c[0])
        .collect();
    let inverse = vp.inverse().as_dmat4();
    let rays = (0..w)
        .map(|x| {
            let ndc = 2.0 * (f64::from(x) + 0.5) / f64::from(w) - 1.0;
            let ndc_y = 2.0 * 2.5 / f64::from(h) - 1.0;
            let at = |z: f64| inverse.project_point3(DVec3::new(ndc, ndc_y, z));
            (at(1.0) - at(-1.0)).normalize()
        })
        .collect();
    // glGetTexImage returns an sRGB face as stored: decode it as the sampler does.
    let mut image = cube.read_image();
    for t in image.faces.iter_mut().flatten() {
        for c in &mut t[..3] {
            *c = srgb_decode(*c);
        }
    }
    (row, rays, image)
}

fn srgb_decode(c: f32) -> f32 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// The largest change between neighbouring pixels of the row.
fn largest_step(row: &[f32]) -> f32 {
    row.windows(2)
        .map(|p| (p[1] - p[0]).abs())
        .fold(0.0, f32::max)
}

#[test]
fn seamless_filtering_is_continuous_across_a_face_edge_and_the_check_fails_without_it() {
    for seamless in [true, false] {
        let (row, rays, image) = across_the_edge(seamless);
        // The two faces' red, linear: the jump a seam would make.
        let (a, b) = (image.texel(0, 0, 4)[0], image.texel(4, 7, 4)[0]);
        let jump = (a - b).abs();
        assert!(jump > 0.1, "{a} {b}");
        // The GPU agrees with the CPU's sampler of the same kind.
        for (x, (got, d)) in row.iter().zip(&rays).enumerate() {
            let want = image.sample(*d, seamless)[0];
            assert!(
                (f64::from(*got) - want).abs() < 5e-3,
                "seamless {seamless}: pixel {x}: {got} against the CPU's {want}"
            );
        }
        let step = largest_step(&row);
        println!("seamless {seamless}: largest step {step:.4} (the faces differ by {jump:.4})");
        // Continuous: no step near the faces' difference (256 pixels span
        // three texels: a ramp over one texel moves ~1/85 of it a pixel).
        let continuous = step < 0.05 * jump;
        assert_eq!(continuous, seamless, "largest step {step}, jump {jump}");
    }
    // The edge is really in the row: +x at its left end, +z at its right.
    assert_eq!(gloss::math::cube_map::face_st(direction(0, 0.5, 0.5)).0, 0);
}

#[test]
fn faces_that_differ_in_size_or_are_not_square_are_refused_naming_them() {
    let dir = common::out_dir().join("skybox-bad-faces");
    std::fs::create_dir_all(&dir).unwrap();
    let write = |name: &str, w: u32, h: u32| {
        image::RgbaImage::new(w, h).save(dir.join(name)).unwrap();
        format!("\"{name}\"")
    };
    let load = |faces: &[String]| {
        let text = format!(
            "name = \"t\"\n[camera]\neye = [0.0, 0.0, 3.0]\ntarget = [0.0, 0.0, 0.0]\n\
             [skybox]\nfaces = [{}]\n",
            faces.join(", ")
        );
        let path = dir.join("t.toml");
        std::fs::write(&path, text).unwrap();
        format!("{:#}", Scene::load(&path).unwrap_err())
    };
    let mut faces: Vec<String> = (0..6).map(|i| write(&format!("{i}.png"), 16, 16)).collect();
    faces[3] = write("small.png", 8, 8);
    let e = load(&faces);
    assert!(
        e.contains("skybox.faces")
            && e.contains("same size")
            && e.contains("-y")
            && e.contains("8x8")
            && e.contains("16x16"),
        "{e}"
    );
    faces[3] = write("wide.png", 16, 8);
    let e = load(&faces);
    assert!(
        e.contains("square") && e.contains("16x8") && e.contains("wide.png"),
        "{e}"
    );
    let e = load(&faces[..5]);
    assert!(e.contains("six paths") && e.contains("found 5"), "{e}");
    let text =
        "name = \"t\"\n[camera]\neye = [0.0, 0.0, 3.0]\ntarget = [0.0, 0.0, 0.0]\n[skybox]\n";
    let e = format!("{:#}", Scene::parse(text, &dir.join("t.toml")).unwrap_err());
    assert!(e.contains("no faces and no [sky]"), "{e}");
}
