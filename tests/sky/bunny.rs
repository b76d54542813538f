//! The Stanford bunny asset (scenes/assets/bunny.obj, made by
//! scenes/assets/bunny.rs from the vendored npm package `bunny`): all of it
//! is there, it stands on y = 0 one unit tall, and its triangles wind
//! counter-clockwise seen from outside (a positive enclosed volume).

use crate::common;
use glam::Vec3;

#[test]
fn the_bunny_is_whole_upright_and_wound_outwards() {
    let m = gloss::geometry::load_obj(&common::root().join("scenes/assets/bunny.obj"))
        .expect("the bunny loads");
    assert_eq!(m.triangle_count(), 3674);
    let (mut lo, mut hi) = (Vec3::MAX, Vec3::MIN);
    for v in &m.vertices {
        lo = lo.min(Vec3::from(v.position));
        hi = hi.max(Vec3::from(v.position));
    }
    assert!(lo.y.abs() < 1e-4 && (hi.y - 1.0).abs() < 1e-4, "{lo} {hi}");
    assert!(
        (lo.x + hi.x).abs() < 1e-4 && (lo.z + hi.z).abs() < 1e-4,
        "{lo} {hi}"
    );
    let p = |i: u32| Vec3::from(m.vertices[i as usize].position);
    let volume: f32 = (m.indices.chunks(3))
        .map(|t| p(t[0]).dot(p(t[1]).cross(p(t[2]))) / 6.0)
        .sum();
    assert!(
        volume > 0.05,
        "enclosed volume {volume}: the triangles wind inwards"
    );
    // The licence travels with it.
    let licence = std::fs::read_to_string(common::root().join("scenes/assets/bunny/LICENSE.md"))
        .expect("the bunny's licence");
    assert!(licence.contains("Public Domain") && licence.contains("Stanford"));
}
