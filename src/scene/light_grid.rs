//! `[light_grid]`: many point lights placed by a seeded generator (the notes'
//! 256-light example), the same lights for the same seed everywhere.

use super::checks::{finite, non_negative};
use super::{Light, LightKind, Scene, validate_attenuation};
use anyhow::{Result, anyhow, bail};
use glam::Vec3;
use serde::Deserialize;

/// `[light_grid]`: many point lights placed by a seeded generator (the
/// notes' 256-light example). The scene keeps it, so the demo can edit it.
#[derive(Deserialize, Debug, Clone, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct LightGrid {
    pub count: usize,
    #[serde(default = "one_u64")]
    pub seed: u64,
    /// [xmin, xmax, zmin, zmax]
    pub area: [f32; 4],
    /// [lowest, highest]
    pub height: [f32; 2],
    #[serde(default = "one")]
    pub intensity: f32,
    /// [Kc, Kl, Kq]
    #[serde(default = "notes_attenuation")]
    pub attenuation: [f32; 3],
}

fn one_u64() -> u64 {
    1
}
fn one() -> f32 {
    1.0
}
/// Notes 04's [Kc, Kl, Kq], as a `[[lights]]` entry's default.
fn notes_attenuation() -> [f32; 3] {
    [1.0, 0.09, 0.032]
}

/// Check a light grid as the loader does; errors name the key.
pub(super) fn check(g: &LightGrid) -> Result<()> {
    finite("light_grid.area", &g.area)?;
    finite("light_grid.height", &g.height)?;
    non_negative("light_grid.intensity", &[g.intensity])?;
    let [kc, kl, kq] = g.attenuation;
    validate_attenuation(kc, kl, kq).map_err(|e| anyhow!("light_grid.attenuation: {e}"))?;
    if g.count > 100_000 {
        bail!("light_grid.count: at most 100000 lights, found {}", g.count);
    }
    Ok(())
}

impl Scene {
    /// Replace the generated lights with those of `grid` (the demo edits the
    /// grid; `gloss bench --lights` its count). The lights the file lists stay.
    pub fn set_light_grid(&mut self, grid: LightGrid) -> Result<()> {
        check(&grid)?;
        let fixed = self.lights.len() - self.grid_lights.unwrap_or(0);
        self.lights.truncate(fixed);
        self.lights.extend(generate_lights(&grid));
        self.grid_lights = Some(grid.count);
        self.light_grid = Some(grid);
        Ok(())
    }
}

/// A small deterministic generator (SplitMix64) so scenes need no rand crate
/// and the same seed gives the same lights everywhere.
pub(super) struct SplitMix(pub(super) u64);
impl SplitMix {
    pub(super) fn next_f32(&mut self) -> f32 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 40) as f32 / (1u64 << 24) as f32
    }
}

pub(super) fn generate_lights(g: &LightGrid) -> Vec<Light> {
    let mut rng = SplitMix(g.seed);
    let [x0, x1, z0, z1] = g.area;
    (0..g.count)
        .map(|_| {
            let x = x0 + (x1 - x0) * rng.next_f32();
            let z = z0 + (z1 - z0) * rng.next_f32();
            let y = g.height[0] + (g.height[1] - g.height[0]) * rng.next_f32();
            // A saturated hue: one channel full, one random, one low.
            let hue = rng.next_f32() * 6.0;
            let f = hue.fract();
            let color = match hue as u32 {
                0 => Vec3::new(1.0, f, 0.1),
                1 => Vec3::new(1.0 - f, 1.0, 0.1),
                2 => Vec3::new(0.1, 1.0, f),
                3 => Vec3::new(0.1, 1.0 - f, 1.0),
                4 => Vec3::new(f, 0.1, 1.0),
                _ => Vec3::new(1.0, 0.1, 1.0 - f),
            };
            Light {
                range: None,
                kind: LightKind::Point,
                position: Vec3::new(x, y, z),
                direction: Vec3::NEG_Y,
                color,
                intensity: g.intensity,
                kc: g.attenuation[0],
                kl: g.attenuation[1],
                kq: g.attenuation[2],
                inner_angle: 20.0,
                outer_angle: 30.0,
                shadow: None,
            }
        })
        .collect()
}
