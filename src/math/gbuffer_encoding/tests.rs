//! Unit tests for the G-buffer material encoding of notes 03, Geometry Pass.

use super::*;

/// Samples per measured range, as in the module docs' tables.
const SAMPLES: usize = 100_001;
/// Half a UNORM8 step: the most RGBA8 moves a stored value in [0, 1].
const D8: f64 = 1.0 / 510.0;
/// The unit roundoff of half floats, 2^-11: a normal s moves by at most U16 s.
const U16: f64 = 1.0 / 2048.0;
/// The unit roundoff of single floats, 2^-24.
const U32: f64 = 1.0 / 16_777_216.0;

fn profile(range: ValueRange, format: Format, scheme: Scheme) -> ErrorProfile {
    relative_error_profile(range, format, scheme, SAMPLES).unwrap()
}

/// The derived bound on the report's scheme. The format moves the stored s
/// to s' with |s' - s| <= d (RGBA8: d = 1/510) or <= u s (floats).
/// v <= 1 (s = v): the error is |s' - s| / max(s, floor) <= d / max(s, floor)
/// or u. v > 1 (s = 1 / v): |1/s' - 1/s| / (1/s) = |s - s'| / s' <= d / (s - d)
/// or u / (1 - u), largest at the smallest s, 1 / hi; infinite when
/// 1 / hi <= d, where s can round to 0.
fn report_bound(q: Quantity, format: Format) -> f64 {
    let r = q.range();
    let below = r.lo.max(r.floor).min(1.0); // the smallest s counted, v <= 1
    let flipped = 1.0 / r.hi; // the smallest s, v > 1
    let bound = match format {
        Format::Rgba8 if flipped <= D8 => f64::INFINITY,
        Format::Rgba8 => (D8 / below).max(D8 / (flipped - D8)),
        Format::Rgba16F => U16 / (1.0 - U16),
        Format::Rgba32F => U32 / (1.0 - U32),
    };
    bound * (1.0 + 1e-9)
}

/// The derived bound on a log scale. The format moves s by at most d:
/// 1/510 (RGBA8), 2^-12 (half a half-float step in [1/2, 1], the coarsest
/// part of [0, 1]), 2^-25 (single). Then v' + c = (v + c) 2^(e R) with
/// |e| <= d, so |v' - v| <= (v + c)(2^(d R) - 1), and divided by
/// max(v, floor) that is at most (1 + c / floor)(2^(d R) - 1) (c = 0: the
/// factor is 1).
fn log_bound(q: Quantity, format: Format) -> f64 {
    let scale = q.log_scale();
    let d = match format {
        Format::Rgba8 => D8,
        Format::Rgba16F => 1.0 / 4096.0,
        Format::Rgba32F => 1.0 / 33_554_432.0,
    };
    let floor = q.range().floor;
    let factor = if scale.offset() == 0.0 {
        1.0
    } else {
        1.0 + scale.offset() / floor
    };
    factor * ((d * scale.octaves()).exp2() - 1.0) * (1.0 + 1e-9)
}

#[test]
fn report_round_trip_is_exact_in_f64_at_the_ends_and_around_1() {
    let one_up = f64::next_up(1.0);
    let one_down = f64::next_down(1.0);
    for v in [1e-3, 1e3, 1.0, 4.0, 0.0, 10.0, one_up, one_down, 0.5, 2.0] {
        let (s, convert) = encode_report(v);
        assert!((0.0..=1.0).contains(&s), "{v}: stored {s}");
        assert_eq!(decode_report(s, convert), v, "{v}");
    }
    // Elsewhere 1 / (1 / v) is v to one ulp, not always exactly.
    let v = 1.436563;
    let back = decode_report(encode_report(v).0, true);
    assert_ne!(back, v);
    assert!((back - v).abs() <= v * f64::EPSILON, "{back}");
    for i in 0..=10_000 {
        let v = 1.0 + 999.0 * i as f64 / 10_000.0;
        let (s, c) = encode_report(v);
        assert!((decode_report(s, c) - v).abs() <= v * f64::EPSILON, "{v}");
    }
}

#[test]
fn log_scale_round_trip_in_f64_is_exact_at_the_ends() {
    for q in Quantity::ALL {
        let scale = q.log_scale();
        assert_eq!(scale.encode(scale.lo()), 0.0);
        assert_eq!(scale.encode(scale.hi()), 1.0);
        assert_eq!(scale.decode(0.0), scale.lo());
        assert_eq!(scale.decode(1.0), scale.hi());
        for v in [
            scale.lo(),
            scale.hi(),
            1.0,
            f64::next_up(1.0),
            f64::next_down(1.0),
            2.5,
        ] {
            let v = v.clamp(scale.lo(), scale.hi());
            let back = scale.decode(scale.encode(v));
            assert!((back - v).abs() <= 1e-14 * v.max(1e-3), "{q:?} {v}: {back}");
        }
    }
    // No flag, and s grows with v.
    let alpha = Quantity::Alpha.log_scale();
    assert!(!encode(5.0, Scheme::Log(alpha)).1);
    assert!(alpha.encode(0.999) < alpha.encode(1.0) && alpha.encode(1.0) < alpha.encode(1.001));
    assert!((alpha.encode(1.0) - 0.5).abs() < 1e-15);
}

#[test]
fn the_flag_is_set_exactly_above_1() {
    assert_eq!(encode_report(1.0), (1.0, false));
    assert!(!encode_report(f64::next_down(1.0)).1);
    assert!(encode_report(f64::next_up(1.0)).1);
    assert_eq!(encode_report(0.0), (0.0, false));
    assert_eq!(encode_report(1e3), (1e-3, true));
    for i in 0..=6000 {
        let v = 10f64.powf(-3.0 + i as f64 / 1000.0);
        let (s, convert) = encode_report(v);
        assert_eq!(convert, v > 1.0, "{v}");
        assert!((0.0..=1.0).contains(&s), "{v}: {s}");
    }
}

#[test]
fn report_triple_uses_one_gconvert_channel_per_flag() {
    let m = [0.25, 1.5, 10.0];
    let t = encode_report_triple(m);
    assert_eq!(t.g_alpha, [0.25, 1.0 / 1.5, 0.1]);
    assert_eq!(t.g_convert, [0.0, 1.0, 1.0]);
    assert_eq!(decode_report_triple(&t), m);
    for format in Format::ALL {
        let q = t.quantised(format);
        assert_eq!(q.g_convert, t.g_convert, "{format:?}: flags are exact");
        let back = decode_report_triple(&q);
        for (i, quantity) in Quantity::ALL.into_iter().enumerate() {
            let err = (back[i] - m[i]).abs() / m[i];
            assert!(
                err <= report_bound(quantity, format),
                "{format:?} {quantity:?}: {err}"
            );
        }
    }
    // The log triple: three channels, no flags, and near at RGBA8.
    let s = encode_log_triple(m).map(quantise_unorm8);
    let back = decode_log_triple(s);
    for (i, quantity) in Quantity::ALL.into_iter().enumerate() {
        let err = (back[i] - m[i]).abs() / m[i];
        assert!(
            err <= log_bound(quantity, Format::Rgba8),
            "{quantity:?}: {err}"
        );
    }
}

#[test]
fn packed_flags_survive_every_format() {
    for bits in 0..8u32 {
        let flags: [bool; 3] = std::array::from_fn(|i| bits & (1 << i) != 0);
        let w = pack_flags(flags);
        assert_eq!(w, bits as f64 / 7.0);
        for format in Format::ALL {
            assert_eq!(unpack_flags(format.quantise(w)), flags, "{bits} {format:?}");
        }
    }
    assert_eq!(unpack_flags(f64::NAN), [false; 3]);
    assert_eq!(unpack_flags(-1.0), [false; 3]);
    assert_eq!(unpack_flags(3.0), [true; 3]);
}

#[test]
fn each_format_stays_within_its_derived_bound() {
    for q in Quantity::ALL {
        for format in Format::ALL {
            let report = profile(q.range(), format, Scheme::Report);
            let bound = report_bound(q, format);
            assert!(
                report.max <= bound,
                "report {q:?} {format:?}: {report:?} > {bound}"
            );
            let log = profile(q.range(), format, Scheme::Log(q.log_scale()));
            let log_max = log_bound(q, format);
            assert!(
                log.max <= log_max,
                "log {q:?} {format:?}: {log:?} > {log_max}"
            );
            // The bounds are reached (to 10 %): the sampling finds the worst.
            assert!(log.max >= 0.9 * log_max, "log {q:?} {format:?}: {log:?}");
            if bound.is_finite() {
                assert!(
                    report.max >= 0.9 * bound,
                    "report {q:?} {format:?}: {report:?}"
                );
            }
        }
    }
    // RGBA8 is infinite for alpha: alpha > 510 stores 1 / alpha < 1/510,
    // which rounds to 0 and decodes to 1 / 0 (510 itself is a tie, rounded
    // up to 1/255: it comes back as 255).
    let alpha8 = profile(Quantity::Alpha.range(), Format::Rgba8, Scheme::Report);
    assert_eq!(alpha8.max, f64::INFINITY);
    assert_eq!(
        round_trip(511.0, Format::Rgba8, Scheme::Report),
        f64::INFINITY
    );
    assert_eq!(round_trip(510.0, Format::Rgba8, Scheme::Report), 255.0);
    // And alpha below 1/510 decodes as 0.
    assert_eq!(round_trip(1.9e-3, Format::Rgba8, Scheme::Report), 0.0);
    // The figures of the module docs, to the digits given there.
    let close = |a: f64, b: f64| (a - b).abs() <= 0.005 * b;
    let at = |q: Quantity, f, s| profile(q.range(), f, s).max;
    let log = |q: Quantity| Scheme::Log(q.log_scale());
    assert!(close(
        at(Quantity::Alpha, Format::Rgba8, log(Quantity::Alpha)),
        2.75e-2
    ));
    assert!(close(
        at(Quantity::Eta, Format::Rgba8, Scheme::Report),
        7.80e-3
    ));
    assert!(close(
        at(Quantity::Eta, Format::Rgba8, log(Quantity::Eta)),
        2.72e-3
    ));
    assert!(close(
        at(Quantity::Ks, Format::Rgba8, Scheme::Report),
        1.96e-1
    ));
    assert!(close(
        at(Quantity::Ks, Format::Rgba8, log(Quantity::Ks)),
        2.00e-2
    ));
    assert!(close(
        at(Quantity::Alpha, Format::Rgba16F, Scheme::Report),
        4.85e-4
    ));
    assert!(close(
        at(Quantity::Alpha, Format::Rgba16F, log(Quantity::Alpha)),
        3.38e-3
    ));
}

/// The max error over each decade (or octave) of `range`'s log-spaced part.
fn piecewise_max(range: ValueRange, pieces: u32, format: Format, scheme: Scheme) -> Vec<f64> {
    let start = range.lo.max(range.floor);
    let ratio = (range.hi / start).powf(1.0 / pieces as f64);
    (0..pieces)
        .map(|k| {
            let lo = start * ratio.powi(k as i32);
            let piece = ValueRange::new(lo, lo * ratio, range.floor);
            relative_error_profile(piece, format, scheme, 20_001)
                .unwrap()
                .max
        })
        .collect()
}

#[test]
fn log_scale_error_is_flat_and_beats_the_report_at_rgba8() {
    let spread = |m: &[f64]| {
        let hi = m.iter().cloned().fold(0.0, f64::max);
        let lo = m.iter().cloned().fold(f64::INFINITY, f64::min);
        hi / lo
    };
    for q in Quantity::ALL {
        let scheme = Scheme::Log(q.log_scale());
        let log = profile(q.range(), Format::Rgba8, scheme);
        let report = profile(q.range(), Format::Rgba8, Scheme::Report);
        assert!(log.max < report.max, "{q:?}: {log:?} {report:?}");
        assert!(log.mean < report.mean, "{q:?}: {log:?} {report:?}");
        // Flat: the worst error of every sixth of the range (in log) is
        // within 1.5 of every other's; in fact within 1 % for alpha and eta,
        // and within k_s's factor 1 + c / v <= 1.1 (above its floor).
        let pieces = piecewise_max(q.range(), 6, Format::Rgba8, scheme);
        let flat = if q == Quantity::Ks { 1.11 } else { 1.01 };
        assert!(spread(&pieces) < flat, "{q:?}: {pieces:?}");
        // A flat rounding error is uniform in [0, max], so its mean is about
        // half its max: max / mean is 2, not within 1.5.
        if q != Quantity::Ks {
            let ratio = log.max / log.mean;
            assert!((1.9..2.1).contains(&ratio), "{q:?}: {ratio}");
        }
    }
    // The report's alpha error at RGBA8 spans decades: about d / min(v, 1/v).
    let alpha = Quantity::Alpha;
    let report = piecewise_max(alpha.range(), 6, Format::Rgba8, Scheme::Report);
    assert!(report[2] < 0.025 && report[3] < 0.025, "{report:?}");
    assert!(report[0] >= 0.5 && report[5] == f64::INFINITY, "{report:?}");
    // Where the report wins at RGBA8: alpha in [0.1, 10] (the crossover is
    // near 0.07 and 14, where d / min(v, 1/v) = 2.75 %).
    let near_1 = ValueRange::new(0.1, 10.0, 0.0);
    let report = profile(near_1, Format::Rgba8, Scheme::Report);
    let log = profile(near_1, Format::Rgba8, Scheme::Log(alpha.log_scale()));
    assert!(report.max < log.max, "{report:?} {log:?}");
}

#[test]
fn at_rgba16f_the_report_and_plain_values_beat_the_log_scale() {
    for q in Quantity::ALL {
        let report = profile(q.range(), Format::Rgba16F, Scheme::Report);
        let direct = profile(q.range(), Format::Rgba16F, Scheme::Direct);
        let log = profile(q.range(), Format::Rgba16F, Scheme::Log(q.log_scale()));
        // A half float holds 1e-3..1e3 as it is: no flip, no flag, at most
        // 2^-11 off.
        assert!(direct.max <= U16, "{q:?}: {direct:?}");
        assert!(report.max <= U16 / (1.0 - U16), "{q:?}: {report:?}");
        match q {
            // The log scale spends 2^-12 of s on 2 octaves: better.
            Quantity::Eta => assert!(log.max < report.max, "{log:?} {report:?}"),
            _ => assert!(log.max > 4.0 * report.max, "{q:?}: {log:?} {report:?}"),
        }
    }
    // A plain value does not fit RGBA8: it clamps to [0, 1].
    assert_eq!(round_trip(4.0, Format::Rgba8, Scheme::Direct), 1.0);
}

#[test]
fn ks_is_measured_absolutely_below_its_floor() {
    let r = Quantity::Ks.range();
    assert_eq!(r.error(0.0, 0.002), 0.2);
    assert_eq!(r.error(0.005, 0.006), 0.1);
    assert!((r.error(5.0, 5.5) - 0.1).abs() < 1e-15);
    assert_eq!(r.error(1.0, f64::NAN), f64::INFINITY);
    // 0 and the stretch below the floor are sampled too.
    let p = profile(r, Format::Rgba8, Scheme::Report);
    assert_eq!(p.samples, SAMPLES + SAMPLES / 4);
    assert!(p.worst_at < 0.01, "{p:?}");
    assert_eq!(round_trip(0.0, Format::Rgba8, Scheme::Report), 0.0);
    assert_eq!(
        round_trip(0.0, Format::Rgba8, Scheme::Log(Quantity::Ks.log_scale())),
        0.0
    );
}

#[test]
fn out_of_range_and_non_finite_inputs_are_clamped_or_refused() {
    // Encoders clamp, as a shader must.
    assert_eq!(encode_report(-1.0), (0.0, false));
    assert_eq!(encode_report(f64::NAN), (0.0, false));
    assert_eq!(encode_report(f64::INFINITY), (0.0, true));
    assert_eq!(decode_report(0.0, true), f64::INFINITY);
    assert_eq!(encode(f64::NAN, Scheme::Direct), (0.0, false));
    let alpha = Scheme::Log(Quantity::Alpha.log_scale());
    assert_eq!(round_trip(2e3, Format::Rgba32F, alpha), 1e3);
    assert_eq!(round_trip(1e-4, Format::Rgba32F, alpha), 1e-3);
    assert_eq!(round_trip(f64::NAN, Format::Rgba8, alpha), 1e-3);
    assert_eq!(round_trip(f64::INFINITY, Format::Rgba16F, alpha), 1e3);
    assert_eq!(Quantity::Alpha.log_scale().decode(f64::NAN), 1e-3);
    assert_eq!(Quantity::Alpha.log_scale().decode(1.5), 1e3);
    // Scales and ranges that make no sense are refused.
    assert!(LogScale::new(0.0, 10.0, 0.0).is_err());
    assert!(LogScale::new(1.0, 1.0, 0.0).is_err());
    assert!(LogScale::new(1.0, 2.0, -0.5).is_err());
    assert!(LogScale::new(f64::NAN, 2.0, 0.0).is_err());
    assert!(LogScale::new(1.0, f64::INFINITY, 0.0).is_err());
    assert_eq!(
        LogScale::new(0.0, 10.0, 1e-3).unwrap(),
        Quantity::Ks.log_scale()
    );
    let f = Format::Rgba8;
    let s = Scheme::Report;
    let bad = |lo, hi, floor, n| relative_error_profile(ValueRange::new(lo, hi, floor), f, s, n);
    assert!(bad(1.0, 2.0, 0.0, 1).is_err());
    assert!(bad(2.0, 1.0, 0.0, 100).is_err());
    assert!(bad(1.0, f64::INFINITY, 0.0, 100).is_err());
    assert!(bad(0.0, 10.0, 0.0, 100).is_err());
    assert!(bad(-1.0, 10.0, 0.01, 100).is_err());
    assert!(bad(0.0, 10.0, 10.0, 100).is_err());
    assert!(bad(f64::NAN, 10.0, 0.0, 100).is_err());
    assert!(bad(1.0, 2.0, 0.0, 2).is_ok());
}
