//! Frustum culling (notes 01 §6.3) in the shadow pass (notes 01 §8.5): a
//! spot light's shadow map draws only the casters inside the light's
//! frustum, its near plane dropped (the pass clamps depth, so a caster
//! between the light and the near plane still casts:
//! `a_caster_nearer_the_light_than_the_near_plane_still_casts` in
//! hard_cases.rs runs with culling on). Culled or not, the image is the
//! same, and the casters far outside the cone are not drawn.

use crate::common;
use gloss::renderer::{Output, render_scene};
use gloss::scene::Scene;

/// A floor, a box under a narrow spot light, and a row of boxes well
/// outside its cone.
fn scene() -> Scene {
    let mut text = String::from(
        "name = \"t\"\n[camera]\neye = [0.0, 8.0, 12.0]\ntarget = [0.0, 0.0, 0.0]\n\
         [render]\nsize = [240, 160]\nambient = [0.05, 0.05, 0.05]\n\
         [[lights]]\ntype = \"spot\"\nposition = [0.0, 5.0, 0.0]\ndirection = [0.0, -1.0, 0.0]\n\
         intensity = 3.0\ninner_angle = 12.0\nouter_angle = 18.0\nshadow = true\n\
         [[objects]]\nname = \"floor\"\nmesh = \"plane\"\nscale = [10.0, 1.0, 10.0]\n\
         [[objects]]\nname = \"lit\"\nmesh = \"cube\"\nposition = [0.3, 1.0, 0.0]\nscale = [0.4, 0.4, 0.4]\n",
    );
    for i in 0..8 {
        text += &format!(
            "[[objects]]\nmesh = \"cube\"\nposition = [{}.0, 0.5, -6.0]\nscale = [0.4, 0.4, 0.4]\n",
            i - 4
        );
    }
    Scene::parse(&text, &common::root().join("scenes/t.toml")).unwrap()
}

#[test]
fn the_shadow_pass_culls_casters_outside_the_lights_frustum() {
    let s = scene();
    let ctx = common::context(common::backend());
    let r = render_scene(&ctx, &s, Output::Srgb8).unwrap();
    let stats = r.last_times.shadow_culling.expect("a shadow map was drawn");
    // The floor and the box under the light are drawn; the row is not.
    assert_eq!(
        (stats.objects, stats.drawn, stats.culled),
        (10, 2, 8),
        "{stats:?}"
    );
    let mut off = s.clone();
    off.render.frustum_culling = false;
    let unculled = render_scene(&ctx, &off, Output::Srgb8).unwrap();
    assert!(unculled.last_times.shadow_culling.is_none());
    assert!(
        r.read_image() == unculled.read_image(),
        "culling changed the image"
    );
}
