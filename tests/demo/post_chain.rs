//! The post chain in the demo (src/demo/panel/post_chain.rs,
//! src/demo/post_chain.rs): the panel's widgets, clicked through AccessKit,
//! add a blur, change its sigma, move it and remove it, tune bloom and
//! FXAA, and the frame plan follows; removing or moving gamma is refused with the scene loader's
//! message and the old chain keeps running; the inspector shows each of the
//! chain's textures as it holds them at the end of the frame, one mip
//! level of a texture, and each of bloom's levels; an edited chain saved and loaded again renders the
//! same image.

use crate::common;
use crate::driver::{Driver, input};
use gloss::demo::inspector::{Inspector, Mode, Shown, View, views};
use gloss::demo::panel::Action;
use gloss::demo::post_chain::{REFUSED, checked, name_steps, with_added};
use gloss::gl::framebuffer::Framebuffer;
use gloss::gl::program::Sources;
use gloss::lighting::srgb_encode;
use gloss::renderer::{Output, Renderer, render_scene};
use gloss::scene::post::{ChainForm, PASS_NAMES, PostPass, Taps};
use gloss::scene::{Scene, knobs};
use glow::HasContext;

/// Carry out the panel's actions as the demo does (src/demo/actions.rs):
/// a chain is checked, then given to the renderer; new settings too. The
/// first refusal's message, if any.
fn apply(scene: &mut Scene, r: &mut Renderer, actions: Vec<Action>) -> Option<String> {
    for a in actions {
        let edited = match a {
            Action::Post(chain) => checked(scene, &chain),
            Action::Settings(s) => {
                let mut e = scene.clone();
                e.render = s;
                Ok(e)
            }
            other => panic!("an action the post chain's section does not ask: {other:?}"),
        };
        match edited.and_then(|e| r.set_scene_values(&e).map(|()| e)) {
            Ok(e) => *scene = e,
            Err(e) => return Some(format!("{e:#}")),
        }
    }
    None
}

/// The chain's passes in the plan, in order, by name.
fn post_passes(r: &Renderer) -> Vec<&'static str> {
    let post = |p: &&gloss::frame::plan::Pass| p.code.contains("techniques/post/");
    r.plan.passes.iter().filter(post).map(|p| p.name).collect()
}

/// The chain's targets in the plan (the output aside).
fn chain_targets(r: &Renderer) -> Vec<&'static str> {
    let chain = |n: &&str| *n == "hdr" || n.starts_with("post_");
    r.plan
        .targets
        .iter()
        .map(|t| t.name)
        .filter(chain)
        .collect()
}

/// Render and check that the frame raised no GL error (the debug context
/// also fails a draw that samples a texture of its own framebuffer).
fn render(ctx: &gloss::gl::Headless, scene: &Scene, r: &mut Renderer) -> image::RgbaImage {
    r.render(&scene.camera).unwrap();
    ctx.debug
        .check(&ctx.gl, "a post chain edited in the panel")
        .unwrap();
    r.read_image()
}

#[test]
fn the_panel_adds_tunes_moves_and_removes_a_blur() {
    let ctx = common::context(common::backend());
    let mut scene = common::scene("post-effects.toml");
    let mut r = Renderer::new(&ctx.gl, &ctx.debug, &scene, &Sources::Embedded, 64, 36).unwrap();
    let before = render(&ctx, &scene, &mut r);
    let plan_before = r.plan.clone();
    assert_eq!(
        post_passes(&r),
        ["tone mapping", "kernel", "gamma correction"]
    );
    let mut d = Driver::new();

    // Add: a blur, before the final gamma, two steps in the plan.
    d.click(&input(&scene, &r), "add a pass…");
    let actions = d.click(&input(&scene, &r), "blur");
    assert_eq!(apply(&mut scene, &mut r, actions), None);
    let names: Vec<_> = scene.post.iter().map(PostPass::name).collect();
    assert_eq!(names, ["tonemap", "kernel", "blur", "gamma"]);
    let blur = PostPass::Blur {
        sigma: 2.0,
        radius: 6,
        taps: Taps::Direct,
    };
    assert_eq!(scene.post[2], blur);
    let want = ["tone mapping", "kernel", "blur", "blur", "gamma correction"];
    assert_eq!(post_passes(&r), want);
    let added = render(&ctx, &scene, &mut r);
    assert_ne!(added, before, "the blur changes the image");

    // Sigma: the radius follows it (ceil(3 sigma)), the plan says so.
    let actions = d.set_value(&input(&scene, &r), "sigma (texels)", 4.0);
    assert_eq!(apply(&mut scene, &mut r, actions), None);
    let PostPass::Blur { sigma, radius, .. } = scene.post[2] else {
        panic!("{:?}", scene.post[2]);
    };
    assert!(
        (sigma - 4.0).abs() < 1e-6 && radius == 12,
        "{sigma} {radius}"
    );
    assert!(
        (r.plan.passes.iter()).any(|p| p.draws.contains("Gaussian sigma 4 radius 12")),
        "{}",
        r.plan
    );
    let wider = render(&ctx, &scene, &mut r);
    assert_ne!(wider, added, "a wider blur changes the image");

    // Up: the blur runs before the kernel.
    let actions = d.click(&input(&scene, &r), "move post[2] (blur) up");
    assert_eq!(apply(&mut scene, &mut r, actions), None);
    let want = ["tone mapping", "blur", "blur", "kernel", "gamma correction"];
    assert_eq!(post_passes(&r), want);
    render(&ctx, &scene, &mut r);

    // Remove: the chain, the plan and the image are what they were.
    let actions = d.click(&input(&scene, &r), "remove post[1] (blur)");
    assert_eq!(apply(&mut scene, &mut r, actions), None);
    assert_eq!(r.plan, plan_before);
    assert_eq!(render(&ctx, &scene, &mut r), before);

    // Down to gamma alone: no inner step, so no ping-pong pair.
    assert_eq!(chain_targets(&r), ["hdr", "post_ping_pong"]);
    for gone in ["post[0] (tonemap)", "post[0] (kernel)"] {
        let actions = d.click(&input(&scene, &r), &format!("remove {gone}"));
        assert_eq!(apply(&mut scene, &mut r, actions), None);
    }
    assert_eq!(post_passes(&r), ["gamma correction"]);
    assert_eq!(chain_targets(&r), ["hdr"]);
    render(&ctx, &scene, &mut r);

    // Cascaded, and a tone map added back: one framebuffer per inner step.
    let actions = d.click(&input(&scene, &r), "cascaded (a framebuffer per step)");
    assert_eq!(apply(&mut scene, &mut r, actions), None);
    assert_eq!(scene.render.post_chain, ChainForm::Cascaded);
    d.click(&input(&scene, &r), "add a pass…");
    let actions = d.click(&input(&scene, &r), "tonemap");
    assert_eq!(apply(&mut scene, &mut r, actions), None);
    assert_eq!(post_passes(&r), ["tone mapping", "gamma correction"]);
    assert_eq!(chain_targets(&r), ["hdr", "post_1"]);
    render(&ctx, &scene, &mut r);
}

#[test]
fn removing_or_moving_gamma_is_refused_and_the_old_chain_keeps_running() {
    let ctx = common::context(common::backend());
    let mut scene = common::scene("post-effects.toml");
    let mut r = Renderer::new(&ctx.gl, &ctx.debug, &scene, &Sources::Embedded, 64, 36).unwrap();
    let before = render(&ctx, &scene, &mut r);
    let (post, plan) = (scene.post.clone(), r.plan.clone());
    let mut d = Driver::new();
    for (click, why) in [
        (
            "remove post[2] (gamma)",
            "post: the chain must end with a gamma pass (the 8-bit output holds encoded values): add [[post]] pass = \"gamma\" after post[1] (kernel)",
        ),
        (
            "move post[2] (gamma) up",
            "post[1] (gamma): gamma must be the last pass (it encodes the image for the 8-bit output)",
        ),
    ] {
        let actions = d.click(&input(&scene, &r), click);
        let message = apply(&mut scene, &mut r, actions).expect("refused");
        assert_eq!(message, format!("{REFUSED}: {why}"));
        // The scene, the plan and the image are the old chain's.
        assert_eq!(scene.post, post);
        assert_eq!(r.plan, plan);
        assert_eq!(render(&ctx, &scene, &mut r), before);
        // The panel shows the message (at its top and in the section).
        let shown = gloss::demo::panel::PanelInput {
            error: Some(&message),
            ..input(&scene, &r)
        };
        let (_, nodes) = d.frame(&shown, Vec::new());
        let labels = nodes
            .iter()
            .filter(|(_, n)| crate::driver::named(n, &message));
        assert_eq!(labels.count(), 2, "the message, above and in the section");
    }
    // A 17th entry is refused in the loader's words too.
    let long = with_added(&vec![post[0].clone(); 15], "gamma").unwrap();
    let long = with_added(&long, "invert").unwrap();
    let e = checked(&scene, &long).unwrap_err().to_string();
    assert_eq!(e, format!("{REFUSED}: post: 17 passes, at most 16"));
}

#[test]
fn every_pass_name_can_be_added_before_the_gamma() {
    let scene = common::scene("post-effects.toml");
    for name in PASS_NAMES {
        let chain = with_added(&scene.post, name).unwrap_or_else(|e| panic!("{name}: {e:#}"));
        assert_eq!(chain.len(), 4);
        // A kernel by name is a "kernel" entry.
        let want = match name {
            "sharpen" | "edge" | "emboss" => "kernel",
            other => other,
        };
        let at = if name == "gamma" { 3 } else { 2 };
        assert_eq!(chain[at].name(), want);
        // A second gamma is refused: gamma must be the last pass.
        assert_eq!(checked(&scene, &chain).is_ok(), name != "gamma", "{name}");
    }
}

/// A texture's level as RGBA floats, bottom row first (glGetTexImage: the
/// texture itself, not a framebuffer, which for the ping-pong pair holds
/// only the texture drawn last).
fn read_texture(
    gl: &glow::Context,
    texture: glow::Texture,
    level: i32,
    w: i32,
    h: i32,
) -> Vec<f32> {
    let mut out = vec![0f32; (w * h * 4) as usize];
    unsafe {
        gl.bind_texture(glow::TEXTURE_2D, Some(texture));
        gl.pixel_store_i32(glow::PACK_ALIGNMENT, 4);
        gl.get_tex_image(
            glow::TEXTURE_2D,
            level,
            glow::RGBA,
            glow::FLOAT,
            glow::PixelPackData::Slice(Some(gloss::gl::framebuffer::bytemuck_f32(&mut out))),
        );
        gl.bind_texture(glow::TEXTURE_2D, None);
    }
    out
}

/// The inspector's picture, bottom row first, as RGBA bytes.
fn shown(fb: &Framebuffer) -> Vec<u8> {
    let img = image::imageops::flip_vertical(&fb.read_rgba8_top_down(0));
    img.into_raw()
}

#[test]
fn the_inspector_shows_each_chain_texture_named_by_its_step() {
    let ctx = common::context(common::backend());
    let gl = &ctx.gl;
    let inspector = Inspector::new(gl, &Sources::Embedded).unwrap();
    let (w, h) = (96, 54);
    for form in [ChainForm::PingPong, ChainForm::Cascaded] {
        let mut scene = common::scene("post-effects.toml");
        scene.render.post_chain = form;
        // tonemap, blur (two steps), kernel, gamma: five steps.
        scene = checked(&scene, &with_added(&scene.post, "blur").unwrap()).unwrap();
        scene.post.swap(1, 2);
        let mut r = Renderer::new(gl, &ctx.debug, &scene, &Sources::Embedded, w, h).unwrap();
        render(&ctx, &scene, &mut r);
        let mut all = views(&r.plan, false, &[]);
        name_steps(&mut all, &scene, &r.plan);
        let labels: Vec<String> = all.iter().map(View::label).collect();
        let want: &[&str] = match form {
            ChainForm::PingPong => &[
                "hdr.color: the world, read by step 1 (RGBA16F): light x exposure",
                "post_ping_pong.ping: after step 3 of 5, blur 2/2 (RGBA16F): light x exposure",
                "post_ping_pong.pong: after step 4 of 5, kernel (RGBA16F): light x exposure",
            ],
            ChainForm::Cascaded => &[
                "hdr.color: the world, read by step 1 (RGBA16F): light x exposure",
                "post_1.color: after step 1 of 5, tone mapping (RGBA16F): light x exposure",
                "post_2.color: after step 2 of 5, blur 1/2 (RGBA16F): light x exposure",
                "post_3.color: after step 3 of 5, blur 2/2 (RGBA16F): light x exposure",
                "post_4.color: after step 4 of 5, kernel (RGBA16F): light x exposure",
            ],
        };
        for l in want {
            assert!(labels.iter().any(|x| x == l), "{l}\namong {labels:#?}");
        }
        // hdr is the world image, but this deferred frame ends with the
        // composite: nothing tests depth after it, so hdr has no
        // depth-stencil to show (the depth is the G-buffer's).
        assert!(!all.iter().any(|v| v.target == "hdr" && v.stencil));
        let fb = Framebuffer::new(gl, "inspected", w, h, &[glow::RGBA8], None).unwrap();
        // The output is named by the last step too.
        let output = "output.color: after step 5 of 5, gamma correction (RGBA8): colour";
        assert!(labels.iter().any(|x| x == output), "{labels:#?}");
        let written = |v: &&View| v.written.is_some() && v.target != "output";
        let chain: Vec<&View> = all.iter().filter(written).collect();
        assert_eq!(chain.len(), want.len());
        for v in chain {
            assert_eq!(v.mode, Mode::Light);
            let exposure = 1.5;
            inspector.draw(gl, v, r.targets(), &scene.camera, exposure, &fb);
            ctx.debug.check(gl, "inspecting the chain").unwrap();
            let t = &r.targets().get(v.target).colors[v.color_index.unwrap()];
            let texels = read_texture(gl, t.id, 0, w, h);
            let got = shown(&fb);
            let mut lit = 0;
            for (i, (&g, &x)) in got.iter().zip(&texels).enumerate() {
                if i % 4 == 3 {
                    continue;
                }
                let want = srgb_encode((x * exposure).clamp(0.0, 1.0)) * 255.0;
                assert!(
                    (f32::from(g) - want).abs() <= 1.0,
                    "{}: texel {} channel {}: shown {g}, holds {x} (x{exposure}: {want})",
                    v.label(),
                    i / 4,
                    i % 4
                );
                lit += usize::from(x > 0.05);
            }
            assert!(
                lit > texels.len() / 8,
                "{}: the image is mostly dark",
                v.label()
            );
        }
    }
}

#[test]
fn the_inspector_shows_one_mip_level_of_a_texture() {
    let ctx = common::context(common::backend());
    let gl = &ctx.gl;
    let inspector = Inspector::new(gl, &Sources::Embedded).unwrap();
    let (w, h) = (64, 32);
    // Stripes four texels wide, so that levels 0..2 differ and level 2 is
    // their average; made as a render target is (GL_NEAREST, one level),
    // then glGenerateMipmap.
    let pixels: Vec<u8> = (0..w * h)
        .flat_map(|i| {
            let (x, y) = (i % w, i / w);
            let on = (x / 4 + y / 4) % 2 == 0;
            let v = if on { 240 } else { 16 };
            [v, (x * 4) as u8, (y * 8) as u8, 255]
        })
        .collect();
    let texture = unsafe {
        let t = gl.create_texture().unwrap();
        gl.bind_texture(glow::TEXTURE_2D, Some(t));
        gl.tex_image_2d(
            glow::TEXTURE_2D,
            0,
            glow::RGBA8 as i32,
            w,
            h,
            0,
            glow::RGBA,
            glow::UNSIGNED_BYTE,
            glow::PixelUnpackData::Slice(Some(&pixels)),
        );
        gl.tex_parameter_i32(
            glow::TEXTURE_2D,
            glow::TEXTURE_MIN_FILTER,
            glow::NEAREST as i32,
        );
        gl.tex_parameter_i32(
            glow::TEXTURE_2D,
            glow::TEXTURE_MAG_FILTER,
            glow::NEAREST as i32,
        );
        gl.generate_mipmap(glow::TEXTURE_2D);
        gl.bind_texture(glow::TEXTURE_2D, None);
        t
    };
    let fb = Framebuffer::new(gl, "inspected", w, h, &[glow::RGBA8], None).unwrap();
    let camera = common::scene("plane.toml").camera;
    let mut pictures = Vec::new();
    for level in 0..=3u32 {
        let shown_as = Shown {
            mode: Mode::Color { encode: false },
            level,
            mipmapped: level > 0,
            exposure: 1.0,
        };
        inspector.draw_level(gl, Some(texture), shown_as, &camera, &fb);
        ctx.debug.check(gl, "a mip level in the inspector").unwrap();
        let (lw, lh) = (w >> level, h >> level);
        let texels = read_texture(gl, texture, level as i32, lw, lh);
        let got = shown(&fb);
        // Each pixel of the view shows the texel of the level under it.
        for y in 0..h {
            for x in 0..w {
                let (tx, ty) = (x >> level, y >> level);
                for c in 0..3 {
                    let g = got[((y * w + x) * 4 + c) as usize];
                    let t = texels[((ty * lw + tx) * 4 + c) as usize] * 255.0;
                    assert!(
                        (f32::from(g) - t).abs() <= 1.0,
                        "level {level}, pixel ({x}, {y}) channel {c}: shown {g}, texel {t}"
                    );
                }
            }
        }
        pictures.push(got);
    }
    assert_ne!(pictures[0], pictures[2], "level 2 is not level 0");
    // The texture's own filter is as it was: the level is read through a
    // sampler object, unbound after.
    unsafe {
        gl.bind_texture(glow::TEXTURE_2D, Some(texture));
        let min = gl.get_tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_MIN_FILTER);
        assert_eq!(min, glow::NEAREST as i32);
        gl.bind_texture(glow::TEXTURE_2D, None);
        assert_eq!(gl.get_parameter_i32(glow::SAMPLER_BINDING), 0);
        gl.delete_texture(texture);
    }
    let view = View {
        level: 2,
        ..View::of("bloom", "color", Some(0), glow::RGBA16F, Mode::Light)
    };
    assert_eq!(
        view.label(),
        "bloom.color level 2 (RGBA16F): light x exposure"
    );
}

#[test]
fn the_inspector_shows_each_of_blooms_mip_levels() {
    let ctx = common::context(common::backend());
    let gl = &ctx.gl;
    let inspector = Inspector::new(gl, &Sources::Embedded).unwrap();
    // 54 rows: levels of 27, 13, 6 and 3 rows, not halves of each other.
    let (w, h) = (96, 54);
    let mut scene = common::scene("bloom.toml");
    scene.render.size = (w as u32, h as u32);
    let mut r = Renderer::new(gl, &ctx.debug, &scene, &Sources::Embedded, w, h).unwrap();
    render(&ctx, &scene, &mut r);
    let mut all = views(&r.plan, false, &[]);
    name_steps(&mut all, &scene, &r.plan);
    let labels: Vec<String> = all.iter().map(View::label).collect();
    let sigmas = [6.2, 24.9, 81.0, 263.0];
    for (k, sigma) in sigmas.iter().enumerate() {
        let want = format!(
            "bloom_levels.color level {}: blur {} of 4, sigma {sigma} full-resolution pixels \
             (RGBA16F): light x exposure",
            k + 1,
            k + 1
        );
        assert!(labels.contains(&want), "{want}\namong {labels:#?}");
        let temp = format!(
            "bloom_temp.color level {}: blur {}'s horizontal pass (RGBA16F): light x exposure",
            k + 1,
            k + 1
        );
        assert!(labels.contains(&temp), "{temp}\namong {labels:#?}");
    }
    let fb = Framebuffer::new(gl, "inspected", w, h, &[glow::RGBA8], None).unwrap();
    let exposure = 4.0;
    let levels: Vec<&View> = all.iter().filter(|v| v.target == "bloom_levels").collect();
    assert_eq!(levels.len(), 4, "{labels:#?}");
    let mut pictures = Vec::new();
    for v in levels {
        inspector.draw(gl, v, r.targets(), &scene.camera, exposure, &fb);
        ctx.debug
            .check(gl, "a bloom level in the inspector")
            .unwrap();
        let texture = r.targets().mip("bloom_levels").unwrap().texture.id;
        let (lw, lh) = gloss::gl::texture::level_size(w, h, v.level);
        let texels = read_texture(gl, texture, v.level as i32, lw, lh);
        let got = shown(&fb);
        // Pixel (x, y) shows the texel under its centre: the level
        // stretched over the view.
        for y in 0..h {
            for x in 0..w {
                let tx = ((2 * x + 1) * lw / (2 * w)) as usize;
                let ty = ((2 * y + 1) * lh / (2 * h)) as usize;
                for c in 0..3 {
                    let t = texels[(ty * lw as usize + tx) * 4 + c];
                    let want = srgb_encode((t * exposure).clamp(0.0, 1.0)) * 255.0;
                    let g = got[((y * w + x) * 4) as usize + c];
                    assert!(
                        (f32::from(g) - want).abs() <= 1.0,
                        "{}: pixel ({x}, {y}) channel {c}: shown {g}, texel {t}",
                        v.label()
                    );
                }
            }
        }
        pictures.push(got);
    }
    for i in 1..4 {
        assert_ne!(
            pictures[i - 1],
            pictures[i],
            "level {i} and {} differ",
            i + 1
        );
    }
}

#[test]
fn the_panel_tunes_bloom_and_fxaa() {
    let ctx = common::context(common::backend());
    let mut scene = common::scene("bloom.toml");
    scene.render.size = (96, 54);
    let mut r = Renderer::new(&ctx.gl, &ctx.debug, &scene, &Sources::Embedded, 96, 54).unwrap();
    let before = render(&ctx, &scene, &mut r);
    let mut d = Driver::new();
    // Bloom: every blur at full resolution, linear taps, a wider blur2,
    // more of blur1 in the merge.
    let steps: [(&str, Option<f64>); 6] = [
        ("mips", None),
        ("full", None),
        ("direct", None),
        ("linear", None),
        ("blur2 sigma", Some(30.0)),
        ("weight of blur1", Some(0.2)),
    ];
    for (name, value) in steps {
        let actions = match value {
            Some(v) => d.set_value(&input(&scene, &r), name, v),
            None => d.click(&input(&scene, &r), name),
        };
        assert_eq!(apply(&mut scene, &mut r, actions), None, "{name}");
    }
    let PostPass::Bloom(b) = &scene.post[0] else {
        panic!("{:?}", scene.post);
    };
    assert_eq!(b.scheme, gloss::scene::bloom::BloomScheme::Full);
    assert_eq!(b.taps, Taps::Linear);
    assert_eq!(b.levels[1].sigma, 30.0);
    assert_eq!(b.weights[1], 0.2);
    assert!(
        (r.plan.targets.iter()).any(|t| t.name == "bloom_full1"),
        "the full-resolution scheme's targets:\n{}",
        r.plan
    );
    let bloomed = render(&ctx, &scene, &mut r);
    assert_ne!(bloomed, before, "the bloom's settings change the image");
    // FXAA, added before gamma: its preset and sub-pixel setting.
    d.click(&input(&scene, &r), "add a pass…");
    let actions = d.click(&input(&scene, &r), "fxaa");
    assert_eq!(apply(&mut scene, &mut r, actions), None);
    d.click(&input(&scene, &r), "12");
    let actions = d.click(&input(&scene, &r), "39 (12 search steps)");
    assert_eq!(apply(&mut scene, &mut r, actions), None);
    let actions = d.set_value(&input(&scene, &r), "subpix (0 off, 1 softer)", 0.25);
    assert_eq!(apply(&mut scene, &mut r, actions), None);
    let PostPass::Fxaa(x) = &scene.post[2] else {
        panic!("{:?}", scene.post);
    };
    assert_eq!((x.quality, x.subpix), (39, 0.25));
    assert!(
        (r.plan.passes.iter()).any(|p| p.name == "fxaa"),
        "{}",
        r.plan
    );
    let smoothed = render(&ctx, &scene, &mut r);
    assert_ne!(smoothed, bloomed, "FXAA changes the image");
}

#[test]
fn an_edited_chain_saved_and_loaded_again_renders_the_same_image() {
    let ctx = common::context(common::backend());
    let mut scene = common::scene("post-effects.toml");
    let mut r = Renderer::new(&ctx.gl, &ctx.debug, &scene, &Sources::Embedded, 64, 36).unwrap();
    let mut d = Driver::new();
    // Through the panel: a blur with linear taps and its own radius, a
    // kernel of its own nine weights, the sRGB curve, cascaded.
    let steps: [(&str, Option<f64>); 9] = [
        ("add a pass…", None),
        ("blur", None),
        ("sigma (texels)", Some(1.7)),
        ("radius (texels)", Some(9.0)),
        ("direct", None),
        ("linear", None),
        ("exact sRGB (GL_FRAMEBUFFER_SRGB)", None),
        ("cascaded (a framebuffer per step)", None),
        ("exposure multiplier", Some(0.8)),
    ];
    for (name, value) in steps {
        let actions = match value {
            Some(v) => d.set_value(&input(&scene, &r), name, v),
            None => d.click(&input(&scene, &r), name),
        };
        assert_eq!(apply(&mut scene, &mut r, actions), None, "{name}");
    }
    let PostPass::Kernel(k) = &mut scene.post[1] else {
        panic!("{:?}", scene.post);
    };
    k.preset = None;
    k.weights[4] = 4.5;
    scene = checked(&scene, &scene.post).unwrap();
    let blur = PostPass::Blur {
        sigma: 1.7,
        radius: 9,
        taps: Taps::Linear,
    };
    assert_eq!(scene.post[2], blur);
    assert!(matches!(scene.post[3], PostPass::Gamma { srgb: true, .. }));
    assert!(
        matches!(scene.post[0], PostPass::Tonemap { exposure, .. } if (exposure - 0.8).abs() < 1e-6)
    );
    assert_eq!(
        (knobs::POST_CHAIN.get)(&scene.render),
        knobs::Value::Choice(1)
    );

    let dir = std::env::temp_dir().join("gloss-save-post-chain");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("chain.toml");
    scene.save_as(&file).unwrap();
    let mut again = Scene::load(&file).unwrap();
    assert_eq!(again.post, scene.post);
    assert_eq!(again.render, scene.render);
    for s in [&mut scene, &mut again] {
        s.render.size = (96, 54);
    }
    // One 8-bit step, as for every saved scene (tests/demo/save.rs): a
    // spot light's unit direction is normalised again on loading.
    let a = render_scene(&ctx, &scene, Output::Srgb8)
        .unwrap()
        .read_image();
    let b = render_scene(&ctx, &again, Output::Srgb8)
        .unwrap()
        .read_image();
    common::assert_close("save-post-chain", &b, &a, &crate::save::EXACT);
}
