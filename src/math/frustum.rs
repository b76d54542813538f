//! Notes 01 §6.3, frustum culling: "frustum represented as 6 infinite
//! planes", "derived from the projection view matrix": "extract each axis
//! from the VP matrix and add/subtract from the w axis to obtain plane
//! normals (which then need to be normalised)" (Gribb and Hartmann, "Fast
//! Extraction of Viewing Frustum Planes from the World-View-Projection
//! Matrix", 2001).
//!
//! A point p is inside the frustum when its clip coordinates c = VP p obey
//! -w <= x <= w, -w <= y <= w, -w <= z <= w (GL's clip volume). With r_i the
//! rows of VP, x = r0 . p and w = r3 . p, so `-w <= x` is (r3 + r0) . p >= 0:
//! a plane whose (a, b, c, d) is the row sum. The six planes are r3 ± r0,
//! r3 ± r1, r3 ± r2; dividing each by |(a, b, c)| makes d + n . p the signed
//! distance, which the sphere test needs. The normals point inwards.
//!
//! Bounding volumes, as the notes list them: a sphere is outside when its
//! centre is more than its radius behind a plane; an axis-aligned box is
//! outside when its corner furthest along the plane's normal (the "p-vertex")
//! is behind it, and wholly inside when even the nearest corner is in front
//! of all six.

use glam::{Mat4, Vec3, Vec4};

/// Where a volume lies against the frustum.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Containment {
    Outside,
    /// Crosses at least one plane: may be partly visible.
    Straddles,
    Inside,
}

/// Six planes (n, d), n . p + d >= 0 inside, |n| = 1: left, right, bottom,
/// top, near, far.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frustum {
    pub planes: [Vec4; 6],
}

impl Frustum {
    /// The planes of the clip volume of `view_projection` (GL: z in [-w, w]).
    /// A plane whose normal is zero (a degenerate matrix) keeps everything.
    pub fn from_view_projection(m: &Mat4) -> Frustum {
        let (r0, r1, r2, r3) = (m.row(0), m.row(1), m.row(2), m.row(3));
        let planes = [r3 + r0, r3 - r0, r3 + r1, r3 - r1, r3 + r2, r3 - r2].map(|p| {
            let len = p.truncate().length();
            if len > 0.0 && len.is_finite() {
                p / len
            } else {
                Vec4::new(0.0, 0.0, 0.0, 1.0)
            }
        });
        Frustum { planes }
    }

    /// The same frustum with its near plane dropped (it keeps everything):
    /// what a shadow map drawn with GL_DEPTH_CLAMP covers, since a caster
    /// between the light and the near plane still casts.
    pub fn without_near(mut self) -> Frustum {
        self.planes[4] = Vec4::new(0.0, 0.0, 0.0, 1.0);
        self
    }

    /// The signed distance from plane `i` to `p` (positive inside).
    pub fn distance(&self, i: usize, p: Vec3) -> f32 {
        self.planes[i].truncate().dot(p) + self.planes[i].w
    }

    /// A sphere of centre `c` and radius `r`.
    pub fn sphere(&self, c: Vec3, r: f32) -> Containment {
        let mut inside = true;
        for i in 0..6 {
            let d = self.distance(i, c);
            if d < -r {
                return Containment::Outside;
            }
            inside &= d >= r;
        }
        if inside {
            Containment::Inside
        } else {
            Containment::Straddles
        }
    }

    /// The axis-aligned box from `lo` to `hi`.
    pub fn aabb(&self, lo: Vec3, hi: Vec3) -> Containment {
        let mut inside = true;
        for p in &self.planes {
            let n = p.truncate();
            // The corner furthest along n, and the nearest.
            let far = Vec3::select(n.cmpge(Vec3::ZERO), hi, lo);
            let near = Vec3::select(n.cmpge(Vec3::ZERO), lo, hi);
            if n.dot(far) + p.w < 0.0 {
                return Containment::Outside;
            }
            inside &= n.dot(near) + p.w >= 0.0;
        }
        if inside {
            Containment::Inside
        } else {
            Containment::Straddles
        }
    }
}

/// The world-space box around the local box (`lo`, `hi`) moved by `m`
/// (Arvo, "Transforming Axis-Aligned Bounding Boxes", Graphics Gems 1990):
/// the centre moves, and each half-extent is the absolute 3x3 times the
/// local one.
pub fn transform_aabb(m: &Mat4, lo: Vec3, hi: Vec3) -> (Vec3, Vec3) {
    let c = m.transform_point3((lo + hi) * 0.5);
    let e = (hi - lo) * 0.5;
    let a = glam::Mat3::from_mat4(*m);
    let half = Vec3::new(
        a.row(0).abs().dot(e),
        a.row(1).abs().dot(e),
        a.row(2).abs().dot(e),
    );
    (c - half, c + half)
}

#[cfg(test)]
mod tests;
