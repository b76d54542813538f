//! What the passes that light objects the forward way (lighting/forward.rs,
//! lighting/parallax_mapping.rs, blending/transparent_draws.rs) set up
//! alike: the clip distances, and the per-frame uniforms of the forward
//! shaders. Each call stays in its own place: the technique file calls
//! these where its own listing has them.

use crate::frame::Frame;
use crate::frame::units as unit;
use crate::gl::program::Program;
use glow::HasContext;

/// A reflected view's plane (GL_CLIP_DISTANCE0, notes 05: only what lies in
/// front of the mirror) and the scene's clip planes (notes 01 §3.3,
/// GL_CLIP_DISTANCE1 on); `disable_clip_distances` undoes it.
///
/// # Safety
/// A current GL context.
pub unsafe fn enable_clip_distances(f: &Frame) {
    unsafe {
        if f.view.clips() {
            f.gl.enable(glow::CLIP_DISTANCE0);
        }
        for i in 0..f.scene.clip_planes.len() as u32 {
            f.gl.enable(glow::CLIP_DISTANCE1 + i);
        }
    }
}

/// Every clip distance `enable_clip_distances` may have turned on, off.
///
/// # Safety
/// A current GL context.
pub unsafe fn disable_clip_distances(f: &Frame) {
    unsafe {
        f.gl.disable(glow::CLIP_DISTANCE0);
        for i in 0..f.scene.clip_planes.len() as u32 {
            f.gl.disable(glow::CLIP_DISTANCE1 + i);
        }
    }
}

/// glUseProgram(p), then the frame's camera, ambient light, light count and
/// output encoding, and the material's texture units (diffuse, normal,
/// specular map).
pub fn use_with_frame_uniforms(f: &Frame, p: &Program) {
    let u = f.uniforms;
    p.use_program();
    p.set_mat4("u_view_projection", &u.view_projection);
    p.set_vec3("u_eye", u.eye);
    p.set_vec3("u_ambient", f.scene.render.ambient);
    p.set_i32("u_light_count", u.light_count);
    p.set_bool("u_output_srgb", u.output_srgb);
    p.set_i32("u_diffuse_texture", unit::DIFFUSE_TEXTURE as i32);
    p.set_i32("u_normal_map", unit::NORMAL_MAP as i32);
    p.set_i32("u_specular_map", unit::SPECULAR_MAP as i32);
}
