//! The views of a frame: the camera's, and one per reflection a mirror
//! shows (notes 05, "Planar Reflections"). Every pass that draws the world
//! (forward, the G-buffer, the lighting and composite passes) draws it for
//! one view; a frame with mirrors draws the world several times.
//!
//! A reflected view reflects the *world*: every vertex goes through the
//! reflection matrix R before the camera's view-projection (`VP * R * M *
//! p`). Lighting stays in the unreflected world with the eye reflected
//! instead (`R^-1 * eye`): a reflection is an isometry, so every distance
//! and angle the Phong model uses is unchanged, which is the same as
//! reflecting the lights with the world (a light in front of the mirror
//! lights the reflected objects as it lights the objects).

use glam::{Mat3, Mat4, Vec4};

/// One view of the world.
#[derive(Clone, Debug, PartialEq)]
pub struct View {
    /// In words, for `gloss plan` ("camera", "in mirror 'glass'").
    pub name: String,
    /// R: the world is drawn at `R * x` (identity for the camera's view).
    pub reflection: Mat4,
    /// Keep only what lies on the positive side of this world-space plane
    /// `(n, -n . p)` (gl_ClipDistance[0] with GL_CLIP_DISTANCE0): what lies
    /// behind the mirror must not appear in front of it once reflected.
    pub clip_plane: Option<Vec4>,
    /// Draw only where the stencil buffer holds this value (the mirror's
    /// region on screen).
    pub stencil: Option<u8>,
    /// This view's passes start the image: the first one clears colour and
    /// depth. A reflection drawn into a mirror's region must not.
    pub clears: bool,
    /// Draw with glFrontFace(GL_CW): an odd number of reflections turns
    /// counter-clockwise front faces clockwise (notes 05, "Small Problem").
    /// Off only to show what goes wrong without it.
    pub flip_winding: bool,
}

impl View {
    /// The camera's own view.
    pub fn camera() -> View {
        View {
            name: "camera".into(),
            reflection: Mat4::IDENTITY,
            clip_plane: None,
            stencil: None,
            clears: true,
            flip_winding: false,
        }
    }

    /// Whether `reflection` mirrors handedness (an odd number of reflections).
    pub fn mirrored(&self) -> bool {
        Mat3::from_mat4(self.reflection).determinant() < 0.0
    }

    /// The glFrontFace winding for an object whose own model matrix is
    /// `object_mirrored` (a negative scale), in this view.
    pub fn front_face(&self, object_mirrored: bool) -> u32 {
        if object_mirrored != self.flip_winding {
            glow::CW
        } else {
            glow::CCW
        }
    }

    /// The clip plane to write into `u_clip_plane` (all zeros, clipping
    /// nothing, when GL_CLIP_DISTANCE0 is off).
    pub fn clip_uniform(&self) -> Vec4 {
        self.clip_plane.unwrap_or(Vec4::ZERO)
    }
}
