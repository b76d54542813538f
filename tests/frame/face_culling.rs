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

#[test]
fn a_clockwise_material_shows_what_front_culling_shows() {
    // Winding "cw" makes the mesh's inside faces the front ones: culling
    // back faces then keeps the inside, as culling front faces does for
    // the usual winding.
    let base = common::scene("default.toml");
    for path in [RenderPath::Forward, RenderPath::Deferred] {
        let mut cw = base.clone();
        cw.render.path = path;
        cw.render.size = (160, 90);
        for m in &mut cw.materials {
            m.winding = gloss::scene::Winding::Cw;
        }
        let inside = common::render(&cw, Output::Srgb8).image;
        let front = culling(&base, path, Cull::Front);
        let back = culling(&base, path, Cull::Back);
        assert!(
            inside == front,
            "{path:?}: cw + cull back == ccw + cull front"
        );
        assert!(inside != back, "{path:?}: the winding changes the image");
    }
}

/// A floor at y = -0.5 reaching behind the camera: the near plane (z = -1
/// in eye space) cuts its triangles where they meet it, three quarters
/// down the picture (90° field of view: y / -z = -0.5).
fn cut_floor(wireframe: bool) -> image::RgbaImage {
    let text = "name = \"t\"\n[camera]\neye = [0.0, 0.0, 0.0]\ntarget = [0.0, 0.0, -1.0]\n\
        fov_y = 90.0\nnear = 1.0\n[render]\nsize = [101, 101]\nambient = [1.0, 1.0, 1.0]\n\
        [materials.white]\ndiffuse = [1.0, 1.0, 1.0]\nspecular = [0.0, 0.0, 0.0]\ncull = \"none\"\n\
        [[objects]]\nmesh = \"plane\"\nmaterial = \"white\"\nposition = [0.0, -0.5, -1.0]\nscale = [3.0, 1.0, 3.0]\n";
    let mut s = Scene::parse(text, &common::root().join("scenes/t.toml")).unwrap();
    s.render.wireframe = wireframe;
    common::render(&s, Output::Srgb8).image
}

#[test]
fn wireframe_shows_where_the_near_plane_cuts_the_triangles() {
    let filled = cut_floor(false);
    let wire = cut_floor(true);
    let lit = |img: &image::RgbaImage| img.pixels().filter(|p| p[0] > 128).count();
    // Filled, the floor covers rows 57 (its far edge, y / -z = -0.125) to
    // 75 (the near plane): nearer than that it is clipped away. As lines,
    // far less.
    wire.save(common::out_dir().join("wireframe-near-plane.png"))
        .unwrap();
    assert!(lit(&filled) > 1500, "{}", lit(&filled));
    for x in [10, 50, 90] {
        assert!(
            filled.get_pixel(x, 66)[0] > 128 && filled.get_pixel(x, 85)[0] < 128,
            "column {x}"
        );
    }
    assert!(
        lit(&wire) < lit(&filled) / 4,
        "{} vs {}",
        lit(&wire),
        lit(&filled)
    );
    // The plane's diagonal runs from its far corner towards the camera and
    // stops where the clipper cut it: at the near plane's row, 75 (y_ndc =
    // -0.5); below it nothing is left, as in the filled image.
    let rows_lit =
        |a: u32, b: u32| (a..=b).any(|y| (0..101).any(|x| wire.get_pixel(x, y)[0] > 128));
    assert!(rows_lit(72, 75), "the diagonal reaches the near plane");
    assert!(!rows_lit(77, 100), "nothing nearer than the near plane");
    assert!(!(77..=100).any(|y| (0..101).any(|x| filled.get_pixel(x, y)[0] > 128)));
}
