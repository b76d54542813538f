//! The sun-sky model against hand-computed values, the paper's own checks
//! (zenith ratio 1, glow round the sun, bluer zenith), and a sweep over view
//! directions, sun elevations and turbidities for the hard cases.

use super::*;
use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};

/// The unit direction at `elevation` above the horizon and `azimuth` round it (radians, y up).
fn dir(elevation: f64, azimuth: f64) -> DVec3 {
    DVec3::new(
        elevation.cos() * azimuth.cos(),
        elevation.sin(),
        elevation.cos() * azimuth.sin(),
    )
}

/// The azimuth every test's sun stands at.
const SUN_AZIMUTH: f64 = 0.7;

fn sky(sun_degrees: f64, t: f64) -> Sky {
    Sky::new(dir(sun_degrees.to_radians(), SUN_AZIMUTH), t).unwrap()
}

fn close(a: f64, b: f64, tolerance: f64) -> bool {
    (a - b).abs() <= tolerance
}

fn largest(c: [f64; 3]) -> f64 {
    c[0].max(c[1]).max(c[2])
}

const TURBIDITIES: [f64; 3] = [TURBIDITY_MIN, 5.0, TURBIDITY_MAX];
const SUN_DEGREES: [f64; 8] = [-10.0, -0.001, 0.0, 0.001, 5.0, 30.0, 60.0, 90.0];

#[test]
fn zenith_values_match_hand_computed_ones() {
    // T = 5, theta_s = pi/4: chi = (4/9 - 5/120) pi/2 = 29 pi / 144 = 0.632682,
    // tan chi = 0.733230; Y_z = (20.2265 - 4.9710) 0.733230 - 1.0775 + 2.4192
    // = 15.2555 x 0.733230 + 1.3417 = 12.52750 kcd/m^2.
    assert!(close(zenith_luminance(5.0, FRAC_PI_4), 12.52750, 1e-5));
    // T = 2, theta_s = 0 (the sun overhead): chi = (4/9 - 1/60) pi = 1.343904,
    // tan chi = 4.331476; Y_z = 3.1196 x 4.331476 + 1.9882 = 15.50067.
    assert!(close(zenith_luminance(2.0, 0.0), 15.50067, 1e-5));
    // T = 3, the sun on the horizon: chi = 0, Y_z = -0.6465 + 2.4192.
    assert!(close(zenith_luminance(3.0, FRAC_PI_2), 1.7727, 1e-12));
    // theta_s = 0 leaves the constant column: x_z = 0.00394 T + 0.25886.
    let [x, y] = zenith_chromaticity(2.0, 0.0);
    assert!(
        close(x, 0.26674, 1e-12) && close(y, 0.27720, 1e-12),
        "{x} {y}"
    );
    // theta_s = 1 sums each row: x rows 0, 0.00666, 0.22435; y rows
    // -0.00018, 0.01119, 0.21948; weighted by T^2 = 4, T = 2, 1.
    let [x, y] = zenith_chromaticity(2.0, 1.0);
    assert!(
        close(x, 0.23767, 1e-12) && close(y, 0.24114, 1e-12),
        "{x} {y}"
    );
    // Sky::new stores the same, for a sun 45 degrees up.
    let s = sky(45.0, 5.0);
    assert!(close(s.theta_s, FRAC_PI_4, 1e-12));
    assert!(close(s.zenith[2], 12.52750, 1e-5), "{:?}", s.zenith);
    // The Perez coefficients are the appendix's lines at T: B of Y at T = 5.
    assert!(close(s.perez[2][1], -0.3554 * 5.0 + 0.4275, 1e-15));
}

#[test]
fn the_zenith_view_gives_the_zenith_values_exactly() {
    for t in TURBIDITIES {
        for sun_degrees in SUN_DEGREES {
            let s = sky(sun_degrees, t);
            let [x_z, y_z, big_y_z] = s.zenith;
            // F(0, theta_s) / F(0, theta_s): the same call, so exactly 1.
            assert_eq!(s.xyY(DVec3::Y), [x_z, y_z, big_y_z * s.fade]);
            // A view of any length is normalised; zero reads as the zenith.
            assert_eq!(s.xyY(DVec3::Y * 3.0), s.xyY(DVec3::Y));
            assert_eq!(s.xyY(DVec3::ZERO), s.xyY(DVec3::Y));
        }
    }
}

#[test]
fn sweep_is_finite_non_negative_and_continuous() {
    // Neighbours 0.01 rad apart (in elevation, and in azimuth) differ in no
    // channel by more than STEP_BOUND x the largest channel of the two. The
    // steepest place is the glow round a low sun at T = 2 (about 5%).
    const STEP: f64 = 0.01;
    const STEP_BOUND: f64 = 0.1;
    for t in TURBIDITIES {
        for sun_degrees in SUN_DEGREES {
            let s = sky(sun_degrees, t);
            // Elevation -0.3 to past the zenith, through exactly 0 (i = 0).
            for i in -30..=158 {
                let e = i as f64 * STEP;
                for j in 0..629 {
                    let a = j as f64 * STEP;
                    let c = s.radiance_rgb(dir(e, a));
                    let [_, y, big_y] = s.xyY(dir(e, a));
                    assert!(c.iter().all(|v| v.is_finite() && *v >= 0.0), "{c:?}");
                    assert!(y > 0.2 && big_y >= 0.0, "T {t} sun {sun_degrees}: y {y}");
                    for n in [dir(e + STEP, a), dir(e, a + STEP)] {
                        let m = s.radiance_rgb(n);
                        let bound = STEP_BOUND * largest(c).max(largest(m));
                        for k in 0..3 {
                            assert!(
                                (c[k] - m[k]).abs() <= bound,
                                "T {t} sun {sun_degrees} e {e} a {a}: {c:?} vs {m:?}"
                            );
                        }
                    }
                }
            }
            // Straight down, the horizon on both sides of the sun, at the sun.
            for v in [
                -DVec3::Y,
                DVec3::X,
                -DVec3::X,
                DVec3::Z,
                -DVec3::Z,
                s.sun,
                -s.sun,
            ] {
                let c = s.radiance_rgb(v);
                assert!(c.iter().all(|v| v.is_finite() && *v >= 0.0), "{v}: {c:?}");
            }
            // Just below the horizon is the horizon.
            let (h, below) = (
                s.radiance_rgb(dir(0.0, 2.0)),
                s.radiance_rgb(dir(-1e-9, 2.0)),
            );
            assert!(
                (0..3).all(|k| close(h[k], below[k], 1e-8 * largest(h))),
                "{h:?}"
            );
        }
    }
}

#[test]
fn the_sun_crosses_the_horizon_smoothly_and_fades_in_twilight() {
    for t in TURBIDITIES {
        let (below, on, above) = (sky(-0.001, t), sky(0.0, t), sky(0.001, t));
        assert_eq!(on.theta_s, FRAC_PI_2);
        assert_eq!(below.theta_s, FRAC_PI_2);
        assert!(on.zenith[2] > 0.0 && on.zenith.iter().all(|v| v.is_finite()));
        for i in -10..=157 {
            for j in 0..63 {
                let v = dir(i as f64 * 0.01, j as f64 * 0.1);
                let c = on.radiance_rgb(v);
                for other in [&below, &above] {
                    let d = other.radiance_rgb(v);
                    // 0.001 degrees is 1.7e-5 rad; the steepest change is
                    // Y_z at T = 10, 26 kcd/m^2 a radian on 0.26: 0.2%.
                    for k in 0..3 {
                        assert!((c[k] - d[k]).abs() <= 3e-3 * largest(c), "{c:?} {d:?}");
                    }
                }
            }
        }
        // Half faded half way through twilight, black at its end and beyond.
        assert!(close(sky(-3.0, t).fade, 0.5, 1e-12));
        for gone in [-6.0, -10.0, -90.0] {
            let s = sky(gone, t);
            assert_eq!(s.fade, 0.0);
            assert_eq!(s.radiance_rgb(DVec3::Y), [0.0; 3]);
            assert_eq!(s.radiance_rgb(dir(0.0, SUN_AZIMUTH)), [0.0; 3]);
        }
        // A sun below the horizon shapes the sky from the horizon at its azimuth.
        let s = sky(-3.0, t);
        assert!((s.sky_sun - dir(0.0, SUN_AZIMUTH)).length() < 1e-12);
    }
}

#[test]
fn brighter_near_the_sun_and_bluer_at_the_zenith() {
    let luminance = |c: [f64; 3]| 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
    for t in TURBIDITIES {
        for sun_degrees in [5.0, 30.0, 60.0] {
            // At the sun's elevation (the same first factor of F, which
            // alone makes a T = 2 horizon 6 times the zenith): 0.1 rad of
            // azimuth beside the sun, and on the far side of the sky.
            let s = sky(sun_degrees, t);
            let e = f64::to_radians(sun_degrees);
            let near = s.radiance_rgb(dir(e, SUN_AZIMUTH + 0.1));
            let opposite = s.radiance_rgb(dir(e, SUN_AZIMUTH + PI));
            assert!(
                luminance(near) > 2.0 * luminance(opposite),
                "T {t} sun {sun_degrees}: {near:?} {opposite:?}"
            );
        }
        // A high sun: the zenith is bluer (b / r) than the horizon, both
        // away from the sun and opposite it.
        let s = sky(60.0, t);
        let blue = |c: [f64; 3]| c[2] / c[0];
        let zenith = blue(s.radiance_rgb(DVec3::Y));
        for a in [SUN_AZIMUTH + FRAC_PI_2, SUN_AZIMUTH + PI] {
            let horizon = blue(s.radiance_rgb(dir(2f64.to_radians(), a)));
            assert!(zenith > horizon, "T {t}: zenith {zenith} horizon {horizon}");
        }
    }
}

#[test]
fn the_range_ends_keep_the_model_positive_and_bounded() {
    // The horizon handling needs every B < 0 (e^(B / cos theta) <= 1), and F
    // stays positive: 1 + A e^B > 0 for the first factor, C > 0 and 1 + E > 0
    // for the second. Coefficients are linear in T; check a fine grid anyway.
    for i in 0..=80 {
        let t = TURBIDITY_MIN + (TURBIDITY_MAX - TURBIDITY_MIN) * i as f64 / 80.0;
        let s = sky(30.0, t);
        for [a, b, c, _, e] in s.perez {
            assert!(b < 0.0 && c > 0.0 && 1.0 + e > 0.0, "T {t}");
            assert!(
                1.0 + a * b.exp() > 0.1,
                "T {t}: 1 + A e^B = {}",
                1.0 + a * b.exp()
            );
        }
        assert!(zenith_luminance(t, FRAC_PI_2) > 0.2, "T {t}");
    }
    // Why the range stops near 2: below 1.643, Y's 1 + A e^B turns negative.
    let y_first_factor = |t: f64| 1.0 + (0.1787 * t - 1.4630) * (-0.3554 * t + 0.4275f64).exp();
    assert!(y_first_factor(1.64) < 0.0 && y_first_factor(1.65) > 0.0);
}

#[test]
fn invalid_inputs_are_refused_by_name() {
    let up = DVec3::Y;
    for t in [1.9, 10.01, 0.0, -3.0, f64::NAN, f64::INFINITY] {
        let e = Sky::new(up, t).unwrap_err();
        assert!(e.contains("turbidity") && e.contains("2..=10"), "{e}");
    }
    assert!(
        Sky::new(DVec3::ZERO, 3.0)
            .unwrap_err()
            .contains("no length")
    );
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let e = Sky::new(DVec3::new(0.0, bad, 1.0), 3.0).unwrap_err();
        assert!(
            e.contains("sun direction") && e.contains("not finite"),
            "{e}"
        );
    }
    // The ends themselves are taken; a sun of any length is normalised.
    assert!(Sky::new(up, TURBIDITY_MIN).is_ok() && Sky::new(up, TURBIDITY_MAX).is_ok());
    assert_eq!(Sky::new(up * 7.0, 3.0).unwrap().sun, up);
}

#[test]
fn d65_white_is_equal_rgb() {
    let c = xyz_to_linear_srgb(xyy_to_xyz([0.3127, 0.3290, 1.0]));
    assert!(c.iter().all(|v| close(*v, 1.0, 1e-3)), "{c:?}");
}

/// glsl/common/preetham.glsl's `preetham_sky` word for word, in f32 from the uniforms.
fn glsl_sky(u: &SkyUniforms, view: glam::Vec3) -> [f32; 3] {
    use glam::Vec3;
    let p = u.perez.map(Vec3::from);
    let sun = Vec3::from(u.sun);
    let perez = |cos_theta: f32, gamma: f32| {
        let cos_gamma = gamma.cos();
        (Vec3::ONE + p[0] * (p[1] / cos_theta).exp())
            * (Vec3::ONE + p[2] * (p[3] * gamma).exp() + p[4] * cos_gamma * cos_gamma)
    };
    let cos_theta = view.y.max(1e-3);
    let gamma = view.dot(sun).clamp(-1.0, 1.0).acos();
    let theta_s = sun.y.clamp(0.0, 1.0).acos();
    let xyy = Vec3::from(u.zenith) * perez(cos_theta, gamma) / perez(1.0, theta_s);
    let y = xyy.y.max(1e-6);
    let xyz = Vec3::new(xyy.x * xyy.z / y, xyy.z, (1.0 - xyy.x - y) * xyy.z / y);
    let rows = XYZ_TO_SRGB.map(|r| Vec3::new(r[0] as f32, r[1] as f32, r[2] as f32));
    rows.map(|r| r.dot(xyz).max(0.0))
}

#[test]
fn the_uniforms_reproduce_the_cpu_sky_in_f32() {
    for t in TURBIDITIES {
        for sun_degrees in SUN_DEGREES {
            let s = sky(sun_degrees, t);
            let u = s.uniforms();
            assert_eq!(
                u.perez[1][2], s.perez[2][1] as f32,
                "u_perez[B].Y is B of Y"
            );
            for i in -10..=157 {
                for j in 0..63 {
                    let v = dir(i as f64 * 0.01, j as f64 * 0.1);
                    let cpu = s.radiance_rgb(v);
                    let gpu = glsl_sky(&u, v.as_vec3());
                    for k in 0..3 {
                        let tolerance = 2e-3 * largest(cpu) + 1e-6;
                        assert!(
                            (cpu[k] - gpu[k] as f64).abs() <= tolerance,
                            "T {t} sun {sun_degrees} {v}: {cpu:?} vs {gpu:?}"
                        );
                    }
                }
            }
        }
    }
}
