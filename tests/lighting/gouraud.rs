//! Gouraud shading (notes 01 §8.2: "lighting calculated per vertex ...
//! colours interpolated across the triangle") against its CPU reference: the
//! Phong formula (notes 01 §8.3) evaluated at each vertex of the plane, then
//! interpolated barycentrically at the world point under each pixel. A
//! world-space barycentric is the perspective-correct interpolation the
//! rasteriser does (notes 01 §4.2), so the camera here looks at the plane at
//! a slant. The light sits low near one corner: lit per pixel, the plane
//! shows a bright spot that the four corners' light cannot make, so the
//! reference for Gouraud and the one for Phong differ visibly, and so do
//! the perspective-correct and the affine interpolations.

use crate::common;
use glam::{Vec3, Vec4};
use gloss::frame::lights::model_radius;
use gloss::lighting::phong_light_with;
use gloss::renderer::Output;
use gloss::scene::meshes::mesh_data;
use gloss::scene::{Falloff, Scene, Shading};
use std::path::Path;

fn slanted_plane(shading: Shading) -> Scene {
    let text = r#"
[camera]
eye = [0.0, 3.0, 9.0]
target = [0.0, 0.0, 0.0]
fov_y = 50.0
near = 0.5
far = 50.0

[render]
size = [160, 120]
ambient = [0.05, 0.05, 0.05]

[[lights]]
type = "point"
position = [3.5, 0.8, 3.0]
color = [1.0, 0.9, 0.8]
intensity = 2.0
attenuation = [1.0, 0.09, 0.032]

[materials.floor]
diffuse = [0.7, 0.5, 0.3]
specular = [0.5, 0.5, 0.5]
shininess = 24.0

[[objects]]
name = "floor"
mesh = "plane"
material = "floor"
scale = [5.0, 1.0, 5.0]
"#;
    let mut s = Scene::parse(text, Path::new("gouraud.toml")).unwrap();
    s.render.shading = shading;
    s
}

/// The lit colour (linear) at world point `p` with normal +y, as the
/// shaders compute it: kd (ambient + diffuse light) + ks specular light.
fn lit(s: &Scene, p: Vec3) -> Vec3 {
    let m = &s.materials[s.objects[0].material];
    let v = (s.camera.eye - p).normalize();
    let mut c = s.render.ambient * m.diffuse;
    for l in &s.lights {
        let radius = match s.render.falloff {
            Falloff::Notes => None,
            f => model_radius(l, s.render.cutoff, f).map(|r| (f, r)),
        };
        let (d, sp) = phong_light_with(l, p, Vec3::Y, v, m.shininess, radius);
        c += m.diffuse * d + m.specular * sp;
    }
    c
}

/// Per pixel (x, y from the bottom) well inside one triangle: the Gouraud
/// reference (perspective-correct), the same with affine (screen-space)
/// weights, and Phong's per-pixel colour.
struct Reference {
    x: u32,
    y: u32,
    gouraud: Vec3,
    affine: Vec3,
    phong: Vec3,
}

fn references(s: &Scene) -> Vec<Reference> {
    let (w, h) = (s.render.size.0 as f32, s.render.size.1 as f32);
    let vp = s.camera.projection(w / h) * s.camera.view();
    let inverse = vp.inverse();
    let model = s.objects[0].model;
    let mesh = mesh_data(&s.objects[0].mesh).unwrap();
    let corners: Vec<Vec3> = (mesh.vertices.iter())
        .map(|v| model.transform_point3(Vec3::from(v.position)))
        .collect();
    let colours: Vec<Vec3> = corners.iter().map(|&p| lit(s, p)).collect();
    let screen = |p: Vec3| {
        let c = vp * p.extend(1.0);
        glam::Vec2::new((c.x / c.w + 1.0) * 0.5 * w, (c.y / c.w + 1.0) * 0.5 * h)
    };
    // The world point on y = 0 under window position (x, y).
    let hit = |x: f32, y: f32| -> Option<Vec3> {
        let at = |z: f32| {
            let q = inverse * Vec4::new(2.0 * x / w - 1.0, 2.0 * y / h - 1.0, z, 1.0);
            q.truncate() / q.w
        };
        let (a, b) = (at(-1.0), at(1.0));
        let d = b - a;
        (d.y < 0.0).then(|| a - d * (a.y / d.y))
    };
    // Barycentric weights of q in triangle (a, b, c) in the xz plane (world)
    // or in the screen plane.
    let weights = |q: glam::Vec2, a: glam::Vec2, b: glam::Vec2, c: glam::Vec2| {
        let area = (b - a).perp_dot(c - a);
        let wa = (b - q).perp_dot(c - q) / area;
        let wb = (c - q).perp_dot(a - q) / area;
        Vec3::new(wa, wb, 1.0 - wa - wb)
    };
    let xz = |p: Vec3| glam::Vec2::new(p.x, p.z);
    let triangle_of = |p: Vec3| {
        (mesh.indices.chunks(3)).find_map(|t| {
            let [a, b, c] = [0, 1, 2].map(|k| corners[t[k] as usize]);
            let l = weights(xz(p), xz(a), xz(b), xz(c));
            (l.min_element() > 0.0).then_some((t, l))
        })
    };
    let mut out = Vec::new();
    for y in 0..h as u32 {
        for x in 0..w as u32 {
            let (cx, cy) = (x as f32 + 0.5, y as f32 + 0.5);
            let Some(p) = hit(cx, cy) else { continue };
            let Some((t, l)) = triangle_of(p) else {
                continue;
            };
            // Interior: the pixels two away on every side are in the same triangle.
            let inside = [(-2.0, 0.0), (2.0, 0.0), (0.0, -2.0), (0.0, 2.0)]
                .iter()
                .all(|(dx, dy)| {
                    hit(cx + dx, cy + dy)
                        .and_then(&triangle_of)
                        .is_some_and(|(u, _)| u == t)
                });
            if !inside {
                continue;
            }
            let [a, b, c] = [0, 1, 2].map(|k| t[k] as usize);
            let mix = |l: Vec3| colours[a] * l.x + colours[b] * l.y + colours[c] * l.z;
            let ls = weights(
                glam::Vec2::new(cx, cy),
                screen(corners[a]),
                screen(corners[b]),
                screen(corners[c]),
            );
            out.push(Reference {
                x,
                y,
                gouraud: mix(l),
                affine: mix(ls),
                phong: lit(s, p),
            });
        }
    }
    out
}

/// The largest difference (linear, any channel) between the image and
/// `want` over the reference pixels, and how many pixels differ by more
/// than `tol`.
fn against(
    r: &common::Rendered,
    refs: &[Reference],
    want: impl Fn(&Reference) -> Vec3,
    tol: f32,
) -> (f32, usize) {
    let (mut worst, mut over) = (0.0f32, 0);
    for p in refs {
        let i = ((p.y * r.width + p.x) * 4) as usize;
        let got = Vec3::new(r.linear[i], r.linear[i + 1], r.linear[i + 2]);
        let d = (got - want(p)).abs().max_element();
        worst = worst.max(d);
        over += usize::from(d > tol);
    }
    (worst, over)
}

const TOL: f32 = 2e-3;

#[test]
fn gouraud_is_the_vertex_light_interpolated_perspective_correct() {
    let s = slanted_plane(Shading::Gouraud);
    let refs = references(&s);
    assert!(refs.len() > 5000, "only {} interior pixels", refs.len());
    // The scene tells the three apart: per-pixel light, and affine
    // weights, are far from the reference somewhere.
    let apart = |f: &dyn Fn(&Reference) -> Vec3| {
        (refs.iter())
            .map(|p| (f(p) - p.gouraud).abs().max_element())
            .fold(0.0, f32::max)
    };
    let (phong_gap, affine_gap) = (apart(&|p| p.phong), apart(&|p| p.affine));
    assert!(
        phong_gap > 0.1,
        "per-pixel and per-vertex light differ by only {phong_gap}"
    );
    assert!(
        affine_gap > 0.02,
        "affine and perspective-correct weights differ by only {affine_gap}"
    );

    let r = common::render(&s, Output::Linear32F);
    let (worst, over) = against(&r, &refs, |p| p.gouraud, TOL);
    eprintln!(
        "Gouraud: {} pixels, worst {worst:.2e} (Phong is {phong_gap:.3} away, affine {affine_gap:.3})",
        refs.len()
    );
    assert_eq!(
        over,
        0,
        "{over} of {} pixels differ from the per-vertex reference by more than {TOL} (worst {worst})",
        refs.len()
    );
}

#[test]
fn phong_shading_fails_the_gouraud_reference() {
    // The deliberately wrong variant: lighting per pixel. The check above
    // must reject its image, and Phong's own reference must accept it.
    let s = slanted_plane(Shading::Phong);
    let refs = references(&s);
    let r = common::render(&s, Output::Linear32F);
    let (_, over) = against(&r, &refs, |p| p.gouraud, TOL);
    assert!(
        over * 10 > refs.len(),
        "only {over} of {} Phong pixels fail the Gouraud reference",
        refs.len()
    );
    let (worst, over) = against(&r, &refs, |p| p.phong, TOL);
    assert_eq!(over, 0, "Phong against its own reference: worst {worst}");
}
