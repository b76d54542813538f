//! One world-space triangle and the two questions the shadow reference
//! (notes 01 §8.5) asks of it: where a ray meets it, and how far a point is
//! from it.
//!
//! The ray/triangle test is Möller–Trumbore, two-sided: with edges
//! `e1 = b - a`, `e2 = c - a`, the ray `o + t d` meets the plane at
//! barycentrics (u, v) where
//! ```text
//! p = d x e2,  det = e1 . p,  s = o - a,  q = s x e1
//! u = (s . p) / det,  v = (d . q) / det,  t = (e2 . q) / det
//! ```
//! and hits when u >= 0, v >= 0, u + v <= 1. `det` near 0 is a ray parallel
//! to the triangle's plane: a miss.

use glam::Vec3;

/// A triangle in world space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Triangle {
    pub a: Vec3,
    pub b: Vec3,
    pub c: Vec3,
}

impl Triangle {
    /// Möller–Trumbore (module header): the ray parameter t where
    /// `origin + t * dir` meets the triangle, from either side; None for a
    /// miss, a ray parallel to the triangle's plane or a degenerate triangle.
    /// t may be negative (behind the origin): the caller bounds it.
    pub fn intersect(&self, origin: Vec3, dir: Vec3) -> Option<f32> {
        let e1 = self.b - self.a;
        let e2 = self.c - self.a;
        let p = dir.cross(e2);
        let det = e1.dot(p);
        // |det| = |d| |e1 x e2| |cos|, the cosine between the ray and the
        // plane's normal: parallel below about one f32 step.
        if det.abs() <= 1e-7 * dir.length() * e1.cross(e2).length() || det == 0.0 {
            return None;
        }
        let inv = 1.0 / det;
        let s = origin - self.a;
        let u = s.dot(p) * inv;
        if !(0.0..=1.0).contains(&u) {
            return None;
        }
        let q = s.cross(e1);
        let v = dir.dot(q) * inv;
        if v < 0.0 || u + v > 1.0 {
            return None;
        }
        Some(e2.dot(q) * inv)
    }

    /// The point of the triangle nearest to `p` (Ericson, "Real-Time
    /// Collision Detection" §5.1.5: which vertex, edge or the face is
    /// nearest, from the signs of dot products).
    pub fn closest_point(&self, p: Vec3) -> Vec3 {
        let (a, b, c) = (self.a, self.b, self.c);
        let (ab, ac, ap) = (b - a, c - a, p - a);
        let (d1, d2) = (ab.dot(ap), ac.dot(ap));
        if d1 <= 0.0 && d2 <= 0.0 {
            return a;
        }
        let bp = p - b;
        let (d3, d4) = (ab.dot(bp), ac.dot(bp));
        if d3 >= 0.0 && d4 <= d3 {
            return b;
        }
        let vc = d1 * d4 - d3 * d2;
        if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
            return a + ab * (d1 / (d1 - d3));
        }
        let cp = p - c;
        let (d5, d6) = (ab.dot(cp), ac.dot(cp));
        if d6 >= 0.0 && d5 <= d6 {
            return c;
        }
        let vb = d5 * d2 - d1 * d6;
        if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
            return a + ac * (d2 / (d2 - d6));
        }
        let va = d3 * d6 - d5 * d4;
        if va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0 {
            return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
        }
        let denom = 1.0 / (va + vb + vc);
        a + ab * (vb * denom) + ac * (vc * denom)
    }

    /// Distance from `p` to the nearest point of the triangle.
    pub fn distance(&self, p: Vec3) -> f32 {
        (self.closest_point(p) - p).length()
    }

    pub(super) fn centroid(&self) -> Vec3 {
        (self.a + self.b + self.c) / 3.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tri(a: [f32; 3], b: [f32; 3], c: [f32; 3]) -> Triangle {
        Triangle {
            a: Vec3::from(a),
            b: Vec3::from(b),
            c: Vec3::from(c),
        }
    }

    #[test]
    fn moller_trumbore_hits_misses_and_edge_cases() {
        let t = tri([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
        let down = Vec3::new(0.0, 0.0, -1.0);
        // Hit from the front and (two-sided) from the back.
        assert_eq!(t.intersect(Vec3::new(0.25, 0.25, 1.0), down), Some(1.0));
        assert_eq!(t.intersect(Vec3::new(0.25, 0.25, -2.0), -down), Some(2.0));
        // Behind the origin: a negative t, for the caller to refuse.
        assert_eq!(t.intersect(Vec3::new(0.25, 0.25, 1.0), -down), Some(-1.0));
        // Outside the triangle (u + v > 1), and beside it (u < 0).
        assert_eq!(t.intersect(Vec3::new(0.6, 0.6, 1.0), down), None);
        assert_eq!(t.intersect(Vec3::new(-0.1, 0.5, 1.0), down), None);
        // On an edge and on a vertex: edges are inclusive.
        assert_eq!(t.intersect(Vec3::new(0.5, 0.0, 1.0), down), Some(1.0));
        assert_eq!(t.intersect(Vec3::new(0.0, 0.0, 3.0), down), Some(3.0));
        // Parallel to the plane, in it or above it: a miss.
        assert_eq!(t.intersect(Vec3::new(-1.0, 0.2, 0.0), Vec3::X), None);
        assert_eq!(t.intersect(Vec3::new(-1.0, 0.2, 0.5), Vec3::X), None);
        // Starting on the triangle: t = 0 exactly (the BVH query with t_min = 0
        // does not count it).
        let o = Vec3::new(0.25, 0.25, 0.0);
        assert_eq!(t.intersect(o, Vec3::new(0.3, 0.1, 1.0)), Some(0.0));
        // A degenerate triangle is never hit.
        let flat = tri([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0]);
        assert_eq!(flat.intersect(Vec3::new(0.5, 0.0, 1.0), down), None);
    }

    #[test]
    fn closest_point_in_each_region() {
        let t = tri([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
        let cp = |x: f32, y: f32, z: f32| t.closest_point(Vec3::new(x, y, z));
        assert_eq!(cp(0.2, 0.3, 5.0), Vec3::new(0.2, 0.3, 0.0)); // face
        assert_eq!(cp(-1.0, -1.0, 1.0), Vec3::ZERO); // vertex a
        assert_eq!(cp(3.0, -1.0, 0.0), Vec3::X); // vertex b
        assert_eq!(cp(-1.0, 3.0, 0.0), Vec3::Y); // vertex c
        assert_eq!(cp(0.5, -2.0, 0.0), Vec3::new(0.5, 0.0, 0.0)); // edge ab
        assert_eq!(cp(-2.0, 0.5, 0.0), Vec3::new(0.0, 0.5, 0.0)); // edge ac
        assert_eq!(cp(1.0, 1.0, 0.0), Vec3::new(0.5, 0.5, 0.0)); // edge bc
        assert_eq!(t.distance(Vec3::new(0.2, 0.3, -2.0)), 2.0);
    }
}
