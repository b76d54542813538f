//! The meshes that screen-space and light-volume passes draw, uploaded once.

use crate::geometry;
use crate::gl::Gl;
use crate::gl::mesh::Mesh;
use anyhow::Result;

pub struct FrameMeshes {
    /// One triangle that covers the screen (clip-space positions, identity MVP).
    pub fullscreen: Mesh,
    /// Encloses the unit sphere (every face plane at distance >= 1): a point
    /// light's volume.
    pub volume_sphere: Mesh,
    /// Encloses the cone of half-angle 45°, apex at the origin, axis -Z,
    /// height 1: a spot light's volume.
    pub volume_cone: Mesh,
}

impl FrameMeshes {
    pub fn new(gl: &Gl) -> Result<FrameMeshes> {
        Ok(FrameMeshes {
            fullscreen: Mesh::upload(gl, &geometry::fullscreen_triangle())?,
            volume_sphere: Mesh::upload(gl, &geometry::light_volume_sphere())?,
            volume_cone: Mesh::upload(gl, &geometry::cone(32))?,
        })
    }
}
