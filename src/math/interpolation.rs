//! The CPU twin of how the rasteriser interpolates a vertex attribute
//! across a triangle (notes 01 §4.1): the screen-space barycentric
//! coordinates of a pixel centre, C = a Ca + b Cb + c Cc, and the
//! perspective-correct weights GL uses by default (each divided by its
//! vertex's w, renormalised). With GLSL `noperspective` GL uses the
//! screen-space weights as they are. The tests hold the GPU to both.

use glam::DVec2;

/// The barycentric coordinates (a, b, c) of `p` in the screen-space
/// triangle `t` (a + b + c = 1; all in [0, 1] inside). None for a triangle
/// of zero area.
pub fn barycentric(p: DVec2, t: [DVec2; 3]) -> Option<[f64; 3]> {
    let area = (t[1] - t[0]).perp_dot(t[2] - t[0]);
    if area == 0.0 || !area.is_finite() {
        return None;
    }
    Some([
        (t[2] - t[1]).perp_dot(p - t[1]) / area,
        (t[0] - t[2]).perp_dot(p - t[2]) / area,
        (t[1] - t[0]).perp_dot(p - t[0]) / area,
    ])
}

/// Perspective-correct weights from screen-space ones: divide each by its
/// vertex's clip w, interpolate, renormalise ("divide by w, interpolate,
/// multiply back", notes 01 §5.1).
pub fn perspective_correct(bary: [f64; 3], w: [f64; 3]) -> [f64; 3] {
    let q = [bary[0] / w[0], bary[1] / w[1], bary[2] / w[2]];
    let sum = q[0] + q[1] + q[2];
    q.map(|x| x / sum)
}

/// The distance of `p` from the triangle's nearest edge, in pixels.
pub fn edge_distance(p: DVec2, t: [DVec2; 3]) -> f64 {
    (0..3)
        .map(|k| {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            (b - a).perp_dot(p - a).abs() / (b - a).length()
        })
        .fold(f64::MAX, f64::min)
}

/// The notes' line interpolation: the colour at p between v0 (colour Ca)
/// and v1 (colour Cb) is Cb t + Ca (1 - t), with t = |p - v0| / |v1 - v0|.
/// (The notes write t = |(v1 - p) / (v1 - v0)|, which is the weight of v0,
/// not of v1: with it, C would run from Cb at v0 to Ca at v1.)
pub fn line(p: DVec2, v0: DVec2, v1: DVec2, ca: f64, cb: f64) -> f64 {
    let t = (p - v0).length() / (v1 - v0).length();
    cb * t + ca * (1.0 - t)
}

/// Interpolate three values with weights.
pub fn mix3(w: [f64; 3], v: [f64; 3]) -> f64 {
    w[0] * v[0] + w[1] * v[1] + w[2] * v[2]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn corners_centre_and_perspective() {
        let t = [
            DVec2::new(0.0, 0.0),
            DVec2::new(4.0, 0.0),
            DVec2::new(0.0, 4.0),
        ];
        assert_eq!(barycentric(t[1], t), Some([0.0, 1.0, 0.0]));
        let c = barycentric(DVec2::new(4.0 / 3.0, 4.0 / 3.0), t).unwrap();
        assert!(c.iter().all(|x| (x - 1.0 / 3.0).abs() < 1e-12));
        // Equal w: perspective changes nothing; a far vertex (w = 4) weighs less.
        assert_eq!(perspective_correct(c, [2.0; 3]), c);
        let p = perspective_correct(c, [1.0, 1.0, 4.0]);
        assert!(p[2] < c[2] && (p.iter().sum::<f64>() - 1.0).abs() < 1e-12);
        assert_eq!(barycentric(DVec2::ZERO, [DVec2::ZERO; 3]), None);
        assert!((edge_distance(DVec2::new(1.0, 1.0), t) - 1.0).abs() < 1e-12);
        // Halfway along a line: the mean.
        let m = line(
            DVec2::new(1.0, 0.0),
            DVec2::ZERO,
            DVec2::new(2.0, 0.0),
            0.2,
            0.8,
        );
        assert!((m - 0.5).abs() < 1e-12);
        assert_eq!(
            line(DVec2::ZERO, DVec2::ZERO, DVec2::new(2.0, 0.0), 0.2, 0.8),
            0.2
        );
    }
}
