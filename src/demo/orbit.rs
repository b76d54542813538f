//! The demo's camera control: left-drag orbits around the target, right- or
//! middle-drag pans, the wheel zooms; in fly mode the drag turns the view
//! about the eye and W A S D (Q E) move it.

use crate::scene::{Camera, Projection};
use glam::{Quat, Vec3};
use std::f32::consts::PI;

/// An orbit around the scene camera's target: the eye moves on a sphere
/// about `target`, with the camera's `up` as the pole.
#[derive(Clone, Debug)]
pub(super) struct Orbit {
    base: Camera,
    up: Vec3,
    /// Unit vector from the target to the eye.
    direction: Vec3,
    distance: f32,
    base_distance: f32,
    /// The point orbited (the scene camera's target until panned or flown).
    target: Vec3,
}

/// Radians per pixel of mouse drag.
const ORBIT_SPEED: f32 = 0.01;
/// Keep this far (radians) from the poles, where look-at degenerates.
const POLE_MARGIN: f32 = 0.01;

impl Orbit {
    pub(super) fn new(camera: &Camera) -> Orbit {
        let up = camera.up.normalize_or(Vec3::Y);
        let offset = camera.eye - camera.target;
        let (direction, distance) = if offset.is_finite() && offset.length() > 1e-6 {
            (offset.normalize(), offset.length())
        } else {
            (up.any_orthonormal_vector(), 1.0)
        };
        Orbit {
            base: camera.clone(),
            up,
            direction,
            distance,
            base_distance: distance,
            target: camera.target,
        }
    }

    fn eye(&self) -> Vec3 {
        self.target + self.direction * self.distance
    }

    /// The camera's right and up on screen.
    fn screen_axes(&self) -> (Vec3, Vec3) {
        let right = self
            .up
            .cross(self.direction)
            .normalize_or(self.up.any_orthonormal_vector());
        (right, self.direction.cross(right))
    }

    /// Take `camera`'s projection and near and far planes; the view stays.
    pub(super) fn set_lens(&mut self, camera: &Camera) {
        self.base.projection = camera.projection;
        self.base.near = camera.near;
        self.base.far = camera.far;
    }

    /// Drag by (dx, dy) pixels with the right or middle button: move the
    /// target (and the eye with it) across the screen.
    pub(super) fn pan(&mut self, dx: f32, dy: f32) {
        if !(dx.is_finite() && dy.is_finite()) {
            return;
        }
        let (right, up) = self.screen_axes();
        let k = self.distance * 0.0015;
        self.target += (-right * dx + up * dy) * k;
    }

    /// Fly mode's drag: turn the view about the eye, which stays put.
    pub(super) fn look(&mut self, dx: f32, dy: f32) {
        let eye = self.eye();
        self.rotate(-dx, -dy);
        self.target = eye - self.direction * self.distance;
    }

    /// Fly mode's keys: move `forward`, `right` and `up` (each -1, 0 or 1)
    /// for `seconds`, at half the scene camera's distance per second.
    pub(super) fn fly(&mut self, forward: f32, right: f32, up: f32, seconds: f32) {
        let (r, _) = self.screen_axes();
        let step = self.base_distance * 0.5 * seconds.clamp(0.0, 0.25);
        self.target += (-self.direction * forward + r * right + self.up * up) * step;
    }

    /// Drag by (dx, dy) pixels: dx turns around `up`, dy tilts toward or away from it.
    pub(super) fn rotate(&mut self, dx: f32, dy: f32) {
        if !(dx.is_finite() && dy.is_finite()) {
            return;
        }
        let yaw = Quat::from_axis_angle(self.up, -dx * ORBIT_SPEED);
        let mut d = yaw * self.direction;
        let theta = d.angle_between(self.up);
        let new_theta = (theta - dy * ORBIT_SPEED).clamp(POLE_MARGIN, PI - POLE_MARGIN);
        let axis = self.up.cross(d);
        let axis = if axis.length_squared() > 1e-12 {
            axis.normalize()
        } else {
            self.up.any_orthonormal_vector()
        };
        d = Quat::from_axis_angle(axis, new_theta - theta) * d;
        self.direction = d.normalize_or(self.direction);
    }

    /// Wheel `steps` (positive: closer), within 1/100 and 100 times the scene's distance.
    pub(super) fn zoom(&mut self, steps: f32) {
        if !steps.is_finite() {
            return;
        }
        self.distance = (self.distance * 0.9f32.powf(steps))
            .clamp(self.base_distance * 0.01, self.base_distance * 100.0);
    }

    /// The scene camera moved to the orbit's eye. Zooming also scales an
    /// orthographic view and pushes the far plane out.
    pub(super) fn camera(&self) -> Camera {
        let mut c = self.base.clone();
        let scale = self.distance / self.base_distance;
        c.target = self.target;
        c.eye = self.eye();
        c.up = self.up;
        if let Projection::Orthographic { half_height } = c.projection {
            c.projection = Projection::Orthographic {
                half_height: half_height * scale,
            };
        }
        c.far = self.base.far * scale.max(1.0);
        c
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn camera() -> Camera {
        Camera {
            eye: Vec3::new(0.0, 2.0, 5.0),
            target: Vec3::new(0.0, 1.0, 0.0),
            up: Vec3::Y,
            projection: Projection::Perspective {
                fov_y_degrees: 45.0,
            },
            near: 0.1,
            far: 50.0,
        }
    }

    #[test]
    fn orbit_starts_at_the_scene_camera() {
        let c = Orbit::new(&camera()).camera();
        assert!((c.eye - camera().eye).length() < 1e-5);
        assert_eq!(c.target, camera().target);
    }

    #[test]
    fn orbit_keeps_distance_and_stays_off_the_poles() {
        let mut o = Orbit::new(&camera());
        let r = (camera().eye - camera().target).length();
        o.rotate(123.0, -40.0);
        assert!(((o.camera().eye - o.base.target).length() - r).abs() < 1e-4);
        o.rotate(0.0, -10_000.0); // far past the pole
        let theta = o.direction.angle_between(Vec3::Y);
        assert!((POLE_MARGIN - 1e-3..=PI - POLE_MARGIN + 1e-3).contains(&theta));
        o.rotate(f32::NAN, 1.0);
        assert!(o.direction.is_finite());
    }

    #[test]
    fn zoom_is_bounded() {
        let mut o = Orbit::new(&camera());
        o.zoom(1e6);
        assert!(o.distance >= o.base_distance * 0.01 - 1e-6);
        o.zoom(-1e6);
        assert!(o.distance <= o.base_distance * 100.0 + 1e-3);
        assert!(o.camera().far >= camera().far);
    }

    #[test]
    fn degenerate_camera_still_orbits() {
        let mut c = camera();
        c.eye = c.target;
        c.up = Vec3::ZERO;
        let mut o = Orbit::new(&c);
        o.rotate(10.0, 10.0);
        o.zoom(3.0);
        assert!(o.camera().eye.is_finite());
    }

    #[test]
    fn pan_moves_eye_and_target_together() {
        let mut o = Orbit::new(&camera());
        let before = o.camera();
        o.pan(30.0, -20.0);
        let after = o.camera();
        let moved = after.target - before.target;
        assert!(moved.length() > 1e-3);
        assert!((after.eye - before.eye - moved).length() < 1e-5);
        // Across the screen: perpendicular to the view.
        assert!(moved.dot(before.target - before.eye).abs() < 1e-4);
    }

    #[test]
    fn fly_look_keeps_the_eye_and_fly_moves_along_the_view() {
        let mut o = Orbit::new(&camera());
        let eye = o.camera().eye;
        o.look(40.0, 15.0);
        let c = o.camera();
        assert!(
            (c.eye - eye).length() < 1e-4,
            "looking around keeps the eye"
        );
        let view = (c.target - c.eye).normalize();
        o.fly(1.0, 0.0, 0.0, 0.1);
        let moved = o.camera().eye - c.eye;
        assert!(moved.length() > 1e-4);
        assert!(
            (moved.normalize() - view).length() < 1e-4,
            "W moves where the camera looks"
        );
    }
}
