//! Polygons to triangles: an OBJ face of n > 3 corners, convex or not,
//! through ear clipping (the `earcut` crate, a port of mapbox/earcut). The
//! face is projected onto its best-fitting plane (Newell's normal), clipped
//! there, and each triangle is wound as the face is, counter-clockwise seen
//! from the side its normal points to. A fan (what tobj's own triangulation
//! does) fills a concave face's notch and a ring's hole; ear clipping
//! leaves them empty.

use glam::{DVec3, Vec3};

/// Newell's normal of the polygon `p` (not normalised; zero for a
/// degenerate one): robust for non-planar and concave polygons.
pub fn newell_normal(p: &[Vec3]) -> Vec3 {
    let mut n = DVec3::ZERO;
    for (i, a) in p.iter().enumerate() {
        let (a, b) = (a.as_dvec3(), p[(i + 1) % p.len()].as_dvec3());
        n += DVec3::new(
            (a.y - b.y) * (a.z + b.z),
            (a.z - b.z) * (a.x + b.x),
            (a.x - b.x) * (a.y + b.y),
        );
    }
    n.as_vec3()
}

/// Triangles (indices into `p`) covering the polygon `p`, wound as `p`
/// is. A triangle passes through; a polygon with no area gives a fan (its
/// triangles have no area either, as tobj's would).
pub fn triangulate(p: &[Vec3]) -> Vec<u32> {
    let n = p.len();
    if n < 3 {
        return Vec::new();
    }
    if n == 3 {
        return vec![0, 1, 2];
    }
    let normal = newell_normal(p);
    let fan = || (1..n as u32 - 1).flat_map(|i| [0, i, i + 1]).collect();
    let area2 = normal.length_squared();
    if area2.is_nan() || area2 <= 0.0 {
        return fan();
    }
    let points: Vec<[f64; 3]> = p.iter().map(|v| v.as_dvec3().to_array()).collect();
    let mut flat = Vec::with_capacity(n);
    if !earcut::utils3d::project3d_to_2d(&points, n, &mut flat) {
        return fan();
    }
    let mut out: Vec<u32> = Vec::with_capacity(3 * (n - 2));
    earcut::Earcut::new().earcut(flat, &[] as &[u32], &mut out);
    if out.is_empty() {
        return fan();
    }
    // earcut winds as it likes: turn each triangle to face the polygon's way.
    for t in out.chunks_exact_mut(3) {
        let [a, b, c] = [t[0], t[1], t[2]].map(|i| p[i as usize]);
        if (b - a).cross(c - a).dot(normal) < 0.0 {
            t.swap(1, 2);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn area(p: &[Vec3], t: &[u32]) -> f32 {
        t.chunks_exact(3)
            .map(|t| {
                let [a, b, c] = [t[0], t[1], t[2]].map(|i| p[i as usize]);
                0.5 * (b - a).cross(c - a).length()
            })
            .sum()
    }

    fn inside(p: &[Vec3], t: &[u32], q: Vec3) -> bool {
        t.chunks_exact(3).any(|t| {
            let [a, b, c] = [t[0], t[1], t[2]].map(|i| p[i as usize]);
            let s = |u: Vec3, v: Vec3| (v - u).cross(q - u).z;
            let (x, y, z) = (s(a, b), s(b, c), s(c, a));
            (x > 0.0 && y > 0.0 && z > 0.0) || (x < 0.0 && y < 0.0 && z < 0.0)
        })
    }

    /// A C shape, 3 x 3 with a 1 x 1 notch cut from the middle of its right side.
    fn c_shape() -> Vec<Vec3> {
        [
            (0., 0.),
            (3., 0.),
            (3., 1.),
            (1., 1.),
            (1., 2.),
            (3., 2.),
            (3., 3.),
            (0., 3.),
        ]
        .map(|(x, y)| Vec3::new(x, y, 0.0))
        .to_vec()
    }

    #[test]
    fn a_concave_face_keeps_its_notch_empty() {
        let p = c_shape();
        let t = triangulate(&p);
        assert_eq!(t.len(), 3 * 6);
        // 9 - the notch (2 x 1) = 7.
        assert!((area(&p, &t) - 7.0).abs() < 1e-5, "{}", area(&p, &t));
        assert!(
            !inside(&p, &t, Vec3::new(2.0, 1.5, 0.0)),
            "the notch is filled"
        );
        assert!(inside(&p, &t, Vec3::new(0.5, 1.5, 0.0)));
        for tri in t.chunks_exact(3) {
            let [a, b, c] = [tri[0], tri[1], tri[2]].map(|i| p[i as usize]);
            assert!((b - a).cross(c - a).z > 0.0, "wound against the face");
        }
    }

    #[test]
    fn a_ring_keeps_its_hole_empty() {
        // Outer square 0..4, inner square 1..3, joined by a slit along y = 0..1 at x = 0..1
        // (how an OBJ writes a ring as one face).
        let p: Vec<Vec3> = [
            (1., 1.),
            (1., 0.),
            (4., 0.),
            (4., 4.),
            (0., 4.),
            (0., 0.),
            (1., 0.),
            (1., 1.),
            (1., 3.),
            (3., 3.),
            (3., 1.),
        ]
        .map(|(x, y)| Vec3::new(x, y, 0.0))
        .to_vec();
        let t = triangulate(&p);
        assert!((area(&p, &t) - 12.0).abs() < 1e-4, "{}", area(&p, &t));
        assert!(
            !inside(&p, &t, Vec3::new(2.0, 2.0, 0.0)),
            "the hole is filled"
        );
        assert!(inside(&p, &t, Vec3::new(3.5, 2.0, 0.0)));
    }

    #[test]
    fn a_tilted_clockwise_face_keeps_its_winding() {
        // The C shape turned to face -x and listed backwards.
        let mut p: Vec<Vec3> = c_shape().iter().map(|v| Vec3::new(0.0, v.y, v.x)).collect();
        p.reverse();
        let n = newell_normal(&p).normalize();
        let t = triangulate(&p);
        for tri in t.chunks_exact(3) {
            let [a, b, c] = [tri[0], tri[1], tri[2]].map(|i| p[i as usize]);
            assert!((b - a).cross(c - a).dot(n) > 0.0);
        }
        assert!((area(&p, &t) - 7.0).abs() < 1e-5);
    }
}
