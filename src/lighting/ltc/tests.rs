use super::*;
use crate::lighting::area_light::{monte_carlo_specular, polygon_irradiance};

/// A 1 x 1 light 1 above the origin, facing down.
fn ceiling() -> QuadLight {
    QuadLight::rectangle(
        DVec3::new(0.0, 1.0, 0.0),
        DVec3::NEG_Y,
        DVec3::Z,
        (1.0, 1.0),
    )
}

/// A 2 x 1 light standing upright at z = -1.5, facing +z, its lower edge
/// 0.25 below the floor's plane y = 0 (it straddles the floor's horizon).
fn wall() -> QuadLight {
    QuadLight::rectangle(DVec3::new(0.3, 0.25, -1.5), DVec3::Z, DVec3::Y, (2.0, 1.0))
}

/// The eye direction at `deg` degrees from the normal +y, tilted toward +z.
fn view(deg: f64) -> DVec3 {
    let t = deg.to_radians();
    DVec3::new(0.0, t.cos(), t.sin())
}

#[test]
fn the_tables_are_the_papers_fit() {
    // 64 x 64 texels each; at normal incidence the fit is isotropic
    // (m00 = m22 / alpha-ish, m02 = m20 = 0) and the magnitude is the
    // directional albedo, 1 for the smoothest lobe seen head-on.
    assert_eq!(ltc_1().len(), LTC_SIZE * LTC_SIZE);
    assert_eq!(ltc_2().len(), LTC_SIZE * LTC_SIZE);
    for a in 0..LTC_SIZE {
        let t = ltc_1()[a];
        assert!(t[1].abs() < 1e-6 && t[2].abs() < 1e-6, "{a}: {t:?}");
    }
    assert!((ltc_2()[1][0] - 1.0).abs() < 1e-6);
    // The magnitude is the directional albedo with F = 1, the Fresnel term
    // the same with F = (1 - v.h)^5: against gloss's own BRDF (its D and G)
    // by quadrature, across the table. This is where gloss's D and G are
    // shown to be the fit's.
    let mut worst: f64 = 0.0;
    for alpha in [0.05, 0.25, 0.5, 1.0] {
        for deg in [0.0, 30.0, 60.0, 80.0] {
            let t = f64::to_radians(deg);
            let v = DVec3::new(t.sin(), 0.0, t.cos());
            let t2 = bilinear(ltc_2(), table_coords(alpha, v.z));
            let albedo = crate::lighting::microfacet::albedo_with(v, alpha, 1.0, 256, |_| 1.0);
            let schlick =
                crate::lighting::microfacet::albedo_with(v, alpha, 1.0, 256, |c| (1.0 - c).powi(5));
            eprintln!(
                "alpha {alpha} view {deg}: magnitude {:.4} against {albedo:.4}, fresnel {:.4} against {schlick:.4}",
                t2[0], t2[1]
            );
            worst = worst
                .max((t2[0] - albedo).abs())
                .max((t2[1] - schlick).abs());
        }
    }
    assert!(worst < 0.02, "worst table difference {worst}");
}

#[test]
fn the_diffuse_term_is_the_exact_polygon_integral() {
    let cases = [
        (DVec3::ZERO, DVec3::Y),
        (
            DVec3::new(0.4, 0.0, -0.2),
            DVec3::new(0.3, 1.0, 0.1).normalize(),
        ),
        (DVec3::new(0.0, 0.5, 0.0), DVec3::X),
        (DVec3::new(2.5, 0.0, 0.0), DVec3::Y),
        (DVec3::new(0.0, 0.5, 0.0), DVec3::NEG_Y),
        (DVec3::new(0.0, 2.0, 0.0), DVec3::NEG_Y),
    ];
    for light in [ceiling(), wall()] {
        for (p, n) in cases {
            let exact = polygon_irradiance(p, n, &light) / PI;
            let ff = diffuse_form_factor(p, n, &light, false);
            assert!((ff - exact).abs() < 1e-12, "{p} {n}: {ff} against {exact}");
        }
    }
    // Two-sided: seen from behind, the light reversed.
    let light = ceiling();
    let (p, n) = (DVec3::new(0.1, 2.0, 0.0), DVec3::NEG_Y);
    let mut reversed = light;
    reversed.corners.reverse();
    let behind = polygon_irradiance(p, n, &reversed) / PI;
    assert!(behind > 0.05);
    assert_eq!(diffuse_form_factor(p, n, &light, false), 0.0);
    assert!((diffuse_form_factor(p, n, &light, true) - behind).abs() < 1e-12);
}

/// The measured LTC error against gloss's own BRDF integrated by Monte
/// Carlo, over smooth to rough, head-on to grazing, a light overhead, one
/// straddling the horizon and one in the mirror direction. The error is
/// given relative to the Monte Carlo value and relative to the light's
/// larger of it and the light's diffuse form factor (what a white
/// Lambertian surface gets from it, which the eye compares a dim highlight
/// with). Beside it the fit's own error (F ~ 1 on both sides, eta 1e3):
/// at grazing angles most of the error is the table's one Fresnel average
/// for the whole lobe. Prints the table the docs page quotes; the bounds
/// are the measured worst cases, rounded up.
#[test]
fn ltc_specular_against_monte_carlo_of_glosss_brdf() {
    let p = DVec3::new(0.2, 0.0, 0.3);
    // Worst relative errors: facing lights (ceiling, mirror direction) up
    // to 45 degrees; the wall straddling the horizon up to 45; any at 80
    // (relative to the larger of the value and the form factor).
    let (mut facing, mut straddling, mut grazing): (f64, f64, f64) = (0.0, 0.0, 0.0);
    for alpha in [0.1, 0.3, 0.6, 1.0] {
        for deg in [0.0, 45.0, 80.0] {
            let v = view(deg);
            let r = DVec3::new(0.0, v.y, -v.z);
            let mirror = QuadLight::rectangle(p + 2.0 * r, -r, DVec3::X, (1.0, 1.0));
            for (name, light) in [("ceiling", ceiling()), ("wall", wall()), ("mirror", mirror)] {
                let ltc = ltc_specular(p, DVec3::Y, v, &light, (alpha, 1.5), false);
                let (mc, se) = monte_carlo_specular(p, DVec3::Y, v, &light, (alpha, 1.5), 300, 11);
                // The fit alone: F ~ 1 (eta 1e3) on both sides.
                let fit = ltc_specular(p, DVec3::Y, v, &light, (alpha, 1e3), false);
                let (mc_fit, _) =
                    monte_carlo_specular(p, DVec3::Y, v, &light, (alpha, 1e3), 300, 11);
                let ff = diffuse_form_factor(p, DVec3::Y, &light, false);
                let rel = (ltc - mc).abs() / mc;
                let of_larger = (ltc - mc).abs() / mc.max(ff);
                eprintln!(
                    "| {name} | {alpha} | {deg} | {ltc:.5} | {mc:.5} +- {se:.1e} | {:+.1} % | {:+.1} % |",
                    100.0 * (ltc - mc) / mc,
                    100.0 * (fit - mc_fit) / mc_fit,
                );
                assert!(se < 0.02 * mc + 1e-6, "{name} {alpha} {deg}: {mc} {se}");
                match (name, deg < 60.0) {
                    (_, false) => grazing = grazing.max(of_larger),
                    ("wall", true) => straddling = straddling.max(rel),
                    _ => facing = facing.max(rel),
                }
            }
        }
    }
    eprintln!(
        "worst: facing {:.1} %, straddling the horizon {:.1} %, grazing {:.1} % of max(value, form factor)",
        100.0 * facing,
        100.0 * straddling,
        100.0 * grazing
    );
    assert!(facing < 0.20, "facing: {facing}");
    assert!(straddling < 0.60, "straddling: {straddling}");
    assert!(grazing < 0.80, "grazing: {grazing}");
}

#[test]
fn nothing_from_a_light_behind_the_surface_or_seen_from_behind() {
    let v = view(30.0);
    // Below the floor: the light's whole quad under the horizon.
    let below = QuadLight::rectangle(DVec3::new(0.0, -1.0, 0.0), DVec3::Y, DVec3::Z, (1.0, 1.0));
    assert_eq!(
        ltc_specular(DVec3::ZERO, DVec3::Y, v, &below, (0.3, 1.5), false),
        0.0
    );
    assert_eq!(
        ltc_specular(DVec3::ZERO, DVec3::Y, v, &below, (0.3, 1.5), true),
        0.0
    );
    // Above, but facing up: its back is toward the floor.
    let up = QuadLight::rectangle(DVec3::new(0.0, 1.0, 0.0), DVec3::Y, DVec3::Z, (1.0, 1.0));
    assert_eq!(
        ltc_specular(DVec3::ZERO, DVec3::Y, v, &up, (0.3, 1.5), false),
        0.0
    );
    let two = ltc_specular(DVec3::ZERO, DVec3::Y, v, &up, (0.3, 1.5), true);
    let front = ltc_specular(DVec3::ZERO, DVec3::Y, v, &ceiling(), (0.3, 1.5), false);
    assert!((two - front).abs() < 1e-12 * front, "{two} {front}");
}

#[test]
fn a_light_sinking_through_the_horizon_fades_continuously() {
    // The wall light lowered in steps of 1 mm through the floor's plane:
    // no jump bigger than the steps around it make.
    let v = view(60.0);
    let p = DVec3::new(0.0, 0.0, 0.5);
    let mut last: Option<f64> = None;
    for i in 0..=1500 {
        let y = 0.75 - 0.001 * f64::from(i);
        let light = QuadLight::rectangle(DVec3::new(0.3, y, -1.5), DVec3::Z, DVec3::Y, (2.0, 1.0));
        let s = ltc_specular(p, DVec3::Y, v, &light, (0.3, 1.5), false);
        let d = diffuse_form_factor(p, DVec3::Y, &light, false);
        assert!(s.is_finite() && d.is_finite() && s >= 0.0 && d >= 0.0);
        if let Some(prev) = last {
            assert!(
                (s + d - prev).abs() < 2e-3,
                "at y = {y}: {prev} then {}",
                s + d
            );
        }
        last = Some(s + d);
        if y < -0.5 {
            assert_eq!(s + d, 0.0, "at y = {y}");
        }
    }
}
