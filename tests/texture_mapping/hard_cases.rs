//! Texture hard cases (notes 01 §5): a non-power-of-two texture (3 x 5), a
//! 1 x 1 texture, and every PNG colour type gloss reads (grey, grey +
//! alpha, RGB, RGBA; 8 and 16 bits a channel). Each is drawn over a quad
//! that fills an orthographic view, with nearest filtering, so that pixel
//! columns and rows fall on known texels; every texel must read back as the
//! file holds it (16-bit channels rounded to 8 bits, the sRGB decode of a
//! colour texture undone within half a step). The malformed and absurd
//! PNGs are refused in tests/errors/png.rs; normal maps are read as linear
//! data, which tests/lighting/bump_mapping.rs checks.

use crate::common;
use gloss::lighting::srgb_encode;
use gloss::renderer::Output;
use image::DynamicImage;

/// The texel (x, y) of a W x H test image, as 8-bit RGBA: distinct per texel.
fn texel(x: u32, y: u32) -> [u8; 4] {
    [
        (40 + 50 * x) as u8,
        (20 + 45 * y) as u8,
        (200 - 30 * x - 20 * y) as u8,
        255,
    ]
}

/// A quad filling a view of `w * 8` x `h * 8` pixels shows texture `png`
/// with nearest filtering: pixel (8 i + 4, 8 j + 4) (rows from the top)
/// reads texel (i, j) (rows from the top of the image file).
fn render(png: &std::path::Path, w: u32, h: u32, filter: &str) -> image::RgbaImage {
    let (pw, ph) = (w * 8, h * 8);
    let half_h = 1.0;
    let half_w = half_h * f64::from(pw) / f64::from(ph);
    let text = format!(
        "name = \"t\"\n[camera]\nprojection = \"orthographic\"\neye = [0.0, 0.0, 5.0]\n\
         target = [0.0, 0.0, 0.0]\nhalf_height = {half_h:.1}\nnear = 1.0\nfar = 10.0\n\
         [render]\nsize = [{pw}, {ph}]\nambient = [1.0, 1.0, 1.0]\n\
         [materials.m]\ndiffuse = [1.0, 1.0, 1.0]\nspecular = [0.0, 0.0, 0.0]\n\
         diffuse_texture = \"{}\"\nfilter = \"{filter}\"\nwrap = \"clamp\"\n\
         [[objects]]\nmesh = \"plane\"\nmaterial = \"m\"\nrotation = [90.0, 0.0, 0.0]\n\
         scale = [{half_w}, 1.0, {half_h:.1}]\n",
        png.display()
    );
    let s = crate::scene(&text);
    let r = common::render(&s, Output::Linear32F);
    // Encode the linear result to 8 bits, as the file's values were.
    image::RgbaImage::from_fn(pw, ph, |x, y| {
        let i = (((ph - 1 - y) * pw + x) * 4) as usize;
        let c = |k: usize| (srgb_encode(r.linear[i + k]) * 255.0).round() as u8;
        image::Rgba([c(0), c(1), c(2), 255])
    })
}

fn check(name: &str, img: DynamicImage, want: impl Fn(u32, u32) -> [u8; 3]) {
    let (w, h) = (img.width(), img.height());
    let png = common::out_dir().join(format!("hard-case-{name}.png"));
    img.save(&png).expect("write the test PNG");
    let shown = render(&png, w, h, "nearest");
    for j in 0..h {
        for i in 0..w {
            let p = shown.get_pixel(8 * i + 4, 8 * j + 4);
            assert_eq!(
                [p[0], p[1], p[2]],
                want(i, j),
                "{name}: texel ({i}, {j}) of {w}x{h}"
            );
        }
    }
}

#[test]
fn every_png_colour_type_reads_back_its_texels_on_a_3x5_texture() {
    let (w, h) = (3, 5);
    let rgba = image::RgbaImage::from_fn(w, h, |x, y| image::Rgba(texel(x, y)));
    let grey = |x, y| texel(x, y)[0];
    check("rgba8", DynamicImage::ImageRgba8(rgba.clone()), |x, y| {
        let t = texel(x, y);
        [t[0], t[1], t[2]]
    });
    check(
        "rgb8",
        DynamicImage::ImageRgb8(image::RgbImage::from_fn(w, h, |x, y| {
            let t = texel(x, y);
            image::Rgb([t[0], t[1], t[2]])
        })),
        |x, y| {
            let t = texel(x, y);
            [t[0], t[1], t[2]]
        },
    );
    check(
        "grey8",
        DynamicImage::ImageLuma8(image::GrayImage::from_fn(w, h, |x, y| {
            image::Luma([grey(x, y)])
        })),
        |x, y| [grey(x, y); 3],
    );
    check(
        "grey-alpha8",
        DynamicImage::ImageLumaA8(image::GrayAlphaImage::from_fn(w, h, |x, y| {
            image::LumaA([grey(x, y), 200])
        })),
        |x, y| [grey(x, y); 3],
    );
    // 16 bits a channel: v16 = 257 v8 + 100 rounds back to v8.
    let wide = |v: u8| 257 * u16::from(v) + 100;
    check(
        "rgba16",
        DynamicImage::ImageRgba16(image::ImageBuffer::from_fn(w, h, |x, y| {
            let t = texel(x, y);
            image::Rgba([wide(t[0]), wide(t[1]), wide(t[2]), 65535])
        })),
        |x, y| {
            let t = texel(x, y);
            [t[0], t[1], t[2]]
        },
    );
    check(
        "grey16",
        DynamicImage::ImageLuma16(image::ImageBuffer::from_fn(w, h, |x, y| {
            image::Luma([wide(grey(x, y))])
        })),
        |x, y| [grey(x, y); 3],
    );
}

#[test]
fn a_1x1_texture_fills_the_quad_with_any_filter() {
    let png = common::out_dir().join("hard-case-1x1.png");
    image::RgbImage::from_pixel(1, 1, image::Rgb([90, 160, 220]))
        .save(&png)
        .unwrap();
    for filter in ["nearest", "bilinear", "trilinear", "anisotropic"] {
        let shown = render(&png, 1, 1, filter);
        assert!(
            shown.pixels().all(|p| [p[0], p[1], p[2]] == [90, 160, 220]),
            "{filter}"
        );
    }
}

#[test]
fn a_non_power_of_two_texture_has_its_mip_chain() {
    // 3 x 5: levels 3x5, 1x2, 1x1 (each side halved, rounded down, at least 1).
    assert_eq!(gloss::gl::texture::max_level(3, 5), 2);
    assert_eq!(gloss::gl::texture::level_size(3, 5, 1), (1, 2));
    assert_eq!(
        gloss::math::texture_mapping::mip_chain_bytes(3, 5, 4),
        4 * (15 + 2 + 1)
    );
}
