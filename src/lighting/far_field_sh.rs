//! The spherical-harmonics far field on the CPU (beyond the notes;
//! src/techniques/deferred/far_field.rs, glsl/common/far_field_sh.glsl):
//! the far lights' incoming light at a point as order-2 spherical harmonics,
//! convolved with the clamped cosine (Ramamoorthi and Hanrahan, "An
//! Efficient Representation for Irradiance Environment Maps", SIGGRAPH
//! 2001), and the bound on what a pixel gets wrong when it evaluates a
//! nearby sample's harmonics at its own normal. Written apart from the
//! shader so that tests can check the shader's images and bound against it,
//! and the bound against the exact sum.

use crate::lighting::smoothstep;
use glam::Vec3;
use std::f32::consts::PI;

/// The near weight is 1 up to this fraction of the near part's end
/// (far_field::NEAR_INNER).
pub const NEAR_INNER: f32 = 0.5;

/// The order-2 approximation of the clamped cosine is off by at most this
/// fraction of one light's radiance, at 90 degrees from the light: with
/// x = cos theta it is 1/4 + x/2 + 5/32 (3 x^2 - 1), 3/32 at x = 0.
pub const TRUNCATION: f32 = 3.0 / 32.0;
/// Its error g(x) = 3/32 + x/2 + 15/32 x^2 - max(x, 0) takes values in
/// [-1/24, 3/32], a range of 2/15, and changes by at most 1/2 per unit of x.
pub const TRUNCATION_RANGE: f32 = 2.0 / 15.0;
pub const TRUNCATION_SLOPE: f32 = 0.5;
/// A pixel uses a sample's harmonics only where the truncation's change,
/// min(2/15, |N - N_s| / 2) C k_d, is at most this (linear light); it sums
/// its far part itself otherwise (SH_TOLERANCE in glsl/common/far_field_sh.glsl).
pub const SH_TOLERANCE: f32 = 0.5 / 255.0;

/// Whether a sample whose far radiances sum to `total` (brightest
/// channels) serves a pixel of diffuse colour `kd` (brightest channel)
/// whose normal is `turn` = |N - N_s| from the sample's.
pub fn serves(total: f32, turn: f32, kd: f32) -> bool {
    TRUNCATION_RANGE.min(TRUNCATION_SLOPE * turn) * total * kd <= SH_TOLERANCE
}

/// A point light as the far field sees it.
#[derive(Clone, Copy, Debug)]
pub struct FarLight {
    pub position: Vec3,
    /// Colour x intensity.
    pub color: Vec3,
    /// Kc, Kl, Kq.
    pub atten: Vec3,
    /// The cutoff radius.
    pub radius: f32,
}

impl FarLight {
    fn attenuation(&self, d: f32) -> f32 {
        let a = self.atten;
        1.0 / (a.x + a.y * d + a.z * d * d)
    }

    /// 1 - near weight at distance `d` (glsl near_weight), the near part
    /// ending at `near_scale` x the radius.
    pub fn far_weight(&self, d: f32, near_scale: f32) -> f32 {
        if self.radius <= 0.0 {
            return 1.0;
        }
        let outer = near_scale * self.radius;
        smoothstep(NEAR_INNER * outer, outer, d)
    }

    /// The far radiance at `p` (what its diffuse light is on a surface
    /// facing it) and the unit direction to the light.
    pub fn far_radiance(&self, p: Vec3, near_scale: f32) -> (Vec3, Vec3) {
        let to = self.position - p;
        let d = to.length();
        let w = self.far_weight(d, near_scale);
        (
            self.color * self.attenuation(d.max(0.01)) * w,
            to / d.max(1e-20),
        )
    }
}

/// The nine real spherical harmonics of bands 0 to 2 at unit direction `n`.
pub fn basis(n: Vec3) -> [f32; 9] {
    [
        0.282_095,
        0.488_603 * n.y,
        0.488_603 * n.z,
        0.488_603 * n.x,
        1.092_548 * n.x * n.y,
        1.092_548 * n.y * n.z,
        0.315_392 * (3.0 * n.z * n.z - 1.0),
        1.092_548 * n.x * n.z,
        0.546_274 * (n.x * n.x - n.y * n.y),
    ]
}

/// The clamped cosine's factor for coefficient `j`'s band.
pub fn band_factor(j: usize) -> f32 {
    match j {
        0 => PI,
        1..=3 => 2.0 * PI / 3.0,
        _ => PI / 4.0,
    }
}

/// The far light at `p` projected and convolved: nine RGB coefficients.
pub fn project(lights: &[FarLight], p: Vec3, near_scale: f32) -> [Vec3; 9] {
    let mut c = [Vec3::ZERO; 9];
    for l in lights {
        let (rad, dir) = l.far_radiance(p, near_scale);
        for (cj, y) in c.iter_mut().zip(basis(dir)) {
            *cj += y * rad;
        }
    }
    for (j, cj) in c.iter_mut().enumerate() {
        *cj *= band_factor(j);
    }
    c
}

/// `project`, with band 0 moved so that a surface at `p` facing `n_s` gets
/// its exact far irradiance (as the far pass stores it).
pub fn project_exact_at(lights: &[FarLight], p: Vec3, n_s: Vec3, near_scale: f32) -> [Vec3; 9] {
    let mut c = project(lights, p, near_scale);
    let at = (c.iter().zip(basis(n_s))).fold(Vec3::ZERO, |e, (cj, y)| e + *cj * y);
    c[0] += (exact(lights, p, n_s, near_scale) - at) / basis(n_s)[0];
    c
}

/// The irradiance the coefficients give a surface facing `n`.
pub fn irradiance(c: &[Vec3; 9], n: Vec3) -> Vec3 {
    let e = (c.iter().zip(basis(n))).fold(Vec3::ZERO, |e, (cj, y)| e + *cj * y);
    e.max(Vec3::ZERO)
}

/// The exact far irradiance at `p` facing `n` (point lights, max(N . L, 0)).
pub fn exact(lights: &[FarLight], p: Vec3, n: Vec3, near_scale: f32) -> Vec3 {
    lights.iter().fold(Vec3::ZERO, |e, l| {
        let (rad, dir) = l.far_radiance(p, near_scale);
        e + rad * n.dot(dir).max(0.0)
    })
}

/// The bound on |irradiance(project_exact_at(x_s, n_s), n) - exact(x, n)|
/// (brightest channel) for a pixel x within `rho` of the sample x_s, `off`
/// from it, whose normal n is `turn` = |n - n_s| from the sample's, as the
/// shader computes it (glsl far_sh_bound_terms and far_field_sh_bound),
/// without the RGBA16F rounding and the light sphere's horizon (the shader
/// adds both): per light, min(2/15, turn / 2) c(x_s) for the truncation
/// and 6 c(d_min) / d_min |x - x_s| for the move, d_min = max(inner
/// radius, |light - x_s| - rho).
pub fn bound(
    lights: &[FarLight],
    sample: Vec3,
    off: f32,
    rho: f32,
    near_scale: f32,
    turn: f32,
) -> f32 {
    let mut total = 0.0;
    let mut gradient = 0.0;
    for l in lights {
        let d_s = (l.position - sample).length();
        let a = NEAR_INNER * near_scale * l.radius;
        if d_s + rho <= a {
            continue;
        }
        let (rad, _) = l.far_radiance(sample, near_scale);
        total += rad.max_element();
        let d = a.max(d_s - rho);
        gradient += l.color.max_element() * l.attenuation(d) * 6.0 / d;
    }
    TRUNCATION_RANGE.min(TRUNCATION_SLOPE * turn) * total + gradient * off
}
