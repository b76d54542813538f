//! A bounding volume hierarchy over world-space triangles, for the exact
//! shadow reference of `shadow_reference` (notes 01 §8.5: a point is in
//! shadow when something lies between it and the light; here we ask the
//! triangles directly instead of a shadow map).
//!
//! Each node is an axis-aligned box around its triangles; an inner node
//! splits them in two at the median centroid along the box's longest axis,
//! a leaf holds at most `LEAF_SIZE`. A ray visits only the boxes it passes
//! through (the slab test), so a query costs about log2(n) boxes and a few
//! triangles instead of all n triangles.
//!
//! Written by hand (about 200 lines) rather than taken from a crate: the
//! `bvh` crate's current versions are built on nalgebra (and rayon), its
//! older glam versions on a glam other than ours, and parry3d is built on
//! nalgebra; gloss does all its maths in glam.

use super::triangle::Triangle;
use glam::Vec3;

/// Most triangles in a leaf.
const LEAF_SIZE: usize = 4;

/// A box node: a leaf (`count > 0`) holds `triangles[start..start + count]`;
/// an inner node's children are the next node and node `start`.
#[derive(Clone, Copy, Debug)]
struct Node {
    lo: Vec3,
    hi: Vec3,
    start: u32,
    count: u32,
}

/// The hierarchy: nodes in depth-first order, the triangles reordered so
/// that each leaf's are contiguous.
#[derive(Clone, Debug, Default)]
pub struct Bvh {
    nodes: Vec<Node>,
    triangles: Vec<Triangle>,
}

fn bounds(triangles: &[Triangle]) -> (Vec3, Vec3) {
    let mut lo = Vec3::splat(f32::INFINITY);
    let mut hi = Vec3::splat(f32::NEG_INFINITY);
    for t in triangles {
        lo = lo.min(t.a).min(t.b).min(t.c);
        hi = hi.max(t.a).max(t.b).max(t.c);
    }
    (lo, hi)
}

impl Bvh {
    pub fn new(mut triangles: Vec<Triangle>) -> Bvh {
        let mut nodes = Vec::with_capacity(2 * triangles.len() / LEAF_SIZE + 1);
        if !triangles.is_empty() {
            build(&mut nodes, &mut triangles, 0);
        }
        Bvh { nodes, triangles }
    }

    /// The triangles, in the hierarchy's order.
    pub fn triangles(&self) -> &[Triangle] {
        &self.triangles
    }

    /// The box around every triangle (None when there are none).
    pub fn bounds(&self) -> Option<(Vec3, Vec3)> {
        self.nodes.first().map(|n| (n.lo, n.hi))
    }

    /// Whether the ray `origin + t * dir` meets a triangle at some t with
    /// `t_min < t < t_max` for which `counts(triangle)` is true.
    pub fn any_hit(
        &self,
        origin: Vec3,
        dir: Vec3,
        t_min: f32,
        t_max: f32,
        counts: impl Fn(&Triangle) -> bool,
    ) -> bool {
        let mut found = false;
        self.walk(origin, dir, t_min, t_max, |tri, t| {
            if t > t_min && t < t_max && counts(tri) {
                found = true;
            }
            (found, t_max)
        });
        found
    }

    /// The smallest t in `(0, t_max)` where the ray meets a triangle.
    pub fn closest_hit(&self, origin: Vec3, dir: Vec3, t_max: f32) -> Option<f32> {
        let mut best = t_max;
        self.walk(origin, dir, 0.0, t_max, |_, t| {
            if t > 0.0 && t < best {
                best = t;
            }
            (false, best)
        });
        (best < t_max).then_some(best)
    }

    /// Visits the triangles whose boxes the ray enters within `t_min..t_max`;
    /// `hit(triangle, t)` returns (stop, the new t_max).
    fn walk(
        &self,
        origin: Vec3,
        dir: Vec3,
        t_min: f32,
        mut t_max: f32,
        mut hit: impl FnMut(&Triangle, f32) -> (bool, f32),
    ) {
        if self.nodes.is_empty() {
            return;
        }
        // Depth is at most log2(n) + 1 (median splits); 64 is plenty.
        let mut stack = [0u32; 64];
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let i = stack[top] as usize;
            let n = &self.nodes[i];
            if !slab(origin, dir, n.lo, n.hi, t_min, t_max) {
                continue;
            }
            if n.count > 0 {
                let (s, c) = (n.start as usize, n.count as usize);
                for tri in &self.triangles[s..s + c] {
                    if let Some(t) = tri.intersect(origin, dir) {
                        let (stop, max) = hit(tri, t);
                        if stop {
                            return;
                        }
                        t_max = max;
                    }
                }
            } else {
                stack[top] = i as u32 + 1;
                stack[top + 1] = n.start;
                top += 2;
            }
        }
    }
}

/// Builds the subtree of `triangles` (which start at index `offset` of the
/// whole list) and returns its node's index.
fn build(nodes: &mut Vec<Node>, triangles: &mut [Triangle], offset: usize) -> usize {
    let (lo, hi) = bounds(triangles);
    // Grown by a millionth of the coordinates' size, many f32 steps, so that
    // rounding in the slab test never loses a triangle on the box's face.
    let pad = Vec3::splat(1e-6 * lo.abs().max(hi.abs()).max_element() + 1e-30);
    let (lo, hi) = (lo - pad, hi + pad);
    let me = nodes.len();
    nodes.push(Node {
        lo,
        hi,
        start: offset as u32,
        count: triangles.len() as u32,
    });
    if triangles.len() <= LEAF_SIZE {
        return me;
    }
    // Median split along the longest axis of the centroids' box.
    let (mut clo, mut chi) = (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY));
    for t in triangles.iter() {
        clo = clo.min(t.centroid());
        chi = chi.max(t.centroid());
    }
    let axis = (chi - clo).max_position();
    let mid = triangles.len() / 2;
    triangles.select_nth_unstable_by(mid, |x, y| {
        x.centroid()[axis].total_cmp(&y.centroid()[axis])
    });
    let (left, right) = triangles.split_at_mut(mid);
    build(nodes, left, offset);
    let r = build(nodes, right, offset + mid);
    nodes[me].start = r as u32;
    nodes[me].count = 0;
    me
}

/// The slab test: whether the ray enters the box [lo, hi] for some t in
/// `t_min..=t_max`. A zero direction component keeps the ray in (or out of)
/// that slab for every t.
fn slab(origin: Vec3, dir: Vec3, lo: Vec3, hi: Vec3, t_min: f32, t_max: f32) -> bool {
    let (mut near, mut far) = (t_min, t_max);
    for k in 0..3 {
        let (o, d) = (origin[k], dir[k]);
        if d == 0.0 {
            if o < lo[k] || o > hi[k] {
                return false;
            }
            continue;
        }
        let (t0, t1) = ((lo[k] - o) / d, (hi[k] - o) / d);
        near = near.max(t0.min(t1));
        far = far.min(t0.max(t1));
        if near > far {
            return false;
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::lcg::Lcg;

    fn tri(a: [f32; 3], b: [f32; 3], c: [f32; 3]) -> Triangle {
        Triangle {
            a: Vec3::from(a),
            b: Vec3::from(b),
            c: Vec3::from(c),
        }
    }

    #[test]
    fn a_ray_starting_on_a_triangle_does_not_hit_it() {
        let t = tri([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
        let (o, down) = (Vec3::new(0.25, 0.25, 0.0), Vec3::new(0.0, 0.0, -1.0));
        let bvh = Bvh::new(vec![t]);
        assert!(!bvh.any_hit(o, Vec3::Z, 0.0, f32::INFINITY, |_| true));
        assert!(bvh.any_hit(o + Vec3::Z, down, 0.0, 1.5, |_| true));
        assert!(!bvh.any_hit(o + Vec3::Z, down, 0.0, 0.5, |_| true));
        assert!(!bvh.any_hit(o + Vec3::Z, down, 0.0, 1.5, |_| false));
        assert_eq!(bvh.closest_hit(o + Vec3::Z, down, 5.0), Some(1.0));
    }

    #[test]
    fn bvh_equals_brute_force_on_random_rays() {
        let mut r = Lcg(7);
        let triangles: Vec<Triangle> = (0..2000)
            .map(|_| {
                let a = r.vec(-2.0, 2.0);
                Triangle {
                    a,
                    b: a + r.vec(-0.5, 0.5),
                    c: a + r.vec(-0.5, 0.5),
                }
            })
            .collect();
        let bvh = Bvh::new(triangles.clone());
        assert_eq!(bvh.triangles().len(), 2000);
        let (mut hits, mut anys) = (0, 0);
        for i in 0..3000 {
            let o = r.vec(-3.0, 3.0);
            let mut d = r.vec(-1.0, 1.0);
            // Some rays along an axis, whose other components are zero.
            if i % 10 == 0 {
                d = Vec3::new(0.0, d.y, 0.0);
            }
            let t_max = 6.0 * r.next();
            let brute = triangles
                .iter()
                .filter_map(|t| t.intersect(o, d))
                .filter(|&t| t > 0.0 && t < t_max)
                .min_by(f32::total_cmp);
            assert_eq!(bvh.closest_hit(o, d, t_max), brute, "ray {i}");
            let any = brute.is_some();
            assert_eq!(bvh.any_hit(o, d, 0.0, t_max, |_| true), any, "ray {i}");
            hits += usize::from(brute.is_some());
            anys += usize::from(any);
        }
        // The test means something: many rays hit, many miss.
        assert!(hits > 900 && hits < 2100, "{hits} of 3000 rays hit");
        assert_eq!(hits, anys);
    }

    #[test]
    fn an_empty_hierarchy_hits_nothing() {
        let bvh = Bvh::new(Vec::new());
        assert_eq!(bvh.bounds(), None);
        assert_eq!(bvh.closest_hit(Vec3::ZERO, Vec3::X, f32::INFINITY), None);
        assert!(!bvh.any_hit(Vec3::ZERO, Vec3::X, 0.0, f32::INFINITY, |_| true));
    }
}
