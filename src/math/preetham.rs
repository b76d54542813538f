//! The sun-sky model of notes 03, Sun Sky: A. J. Preetham, P. Shirley and
//! B. Smits, "A Practical Analytic Model for Daylight" (SIGGRAPH 1999), on
//! the CPU in f64. glsl/common/preetham.glsl is its GPU twin; `Sky::uniforms`
//! gives the values that file's uniforms take.
//!
//! The model gives the sky's colour in a view direction as CIE xyY: a
//! luminance Y in kcd/m^2 and a chromaticity (x, y). Each of the three is its
//! value at the zenith times a ratio of Perez's sky distribution F:
//!
//!   F(theta, gamma) = (1 + A e^(B / cos theta)) (1 + C e^(D gamma) + E cos^2 gamma)   (paper eq. 3)
//!   Y = Y_z F(theta, gamma) / F(0, theta_s), and alike for x and y                    (paper eq. 4)
//!
//! theta is the view's angle from the zenith, gamma its angle from the sun and
//! theta_s the sun's angle from the zenith. The first factor shapes the sky
//! from zenith to horizon, the second is the glow around the sun. A..E and
//! the zenith values depend only on the turbidity T (how hazy the air is: 2
//! a clear sky, 10 a hazy one) and on theta_s, through the fits of the
//! paper's Appendix A.2, so `Sky::new` computes them once per sun position
//! and a view direction costs the ratio above. xyY then goes to CIE XYZ and
//! to linear sRGB.
//!
//! Where the formulas break, and what this module does there:
//! * At and below the horizon, cos theta <= 0. Every B is negative (for T in
//!   range), so e^(B / cos theta) -> 0 as cos theta -> 0+, but it divides by
//!   zero at the horizon and overflows below it. cos theta is clamped to
//!   `HORIZON_COS` and gamma is kept: below the horizon the sky repeats its
//!   horizon, finite and continuous; a ground drawn over it hides it.
//! * The sun at the horizon: theta_s = pi/2 gives chi = 0 in Y_z's formula,
//!   so Y_z = 2.4192 - 0.2155 T > 0. The fits know no twilight: below the
//!   horizon chi < 0 and Y_z turns negative within a degree at T = 10. The
//!   sky of a sun below the horizon is the sky of a sun on the horizon at
//!   the same azimuth, faded to black (smoothstep) over `TWILIGHT`.
//! * Turbidity outside `TURBIDITY_MIN..=TURBIDITY_MAX`, 2..=10, the range
//!   the paper fits, is refused. Below it the fits are extrapolated and the
//!   normaliser F(0, theta_s) shrinks towards 0: it holds the factor
//!   1 + A e^B of Y, which is 0.17 at T = 2, 0.03 at 1.7 and negative
//!   below 1.643. At 1.7 a setting sun's glow on the horizon would reach
//!   about 420 kcd/m^2 (68 at T = 2, 8 at T = 5).

use glam::DVec3;

/// The least turbidity `Sky::new` takes: where the paper's fit starts.
pub const TURBIDITY_MIN: f64 = 2.0;
/// The greatest turbidity `Sky::new` takes (the paper's fit ends at 10).
pub const TURBIDITY_MAX: f64 = 10.0;
/// cos theta never goes below this: e^(B / HORIZON_COS) is below 1e-57 for
/// every B in range, so the horizon has its limiting value, and below the
/// horizon the sky repeats it.
pub const HORIZON_COS: f64 = 1e-3;
/// How far below the horizon (radians; 6 degrees, civil twilight) the sun
/// may go before the sky is black.
pub const TWILIGHT: f64 = 6.0 * std::f64::consts::PI / 180.0;
/// `radiance_rgb`'s luminance per kcd/m^2 of the model's Y: 1.0 is 10 kcd/m^2,
/// so a clear zenith (T = 2.5) at a 30-degree sun is about 0.4, and the sky
/// next to a high sun in a hazy sky up to about 60.
pub const Y_SCALE: f64 = 0.1;

/// The paper's Appendix A.2: the Perez coefficients A..E of x, y and Y,
/// each linear in the turbidity: (slope, intercept) for slope T + intercept.
#[rustfmt::skip]
const PEREZ_FIT: [[(f64, f64); 5]; 3] = [
    // A                  B                   C                   D                   E
    [(-0.0193, -0.2592), (-0.0665, 0.0008), (-0.0004, 0.2125), (-0.0641, -0.8989), (-0.0033, 0.0452)], // x
    [(-0.0167, -0.2608), (-0.0950, 0.0092), (-0.0079, 0.2102), (-0.0441, -1.6537), (-0.0109, 0.0529)], // y
    [( 0.1787, -1.4630), (-0.3554, 0.4275), (-0.0227, 5.3251), ( 0.1206, -2.5771), (-0.0670, 0.3703)], // Y
];

/// The paper's Appendix A.2 zenith chromaticity:
/// x_z = [T^2 T 1] ZENITH_X [theta_s^3 theta_s^2 theta_s 1]^T, y_z alike.
#[rustfmt::skip]
const ZENITH_X: [[f64; 4]; 3] = [
    [ 0.00166, -0.00375,  0.00209, 0.0    ],
    [-0.02903,  0.06377, -0.03202, 0.00394],
    [ 0.11693, -0.21196,  0.06052, 0.25886],
];
#[rustfmt::skip]
const ZENITH_Y: [[f64; 4]; 3] = [
    [ 0.00275, -0.00610,  0.00317, 0.0    ],
    [-0.04214,  0.08970, -0.04153, 0.00516],
    [ 0.15346, -0.26756,  0.06670, 0.26688],
];

/// CIE XYZ to linear sRGB (Rec. 709 primaries, D65 white), the matrix of
/// IEC 61966-2-1:1999 (the sRGB standard), rows R, G, B.
#[rustfmt::skip]
pub const XYZ_TO_SRGB: [[f64; 3]; 3] = [
    [ 3.2406, -1.5372, -0.4986],
    [-0.9689,  1.8758,  0.0415],
    [ 0.0557, -0.2040,  1.0570],
];

/// A sun-sky: the turbidity, the sun and what the model precomputes from them.
/// Built by `Sky::new`; the fields are public to read.
#[derive(Clone, Debug, PartialEq)]
pub struct Sky {
    /// T, in `TURBIDITY_MIN..=TURBIDITY_MAX`.
    pub turbidity: f64,
    /// The unit direction to the sun as given (y up).
    pub sun: DVec3,
    /// The unit direction the sky's shape uses: `sun`, or for a sun below
    /// the horizon the horizon direction at its azimuth.
    pub sky_sun: DVec3,
    /// theta_s of `sky_sun`, in [0, pi/2].
    pub theta_s: f64,
    /// 1 for a sun at or above the horizon, falling to 0 at `TWILIGHT` below
    /// (smoothstep in the sun's elevation).
    pub fade: f64,
    /// A..E for x, y and Y: `perez[channel][coefficient]`, channel 0 x, 1 y, 2 Y.
    pub perez: [[f64; 5]; 3],
    /// The zenith's x_z, y_z and Y_z (kcd/m^2, before the fade).
    pub zenith: [f64; 3],
}

/// The values glsl/common/preetham.glsl's uniforms take, in its order.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SkyUniforms {
    /// `u_perez[i]`: coefficient i (A..E) for (x, y, Y).
    pub perez: [[f32; 3]; 5],
    /// `u_zenith`: (x_z, y_z, Y_z x `Y_SCALE` x fade).
    pub zenith: [f32; 3],
    /// `u_sun`: `Sky::sky_sun`.
    pub sun: [f32; 3],
}

impl Sky {
    /// The sky for the direction to the sun `sun` (any length, y up) and
    /// turbidity `turbidity`. Refuses a zero or non-finite sun and a
    /// turbidity outside `TURBIDITY_MIN..=TURBIDITY_MAX`.
    pub fn new(sun: DVec3, turbidity: f64) -> Result<Sky, String> {
        if !sun.is_finite() {
            return Err(format!("sun direction {sun} is not finite"));
        }
        let Some(sun) = sun.try_normalize() else {
            return Err(format!("sun direction {sun} has no length"));
        };
        if !(TURBIDITY_MIN..=TURBIDITY_MAX).contains(&turbidity) {
            return Err(format!(
                "turbidity {turbidity} is outside {TURBIDITY_MIN}..={TURBIDITY_MAX}, \
                 the range the Preetham model is valid in"
            ));
        }
        let t = turbidity;
        // The sun below the horizon: its colour is that of the sun on the
        // horizon at its azimuth (straight down has none: any will do, the
        // fade is 0 there).
        let sky_sun = if sun.y >= 0.0 {
            sun
        } else {
            DVec3::new(sun.x, 0.0, sun.z)
                .try_normalize()
                .unwrap_or(DVec3::X)
        };
        // sky_sun.y is in [0, 1]: theta_s in [0, pi/2], exactly pi/2 on the horizon.
        let theta_s = sky_sun.y.clamp(0.0, 1.0).acos();
        let s = ((sun.y.clamp(-1.0, 1.0).asin() + TWILIGHT) / TWILIGHT).clamp(0.0, 1.0);
        let fade = s * s * (3.0 - 2.0 * s);
        let perez = PEREZ_FIT.map(|channel| channel.map(|(slope, c)| slope * t + c));
        let [x_z, y_z] = zenith_chromaticity(t, theta_s);
        Ok(Sky {
            turbidity,
            sun,
            sky_sun,
            theta_s,
            fade,
            perez,
            zenith: [x_z, y_z, zenith_luminance(t, theta_s)],
        })
    }

    /// The sky's CIE xyY in direction `view` (any length, y up; zero reads
    /// as the zenith): chromaticity x, y and luminance Y in kcd/m^2, times
    /// the fade. At the zenith it is exactly (x_z, y_z, Y_z x fade).
    #[allow(non_snake_case)]
    pub fn xyY(&self, view: DVec3) -> [f64; 3] {
        let view = view.try_normalize().unwrap_or(DVec3::Y);
        let cos_theta = view.y.max(HORIZON_COS);
        let gamma = view.dot(self.sky_sun).clamp(-1.0, 1.0).acos();
        // value = value_zenith F(theta, gamma) / F(0, theta_s) (paper eq. 4).
        let ratio = |c: usize| {
            perez(self.perez[c], cos_theta, gamma) / perez(self.perez[c], 1.0, self.theta_s)
        };
        [
            self.zenith[0] * ratio(0),
            self.zenith[1] * ratio(1),
            self.zenith[2] * ratio(2) * self.fade,
        ]
    }

    /// The sky's linear sRGB radiance in direction `view`: `xyY` with Y
    /// times `Y_SCALE`, to XYZ and through `XYZ_TO_SRGB`. A colour outside
    /// the sRGB gamut has its negative channels clamped to 0: that happens
    /// only to the yellow glow round a low sun at T near 2, and takes off
    /// under 3% of the largest channel.
    pub fn radiance_rgb(&self, view: DVec3) -> [f64; 3] {
        let [x, y, big_y] = self.xyY(view);
        let xyz = xyy_to_xyz([x, y, big_y * Y_SCALE]);
        xyz_to_linear_srgb(xyz).map(|c| c.max(0.0))
    }

    /// The values of glsl/common/preetham.glsl's uniforms for this sky:
    /// the Perez coefficients by coefficient, the zenith with Y already
    /// scaled and faded, and the sun the sky's shape uses.
    pub fn uniforms(&self) -> SkyUniforms {
        let p = &self.perez;
        let [x_z, y_z, big_y_z] = self.zenith;
        SkyUniforms {
            perez: std::array::from_fn(|i| [p[0][i] as f32, p[1][i] as f32, p[2][i] as f32]),
            zenith: [
                x_z as f32,
                y_z as f32,
                (big_y_z * Y_SCALE * self.fade) as f32,
            ],
            sun: self.sky_sun.as_vec3().to_array(),
        }
    }
}

/// Perez's F(theta, gamma) (paper eq. 3) for coefficients [A, B, C, D, E],
/// with theta given by its cosine. The caller keeps cos_theta > 0.
pub fn perez([a, b, c, d, e]: [f64; 5], cos_theta: f64, gamma: f64) -> f64 {
    let cos_gamma = gamma.cos();
    (1.0 + a * (b / cos_theta).exp()) * (1.0 + c * (d * gamma).exp() + e * cos_gamma * cos_gamma)
}

/// The zenith luminance Y_z in kcd/m^2 (paper Appendix A.2):
/// (4.0453 T - 4.9710) tan chi - 0.2155 T + 2.4192, chi = (4/9 - T/120)(pi - 2 theta_s).
/// For theta_s in [0, pi/2] and T in range, chi is in [0, 1.344]: below
/// pi/2, so tan chi is finite.
pub fn zenith_luminance(t: f64, theta_s: f64) -> f64 {
    let chi = (4.0 / 9.0 - t / 120.0) * (std::f64::consts::PI - 2.0 * theta_s);
    (4.0453 * t - 4.9710) * chi.tan() - 0.2155 * t + 2.4192
}

/// The zenith chromaticity [x_z, y_z] (paper Appendix A.2): cubics in
/// theta_s weighted by T^2, T and 1.
pub fn zenith_chromaticity(t: f64, theta_s: f64) -> [f64; 2] {
    let ts = [theta_s.powi(3), theta_s.powi(2), theta_s, 1.0];
    let tt = [t * t, t, 1.0];
    let poly = |m: &[[f64; 4]; 3]| -> f64 {
        (0..3)
            .map(|i| tt[i] * (0..4).map(|j| m[i][j] * ts[j]).sum::<f64>())
            .sum()
    };
    [poly(&ZENITH_X), poly(&ZENITH_Y)]
}

/// CIE xyY to XYZ: X = x Y / y, Z = (1 - x - y) Y / y. y is kept from 0
/// (the sky's y stays above 0.2; the guard only keeps a bad input finite).
pub fn xyy_to_xyz([x, y, big_y]: [f64; 3]) -> [f64; 3] {
    let y = y.max(1e-6);
    [x * big_y / y, big_y, (1.0 - x - y) * big_y / y]
}

/// CIE XYZ to linear sRGB through `XYZ_TO_SRGB` (no clamping).
pub fn xyz_to_linear_srgb(xyz: [f64; 3]) -> [f64; 3] {
    XYZ_TO_SRGB.map(|row| row[0] * xyz[0] + row[1] * xyz[1] + row[2] * xyz[2])
}

#[cfg(test)]
mod tests;
