//! Tests of the procedural meshes in `shapes`: vertex and triangle counts,
//! sizes, uv layout and tangents.

use super::*;
use crate::geometry::bounding_radius;

#[test]
fn procedural_counts() {
    let s = uv_sphere(12, 24);
    assert_eq!(s.vertices.len(), 13 * 25);
    assert_eq!(s.indices.len(), 6 * 24 * 11);
    assert_eq!(icosphere(0).triangle_count(), 20);
    assert_eq!(icosphere(2).triangle_count(), 320);
    assert_eq!(icosphere(100).triangle_count(), 20 * 4usize.pow(7));
    let c = cube();
    assert_eq!((c.vertices.len(), c.indices.len()), (24, 36));
    let p = plane(1.0, 1.0, 4);
    assert_eq!((p.vertices.len(), p.indices.len()), (25, 96));
    let cy = cylinder(16);
    assert_eq!(cy.vertices.len(), 2 * 17 + 2 * (16 + 1));
    assert_eq!(cy.triangle_count(), 2 * 16 + 2 * 16);
    let co = cone(16);
    assert_eq!(co.vertices.len(), 17 + 16 + 17);
    assert_eq!(co.triangle_count(), 32);
    let t = torus(1.0, 0.25, 32, 12);
    assert_eq!(
        (t.vertices.len(), t.triangle_count()),
        (33 * 13, 2 * 32 * 12)
    );
    let f = fullscreen_triangle();
    assert_eq!((f.vertices.len(), f.indices.len()), (3, 3));
}

#[test]
fn procedural_shapes_have_the_documented_size() {
    for v in uv_sphere(8, 8)
        .vertices
        .iter()
        .chain(&icosphere(2).vertices)
    {
        assert!((Vec3::from(v.position).length() - 1.0).abs() < 1e-5);
    }
    assert!((bounding_radius(&cube()) - 3.0f32.sqrt()).abs() < 1e-6);
    assert!((bounding_radius(&cylinder(8)) - 2.0f32.sqrt()).abs() < 1e-6);
    assert_eq!(bounding_radius(&MeshData::default()), 0.0);
    assert!((bounding_radius(&torus(2.0, 0.5, 8, 8)) - 2.5).abs() < 1e-5);
    for v in &plane(4.0, 2.0, 2).vertices {
        assert_eq!(v.position[1], 0.0);
        assert!(v.position[0].abs() <= 2.0 && v.position[2].abs() <= 1.0);
        assert!(v.uv.iter().all(|&x| (0.0..=1.0).contains(&x)));
    }
    for v in &cylinder(8).vertices {
        assert!(v.position[1].abs() <= 1.0);
    }
}

#[test]
fn sphere_uvs_do_not_wrap_and_tangents_run_east() {
    for (name, m) in [
        ("icosphere", icosphere(3)),
        ("uv_sphere", uv_sphere(16, 32)),
    ] {
        for t in m.indices.chunks_exact(3) {
            let u = [t[0], t[1], t[2]].map(|i| m.vertices[i as usize].uv[0]);
            let span = u.iter().fold(f32::MIN, |a, &b| a.max(b))
                - u.iter().fold(f32::MAX, |a, &b| a.min(b));
            assert!(span < 0.5, "{name}: triangle wraps around the u seam");
        }
        for v in &m.vertices {
            let p = Vec3::from(v.position);
            if p.y.abs() < 0.9 {
                // dP/du points east: (z, 0, -x), +x on the +z side.
                let east = Vec3::new(p.z, 0.0, -p.x).normalize();
                let t = Vec3::new(v.tangent[0], v.tangent[1], v.tangent[2]);
                assert!(t.dot(east) > 0.95, "{name}: tangent {t} at {p}");
            }
        }
    }
}

#[test]
fn fullscreen_triangle_covers_clip_space() {
    let f = fullscreen_triangle();
    let pos: Vec<[f32; 3]> = f.vertices.iter().map(|v| v.position).collect();
    assert_eq!(
        pos,
        vec![[-1.0, -1.0, 0.0], [3.0, -1.0, 0.0], [-1.0, 3.0, 0.0]]
    );
    // uv is linear in position: clip (-1,-1) -> (0,0) and (1,1) -> (1,1).
    for v in &f.vertices {
        assert_eq!(
            v.uv,
            [(v.position[0] + 1.0) / 2.0, (v.position[1] + 1.0) / 2.0]
        );
    }
}

#[test]
fn plane_tangent_is_plus_x() {
    for v in &plane(3.0, 5.0, 4).vertices {
        assert_eq!(v.normal, [0.0, 1.0, 0.0]);
        let t = v.tangent;
        assert!((t[0] - 1.0).abs() < 1e-6 && t[1].abs() < 1e-6 && t[2].abs() < 1e-6);
        assert_eq!(t[3], 1.0);
    }
}
