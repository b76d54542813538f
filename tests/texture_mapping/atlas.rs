//! Notes 01 §5, a texture atlas (scenes/texture-atlas.toml,
//! scenes/assets/atlas.rs): each face of a cube reads one tile of a shared
//! texture, and each tile has colour in some channels only (red, green,
//! blue, magenta: the others 0). Drawn with an ambient of 1 and no lights,
//! a pixel of a face that reads only its own tile has 0 in its tile's
//! empty channels; a pixel that shows another tile's colour has bled. The
//! CPU finds each pixel's face by casting its ray at the cube. The atlas
//! whose tiles meet edge to edge bleeds at its faces' edges under
//! mip-mapped filtering; the padded atlas (8-texel gutters, max_lod 3)
//! bleeds at no pixel.

use crate::common;
use glam::{Vec3, Vec4};
use gloss::renderer::Output;
use gloss::scene::Scene;

/// The channels tile k leaves empty (red, green, blue, magenta).
fn empty_channels(k: usize) -> &'static [usize] {
    match k {
        0 => &[1, 2],
        1 => &[0, 2],
        2 => &[0, 1],
        _ => &[1],
    }
}

/// The face of the cube (local [-1, 1]^3; faces +x, -x, +y, -y, +z, -z as
/// `geometry::cube` orders them) the ray from `origin` along `dir` enters,
/// in local coordinates; None if it misses or enters within `margin` of an
/// edge between faces.
fn entry_face(origin: Vec3, dir: Vec3, margin: f32) -> Option<usize> {
    let (mut t_in, mut axis) = (f32::MIN, 0);
    let mut t_out = f32::MAX;
    for a in 0..3 {
        let (t0, t1) = ((-1.0 - origin[a]) / dir[a], (1.0 - origin[a]) / dir[a]);
        let (near, far) = (t0.min(t1), t0.max(t1));
        if near > t_in {
            t_in = near;
            axis = a;
        }
        t_out = t_out.min(far);
    }
    if t_in > t_out || t_in < 0.0 {
        return None;
    }
    let p = origin + dir * t_in;
    let others = (0..3).filter(|&a| a != axis);
    if others.into_iter().any(|a| p[a].abs() > 1.0 - margin) {
        return None;
    }
    Some(2 * axis + usize::from(p[axis] < 0.0))
}

/// Pixels of object `object` that show another tile's colour, and pixels seen.
fn bleeding(s: &Scene, r: &common::Rendered, object: usize) -> (usize, usize) {
    let (w, h) = (r.width as usize, r.height as usize);
    let inverse = (s.camera.projection(w as f32 / h as f32) * s.camera.view()).inverse();
    let to_local = s.objects[object].model.inverse();
    let (mut bled, mut seen) = (0, 0);
    for y in 0..h {
        for x in 0..w {
            let ndc = |a: usize, n: usize| 2.0 * (a as f32 + 0.5) / n as f32 - 1.0;
            let at = |z: f32| {
                let q = inverse * Vec4::new(ndc(x, w), ndc(y, h), z, 1.0);
                to_local.transform_point3(q.truncate() / q.w)
            };
            let (a, b) = (at(-1.0), at(1.0));
            let Some(face) = entry_face(a, b - a, 0.02) else {
                continue;
            };
            seen += 1;
            let i = (y * w + x) * 4;
            if empty_channels(face % 4)
                .iter()
                .any(|&c| r.linear[i + c] > 0.01)
            {
                bled += 1;
            }
        }
    }
    (bled, seen)
}

#[test]
fn the_edge_to_edge_atlas_bleeds_and_the_padded_one_does_not() {
    let mut s = common::scene("texture-atlas.toml");
    s.lights.clear();
    s.render.ambient = Vec3::ONE;
    let r = common::render(&s, Output::Linear32F);
    let (bled, seen) = bleeding(&s, &r, 0);
    let (padded_bled, padded_seen) = bleeding(&s, &r, 1);
    println!("edge to edge: {bled} of {seen} pixels bled; padded: {padded_bled} of {padded_seen}");
    assert!(seen > 2000 && padded_seen > 2000, "{seen} {padded_seen}");
    assert!(
        bled > 50,
        "the edge-to-edge atlas bled at only {bled} of {seen} pixels"
    );
    assert_eq!(
        padded_bled, 0,
        "the padded atlas bled at {padded_bled} of {padded_seen} pixels"
    );
    // Point sampling level 0 reads one texel inside the tile: no bleeding,
    // even edge to edge.
    s.render.texture_filter = gloss::scene::texturing::FilterOverride::Nearest;
    let r = common::render(&s, Output::Linear32F);
    assert_eq!(bleeding(&s, &r, 0).0, 0);
}

#[test]
fn max_lod_is_checked() {
    let text = "name = \"t\"\n[camera]\neye = [0.0, 0.0, 5.0]\ntarget = [0.0, 0.0, 0.0]\n\
                [materials.m]\nmax_lod = -1.0\n[[objects]]\nmesh = \"cube\"\nmaterial = \"m\"\n";
    let e = Scene::parse(text, &common::root().join("scenes/t.toml"))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("materials.m.max_lod") && e.contains("0..=1000"),
        "{e}"
    );
}
