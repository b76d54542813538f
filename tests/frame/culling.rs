//! Notes 01 §6.3 frustum culling, walked through the scene graph (§6.4;
//! src/frame/culling.rs): it changes no pixel, on any kind of view
//! (reflections, split views, a curved mirror); it culls what the camera
//! cannot see in the 10,000-object city; a child inside the frustum is drawn
//! though its parent is outside; a subtree wholly outside costs one test.

use crate::common;
use gloss::frame::culling::scene_stats;
use gloss::renderer::{Output, render_scene};
use gloss::scene::Scene;

#[test]
fn culling_changes_no_pixel_on_any_kind_of_view() {
    for name in [
        "default.toml",
        "mirrors-several.toml",
        "mirror-curved.toml",
        "viewports.toml",
        "transparency.toml",
        "skinned-arm.toml",
        "frustum-culling.toml",
    ] {
        let mut s = common::scene(name);
        s.render.size = (160, 90);
        let culled = common::render(&s, Output::Srgb8).image;
        s.render.frustum_culling = false;
        let all = common::render(&s, Output::Srgb8).image;
        assert!(culled == all, "{name}: culling changed the image");
    }
}

#[test]
fn the_city_draws_what_the_camera_sees_and_counts_it() {
    let ctx = common::context(common::backend());
    let mut s = common::scene("frustum-culling.toml");
    s.render.size = (160, 90);
    assert_eq!(s.objects.len(), 10_001);
    let r = render_scene(&ctx, &s, Output::Srgb8).unwrap();
    let shown = r.last_times.culling.expect("culling is on");
    // The renderer's walk is the one `gloss plan` prints.
    assert_eq!(shown, scene_stats(&s).unwrap());
    assert_eq!(shown.objects, 10_001);
    assert!(shown.drawn < 2_500 && shown.drawn > 100, "{shown:?}");
    // The tree saves tests: far fewer than one per object.
    assert!(shown.tests < 4_000, "{shown:?}");
    s.render.frustum_culling = false;
    let off = render_scene(&ctx, &s, Output::Srgb8).unwrap();
    assert_eq!(off.last_times.culling, None);
}

fn scene(objects: &str) -> Scene {
    let text = format!(
        "name = \"t\"\n[camera]\neye = [0.0, 0.0, 10.0]\ntarget = [0.0, 0.0, 0.0]\nfar = 50.0\n{objects}"
    );
    Scene::parse(&text, &common::root().join("scenes/t.toml")).unwrap()
}

#[test]
fn a_child_inside_is_drawn_though_its_parent_is_outside() {
    // The parent stands 1000 to the right, its child 1000 back to the left.
    let s = scene(
        "[[objects]]\nname = \"far\"\nmesh = \"cube\"\nposition = [1000.0, 0.0, 0.0]\n\
         [[objects]]\nname = \"near\"\nmesh = \"cube\"\nparent = \"far\"\nposition = [-1000.0, 0.0, 0.0]\n",
    );
    let c = scene_stats(&s).unwrap();
    assert_eq!((c.drawn, c.culled), (1, 1), "{c:?}");
}

#[test]
fn a_subtree_wholly_outside_costs_one_test() {
    let mut objects = String::from(
        "[[objects]]\nname = \"root\"\nmesh = \"cube\"\nposition = [0.0, 0.0, 100.0]\n",
    );
    for i in 0..50 {
        objects.push_str(&format!(
            "[[objects]]\nname = \"c{i}\"\nmesh = \"sphere\"\nparent = \"root\"\nposition = [{}.0, 0.0, 0.0]\n",
            i % 5
        ));
    }
    // Behind the camera: one box test for all 51.
    let c = scene_stats(&scene(&objects)).unwrap();
    assert_eq!((c.drawn, c.culled, c.tests), (0, 51, 1), "{c:?}");
    // In front, wholly inside: one test, and all drawn.
    let c = scene_stats(&scene(&objects.replacen("100.0", "-10.0", 1))).unwrap();
    assert_eq!((c.drawn, c.culled, c.tests), (51, 0, 1), "{c:?}");
}

#[test]
fn object_fields_that_cannot_be_made_are_refused() {
    let field = |body: &str| {
        let text = format!(
            "name = \"t\"\n[camera]\neye = [0.0, 0.0, 10.0]\ntarget = [0.0, 0.0, 0.0]\n[[object_fields]]\n{body}\n"
        );
        match Scene::parse(&text, &common::root().join("scenes/t.toml")) {
            Ok(_) => panic!("accepted: {body}"),
            Err(e) => format!("{e:#}"),
        }
    };
    let e = field("count = 2\narea = [5.0, -5.0, 0.0, 1.0]");
    assert!(
        e.contains("object_fields[0].area") && e.contains("increasing"),
        "{e}"
    );
    let e = field("count = 20000\nchildren = 9\narea = [0.0, 1.0, 0.0, 1.0]");
    assert!(
        e.contains("200000 objects in all, the limit is 100000"),
        "{e}"
    );
    let e = field("count = 1\narea = [0.0, 1.0, 0.0, 1.0]\nchild_size = [0.0, 1.0]");
    assert!(e.contains("object_fields[0].child_size"), "{e}");
    let e = field("count = 1\narea = [0.0, 1.0, 0.0, 1.0]\nmaterial = \"gold\"");
    assert!(e.contains("no material named \"gold\""), "{e}");
    let e = field("count = 1\narea = [0.0, 1.0, 0.0, 1.0]\nheight = 3.0");
    assert!(e.contains("unknown field `height`"), "{e}");
}

#[test]
fn the_transparency_pass_draws_only_what_is_in_view() {
    // A pane behind the camera and one in front: culled or not, the image
    // is the same, and the walk marks only the one in front.
    let s = scene(
        "[materials.glass]\nopacity = 0.5\n\
         [[objects]]\nname = \"behind\"\nmesh = \"cube\"\nmaterial = \"glass\"\nposition = [0.0, 0.0, 20.0]\n\
         [[objects]]\nname = \"front\"\nmesh = \"cube\"\nmaterial = \"glass\"\n",
    );
    let ctx = common::context(common::backend());
    let r = render_scene(&ctx, &s, Output::Srgb8).unwrap();
    let vp = s.camera.projection(s.aspect()) * s.camera.view();
    assert_eq!(r.draws().in_view(&vp).0, [false, true]);
    let mut off = s.clone();
    off.render.frustum_culling = false;
    assert!(r.read_image() == common::render_with(&ctx, &off, Output::Srgb8).image);
}
