//! src/demo/pictures.rs: `gloss render --target` writes what only the
//! inspector draws. `shadow_map.N` is light N's cube unfolded into the
//! cross, each pixel the stored value of the texel under it stretched
//! between the least and greatest value below 1.0; `bloom_levels.N` is mip
//! level N stretched over the picture, each pixel its texel's light
//! sRGB-encoded. A name it cannot draw says what it can.

use crate::common;
use crate::shadow_views::{close, range, shown};
use gloss::demo::pictures::target_picture;
use gloss::demo::shadow_views::BACKGROUND;
use gloss::gl::Headless;
use gloss::gl::program::Sources;
use gloss::lighting::srgb_encode;
use gloss::renderer::{Output, Renderer, render_scene};
use glow::HasContext;

/// Renders `name` at `size`, its shadow maps `texels` on a side.
fn rendered(ctx: &Headless, name: &str, size: (u32, u32), texels: u32) -> Renderer {
    let mut scene = common::scene(name);
    scene.render.size = size;
    for l in &mut scene.lights {
        if let Some(s) = &mut l.shadow {
            s.resolution = texels;
        }
    }
    render_scene(ctx, &scene, Output::Srgb8).unwrap()
}

fn picture(ctx: &Headless, r: &Renderer, name: &str) -> anyhow::Result<image::RgbaImage> {
    let p = target_picture(&ctx.gl, &Sources::Embedded, r, name);
    ctx.debug.check(&ctx.gl, name).unwrap();
    p
}

fn rgb(p: &image::Rgba<u8>) -> [u8; 3] {
    [p.0[0], p.0[1], p.0[2]]
}

#[test]
fn shadow_map_n_is_light_ns_cube_unfolded_into_the_cross() {
    let ctx = common::context(common::backend());
    // 512 x 384: 128-pixel faces, two pixels a texel of a 64-texel face.
    let (f, n) = (128u32, 64usize);
    let r = rendered(&ctx, "shadows-point.toml", (512, 384), n as u32);
    let light = r.shadows().maps[0].0.light;
    let img = picture(&ctx, &r, &format!("shadow_map.{light}")).unwrap();
    assert_eq!(img.dimensions(), (512, 384));
    let map = &r.shadows().maps[0].1;
    let faces: Vec<Vec<f32>> = (0..6).map(|k| map.read(k)).collect();
    let (lo, hi) = range(faces.iter().flatten());
    assert!(lo < hi, "the map holds depth: {lo}..{hi}");
    // Cells of the cross (column, row from the top): +x, -x, +y, -y, +z, -z.
    let cells = [(2, 1), (0, 1), (1, 0), (1, 2), (1, 1), (3, 1)];
    for (cx, cy) in [(0, 0), (2, 0), (3, 0), (0, 2), (2, 2), (3, 2)] {
        let p = img.get_pixel(cx * f + f / 2, cy * f + f / 2);
        assert_eq!(rgb(p), BACKGROUND, "cell ({cx}, {cy}) is outside the cross");
    }
    for (face, &(cx, cy)) in cells.iter().enumerate() {
        let mut shades = std::collections::BTreeSet::new();
        // Every other pixel of the cell, each the centre of its texel's
        // 2 x 2 block; a face's row t = 0 is at the top of its cell.
        for (s, t) in (0..n).flat_map(|t| (0..n).map(move |s| (s, t))) {
            let (x, y) = (cx * f + 2 * s as u32, cy * f + 2 * t as u32);
            let d = faces[face][t * n + s];
            let want = shown(d, (lo, hi));
            let got = rgb(img.get_pixel(x, y));
            assert!(
                close(got, want),
                "face {face} texel ({s}, {t}) = {d}: ({x}, {y}) shows {got:?}, not {want:?}"
            );
            shades.insert(got[0]);
        }
        assert!(shades.len() > 8, "face {face}: {} shades", shades.len());
    }
}

/// Level `level` of `target`'s texture as floats (RGBA), row 0 at the bottom.
fn read_level(ctx: &Headless, r: &Renderer, target: &str, level: u32) -> (Vec<f32>, i32, i32) {
    let m = r.targets().mip(target).expect("a mip target");
    let l = m.levels.iter().find(|l| l.level == level).unwrap();
    let mut out = vec![0f32; (l.width * l.height * 4) as usize];
    unsafe {
        let gl = &ctx.gl;
        gl.bind_framebuffer(glow::READ_FRAMEBUFFER, Some(l.framebuffer));
        gl.read_pixels(
            0,
            0,
            l.width,
            l.height,
            glow::RGBA,
            glow::FLOAT,
            glow::PixelPackData::Slice(Some(gloss::gl::framebuffer::bytemuck_f32(&mut out))),
        );
        gl.bind_framebuffer(glow::READ_FRAMEBUFFER, None);
    }
    (out, l.width, l.height)
}

#[test]
fn target_n_is_mip_level_n_stretched_texel_by_texel() {
    let ctx = common::context(common::backend());
    let (w, h) = (256u32, 144u32);
    let r = rendered(&ctx, "bloom.toml", (w, h), 64);
    for level in 1..=4 {
        let name = format!("bloom_levels.{level}");
        let img = picture(&ctx, &r, &name).unwrap();
        assert_eq!(img.dimensions(), (w, h), "{name}");
        let (texels, lw, lh) = read_level(&ctx, &r, "bloom_levels", level);
        assert_eq!((lw, lh), ((w >> level) as i32, (h >> level) as i32));
        let mut lit = 0;
        for y in (0..h).step_by(3) {
            for x in (0..w).step_by(3) {
                // The pixel's centre, in the level's texels (row 0 at the bottom).
                let s = ((x as f32 + 0.5) / w as f32 * lw as f32) as usize;
                let t = ((((h - 1 - y) as f32) + 0.5) / h as f32 * lh as f32) as usize;
                let i = (t * lw as usize + s) * 4;
                let want = [0, 1, 2]
                    .map(|k| (srgb_encode(texels[i + k]).clamp(0.0, 1.0) * 255.0).round() as u8);
                let got = rgb(img.get_pixel(x, y));
                assert!(
                    close(got, want),
                    "{name}: ({x}, {y}) shows {got:?}; texel ({s}, {t}) gives {want:?}"
                );
                lit += usize::from(want != [0; 3]);
            }
        }
        assert!(lit > 100, "{name}: the blur holds light ({lit} pixels)");
    }
}

#[test]
fn a_name_it_cannot_draw_says_what_it_can() {
    let ctx = common::context(common::backend());
    let r = rendered(&ctx, "shadows-point.toml", (64, 48), 16);
    let light = r.shadows().maps[0].0.light;
    let e = err_of(&ctx, &r, "shadow_map");
    assert!(e.contains("name a light's index"), "{e}");
    let e = err_of(&ctx, &r, "shadow_map.9");
    assert!(
        e.contains("light 9 casts no shadow") && e.contains(&format!("that do: {light}")),
        "{e}"
    );
    let e = err_of(&ctx, &r, "shadow_map.x");
    assert!(e.contains("\"x\" is not a light's index"), "{e}");
    let r = rendered(&ctx, "bloom.toml", (64, 48), 16);
    let e = err_of(&ctx, &r, "bloom_levels.7");
    assert!(e.contains("has the mip levels 1..=4"), "{e}");
    let e = err_of(&ctx, &r, "bloom_levels");
    assert!(
        e.contains("name a mip level, such as bloom_levels.1"),
        "{e}"
    );
    let e = err_of(&ctx, &r, "shadow_map.0");
    assert!(e.contains("no light of this scene casts a shadow"), "{e}");
}

fn err_of(ctx: &Headless, r: &Renderer, name: &str) -> String {
    format!("{:#}", picture(ctx, r, name).unwrap_err())
}
