//! Textures on fixed texture units (src/frame/units.rs names them): a list
//! of (unit, target, texture) bound in order, and unbound in the same order.
//! An owner's helper like the others here: `gloss trace` lists each call at
//! the line that asked for the list (with this file as `via`), so a listing
//! and the frame's unit checks (src/trace/units.rs) still see which code
//! bound what.

use glow::HasContext;

/// One texture on one fixed unit: `glActiveTexture(GL_TEXTURE0 + unit)`,
/// then `glBindTexture(target, texture)`.
#[derive(Clone, Copy, Debug)]
pub struct OnUnit {
    pub unit: u32,
    /// GL_TEXTURE_2D, GL_TEXTURE_CUBE_MAP, GL_TEXTURE_2D_ARRAY.
    pub target: u32,
    pub texture: glow::Texture,
}

/// Bind `texture` to `target` on `unit`; the active unit stays `unit`.
pub fn bind_one(gl: &glow::Context, unit: u32, target: u32, texture: Option<glow::Texture>) {
    unsafe {
        gl.active_texture(glow::TEXTURE0 + unit);
        gl.bind_texture(target, texture);
    }
}

/// Bind each texture on its unit, in the list's order, then make unit 0
/// active again.
pub fn bind(gl: &glow::Context, textures: &[OnUnit]) {
    for t in textures {
        bind_one(gl, t.unit, t.target, Some(t.texture));
    }
    unsafe { gl.active_texture(glow::TEXTURE0) };
}

/// Undo `bind`: nothing bound to each target on each unit, in the same
/// order, then unit 0 active again.
pub fn unbind(gl: &glow::Context, textures: &[OnUnit]) {
    for t in textures {
        bind_one(gl, t.unit, t.target, None);
    }
    unsafe { gl.active_texture(glow::TEXTURE0) };
}
