//! Cameras and split views in a scene file (notes 01 §4.2 "Scissor testing":
//! "can set unique scissor box per viewport"). `[camera]` is the scene's
//! camera (the demo's orbit moves it); `[[views]]` splits the frame into
//! rectangles, each drawn from its own camera (or the scene's):
//!
//! ```toml
//! [[views]]
//! name = "top"
//! viewport = [0.0, 0.5, 0.5, 0.5]   # x, y, width, height: fractions of the frame, y up
//! camera = { projection = "orthographic", eye = [0.0, 10.0, 0.0], target = [0.0, 0.0, 0.0], up = [0.0, 0.0, -1.0], half_height = 4.0 }
//! ```

use super::checks::finite;
use super::file::{CameraFile, SceneFile};
use super::{Camera, Projection};
use anyhow::{Result, anyhow, bail};
use glam::Vec3;
use std::path::Path;

/// A rectangle of the frame drawn from its own camera.
#[derive(Clone, Debug, PartialEq)]
pub struct SplitView {
    pub name: String,
    /// x, y, width, height as fractions of the frame (y up, as glViewport).
    pub viewport: [f32; 4],
    /// None: the scene's camera.
    pub camera: Option<Camera>,
}

/// Check the `[[views]]` list: each rectangle inside the frame, not empty.
pub(super) fn views(f: &SceneFile, _base: &Path) -> Result<Vec<SplitView>> {
    let mut out = Vec::new();
    for (i, v) in f.views.iter().enumerate() {
        let key = format!("views[{i}]");
        check_viewport(i, v.viewport)?;
        let camera = v
            .camera
            .as_ref()
            .map(|c| camera(c, &format!("{key}.camera")))
            .transpose()?;
        out.push(SplitView {
            name: v.name.clone().unwrap_or_else(|| format!("view {i}")),
            viewport: v.viewport,
            camera,
        });
    }
    Ok(out)
}

/// Check view `i`'s rectangle: inside the frame and not empty.
pub fn check_viewport(i: usize, viewport: [f32; 4]) -> Result<()> {
    let key = format!("views[{i}].viewport");
    finite(&key, &viewport)?;
    let [x, y, w, h] = viewport;
    let inside = x >= 0.0 && y >= 0.0 && x + w <= 1.0 + 1e-6 && y + h <= 1.0 + 1e-6;
    if !(inside && w > 0.0 && h > 0.0) {
        bail!(
            "{key}: expected [x, y, width, height] fractions with the rectangle inside [0, 1] and not empty, found {viewport:?}"
        );
    }
    Ok(())
}

/// Check a camera table (`key` names it in messages: "camera", "views[2].camera").
pub(super) fn camera(c: &CameraFile, key: &str) -> Result<Camera> {
    finite(&format!("{key}.eye"), &c.eye)?;
    finite(&format!("{key}.target"), &c.target)?;
    finite(&format!("{key}.up"), &c.up)?;
    finite(&format!("{key}.near/far"), &[c.near, c.far])?;
    let eye = Vec3::from(c.eye);
    let target = Vec3::from(c.target);
    let up = Vec3::from(c.up);
    if (target - eye).length() < 1e-6 {
        bail!("{key}: eye and target are the same point");
    }
    if (target - eye)
        .normalize()
        .cross(up.normalize_or_zero())
        .length()
        < 1e-6
    {
        bail!("{key}.up: must not be parallel to the view direction (or zero)");
    }
    if !(c.near > 0.0 && c.far > c.near) {
        bail!(
            "{key}.near/far: expected 0 < near < far, found near = {}, far = {}",
            c.near,
            c.far
        );
    }
    let projection = match c.projection.as_str() {
        "perspective" => {
            if !(c.fov_y > 0.5 && c.fov_y < 179.0) {
                bail!(
                    "{key}.fov_y: expected degrees in (0.5, 179), found {}",
                    c.fov_y
                );
            }
            Projection::Perspective {
                fov_y_degrees: c.fov_y,
            }
        }
        "orthographic" => {
            let h = c
                .half_height
                .ok_or_else(|| anyhow!("{key}.half_height: required for an orthographic camera"))?;
            if !(h.is_finite() && h > 0.0) {
                bail!("{key}.half_height: expected a positive number, found {h}");
            }
            Projection::Orthographic { half_height: h }
        }
        other => bail!(
            "{key}.projection: expected \"perspective\" or \"orthographic\", found \"{other}\""
        ),
    };
    let camera = Camera {
        eye,
        target,
        up,
        projection,
        near: c.near,
        far: c.far,
    };
    super::camera_limits::check(&camera, key)?;
    Ok(camera)
}
