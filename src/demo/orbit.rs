//! The demo's camera control: left-drag orbits around the scene camera's
//! target, the wheel zooms.

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
        }
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
        c.eye = c.target + self.direction * self.distance;
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
}
