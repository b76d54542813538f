//! The shadow reference against hand-made cases and the analytic conic.

use super::*;
use crate::geometry;
use std::path::Path;

/// A square of side 2 s in the plane y = h, as two triangles.
fn square(s: f32, h: f32) -> Vec<Triangle> {
    let p = |x: f32, z: f32| Vec3::new(x * s, h, z * s);
    vec![
        Triangle {
            a: p(-1.0, -1.0),
            b: p(1.0, -1.0),
            c: p(1.0, 1.0),
        },
        Triangle {
            a: p(-1.0, -1.0),
            b: p(1.0, 1.0),
            c: p(-1.0, 1.0),
        },
    ]
}

#[test]
fn occluded_by_what_lies_between_and_never_by_its_own_surface() {
    // A floor of side 20 at y = 0 and a blocker of side 2 at y = 1.
    let mut t = square(10.0, 0.0);
    t.extend(square(1.0, 1.0));
    let s = SceneTriangles::from_triangles(t);
    // The size is the diagonal of the box around them: sqrt(20² + 1² + 20²).
    assert!((s.epsilon - 1e-4 * 801f32.sqrt()).abs() < 1e-7);
    let under = Vec3::new(0.3, 0.0, -0.2);
    assert!(s.occluded(under, LightRay::Position(Vec3::new(0.0, 3.0, 0.0))));
    assert!(s.occluded(under, LightRay::Direction(Vec3::new(0.1, -1.0, 0.0))));
    // The segment stops at the light: a light under the blocker.
    assert!(!s.occluded(under, LightRay::Position(Vec3::new(0.0, 0.5, 0.0))));
    // Beside the blocker, lit; the same point a depth-quantum under the
    // floor, with the light grazing the floor (the ray meets the floor
    // 1e-5 / 0.01 = 1e-3 along), is lit too: the floor is its own surface.
    let beside = Vec3::new(5.0, 0.0, 5.0);
    let grazing = LightRay::Direction(Vec3::new(-1.0, -0.01, 0.0).normalize());
    assert!(!s.occluded(beside, grazing));
    assert!(!s.occluded(beside - Vec3::new(0.0, 1e-5, 0.0), grazing));
    assert!(!s.occluded(beside, LightRay::Position(Vec3::new(5.0, 2.0, 5.0))));
    // On the blocker's top, facing the light: lit; on its underside, the
    // point light above: the blocker itself is within epsilon, so lit; the
    // floor is behind the point (t < 0), so it does not count either.
    assert!(!s.occluded(
        Vec3::new(0.0, 1.0, 0.0),
        LightRay::Position(Vec3::new(0.0, 3.0, 0.0))
    ));
    // A zero direction or a light on the point: nothing to shadow.
    assert!(!s.occluded(under, LightRay::Direction(Vec3::ZERO)));
    assert!(!s.occluded(under, LightRay::Position(under)));
}

const SPHERE_SCENE: &str = r#"
[camera]
eye = [0.0, 9.0, 7.0]
target = [0.5, 0.0, 0.5]
fov_y = 45.0
near = 0.1
far = 60.0

[render]
size = [320, 180]

[[lights]]
type = "point"
position = [1.0, 5.0, 0.8]

[materials.grey]
diffuse = [0.8, 0.8, 0.8]

[materials.glass]
diffuse = [0.8, 0.8, 0.8]
opacity = 0.5

[[objects]]
name = "floor"
mesh = "plane"
material = "grey"
scale = [8.0, 1.0, 8.0]

[[objects]]
name = "ball"
mesh = "sphere"
material = "grey"
position = [0.0, 1.5, 0.0]
scale = [0.75, 0.75, 0.75]

[[objects]]
name = "pane"
mesh = "cube"
material = "glass"
position = [3.0, 1.0, 3.0]
"#;

const CENTRE: Vec3 = Vec3::new(0.0, 1.5, 0.0);
const RADIUS: f32 = 0.75;

fn sphere_scene() -> (Scene, SceneTriangles) {
    let scene = Scene::parse(SPHERE_SCENE, Path::new("t.toml")).unwrap();
    let tris = SceneTriangles::new(&scene).unwrap();
    (scene, tris)
}

/// How far inside the true sphere the tessellated one reaches: the least
/// distance from the centre to a triangle of the unit uv sphere (its
/// vertices lie on the sphere, its flat faces cut inside by the chord error).
fn inner_radius() -> f32 {
    let m = geometry::uv_sphere(32, 64);
    let p = |i: u32| Vec3::from(m.vertices[i as usize].position);
    m.indices
        .chunks_exact(3)
        .map(|t| {
            Triangle {
                a: p(t[0]),
                b: p(t[1]),
                c: p(t[2]),
            }
            .distance(Vec3::ZERO)
        })
        .fold(f32::INFINITY, f32::min)
}

#[test]
fn casters_leave_out_transparent_objects() {
    let (_, tris) = sphere_scene();
    let plane = geometry::plane(2.0, 2.0, 1).triangle_count();
    let sphere = geometry::uv_sphere(32, 64).triangle_count();
    assert_eq!(tris.triangle_count(), plane + sphere);
}

/// The scene's window depth, ray-traced through each pixel centre and
/// rounded as a 24-bit depth buffer, and its inverse view-projection.
fn depth_buffer(scene: &Scene, tris: &SceneTriangles) -> (Vec<f32>, Mat4) {
    let (w, h) = (scene.render.size.0 as usize, scene.render.size.1 as usize);
    let vp = scene.camera.projection(scene.aspect()) * scene.camera.view();
    let inv = vp.inverse();
    let depth = (0..w * h)
        .map(|i| {
            let near = pixel_world_point(i % w, i / w, 0.0, inv, w, h);
            let far = pixel_world_point(i % w, i / w, 1.0, inv, w, h);
            match tris.bvh().closest_hit(near, far - near, 1.0) {
                Some(t) => {
                    // Rounded to 24 bits, as a GL depth buffer stores it.
                    let d = vp.project_point3(near + (far - near) * t).z * 0.5 + 0.5;
                    let steps = ((1u32 << 24) - 1) as f32;
                    ((d as f64 * steps as f64).round() / steps as f64) as f32
                }
                None => 1.0,
            }
        })
        .collect();
    (depth, inv)
}

#[test]
fn the_mask_of_a_sphere_over_a_plane_is_the_analytic_conic() {
    let (scene, tris) = sphere_scene();
    let (w, h) = (320, 180);
    let (depth, inv) = depth_buffer(&scene, &tris);
    let mask = tris.reference_mask(&scene, 0, &depth, inv, w, h);
    let light = scene.lights[0].position;
    // The mesh lies between the spheres of radius r_in and RADIUS: a floor
    // point whose segment to the light passes within r_in of the centre is
    // surely shadowed, one that passes farther than RADIUS surely lit.
    let r_in = RADIUS * inner_radius();
    assert!(r_in > 0.99 * RADIUS && r_in < RADIUS, "{r_in}");
    let (mut floor, mut shadowed, mut unsure) = (0, 0, 0);
    for (i, v) in mask.iter().enumerate() {
        let p = pixel_world_point(i % w, i / w, depth[i], inv, w, h);
        if *v == Visibility::Background || p.y.abs() > 1e-3 {
            continue; // the sky or the ball
        }
        floor += 1;
        let surely = sphere_shadow_on_plane(light, CENTRE, r_in, p);
        let maybe = sphere_shadow_on_plane(light, CENTRE, RADIUS, p);
        if surely != maybe {
            unsure += 1;
            continue;
        }
        assert_eq!(*v == Visibility::Shadowed, surely, "pixel {i} at {p}");
        shadowed += usize::from(surely);
    }
    // The floor fills most of the picture, the shadow a good part of it and
    // the polygon's uncertain rim few pixels.
    assert!(floor > w * h / 2, "{floor} floor pixels");
    assert!(shadowed > 600, "{shadowed} shadowed");
    eprintln!("{floor} floor pixels, {shadowed} shadowed, {unsure} unsure");
    assert!(unsure < shadowed / 20, "{unsure} unsure of {shadowed}");
}

#[test]
fn a_directional_light_is_a_point_light_far_away() {
    let (_, tris) = sphere_scene();
    let direction = Vec3::new(-0.3, -1.0, -0.2).normalize();
    let far = CENTRE - direction * 1e4;
    let (mut agree, mut shadowed) = (0, 0);
    for i in 0..40 {
        for j in 0..40 {
            let p = Vec3::new(-2.0 + 0.1 * i as f32, 0.0, -2.0 + 0.1 * j as f32);
            let d = tris.occluded(p, LightRay::Direction(direction));
            // The analytic conic, the light 1e4 away: rays parallel to a
            // few 1e-4 of the sphere's size. Away from its rim, all agree.
            let exact = segment_distance(CENTRE, p, p - direction * 1e4);
            if (exact - RADIUS).abs() < 0.01 {
                continue;
            }
            assert_eq!(d, tris.occluded(p, LightRay::Position(far)), "{p}");
            assert_eq!(d, sphere_shadow_on_plane(far, CENTRE, RADIUS, p), "{p}");
            agree += 1;
            shadowed += usize::from(d);
        }
    }
    assert!(
        agree > 1500 && shadowed > 100,
        "{agree} points, {shadowed} shadowed"
    );
}

#[test]
fn a_segment_passing_near_a_point() {
    let (a, b) = (Vec3::ZERO, Vec3::new(2.0, 0.0, 0.0));
    assert_eq!(segment_distance(Vec3::new(1.0, 3.0, 0.0), a, b), 3.0);
    assert_eq!(segment_distance(Vec3::new(-3.0, 4.0, 0.0), a, b), 5.0);
    assert_eq!(segment_distance(Vec3::new(5.0, 0.0, 4.0), a, b), 5.0);
    assert_eq!(segment_distance(Vec3::ONE, a, a), 3f32.sqrt());
    // A sphere of radius 1 at height 2 under a light at height 4: the floor
    // point under it is shadowed, one 3 away is not (the segment passes
    // 3 * 2 / 5 = 1.2 from the centre), one 2 away is (0.89).
    let (light, centre) = (Vec3::new(0.0, 4.0, 0.0), Vec3::new(0.0, 2.0, 0.0));
    assert!(sphere_shadow_on_plane(light, centre, 1.0, Vec3::ZERO));
    assert!(!sphere_shadow_on_plane(
        light,
        centre,
        1.0,
        Vec3::new(3.0, 0.0, 0.0)
    ));
    assert!(sphere_shadow_on_plane(
        light,
        centre,
        1.0,
        Vec3::new(2.0, 0.0, 0.0)
    ));
}
