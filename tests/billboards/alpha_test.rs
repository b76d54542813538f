//! The alpha test (notes 05, "Alpha Test"): "if (alpha_fragment op
//! alpha_reference) pass fragment on", with op one of <, <=, ==, !=, >, >=,
//! always, never. The GLSL function (glsl/common/alpha_test.glsl, run here
//! in a one-row framebuffer, one value per pixel) and its CPU twin
//! (`AlphaTest::passes`) agree for every op at values just below, at and
//! just above the reference; and a material's alpha test cuts the same
//! holes in the forward and deferred paths.

use crate::{common, temp_dir};
use gloss::gl::framebuffer::Framebuffer;
use gloss::gl::mesh::Mesh;
use gloss::gl::program::{Program, Sources};
use gloss::image_compare::compare_rgba8;
use gloss::renderer::Output;
use gloss::scene::{AlphaTest, RenderPath, Scene};
use glow::HasContext;

/// A fragment shader that runs `alpha_test` on value `u_alpha[x]` at pixel x.
const TABLE_FRAG: &str = r#"#version 330 core
#include "common/alpha_test.glsl"
uniform float u_alpha[COUNT];
out vec4 frag_color;
void main() {
    alpha_test(u_alpha[int(gl_FragCoord.x)]);
    frag_color = vec4(1.0);
}
"#;

#[test]
fn every_op_on_the_gpu_agrees_with_its_cpu_twin() {
    let ctx = common::context(common::backend());
    let gl = &ctx.gl;
    // The shipped alpha_test.glsl, beside the table shader.
    let dir = temp_dir("truth-table");
    std::fs::create_dir_all(dir.join("common")).unwrap();
    for f in ["common/alpha_test.glsl", "common/fullscreen.vert"] {
        std::fs::copy(common::root().join("glsl").join(f), dir.join(f)).unwrap();
    }
    std::fs::write(dir.join("table.frag"), TABLE_FRAG).unwrap();
    let step = 1.0 / 4096.0;
    let mut values = Vec::new();
    for reference in [0.0f32, 0.5, 1.0] {
        for v in [reference - step, reference, reference + step, 0.0, 1.0] {
            values.push((reference, v));
        }
    }
    let n = values.len();
    let program = Program::new(
        gl,
        &Sources::Directory(dir.clone()),
        &[
            (glow::VERTEX_SHADER, "common/fullscreen.vert"),
            (glow::FRAGMENT_SHADER, "table.frag"),
        ],
        &[("COUNT", n.to_string())],
    )
    .unwrap();
    let fb = Framebuffer::new(gl, "table", n as i32, 1, &[glow::RGBA8], None).unwrap();
    let mesh = Mesh::upload(gl, &gloss::geometry::fullscreen_triangle()).unwrap();
    let mut checked = 0;
    for op in AlphaTest::ALL {
        // One draw per reference value: u_alpha_ref is one uniform.
        let mut gpu = vec![false; n];
        for reference in [0.0f32, 0.5, 1.0] {
            let alphas: Vec<f32> = values.iter().map(|&(_, v)| v).collect();
            unsafe {
                gl.bind_framebuffer(glow::FRAMEBUFFER, Some(fb.id));
                gl.viewport(0, 0, n as i32, 1);
                gl.clear_color(0.0, 0.0, 0.0, 0.0);
                gl.clear(glow::COLOR_BUFFER_BIT);
                program.use_program();
                program.set_mat4("u_mvp", &glam::Mat4::IDENTITY);
                program.set_i32("u_alpha_test", op.code());
                program.set_f32("u_alpha_ref", reference);
                let loc = gl.get_uniform_location(program.id, "u_alpha");
                gl.uniform_1_f32_slice(loc.as_ref(), &alphas);
                mesh.draw();
                gl.use_program(None);
                gl.bind_framebuffer(glow::FRAMEBUFFER, None);
            }
            let img = fb.read_rgba8_top_down(0);
            for (i, &(r, _)) in values.iter().enumerate() {
                if r == reference {
                    gpu[i] = img.get_pixel(i as u32, 0).0[0] == 255;
                }
            }
        }
        for (i, &(reference, v)) in values.iter().enumerate() {
            assert_eq!(
                gpu[i],
                op.passes(v, reference),
                "{op}: alpha {v} against {reference}: GPU {} and CPU disagree",
                if gpu[i] { "passes" } else { "discards" }
            );
            checked += 1;
        }
    }
    ctx.debug.check(gl, "the truth table").unwrap();
    assert_eq!(checked, 8 * 15);
    // The table is not trivial: at the reference, only the inclusive ops pass.
    let at = |op: AlphaTest| op.passes(0.5, 0.5);
    let inclusive: Vec<_> = AlphaTest::ALL.iter().filter(|o| at(**o)).collect();
    assert_eq!(
        inclusive,
        [
            &AlphaTest::Always,
            &AlphaTest::Lequal,
            &AlphaTest::Equal,
            &AlphaTest::Gequal
        ]
    );
    assert!(
        AlphaTest::Gequal.passes(0.5 + step, 0.5) && !AlphaTest::Gequal.passes(0.5 - step, 0.5)
    );
}

/// A plane textured with the tree sprite, seen from above, on a blue background.
fn tree_plane(test: &str, alpha: &str) -> Scene {
    let dir = temp_dir(test);
    let sprite = common::root().join("scenes/assets/tree.png");
    let text = format!(
        r#"
[camera]
projection = "orthographic"
eye = [0.0, 10.0, 0.0]
target = [0.0, 0.0, 0.0]
up = [0.0, 0.0, -1.0]
half_height = 1.0
near = 1.0
far = 20.0

[render]
size = [128, 128]
ambient = [0.3, 0.3, 0.3]
background = [0.0, 0.0, 1.0]

[[lights]]
type = "directional"
direction = [0.0, -1.0, 0.0]

[materials.tree]
diffuse = [1.0, 1.0, 1.0]
diffuse_texture = "{}"
{alpha}

[[objects]]
mesh = "plane"
material = "tree"
"#,
        sprite.display()
    );
    Scene::parse(&text, &dir.join("scene.toml")).expect("scene loads")
}

fn blue(img: &image::RgbaImage) -> usize {
    img.pixels().filter(|p| p.0[..3] == [0, 0, 255]).count()
}

#[test]
fn a_material_alpha_test_cuts_the_same_holes_in_every_path() {
    let ctx = common::context(common::backend());
    let none = tree_plane("material-none", "");
    let tested = tree_plane(
        "material-gequal",
        "alpha_test = \"gequal\"\nalpha_ref = 0.5",
    );
    let never = tree_plane("material-never", "alpha_test = \"never\"");
    let total = 128 * 128;
    // Without the key: "always", the plane covers the view.
    let plain = common::render_with(&ctx, &none, Output::Srgb8);
    assert_eq!(blue(&plain.image), 0);
    // "never": nothing of the plane is left.
    assert_eq!(
        blue(&common::render_with(&ctx, &never, Output::Srgb8).image),
        total
    );
    // "gequal" 0.5: the background shows where the sprite's alpha < 0.5.
    let sprite = image::open(common::root().join("scenes/assets/tree.png"))
        .unwrap()
        .to_rgba8();
    let transparent = sprite.pixels().filter(|p| p.0[3] < 128).count() as f64 / (128.0 * 128.0);
    let forward = common::render_with(&ctx, &tested, Output::Srgb8);
    let holes = blue(&forward.image) as f64 / total as f64;
    eprintln!("holes {holes:.4}, transparent texels {transparent:.4}");
    // The plane maps the 128x128 sprite onto 128x128 pixels: the same
    // fraction within the filtered edge (1%).
    assert!(
        (holes - transparent).abs() < 0.01,
        "holes {holes}, sprite {transparent}"
    );
    for path in [
        RenderPath::Deferred,
        RenderPath::Volumes,
        RenderPath::Prepass,
    ] {
        let mut s = tested.clone();
        s.render.path = path;
        let r = common::render_with(&ctx, &s, Output::Srgb8);
        let m = compare_rgba8(&r.image, &forward.image, 2.0 / 255.0).unwrap();
        assert_eq!(blue(&r.image), blue(&forward.image), "{path}: {m}");
        assert!(m.frac_over < 0.005, "{path}: {m}");
    }
}
