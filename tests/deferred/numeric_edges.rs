//! Numerical edges where the paths must agree: a point light lying on the
//! surface it lights, with Kc = 0 (its attenuation 1 / (Kl d + Kq d^2) is
//! singular there). src/lighting/attenuation.rs's minimum distance makes
//! the light a small sphere; every path must then give the forward image.

use crate::common;
use crate::{DEFERRED_BOUND, with_path};
use gloss::renderer::Output;
use gloss::scene::{RenderPath, Scene};
use std::path::Path;

/// A plane seen in perspective (the deferred paths rebuild its points from
/// a 24-bit depth, slightly off the plane), a point light at `at`.
fn light_on_plane(at: [f32; 3], attenuation: [f32; 3]) -> Scene {
    let text = format!(
        r#"
name = "light-on-surface"
[camera]
eye = [0.0, 4.0, 6.0]
target = [0.0, 0.0, 0.0]
fov_y = 45.0
near = 0.1
far = 50.0
[render]
size = [160, 120]
ambient = [0.05, 0.05, 0.05]
cutoff = 1e-4
[[lights]]
type = "point"
position = {at:?}
color = [1.0, 0.9, 0.8]
intensity = 1.5
attenuation = {attenuation:?}
[materials.floor]
diffuse = [0.7, 0.5, 0.3]
specular = [0.5, 0.5, 0.5]
shininess = 24.0
[[objects]]
name = "floor"
mesh = "plane"
material = "floor"
scale = [10.0, 1.0, 10.0]
"#
    );
    Scene::parse(&text, Path::new("light-on-surface.toml")).unwrap()
}

#[test]
fn a_light_on_the_surface_with_kc_0_agrees_on_every_path() {
    for (at, k) in [
        ([0.3, 0.0, 0.2], [0.0, 0.09, 0.032]),
        ([0.3, 0.0, 0.2], [0.0, 0.0, 1.0]),
        ([0.3, 0.0, 0.2], [0.0, 1.0, 0.0]),
        // Just above and just below the surface.
        ([0.3, 1e-4, 0.2], [0.0, 0.09, 0.032]),
        ([0.3, -1e-4, 0.2], [0.0, 0.09, 0.032]),
    ] {
        let scene = light_on_plane(at, k);
        let fwd = common::render(&with_path(&scene, RenderPath::Forward), Output::Srgb8);
        // The sphere lights the plane around it (a point on the plane
        // would not: N.L = 0), far above the ambient's 53.
        let brightest = (fwd.image.pixels()).map(|p| p[0]).max().unwrap();
        assert!(brightest > 200, "light at {at:?}: brightest {brightest}");
        for &path in RenderPath::ALL {
            if path == RenderPath::Forward {
                continue;
            }
            let got = common::render(&with_path(&scene, path), Output::Srgb8);
            let m = common::assert_close(
                &format!("light-on-surface-{path}"),
                &got.image,
                &fwd.image,
                &DEFERRED_BOUND,
            );
            eprintln!("light at {at:?}, attenuation {k:?}: {path} vs forward: {m}");
        }
    }
}
