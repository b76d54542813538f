//! Skinning on the CPU (notes 01 §7.1, "Skinned meshes"): the reference the
//! GPU skinning will be checked against, and the hard cases of weights.
//!
//! Linear blend skinning, exactly as the notes write it:
//!
//! ```text
//! position = sum over influences of (t . v) . w
//! ```
//!
//! with t the joint's transform (its pose times its inverse bind matrix), v
//! the vertex in the bind pose and w its weight, the weights summing to 1.
//! Normals are blended the same way through each transform's linear part,
//! then normalised.
//!
//! Blending matrices has a known failure: two joints that twist 180° about
//! a bone blend, halfway, to a matrix that squashes the limb to its axis
//! (the "candy wrapper"). Dual-quaternion skinning (Kavan et al., "Skinning
//! with Dual Quaternions", I3D 2007) blends rigid transforms as unit dual
//! quaternions instead, and the limb keeps its girth (tested below).

use anyhow::{Result, bail};
use glam::{Mat4, Quat, Vec3};

/// At most this many joints influence one vertex (a fixed-size vertex
/// attribute, as the notes say: "must enforce a maximum number of joints
/// that a single vertex can be influenced by").
pub const MAX_INFLUENCES: usize = 4;

/// A vertex's weights, checked: all zero is an error naming `what`; weights
/// that do not sum to 1 are scaled so that they do, and the second value
/// says so (the caller warns). Negative or non-finite weights are errors.
pub fn normalised_weights(
    what: &str,
    w: [f32; MAX_INFLUENCES],
) -> Result<([f32; MAX_INFLUENCES], bool)> {
    if let Some(x) = w.iter().find(|x| !x.is_finite() || **x < 0.0) {
        bail!("{what}: weight {x} is not a number >= 0");
    }
    let sum: f32 = w.iter().sum();
    if sum <= 0.0 {
        bail!("{what}: every weight is 0, so no joint moves the vertex");
    }
    if (sum - 1.0).abs() <= 1e-4 {
        return Ok((w, false));
    }
    Ok((w.map(|x| x / sum), true))
}

/// Linear blend skinning of a position and a normal.
pub fn linear_blend(
    joints: &[Mat4],
    index: [usize; MAX_INFLUENCES],
    weight: [f32; MAX_INFLUENCES],
    v: Vec3,
    n: Vec3,
) -> (Vec3, Vec3) {
    let (mut p, mut m) = (Vec3::ZERO, Vec3::ZERO);
    for k in 0..MAX_INFLUENCES {
        if weight[k] == 0.0 {
            continue;
        }
        let t = joints[index[k]];
        p += t.transform_point3(v) * weight[k];
        m += t.transform_vector3(n) * weight[k];
    }
    (p, m.normalize_or_zero())
}

/// A rigid transform (rotation then translation) as a unit dual quaternion
/// real + ε dual, dual = ½ (0, t) real.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DualQuat {
    pub real: Quat,
    pub dual: Quat,
}

impl DualQuat {
    pub fn from_rotation_translation(r: Quat, t: Vec3) -> DualQuat {
        let r = r.normalize();
        let tq = Quat::from_xyzw(t.x, t.y, t.z, 0.0);
        DualQuat {
            real: r,
            dual: (tq * r) * 0.5,
        }
    }

    /// The rigid part of a joint transform (its scale, if any, is dropped:
    /// dual quaternions hold rotations and translations only).
    pub fn from_mat4(m: &Mat4) -> DualQuat {
        let (_, r, t) = m.to_scale_rotation_translation();
        DualQuat::from_rotation_translation(r, t)
    }

    /// Apply to a point.
    pub fn transform_point(&self, p: Vec3) -> Vec3 {
        let t = (self.dual * 2.0) * self.real.conjugate();
        self.real * p + Vec3::new(t.x, t.y, t.z)
    }
}

/// Dual-quaternion skinning: the joints' dual quaternions blended by weight
/// (each on the first one's hemisphere), normalised, applied to the
/// position; the normal by the blended rotation.
pub fn dual_quaternion_blend(
    joints: &[DualQuat],
    index: [usize; MAX_INFLUENCES],
    weight: [f32; MAX_INFLUENCES],
    v: Vec3,
    n: Vec3,
) -> (Vec3, Vec3) {
    let zero = Quat::from_xyzw(0.0, 0.0, 0.0, 0.0);
    let (mut real, mut dual) = (zero, zero);
    let mut first: Option<Quat> = None;
    for k in 0..MAX_INFLUENCES {
        if weight[k] == 0.0 {
            continue;
        }
        let d = joints[index[k]];
        let anchor = *first.get_or_insert(d.real);
        let s = if d.real.dot(anchor) < 0.0 {
            -weight[k]
        } else {
            weight[k]
        };
        real += d.real * s;
        dual += d.dual * s;
    }
    let len = real.length();
    if len < 1e-12 {
        return (v, n);
    }
    let b = DualQuat {
        real: real * (1.0 / len),
        dual: dual * (1.0 / len),
    };
    (b.transform_point(v), (b.real * n).normalize_or_zero())
}

/// Uniform components kept back from the joint array for the shader's
/// other uniforms (it has none now; a margin for drivers that count
/// internal ones).
const RESERVED_COMPONENTS: i32 = 64;

/// How many joint matrices fit the uniform array on a GL that offers
/// `components` (GL_MAX_VERTEX_UNIFORM_COMPONENTS; GL 3.3 guarantees 1024,
/// so at least 60 joints).
pub fn uniform_joint_limit(components: i32) -> usize {
    ((components - RESERVED_COMPONENTS) / 16).max(1) as usize
}

#[cfg(test)]
mod tests;
