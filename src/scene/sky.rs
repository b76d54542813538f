//! `[sky]`: the Preetham sun-sky of notes 03, Sun Sky (src/math/preetham.rs),
//! drawn behind the world by the sun-sky pass (src/techniques/sky/sun_sky.rs).
//!
//! ```toml
//! [sky]
//! sun = [0.3, 0.25, -1.0]   # the direction to the sun (y up; any length)
//! turbidity = 3.0           # 2 (clear) ..= 10 (hazy)
//! intensity = 1.0           # a factor on the model's radiance (1.0 = 10 kcd/m^2)
//! ```

use crate::math::preetham::Sky;
use anyhow::{Result, anyhow, bail};
use glam::Vec3;
use serde::Deserialize;

#[derive(Deserialize, Debug, Clone)]
#[serde(deny_unknown_fields)]
pub struct SkyFile {
    pub sun: [f32; 3],
    #[serde(default = "three")]
    pub turbidity: f32,
    #[serde(default = "one")]
    pub intensity: f32,
}

fn three() -> f32 {
    3.0
}
fn one() -> f32 {
    1.0
}

/// The scene's sky, checked.
#[derive(Clone, Debug, PartialEq)]
pub struct SkySettings {
    /// The unit direction to the sun.
    pub sun: Vec3,
    pub turbidity: f32,
    pub intensity: f32,
}

impl SkySettings {
    /// The model for this sky (the checks in `sky` make this succeed).
    pub fn model(&self) -> Sky {
        Sky::new(self.sun.as_dvec3(), f64::from(self.turbidity))
            .expect("the sky was checked when the scene loaded")
    }
}

/// Check `[sky]`.
pub(super) fn sky(f: &Option<SkyFile>) -> Result<Option<SkySettings>> {
    let Some(s) = f else { return Ok(None) };
    if !(s.intensity.is_finite() && (0.0..=1e4).contains(&s.intensity)) {
        bail!(
            "sky.intensity: expected a number in 0..=10000, found {}",
            s.intensity
        );
    }
    let sun = Vec3::from(s.sun).as_dvec3();
    let model = Sky::new(sun, f64::from(s.turbidity)).map_err(|e| {
        let key = if e.contains("turbidity") {
            "sky.turbidity"
        } else {
            "sky.sun"
        };
        anyhow!("{key}: {e}")
    })?;
    Ok(Some(SkySettings {
        sun: model.sun.as_vec3(),
        turbidity: s.turbidity,
        intensity: s.intensity,
    }))
}
