//! Notes 01 §5.2, bilinear filtering: "for texel coordinate 7.6 blend colour
//! of texel 7 and 8 by factor 0.6". A 16 x 1 texture stretched over 80
//! pixels by an orthographic camera: pixel i samples texel coordinate
//! (i + 0.5) / 5 - 0.5, so pixel 40 samples 7.6 exactly. Bilinear gives
//! 0.4 t7 + 0.6 t8 there (in linear light: an sRGB texture is decoded
//! before it is filtered), and every pixel equals the CPU twin
//! `linear_1d`; nearest gives texel 8.

use crate::common;
use gloss::lighting::{srgb_decode, srgb_encode};
use gloss::math::texture_mapping::{WrapRule, linear_1d, nearest_texel};
use gloss::renderer::Output;

/// Texel i's 8-bit value: i^2, so neighbours differ and the steps grow.
fn texel(i: usize) -> u8 {
    (i * i) as u8
}

fn strip(filter: &str) -> gloss::scene::Scene {
    // Each test its own file: the tests run at once.
    let png = common::out_dir().join(format!("texture-strip-16x1-{filter}.png"));
    image::RgbImage::from_fn(16, 1, |x, _| {
        let v = texel(x as usize);
        image::Rgb([v, v, v])
    })
    .save(&png)
    .expect("write the 16x1 texture");
    crate::scene(&format!(
        "name = \"t\"\n[camera]\nprojection = \"orthographic\"\neye = [0.0, 0.0, 5.0]\n\
         target = [0.0, 0.0, 0.0]\nhalf_height = 1.0\nnear = 1.0\nfar = 10.0\n\
         [render]\nsize = [80, 8]\nambient = [1.0, 1.0, 1.0]\n\
         [materials.m]\ndiffuse = [1.0, 1.0, 1.0]\nspecular = [0.0, 0.0, 0.0]\n\
         diffuse_texture = \"{}\"\nfilter = \"{filter}\"\nwrap = \"clamp\"\n\
         [[objects]]\nmesh = \"plane\"\nmaterial = \"m\"\nrotation = [90.0, 0.0, 0.0]\n\
         scale = [10.0, 1.0, 1.0]\n",
        png.display()
    ))
}

/// Pixel `i` of the middle row, linear red.
fn red(r: &common::Rendered, i: u32) -> f64 {
    let row = r.height / 2;
    f64::from(r.linear[((row * r.width + i) * 4) as usize])
}

/// The normalised coordinate pixel `i` samples.
fn at(i: u32) -> f64 {
    (f64::from(i) + 0.5) / 80.0
}

/// Nearest filtering: every pixel reads texel floor(16 u) alone. Returns
/// each texel as the GPU decoded it from sRGB (pixel 5 t + 2 lies in texel
/// t), after checking that each rounds back to its 8-bit value
/// when encoded (llvmpipe decodes sRGB with an approximation).
fn nearest_texels(ctx: &gloss::gl::Headless) -> Vec<f64> {
    let r = common::render_with(ctx, &strip("nearest"), Output::Linear32F);
    let decoded: Vec<f64> = (0..16).map(|t| red(&r, 5 * t + 2)).collect();
    for i in 0..80 {
        let t = nearest_texel(at(i), 16, WrapRule::Clamp);
        assert_eq!(red(&r, i), decoded[t], "pixel {i} reads texel {t} alone");
    }
    for (t, &d) in decoded.iter().enumerate() {
        let exact = f64::from(srgb_decode(f32::from(texel(t)) / 255.0));
        let back = f64::from(srgb_encode(d as f32)) * 255.0;
        assert!(
            (back - f64::from(texel(t))).abs() < 0.5,
            "texel {t} ({}): decoded {d} (sRGB gives {exact}), which encodes back to {back}",
            texel(t)
        );
    }
    decoded
}

#[test]
fn bilinear_at_7_6_blends_texels_7_and_8_by_0_6() {
    let ctx = common::context(common::backend());
    let texels = nearest_texels(&ctx);
    let r = common::render_with(&ctx, &strip("bilinear"), Output::Linear32F);
    assert!((at(40) * 16.0 - 0.5 - 7.6).abs() < 1e-12);
    // GL computes the weights to at least 8 bits (llvmpipe: 8): half a
    // 1/256 step of the neighbours' difference, plus float rounding.
    let tol = |a: f64, b: f64| (b - a).abs() / 512.0 + 1e-5;
    let expected = 0.4 * texels[7] + 0.6 * texels[8];
    assert!(
        (red(&r, 40) - expected).abs() <= tol(texels[7], texels[8]),
        "texel coordinate 7.6: {} against 0.4 t7 + 0.6 t8 = {expected}",
        red(&r, 40)
    );
    for i in 0..80 {
        let want = linear_1d(&texels, at(i), WrapRule::Clamp);
        let x = (at(i) * 16.0 - 0.5).floor().clamp(0.0, 14.0) as usize;
        assert!(
            (red(&r, i) - want).abs() <= tol(texels[x], texels[x + 1]),
            "pixel {i}: {} against {want}",
            red(&r, i)
        );
    }
}

#[test]
fn nearest_reads_one_texel_where_bilinear_blends() {
    let ctx = common::context(common::backend());
    let texels = nearest_texels(&ctx);
    // At 7.6 nearest reads texel 8 alone.
    assert_eq!(nearest_texel(at(40), 16, WrapRule::Clamp), 8);
    assert!(texels[8] > texels[7]);
}
