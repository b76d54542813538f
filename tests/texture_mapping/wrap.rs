//! Notes 01 §5, "Clamp", "Repeat", "Mirror": a quad whose texture
//! coordinates run from -0.5 to 1.5 across the screen, seen by an
//! orthographic camera so each pixel centre's (u, v) is known exactly, with
//! the ramp texture and nearest filtering, so each pixel names the texel
//! it read. Every pixel is held to the CPU's wrap rule, under all nine
//! pairs of rules along s and t, and the notes' examples (1.1 and -0.1) are
//! read back.

use crate::common;
use gloss::math::texture_mapping::{WrapRule, nearest_texel};
use gloss::renderer::Output;
use gloss::scene::texturing::Wrap;

const SIZE: u32 = 256;
const TEXELS: usize = 64;

/// The quad fills the 256 x 256 view: u = (i + 0.5) / 256 at pixel column i.
fn quad(wrap_s: Wrap, wrap_t: Wrap) -> gloss::scene::Scene {
    crate::scene(&format!(
        "name = \"t\"\n[camera]\nprojection = \"orthographic\"\neye = [0.0, 0.0, 5.0]\n\
         target = [0.0, 0.0, 0.0]\nhalf_height = 2.0\nnear = 1.0\nfar = 10.0\n\
         [render]\nsize = [{SIZE}, {SIZE}]\nambient = [1.0, 1.0, 1.0]\n\
         [materials.m]\ndiffuse = [1.0, 1.0, 1.0]\nspecular = [0.0, 0.0, 0.0]\n\
         diffuse_texture = \"assets/uv-ramp.png\"\nfilter = \"nearest\"\n\
         wrap = [\"{wrap_s}\", \"{wrap_t}\"]\nuv_scale = [2.0, 2.0]\nuv_offset = [-0.5, -0.5]\n\
         [[objects]]\nmesh = \"plane\"\nmaterial = \"m\"\nrotation = [90.0, 0.0, 0.0]\n\
         scale = [2.0, 1.0, 2.0]\n"
    ))
}

/// The transformed coordinate at pixel column (or row from the bottom) i:
/// 2 (i + 0.5) / 256 - 0.5, so coordinate x 64 is i + 0.5 - 32, never on a
/// texel's edge.
fn coordinate(i: u32) -> f64 {
    2.0 * (f64::from(i) + 0.5) / f64::from(SIZE) - 0.5
}

#[test]
fn every_pixel_reads_the_texel_the_wrap_rules_give() {
    let ctx = common::context(common::backend());
    for &s in Wrap::ALL {
        for &t in Wrap::ALL {
            let img = common::render_with(&ctx, &quad(s, t), Output::Srgb8).image;
            let mut wrong = Vec::new();
            for j in 0..SIZE {
                let v = coordinate(SIZE - 1 - j);
                for i in 0..SIZE {
                    let u = coordinate(i);
                    let expected = (
                        nearest_texel(u, TEXELS, s.rule()) as i64,
                        nearest_texel(v, TEXELS, t.rule()) as i64,
                    );
                    let got = crate::ramp_texel(img.get_pixel(i, j));
                    if got != expected {
                        wrong.push((i, j, got, expected));
                    }
                }
            }
            assert!(
                wrong.is_empty(),
                "wrap [{s}, {t}]: {} pixels read the wrong texel, first (column, row, read, expected): {:?}",
                wrong.len(),
                &wrong[..wrong.len().min(5)]
            );
        }
    }
}

#[test]
fn the_notes_examples_1_1_and_minus_0_1() {
    // Column 204 reads u = 70.25 / 64 = 1.0977 and column 50 u = -6.75 / 64
    // = -0.1055: the same texels as the notes' 1.1 and -0.1 (1.1 x 64 = 70.4
    // is in texel 70 too, and -0.1 x 64 = -6.4 in texel -7).
    let (at_1_1, at_minus_0_1) = (204, 50);
    assert_eq!((coordinate(at_1_1) * 64.0).floor(), (1.1f64 * 64.0).floor());
    assert_eq!(
        (coordinate(at_minus_0_1) * 64.0).floor(),
        (-0.1f64 * 64.0).floor()
    );
    let ctx = common::context(common::backend());
    // (rule, texel read at 1.1, at -0.1): repeat 1.1 -> 0.1 (texel 6),
    // -0.1 -> 0.9 (texel 57); mirror 1.1 -> 0.9, -0.1 -> 0.1; clamp the
    // edges, texels 63 and 0.
    for (wrap, at_1_1_texel, at_minus_texel) in [
        (Wrap::Repeat, 6, 57),
        (Wrap::Mirror, 57, 6),
        (Wrap::Clamp, 63, 0),
    ] {
        assert_eq!(nearest_texel(1.1, TEXELS, wrap.rule()), at_1_1_texel);
        assert_eq!(nearest_texel(-0.1, TEXELS, wrap.rule()), at_minus_texel);
        let img = common::render_with(&ctx, &quad(wrap, Wrap::Clamp), Output::Srgb8).image;
        let row = SIZE / 2;
        assert_eq!(
            crate::ramp_texel(img.get_pixel(at_1_1, row)).0,
            at_1_1_texel as i64,
            "{wrap}: 1.1"
        );
        assert_eq!(
            crate::ramp_texel(img.get_pixel(at_minus_0_1, row)).0,
            at_minus_texel as i64,
            "{wrap}: -0.1"
        );
    }
    assert_eq!(WrapRule::Repeat, Wrap::Repeat.rule());
}

#[test]
fn wrap_keys_are_checked() {
    let bad = |key: &str| {
        let text = format!(
            "name = \"t\"\n[camera]\neye = [0.0, 0.0, 5.0]\ntarget = [0.0, 0.0, 0.0]\n\
             [materials.m]\n{key}\n[[objects]]\nmesh = \"cube\"\nmaterial = \"m\"\n"
        );
        gloss::scene::Scene::parse(&text, &common::root().join("scenes/t.toml"))
            .expect_err(key)
            .to_string()
    };
    let e = bad("wrap = \"tile\"");
    assert!(
        e.contains("materials.m.wrap") && e.contains("clamp, repeat or mirror"),
        "{e}"
    );
    let e = bad("wrap = [\"repeat\", \"mirror\", \"clamp\"]");
    assert!(e.contains("found 3 words"), "{e}");
    let e = bad("filter = \"cubic\"");
    assert!(e.contains("trilinear"), "{e}");
    let e = bad("anisotropy = 64.0");
    assert!(
        e.contains("materials.m.anisotropy") && e.contains("1..=16"),
        "{e}"
    );
    let e = bad("uv_scale = [1.0, nan]");
    assert!(
        e.contains("materials.m.uv_scale") && e.contains("finite"),
        "{e}"
    );
}
