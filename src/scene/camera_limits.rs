//! The limits of a camera that f32 and a 24-bit depth buffer can draw
//! (notes 01 §4.4 "Depth Buffer / Depth Test", src/math/depth.rs). A
//! camera past them does not render wrongly in silence: it is refused with
//! the reason and the value that would do, or, short of that, warned about.
//!
//! - Perspective: one depth step at distance z is z^2 (f - n) / (f n 2^24)
//!   of eye space. At the far plane that is about far / (near 2^24) of the
//!   distance. Past [`REFUSE_STEP`] (5%) the buffer cannot order what is
//!   drawn (and everything beyond near x 2^24 rounds to the far plane's
//!   depth: a near of 1e-7 with a far of 20 draws nothing); past
//!   [`WARN_STEP`] (0.1%) surfaces closer than that z-fight.
//! - A near plane under [`MIN_NEAR`]: the projection's 2 far near /
//!   (near - far) underflows f32.
//! - Orthographic: one pixel must span [`MIN_PIXEL_ULPS`] steps of f32 at
//!   the eye's distance from the origin, or neighbouring pixels see the same
//!   rounded positions (a half_height of 1e-30 gives a different image on
//!   every path).
//! - An object's position or scale past [`MAX_EXTENT`]: its triangles reach
//!   clip-space coordinates where GL's clipping in f32 loses them
//!   (llvmpipe drew half a plane scaled 1e13 and all of one scaled 1e11).

use super::{Camera, Projection};
use crate::math::depth::resolvable_difference;
use anyhow::{Result, bail};

/// The depth step at the far plane, over the distance, past which a
/// perspective camera is refused.
pub const REFUSE_STEP: f64 = 0.05;
/// ... and past which it is warned about.
pub const WARN_STEP: f64 = 0.001;
/// The smallest near plane: 2 far near / (near - far) stays a normal f32.
pub const MIN_NEAR: f32 = 1e-12;
/// The f32 steps (of the eye's distance from the origin) one pixel of an
/// orthographic view spans at least...
pub const MIN_PIXEL_ULPS: f64 = 4.0;
/// ... at this many rows (a 4K window and more; `--size` may go up to it).
pub const ROWS: u32 = 4096;

/// The largest position or scale an object may have, in scene units.
pub const MAX_EXTENT: f32 = 1e9;

/// Refuse a position or scale (`key`: "objects[2].scale") past `MAX_EXTENT`.
pub fn within_world(key: &str, v: &[f32]) -> Result<()> {
    if let Some(x) = v.iter().find(|x| x.abs() > MAX_EXTENT) {
        bail!(
            "{key}: {x:e} is past {MAX_EXTENT:e} scene units: the object's triangles would reach \
             clip-space coordinates where clipping in f32 loses them (a plane scaled by 1e13 \
             is drawn half or not at all)"
        );
    }
    Ok(())
}

/// The depth step at the far plane over the far distance (24-bit depth).
pub fn far_step(near: f32, far: f32) -> f64 {
    let (n, f) = (f64::from(near), f64::from(far));
    resolvable_difference(f, n, f, 24) / f
}

/// Refuse a camera that cannot be drawn (`key` names it: "camera",
/// "views[1].camera").
pub fn check(c: &Camera, key: &str) -> Result<()> {
    let rows = ROWS;
    match c.projection {
        Projection::Perspective { .. } => {
            if c.near < MIN_NEAR {
                bail!(
                    "{key}.near = {:e}: below {MIN_NEAR:e} the projection's term \
                     2 far near / (near - far) underflows f32",
                    c.near
                );
            }
            let step = far_step(c.near, c.far);
            if step > REFUSE_STEP {
                let past = f64::from(c.near) * 2f64.powi(24);
                let min_near = f64::from(c.far) / (REFUSE_STEP * 2f64.powi(24));
                bail!(
                    "{key}.near/far: near = {:e}, far = {}: far / near = {:.3e} is more than the \
                     24-bit depth buffer resolves. One depth step at the far plane is {:.3e} units \
                     ({:.0}% of the distance), and everything beyond near x 2^24 = {past:.3e} has \
                     the far plane's depth (notes 01 §4.4, depth precision; `gloss plan` prints \
                     the step at a few distances). Raise near to at least {min_near:.3e}.",
                    c.near,
                    c.far,
                    f64::from(c.far) / f64::from(c.near),
                    step * f64::from(c.far),
                    step * 100.0
                );
            }
        }
        Projection::Orthographic { half_height } => {
            let scale = c.eye.length().max(c.target.length()).max(1.0);
            let ulp = f64::from(scale) * f64::from(f32::EPSILON);
            let min = MIN_PIXEL_ULPS * ulp * f64::from(rows) / 2.0;
            if f64::from(half_height) < min {
                bail!(
                    "{key}.half_height = {half_height:e} is too small to draw: f32 resolves \
                     positions {scale} units from the origin to {ulp:.2e}, and one of {rows} \
                     rows of pixels would span {:.2e}. At least {min:.2e} is needed.",
                    2.0 * f64::from(half_height) / f64::from(rows)
                );
            }
        }
    }
    Ok(())
}

/// A warning for a camera that draws but z-fights, or None.
pub fn warning(c: &Camera, key: &str) -> Option<String> {
    let Projection::Perspective { .. } = c.projection else {
        return None;
    };
    let step = far_step(c.near, c.far);
    (step > WARN_STEP).then(|| {
        format!(
            "{key}.near/far: one depth step at the far plane is {:.3e} units ({:.2}% of the \
             distance): surfaces closer than that z-fight (notes 01 §4.4). Raise near to \
             {:.3e} for 0.1%",
            step * f64::from(c.far),
            step * 100.0,
            f64::from(c.far) / (WARN_STEP * 2f64.powi(24))
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    fn camera(near: f32, far: f32, projection: Projection) -> Camera {
        Camera {
            eye: Vec3::new(0.0, 4.0, 6.0),
            target: Vec3::ZERO,
            up: Vec3::Y,
            projection,
            near,
            far,
        }
    }

    const PERSPECTIVE: Projection = Projection::Perspective {
        fov_y_degrees: 45.0,
    };

    #[test]
    fn the_far_step_is_far_over_near_2_24() {
        let s = far_step(0.1, 100.0);
        // (f - n) / (n 2^24), in f64 from the f32 near.
        let n = f64::from(0.1f32);
        let want = (100.0 - n) / (n * 2f64.powi(24));
        assert!((s - want).abs() < 1e-15, "{s} vs {want}");
    }

    #[test]
    fn cameras_past_the_limits_are_refused_and_near_them_warned() {
        let ok = camera(0.1, 100.0, PERSPECTIVE);
        assert!(check(&ok, "camera").is_ok());
        assert_eq!(warning(&ok, "camera"), None);
        let e = check(&camera(1e-7, 20.0, PERSPECTIVE), "camera").unwrap_err();
        let e = format!("{e}");
        assert!(e.contains("camera.near/far") && e.contains("depth"), "{e}");
        assert!(e.contains("Raise near to at least 2.384e-5"), "{e}");
        let e = check(&camera(1e-30, 2e-30, PERSPECTIVE), "camera").unwrap_err();
        assert!(format!("{e}").contains("underflows f32"), "{e}");
        // 1e-4 .. 20: a step of 1.2% at the far plane draws, with a warning.
        let near = camera(1e-4, 20.0, PERSPECTIVE);
        assert!(check(&near, "camera").is_ok());
        let w = warning(&near, "camera").unwrap();
        assert!(w.contains("z-fight"), "{w}");
    }

    #[test]
    fn objects_stay_within_the_world() {
        assert!(within_world("objects[0].scale", &[1e9, 1.0, -1e9]).is_ok());
        let e = within_world("objects[0].scale", &[1e10, 1.0, 1.0]).unwrap_err();
        assert!(
            format!("{e}").starts_with("objects[0].scale: 1e10 is past 1e9"),
            "{e}"
        );
    }

    #[test]
    fn an_orthographic_view_must_be_wider_than_f32_resolves() {
        let ortho = |h| camera(1.0, 20.0, Projection::Orthographic { half_height: h });
        assert!(check(&ortho(5.0), "camera").is_ok());
        // 7.2 units from the origin: f32 steps of 8.6e-7, 4 of them a pixel
        // at 4096 rows: a half height of at least 0.007.
        assert!(check(&ortho(0.01), "camera").is_ok());
        assert!(check(&ortho(0.005), "camera").is_err());
        let e = format!("{}", check(&ortho(1e-30), "camera").unwrap_err());
        assert!(e.contains("camera.half_height = 1e-30 is too small"), "{e}");
        assert_eq!(warning(&ortho(0.01), "camera"), None);
    }
}
