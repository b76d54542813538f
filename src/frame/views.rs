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

use crate::gl::program::Program;
use crate::math::reflection;
use crate::scene::Camera;
use glam::{Mat3, Mat4, Vec3, Vec4};

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
    /// A convex spherical mirror's reflection (centre, radius): each vertex
    /// moves to its own virtual image (`curved_image`), and what lies inside
    /// the sphere is cut away. None for every other view.
    pub curved: Option<Vec4>,
    /// A split view's own camera (None: the frame's camera).
    pub camera: Option<Camera>,
    /// A split view's rectangle: x, y, width, height as fractions of the
    /// target, y up (None: the whole target). Its passes draw with
    /// glViewport set to it, and clear only inside it (glScissor).
    pub viewport: Option<[f32; 4]>,
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
            curved: None,
            camera: None,
            viewport: None,
        }
    }

    /// The glViewport rectangle (x, y, width, height in pixels) of this
    /// view in a `width` x `height` target: the split view's rectangle,
    /// rounded so that neighbouring views share their edges, or the whole
    /// target.
    pub fn rect(&self, width: i32, height: i32) -> (i32, i32, i32, i32) {
        let Some([x, y, w, h]) = self.viewport else {
            return (0, 0, width, height);
        };
        let px = |f: f32, n: i32| (f * n as f32).round() as i32;
        let (x0, y0) = (px(x, width), px(y, height));
        let (x1, y1) = (px(x + w, width), px(y + h, height));
        (x0, y0, (x1 - x0).max(1), (y1 - y0).max(1))
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

    /// `parent`'s world reflected in the mirror `name` with world plane
    /// `plane` = (n, -n . p): R = parent's R x the reflection about the plane
    /// (src/math/reflection.rs), clipped by the plane (`clip`), the winding
    /// flipped for an odd number of reflections (`winding`), drawn where the
    /// stencil holds `stencil`. None for a parent that is a curved mirror's
    /// view (curved reflections do not compose with others).
    pub fn in_mirror(
        parent: &View,
        name: &str,
        plane: Vec4,
        clip: bool,
        winding: bool,
        stencil: Option<u8>,
    ) -> Option<View> {
        if parent.curved.is_some() {
            return None;
        }
        let n = plane.truncate();
        let r = parent.reflection * reflection::reflection(-plane.w * n, n)?;
        let name = match parent.stencil {
            None => format!("in mirror '{name}'"),
            Some(_) => format!("in mirror '{name}', {}", parent.name),
        };
        let odd = Mat3::from_mat4(r).determinant() < 0.0;
        Some(View {
            name,
            reflection: r,
            clip_plane: clip.then_some(plane),
            stencil,
            clears: false,
            flip_winding: odd && winding,
            curved: None,
            camera: parent.camera.clone(),
            viewport: parent.viewport,
        })
    }

    /// `parent`'s world seen in the convex spherical mirror `name`, `sphere`
    /// = (centre, radius): each vertex to its own image (`curved_image`),
    /// then the parent's reflection. The radial map reverses the winding.
    pub fn in_curved_mirror(
        parent: &View,
        name: &str,
        sphere: Vec4,
        winding: bool,
        stencil: Option<u8>,
    ) -> Option<View> {
        if parent.curved.is_some() {
            return None;
        }
        let odd = !parent.mirrored();
        Some(View {
            name: format!("in curved mirror '{name}'"),
            clip_plane: None,
            curved: Some(sphere),
            stencil,
            clears: false,
            flip_winding: odd && winding,
            ..parent.clone()
        })
    }

    /// Whether the view cuts anything away (GL_CLIP_DISTANCE0 on).
    pub fn clips(&self) -> bool {
        self.clip_plane.is_some() || self.curved.is_some()
    }

    /// glUniform* for glsl/common/view.glsl (program `p` in use): the clip
    /// plane (zero: nothing, when GL_CLIP_DISTANCE0 is off), the curved
    /// mirror (zero radius: none), the eye it is seen from (this view's
    /// eye, `FrameUniforms::eye`), and the scene's clip planes (`planes`,
    /// at most 7; zero beyond).
    pub fn set_uniforms(&self, p: &Program, eye: Vec3, planes: &[Vec4]) {
        let mut all = [Vec4::ZERO; 7];
        for (a, b) in all.iter_mut().zip(planes) {
            *a = *b;
        }
        p.set_vec4_array("u_clip_planes", &all);
        p.set_vec4("u_clip_plane", self.clip_plane.unwrap_or(Vec4::ZERO));
        p.set_vec4("u_curved_mirror", self.curved.unwrap_or(Vec4::ZERO));
        p.set_vec3("u_curved_eye", eye);
    }
}

/// The image of `p` in a convex spherical mirror of centre `c` and radius
/// `r`, seen from `eye` (the CPU twin of `view_position` in
/// glsl/common/view.glsl): `p` reflected about the sphere's tangent plane at
/// the point whose normal halves the angle, seen from the centre, between
/// the eye and `p`. When `p` and the eye are equally far from the centre,
/// that point is the true reflection point: the law of reflection holds
/// there, and the image lies on the eye's ray through it, so it is drawn
/// exactly where the mirror shows it. Otherwise the point, and the image,
/// are approximate (docs/stencil/mirror.md).
pub fn curved_image(p: Vec3, c: Vec3, r: f32, eye: Vec3) -> Vec3 {
    let to_eye = (eye - c).normalize();
    let h = to_eye + (p - c).normalize();
    let n = h.try_normalize().unwrap_or(to_eye);
    let s = c + r * n;
    p - 2.0 * (p - s).dot(n) * n
}

#[cfg(test)]
mod tests {
    use super::curved_image;
    use glam::Vec3;

    #[test]
    fn a_curved_image_is_exact_for_points_as_far_as_the_eye() {
        let (c, r) = (Vec3::new(1.0, 2.0, 3.0), 2.0);
        let eye = c + Vec3::new(0.0, 1.0, 6.0);
        let d = (eye - c).length();
        for dir in [
            Vec3::new(1.0, 0.2, 0.3),
            Vec3::new(-2.0, 1.0, -0.5),
            Vec3::new(0.1, -1.0, 1.0),
        ] {
            let p = c + dir.normalize() * d;
            let img = curved_image(p, c, r, eye);
            // The reflection point: where the eye's ray to the image meets
            // the sphere; the law of reflection holds there.
            let n = ((eye - c).normalize() + (p - c).normalize()).normalize();
            let s = c + r * n;
            let (to_eye, to_p) = ((eye - s).normalize(), (p - s).normalize());
            assert!((to_eye.dot(n) - to_p.dot(n)).abs() < 1e-5, "angles at {s}");
            assert!(
                to_eye.cross(n).dot(to_p.cross(n)) <= 1e-5,
                "same plane, opposite sides"
            );
            let ray = (img - eye).normalize();
            assert!(
                ray.cross((s - eye).normalize()).length() < 1e-5,
                "{img} not on the ray through {s}"
            );
            // As far behind the tangent plane as p is in front of it.
            assert!(((img - s).dot(n) + (p - s).dot(n)).abs() < 1e-4);
        }
    }
}
