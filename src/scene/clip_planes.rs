//! `[[clip_planes]]`: user clip planes that cut the world open (notes 01
//! §3.3, "Clipping": a primitive is clipped against the view volume and
//! against any plane the application adds, with gl_ClipDistance). Each
//! plane keeps the side its normal points to:
//!
//! ```toml
//! [[clip_planes]]
//! normal = [-1.0, 0.0, 0.0]   # keep x <= 0.2
//! point = [0.2, 0.0, 0.0]     # a point on the plane (default: the origin)
//! ```
//!
//! The mirrors' clip plane is gl_ClipDistance[0] (notes 05); these are
//! gl_ClipDistance[1] on. GL 3.3 promises GL_MAX_CLIP_DISTANCES >= 8, so a
//! scene may have 7; the renderer checks the driver's number too.

use anyhow::{Result, bail};
use glam::{Vec3, Vec4};
use serde::Deserialize;

/// The most planes a scene may have: GL 3.3's 8 clip distances, less the
/// mirrors' one.
pub const MAX_CLIP_PLANES: usize = 7;

#[derive(Deserialize, Debug, Clone, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct ClipPlaneFile {
    pub normal: [f32; 3],
    #[serde(default)]
    pub point: [f32; 3],
}

/// The planes as (n, -n . p) with |n| = 1: dot(plane, (x, 1)) is the signed
/// distance of x, kept where it is >= 0.
pub(super) fn clip_planes(files: &[ClipPlaneFile]) -> Result<Vec<Vec4>> {
    if files.len() > MAX_CLIP_PLANES {
        bail!(
            "clip_planes: {} planes, at most {MAX_CLIP_PLANES} (GL 3.3 promises 8 clip distances and the mirrors use one)",
            files.len()
        );
    }
    let mut out = Vec::new();
    for (i, f) in files.iter().enumerate() {
        let key = |k: &str| format!("clip_planes[{i}].{k}");
        if !f.normal.iter().chain(&f.point).all(|x| x.is_finite()) {
            bail!("{}: every number must be finite", key("normal/point"));
        }
        super::camera_limits::within_world(&key("point"), &f.point)?;
        let n = Vec3::from(f.normal);
        if n.length() < 1e-6 {
            bail!(
                "{}: must not be zero: it says which side is kept",
                key("normal")
            );
        }
        let n = n.normalize();
        out.push(n.extend(-n.dot(Vec3::from(f.point))));
    }
    Ok(out)
}
