//! `[instancing]`: a field of rocks in a ring round a point, drawn with
//! instanced arrays (LearnOpenGL, 4.advanced_opengl "Instancing": the
//! asteroid field; src/techniques/vertex_geometry/instancing.rs):
//!
//! ```toml
//! [instancing]
//! count = 100000              # rocks (1..=1000000)
//! seed = 1
//! center = [0.0, 0.0, 0.0]    # the ring's centre (a planet object there)
//! radius = 40.0               # the ring's radius
//! offset = 6.0                # each rock moved up to this far off the ring
//! scale = [0.05, 0.25]        # each rock's size, smallest and largest
//! color = [0.45, 0.4, 0.35]   # linear RGB, 0..=1
//! ```
//!
//! `render.instancing` chooses one instanced draw (true) or one draw per
//! rock (false): the same image.

use crate::math::{self, lcg::Lcg};
use anyhow::{Result, bail};
use glam::{Mat4, Vec3};
use serde::Deserialize;

/// The most rocks a field may have (64 bytes each on the GPU).
pub const MAX_ROCKS: u32 = 1_000_000;

#[derive(Deserialize, Debug, Clone, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct InstancingFile {
    pub count: u32,
    #[serde(default = "one")]
    pub seed: u64,
    #[serde(default)]
    pub center: [f32; 3],
    pub radius: f32,
    #[serde(default)]
    pub offset: f32,
    #[serde(default = "sizes")]
    pub scale: [f32; 2],
    #[serde(default = "grey")]
    pub color: [f32; 3],
}

fn one() -> u64 {
    1
}
fn sizes() -> [f32; 2] {
    [0.05, 0.25]
}
fn grey() -> [f32; 3] {
    [0.45, 0.4, 0.35]
}

/// The field as checked: the file's values.
#[derive(Debug, Clone, PartialEq)]
pub struct Instancing {
    pub count: u32,
    pub seed: u64,
    pub center: Vec3,
    pub radius: f32,
    pub offset: f32,
    pub scale: [f32; 2],
    pub color: Vec3,
}

pub(super) fn resolve(file: Option<&InstancingFile>) -> Result<Option<Instancing>> {
    let Some(f) = file else {
        return Ok(None);
    };
    if !(1..=MAX_ROCKS).contains(&f.count) {
        bail!(
            "instancing.count: expected 1..={MAX_ROCKS} rocks, found {}",
            f.count
        );
    }
    let finite = |v: &[f32]| v.iter().all(|x| x.is_finite());
    if !finite(&f.center) {
        bail!(
            "instancing.center: expected finite numbers, found {:?}",
            f.center
        );
    }
    if !(f.radius.is_finite() && f.radius > 0.0) {
        bail!(
            "instancing.radius: expected a length > 0, found {}",
            f.radius
        );
    }
    if !(f.offset.is_finite() && f.offset >= 0.0) {
        bail!(
            "instancing.offset: expected a length >= 0, found {}",
            f.offset
        );
    }
    let [lo, hi] = f.scale;
    if !(finite(&f.scale) && lo > 0.0 && lo <= hi) {
        bail!(
            "instancing.scale: expected [smallest, largest] with 0 < smallest <= largest, found {:?}",
            f.scale
        );
    }
    if f.color
        .iter()
        .any(|c| !c.is_finite() || !(0.0..=1.0).contains(c))
    {
        bail!(
            "instancing.color: expected linear RGB with each channel in 0..=1, found {:?}",
            f.color
        );
    }
    Ok(Some(Instancing {
        count: f.count,
        seed: f.seed,
        center: Vec3::from(f.center),
        radius: f.radius,
        offset: f.offset,
        scale: f.scale,
        color: Vec3::from(f.color),
    }))
}

impl Instancing {
    /// Every rock's model matrix, as the lesson places them: rock i at angle
    /// i / count x 360° on the ring, moved by up to `offset` in x and z and
    /// 0.4 x that in y, scaled by a size in `scale`, turned by a random angle
    /// about the axis (0.4, 0.6, 0.8). Seeded: the same field every run.
    pub fn models(&self) -> Vec<Mat4> {
        let mut rng = Lcg(self.seed);
        let axis = Vec3::new(0.4, 0.6, 0.8).normalize();
        (0..self.count)
            .map(|i| {
                let angle = i as f32 / self.count as f32 * std::f32::consts::TAU;
                let mut d = || rng.range(-self.offset, self.offset);
                let x = angle.sin() * self.radius + d();
                let y = d() * 0.4;
                let z = angle.cos() * self.radius + d();
                let p = self.center + Vec3::new(x, y, z);
                let s = rng.range(self.scale[0], self.scale[1]);
                let turn = rng.range(0.0, std::f32::consts::TAU);
                math::translate(p.x, p.y, p.z)
                    * Mat4::from_axis_angle(axis, turn)
                    * math::scale(s, s, s)
            })
            .collect()
    }
}
