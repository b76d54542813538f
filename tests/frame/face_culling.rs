//! Notes 01 §3.4, "Face Culling", per material (`cull` in a material's
//! table): culling every face "effectively disables the rasteriser" (the
//! objects vanish, only the background is left), culling front faces shows
//! a closed mesh's inside, on the forward and deferred paths alike; the key
//! is checked and survives "save as".

use crate::common;
use gloss::image_compare::compare_rgba8;
use gloss::renderer::Output;
use gloss::scene::{Cull, RenderPath, Scene};

fn culling(base: &Scene, path: RenderPath, cull: Cull) -> image::RgbaImage {
    let mut s = base.clone();
    s.render.path = path;
    s.render.size = (160, 90);
    for m in &mut s.materials {
        m.cull = cull;
    }
    common::render(&s, Output::Srgb8).image
}

#[test]
fn culling_every_face_leaves_the_background_and_front_shows_the_inside() {
    let base = common::scene("default.toml");
    for path in [RenderPath::Forward, RenderPath::Deferred] {
        let all = culling(&base, path, Cull::FrontAndBack);
        let bg = all.get_pixel(0, 0).0;
        assert!(
            all.pixels().all(|p| p.0 == bg),
            "{path:?}: something was drawn"
        );
        let back = culling(&base, path, Cull::Back);
        assert!(
            back.pixels().any(|p| p.0 != bg),
            "{path:?}: the scene is drawn"
        );
        let front = culling(&base, path, Cull::Front);
        let m = compare_rgba8(&front, &back, 1.0 / 255.0).unwrap();
        assert!(
            m.frac_over > 0.05,
            "{path:?}: front culling shows the insides: {m}"
        );
        // The default is back-face culling.
        assert!(
            back == common::render(
                &{
                    let mut s = base.clone();
                    s.render.path = path;
                    s.render.size = (160, 90);
                    s
                },
                Output::Srgb8
            )
            .image
        );
    }
}

#[test]
fn the_cull_key_is_checked() {
    let text = std::fs::read_to_string(common::root().join("scenes/plane.toml")).unwrap();
    let path = common::root().join("scenes/plane.toml");
    let front = text.replace("shininess = 24.0", "shininess = 24.0\ncull = \"front\"");
    let s = Scene::parse(&front, &path).unwrap();
    assert!(s.materials.iter().any(|m| m.cull == Cull::Front));
    let bad = text.replace("shininess = 24.0", "shininess = 24.0\ncull = \"sideways\"");
    let e = format!("{:#}", Scene::parse(&bad, &path).unwrap_err());
    assert!(
        e.contains("sideways") && e.contains("front_and_back"),
        "{e}"
    );
}
