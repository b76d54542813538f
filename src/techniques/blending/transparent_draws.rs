//! What the order-independent passes (weighted_blended.rs, depth_peeling.rs)
//! share with each other: which transparent objects a view draws, the
//! uniforms of the lit glass shader (glsl/blending/transparent_surface.glsl,
//! the same as transparency.rs sets), drawing them, and the texture the
//! opaque world's depth is in, and the composite's target and restore. Nothing
//! here chooses blending or the depth test: the technique files do that, in
//! their papers' order (the composite's blend factors are their arguments).

use crate::frame::Frame;
use crate::frame::draw_list::DrawList;
use crate::frame::forward_pass;
use crate::frame::post::world_target;
use crate::frame::uniforms::{LIGHTS_BINDING, unit};
use crate::gl::program::Program;
use crate::scene::texturing::Interpolation;
use glow::HasContext;

/// The transparent objects in this view's frustum (notes 01 §6.3), in scene
/// order: these techniques need no sort.
pub fn transparent_items(f: &Frame) -> Vec<usize> {
    let seen = f.in_view();
    (0..f.draws.items.len())
        .filter(|&i| f.draws.items[i].transparent && seen.as_ref().is_none_or(|s| s[i]))
        .collect()
}

/// The opaque world's depth: the world target's depth-stencil texture.
pub fn opaque_depth(f: &Frame) -> Option<glow::Texture> {
    let world = f.targets.get(world_target(f.scene));
    world.depth_stencil.as_ref().map(|t| t.id)
}

/// Use `p` and set what every transparent fragment reads: the view, the
/// lights, the shadow maps, the scene's clip planes.
///
/// # Safety
/// A current GL context; `restore` undoes it.
pub unsafe fn set_up(f: &Frame, p: &Program) {
    let (gl, u) = (f.gl, f.uniforms);
    unsafe {
        forward_pass::enable_clip_distances(f);
        p.use_program();
        f.view.set_uniforms(p, u.eye, &f.scene.clip_planes);
        p.set_mat4("u_view_projection", &u.view_projection);
        p.set_vec3("u_eye", u.eye);
        p.set_vec3("u_ambient", f.scene.render.ambient);
        p.set_i32("u_light_count", u.light_count);
        p.set_bool("u_output_srgb", u.output_srgb);
        p.set_i32("u_diffuse_texture", unit::DIFFUSE_TEXTURE as i32);
        p.set_i32("u_normal_map", unit::NORMAL_MAP as i32);
        p.set_i32("u_specular_map", unit::SPECULAR_MAP as i32);
        let affine = f.scene.render.interpolation == Interpolation::Affine;
        p.set_bool("u_affine", affine);
        gl.bind_buffer_base(glow::UNIFORM_BUFFER, LIGHTS_BINDING, Some(u.lights_ubo));
        f.shadows.bind(gl);
        gl.active_texture(glow::TEXTURE0 + unit::DIFFUSE_TEXTURE);
    }
}

/// Draw `items` with `p`, each once, both faces (culling is off: the order
/// of the fragments does not matter to these techniques).
///
/// # Safety
/// A current GL context, after `set_up`.
pub unsafe fn draw(f: &Frame, p: &Program, items: &[usize]) {
    for &i in items {
        let d = &f.draws.items[i];
        unsafe {
            f.gl.front_face(f.view.front_face(d.mirrored));
        }
        f.draws.bind_textures(f.gl, p, d, &f.scene.render);
        f.draws.set_object_uniforms(p, d);
        p.set_f32("u_opacity", d.opacity);
        f.draws.mesh(d).draw();
    }
}

/// Undo `set_up`.
///
/// # Safety
/// A current GL context.
pub unsafe fn restore(f: &Frame) {
    let gl = f.gl;
    unsafe {
        forward_pass::disable_clip_distances(f);
        gl.front_face(glow::CCW);
        DrawList::unbind_textures(gl);
        gl.bind_texture(glow::TEXTURE_2D, None);
        gl.active_texture(glow::TEXTURE0);
        gl.bind_buffer_base(glow::UNIFORM_BUFFER, LIGHTS_BINDING, None);
        f.shadows.unbind(gl);
        gl.use_program(None);
    }
}

/// Bind `texture` to texture unit `unit` for sampler `name` of `p`.
///
/// # Safety
/// A current GL context, `p` in use.
pub unsafe fn bind(f: &Frame, p: &Program, name: &str, unit: u32, texture: Option<glow::Texture>) {
    unsafe {
        f.gl.active_texture(glow::TEXTURE0 + unit);
        f.gl.bind_texture(glow::TEXTURE_2D, texture);
        f.gl.active_texture(glow::TEXTURE0);
    }
    p.set_i32(name, unit as i32);
}

/// Unbind texture unit `unit`.
///
/// # Safety
/// A current GL context.
pub unsafe fn unbind(f: &Frame, unit: u32) {
    unsafe {
        f.gl.active_texture(glow::TEXTURE0 + unit);
        f.gl.bind_texture(glow::TEXTURE_2D, None);
        f.gl.active_texture(glow::TEXTURE0);
    }
}

/// The composite onto the world's target: blending with the technique's
/// factors `src`, `dst` (glBlendFunc), colour only (the world's alpha
/// kept), and for a mirror's reflected view inside its stencil region
/// only; `end_composite` restores it.
///
/// # Safety
/// A current GL context.
pub unsafe fn begin_composite(f: &Frame, src: u32, dst: u32) {
    let gl = f.gl;
    let output = f.targets.get(world_target(f.scene));
    unsafe {
        gl.bind_framebuffer(glow::FRAMEBUFFER, Some(output.id));
        let (x, y, w, h) = f.view.rect(output.width, output.height);
        gl.viewport(x, y, w, h);
        gl.enable(glow::BLEND);
        gl.blend_func(src, dst);
        gl.color_mask(true, true, true, false);
        // A mirror's reflected view: inside its stencil region only.
        if let Some(region) = f.view.stencil {
            gl.enable(glow::STENCIL_TEST);
            gl.stencil_func(glow::EQUAL, region.into(), 0xff);
            gl.stencil_op(glow::KEEP, glow::KEEP, glow::KEEP);
        }
    }
}

/// Undo `begin_composite`: no stencil test, every colour channel written,
/// no blending (GL_ONE, GL_ZERO), the default framebuffer bound.
///
/// # Safety
/// A current GL context.
pub unsafe fn end_composite(gl: &glow::Context) {
    unsafe {
        gl.stencil_func(glow::ALWAYS, 0, 0xff);
        gl.disable(glow::STENCIL_TEST);
        gl.color_mask(true, true, true, true);
        gl.blend_func(glow::ONE, glow::ZERO);
        gl.disable(glow::BLEND);
        gl.bind_framebuffer(glow::FRAMEBUFFER, None);
    }
}
