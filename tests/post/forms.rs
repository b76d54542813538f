//! The chain's plumbing (src/frame/post.rs): its two forms, its targets,
//! the feedback-loop rule, bad chains, and the HDR target.

use crate::chain::chain_scene;
use crate::common;
use gloss::frame::post::{HDR, PING_PONG, step_count};
use gloss::gl::framebuffer::Framebuffer;
use gloss::gl::program::{Program, Sources};
use gloss::renderer::{Output, render_scene};
use gloss::scene::Scene;
use gloss::scene::post::ChainForm;
use gloss::techniques::plan;
use glow::HasContext;

/// The shipped scenes with a post chain.
fn chain_scenes() -> Vec<Scene> {
    let mut v: Vec<Scene> = std::fs::read_dir(common::root().join("scenes"))
        .unwrap()
        .filter_map(|e| {
            let p = e.unwrap().path();
            (p.extension()? == "toml").then(|| Scene::load(&p).unwrap())
        })
        .filter(|s| !s.post.is_empty())
        .collect();
    v.sort_by(|a, b| a.name.cmp(&b.name));
    assert!(v.len() >= 3, "the post scenes are shipped");
    v
}

#[test]
fn ping_pong_and_cascaded_give_the_same_image_bit_for_bit() {
    let ctx = common::context(common::backend());
    for mut scene in chain_scenes() {
        scene.render.size = (160, 90);
        let mut images = Vec::new();
        for form in ChainForm::ALL {
            scene.render.post_chain = *form;
            let r = render_scene(&ctx, &scene, Output::Srgb8)
                .unwrap_or_else(|e| panic!("{} ({}): {e:#}", scene.name, form.name()));
            images.push(r.read_image());
        }
        assert!(
            images[0] == images[1],
            "{}: ping-pong and cascaded differ",
            scene.name
        );
    }
}

/// Every pass's draw is checked (tests run with debug checks on, see
/// `check_feedback_before_draw` in src/gl/debug.rs): rendering every shipped
/// chain in both forms, and on every lighting path, raises no feedback loop.
#[test]
fn no_step_of_any_chain_samples_the_texture_it_draws_into() {
    let ctx = common::context(common::backend());
    for mut scene in chain_scenes() {
        scene.render.size = (64, 36);
        for form in ChainForm::ALL {
            for path in gloss::scene::RenderPath::ALL {
                scene.render.post_chain = *form;
                scene.render.path = *path;
                render_scene(&ctx, &scene, Output::Srgb8).unwrap_or_else(|e| {
                    panic!("{} ({}, {}): {e:#}", scene.name, form.name(), path.name())
                });
            }
        }
    }
}

/// The check is real: the textbook ping-pong, both textures attached and
/// glDrawBuffer choosing one, is a feedback loop under GL 3.3 §4.4.3, and
/// the frame's check reports it.
#[test]
fn the_feedback_check_catches_the_both_attached_ping_pong() {
    let ctx = common::context(common::backend());
    let gl = &ctx.gl;
    let both = Framebuffer::new(gl, "both", 8, 8, &[glow::RGBA16F, glow::RGBA16F], None).unwrap();
    let program = Program::new(
        gl,
        &Sources::Embedded,
        &[
            (glow::VERTEX_SHADER, "common/fullscreen.vert"),
            (glow::FRAGMENT_SHADER, "post/color_filters.frag"),
        ],
        &[],
    )
    .unwrap();
    let meshes = gloss::frame::meshes::FrameMeshes::new(gl).unwrap();
    unsafe {
        gl.bind_framebuffer(glow::FRAMEBUFFER, Some(both.id));
        gl.draw_buffers(&[glow::COLOR_ATTACHMENT1]);
        program.use_program();
        gl.bind_texture(glow::TEXTURE_2D, Some(both.colors[0].id));
        program.set_i32("u_image", 0);
        program.set_mat4("u_mvp", &glam::Mat4::IDENTITY);
        meshes.fullscreen.draw();
        gl.bind_texture(glow::TEXTURE_2D, None);
        gl.use_program(None);
        gl.bind_framebuffer(glow::FRAMEBUFFER, None);
    }
    let err = ctx.debug.check(gl, "the textbook ping-pong").unwrap_err();
    assert!(format!("{err:#}").contains("feedback loop"), "{err:#}");
}

#[test]
fn the_chain_allocates_only_the_targets_its_steps_need() {
    let names = |s: &Scene| -> Vec<&str> { plan(s).targets.iter().map(|t| t.name).collect() };
    // No chain: no hdr, no post targets. The output has a depth buffer
    // where a pass needs it (forward), none where the deferred composite
    // ends the frame.
    let none = common::scene("deferred-shading.toml");
    assert!(
        !names(&none)
            .iter()
            .any(|n| *n == HDR || n.starts_with("post"))
    );
    // (SRGB8_ALPHA8: the composite encodes by GL_FRAMEBUFFER_SRGB.)
    assert_eq!(
        plan(&none).target("output").unwrap().attachments(),
        ["color:SRGB8_ALPHA8"]
    );
    let mut forward = none.clone();
    forward.render.path = gloss::scene::RenderPath::Forward;
    assert_eq!(
        plan(&forward).target("output").unwrap().attachments(),
        ["color:RGBA8", "depth_stencil:DEPTH24_STENCIL8"]
    );
    // Gamma alone: one step from hdr to the output, nothing between.
    let one = chain_scene("[[post]]\npass = \"gamma\"\n");
    assert_eq!(step_count(&one), 1);
    let n = names(&one);
    assert!(
        n.contains(&HDR) && !n.iter().any(|n| n.starts_with("post")),
        "{n:?}"
    );
    assert_eq!(
        plan(&one).target("output").unwrap().attachments(),
        ["color:RGBA8"]
    );
    // A blur (two steps) and gamma: ping-pong holds the two steps between.
    let blur = "[[post]]\npass = \"blur\"\nsigma = 1.0\n[[post]]\npass = \"gamma\"\n";
    let mut s = chain_scene(blur);
    assert_eq!(step_count(&s), 3);
    assert!(names(&s).contains(&PING_PONG));
    // Cascaded: one framebuffer per step but the last.
    s.render.post_chain = ChainForm::Cascaded;
    let n = names(&s);
    assert!(
        n.contains(&"post_1") && n.contains(&"post_2") && !n.contains(&"post_3"),
        "{n:?}"
    );
    assert!(!n.contains(&PING_PONG));
    // The plan runs the steps in the file's order, whatever the registry's.
    let order = chain_scene(
        "[[post]]\npass = \"invert\"\n[[post]]\npass = \"tonemap\"\noperator = \"clamp\"\n[[post]]\npass = \"grayscale\"\n[[post]]\npass = \"gamma\"\n",
    );
    let p = plan(&order);
    let post: Vec<&str> = p
        .passes
        .iter()
        .map(|p| p.name)
        .skip_while(|n| *n != "invert")
        .collect();
    assert_eq!(
        post,
        ["invert", "tone mapping", "grayscale", "gamma correction"]
    );
}

#[test]
fn bad_chains_are_errors_naming_the_pass_and_the_key() {
    for (post, expected) in [
        (
            "[[post]]\npass = \"blom\"\n",
            "post[0].pass: unknown pass \"blom\"",
        ),
        (
            "[[post]]\noperator = \"aces\"\n",
            "post[0]: missing key 'pass'",
        ),
        (
            "[[post]]\npass = \"blur\"\n[[post]]\npass = \"gamma\"\n",
            "post[0] (blur): missing key 'sigma'",
        ),
        (
            "[[post]]\npass = \"tonemap\"\n[[post]]\npass = \"gamma\"\n",
            "post[0] (tonemap): missing key 'operator'",
        ),
        (
            "[[post]]\npass = \"box\"\n[[post]]\npass = \"gamma\"\n",
            "post[0] (box): missing key 'radius'",
        ),
        (
            "[[post]]\npass = \"kernel\"\n[[post]]\npass = \"gamma\"\n",
            "post[0] (kernel): missing key 'kernel'",
        ),
        (
            "[[post]]\npass = \"gamma\"\ngama = 2.0\n",
            "post[0] (gamma): unknown key 'gama'",
        ),
        (
            "[[post]]\npass = \"invert\"\nstrength = 1\n[[post]]\npass = \"gamma\"\n",
            "post[0] (invert): unknown key 'strength'",
        ),
        (
            "[[post]]\npass = \"blur\"\nsigma = nan\n[[post]]\npass = \"gamma\"\n",
            "post[0] (blur).sigma",
        ),
        (
            "[[post]]\npass = \"blur\"\nsigma = 2.0\nradius = 500\n[[post]]\npass = \"gamma\"\n",
            "post[0] (blur).radius",
        ),
        (
            "[[post]]\npass = \"kernel\"\nkernel = [1, 2, 3]\n[[post]]\npass = \"gamma\"\n",
            "post[0] (kernel).kernel: expected nine finite numbers",
        ),
        (
            "[[post]]\npass = \"tonemap\"\noperator = \"filmic\"\n[[post]]\npass = \"gamma\"\n",
            "post[0] (tonemap).operator",
        ),
        (
            "[[post]]\npass = \"gamma\"\n[[post]]\npass = \"invert\"\n",
            "post[0] (gamma): gamma must be the last pass",
        ),
        (
            "[[post]]\npass = \"invert\"\n",
            "the chain must end with a gamma pass",
        ),
        (
            "[[post]]\npass = \"gamma\"\nsrgb = true\ngamma = 2.2\n",
            "post[0] (gamma).gamma",
        ),
        (
            "[render]\npost_chain = \"pingpong\"\n",
            "expected ping_pong or cascaded",
        ),
    ] {
        let text = format!("[camera]\neye = [0, 0, 5]\ntarget = [0, 0, 0]\n{post}");
        let err = Scene::parse(&text, std::path::Path::new("bad.toml"))
            .map(|_| ())
            .expect_err(post);
        let msg = format!("{err:#}");
        assert!(
            msg.contains(expected),
            "{post}\n  gave: {msg}\n  expected: {expected}"
        );
    }
}

#[test]
fn a_saved_chain_loads_back_the_same() {
    let scene = common::scene("post-filters.toml");
    let dir = common::out_dir();
    let path = dir.join("post-saved.toml");
    let mut edited = scene.clone();
    edited.render.post_chain = ChainForm::Cascaded;
    edited.post.insert(
        1,
        gloss::scene::post::PostPass::Blur {
            sigma: 1.5,
            radius: 5,
            taps: gloss::scene::post::Taps::Linear,
        },
    );
    edited.save_as(&path).unwrap();
    let back = Scene::load(&path).unwrap();
    assert_eq!(back.post, edited.post);
    assert_eq!(back.render.post_chain, ChainForm::Cascaded);
}

/// 256 lights add up past 1.0. In the HDR target they stay as they are, so
/// tone mapping tells a pixel of 1.5 from one of 3; without a chain the
/// 8-bit output clips both to white.
#[test]
fn the_hdr_target_keeps_256_lights_unclipped_before_tone_mapping() {
    let ctx = common::context(common::backend());
    let mut scene = common::scene("many-lights.toml");
    scene.render.size = (320, 180);
    // Four times the shipped brightness: where the lights overlap they add
    // up to several times 1.0.
    for l in &mut scene.lights {
        l.intensity *= 4.0;
    }
    scene.post = gloss::scene::post::chain(&[
        toml::from_str("pass = \"tonemap\"\noperator = \"reinhard\"").unwrap(),
        toml::from_str("pass = \"gamma\"").unwrap(),
    ])
    .unwrap();
    let r = render_scene(&ctx, &scene, Output::Srgb8).unwrap();
    let hdr = r.targets().get(HDR).read_rgba_f32(0);
    let max = hdr
        .chunks(4)
        .map(|p| p[0].max(p[1]).max(p[2]))
        .fold(0.0f32, f32::max);
    let over: usize = hdr
        .chunks(4)
        .filter(|p| p[0].max(p[1]).max(p[2]) > 1.0)
        .count();
    assert!(
        max > 2.0 && over > 100,
        "the lights add up past 1: max {max}, {over} pixels over 1"
    );
    // Tone mapped, those pixels keep their differences: no channel is
    // saturated (Reinhard stays below 1), so the brightest is not flat white.
    let out = r.read_image();
    let white = out
        .pixels()
        .filter(|p| p[0] == 255 && p[1] == 255 && p[2] == 255)
        .count();
    assert_eq!(white, 0, "Reinhard never reaches 1.0");
    // Without the chain the 8-bit output clips them.
    scene.post.clear();
    let clipped = render_scene(&ctx, &scene, Output::Srgb8)
        .unwrap()
        .read_image();
    let saturated = clipped
        .pixels()
        .filter(|p| p[0] == 255 || p[1] == 255 || p[2] == 255)
        .count();
    assert!(saturated > 100, "without HDR, {saturated} pixels clip");
}

/// The chain reads the world's HDR image whichever path lit it, so every
/// path gives the forward image through it. The paths differ by rounding
/// (half-float G-buffer normals, the order light is added in). The blur
/// averages those differences away: max 3/255, at most 0.1 % of the pixels
/// over 3/255 (measured: max 1/255). The sharpening kernel of post-effects
/// multiplies them by up to 5: max 8/255, at most 0.5 % over 3/255
/// (measured: max 4/255 on 0.01 %).
#[test]
fn every_lighting_path_gives_the_forward_image_through_the_chain() {
    let ctx = common::context(common::backend());
    for (name, max, frac) in [
        ("post-blur.toml", 8.0, 0.005),
        ("post-effects.toml", 40.0, 0.025),
    ] {
        let mut scene = common::scene(name);
        scene.render.size = (240, 135);
        let image = |scene: &Scene| {
            render_scene(&ctx, scene, Output::Srgb8)
                .unwrap()
                .read_image()
        };
        scene.render.path = gloss::scene::RenderPath::Forward;
        let forward = image(&scene);
        for path in [
            gloss::scene::RenderPath::Deferred,
            gloss::scene::RenderPath::Volumes,
            gloss::scene::RenderPath::Prepass,
        ] {
            scene.render.path = path;
            let actual = image(&scene);
            let tol = gloss::image_compare::Tolerance {
                threshold: 3.0 / 255.0,
                max_frac_over: frac,
                max_abs: Some(max / 255.0),
            };
            common::assert_close(
                &format!("post-paths-{name}-{}", path.name()),
                &actual,
                &forward,
                &tol,
            );
        }
    }
}
