//! The feedback-loop check (src/gl/debug.rs, `feedback_loops`) sees a
//! texture sampled while it is attached to the draw framebuffer on every
//! texture target gloss draws into, not only GL_TEXTURE_2D: a face of a
//! cube map (the sky's cube map, a point light's shadow cube), a layer of a
//! 2D array, a multisampled image (MSAA). Each loop is built on purpose and
//! must be caught; the same framebuffer with another texture of the same
//! kind bound must not be.

use crate::common;
use gloss::gl::debug::feedback_loops;
use glow::{HasContext, PixelUnpackData};

/// A texture of `target`, 4 x 4 (6 faces, or 3 layers), `internal` format.
unsafe fn make(gl: &glow::Context, target: u32, internal: u32) -> glow::Texture {
    unsafe {
        let t = gl.create_texture().unwrap();
        gl.bind_texture(target, Some(t));
        let (format, ty) = if internal == glow::DEPTH_COMPONENT24 {
            (glow::DEPTH_COMPONENT, glow::FLOAT)
        } else {
            (glow::RGBA, glow::UNSIGNED_BYTE)
        };
        match target {
            glow::TEXTURE_CUBE_MAP => {
                for face in 0..6 {
                    gl.tex_image_2d(
                        glow::TEXTURE_CUBE_MAP_POSITIVE_X + face,
                        0,
                        internal as i32,
                        4,
                        4,
                        0,
                        format,
                        ty,
                        PixelUnpackData::Slice(None),
                    );
                }
            }
            glow::TEXTURE_2D_ARRAY => gl.tex_image_3d(
                target,
                0,
                internal as i32,
                4,
                4,
                3,
                0,
                format,
                ty,
                PixelUnpackData::Slice(None),
            ),
            glow::TEXTURE_2D_MULTISAMPLE => {
                gl.tex_image_2d_multisample(target, 4, internal as i32, 4, 4, true)
            }
            _ => gl.tex_image_2d(
                target,
                0,
                internal as i32,
                4,
                4,
                0,
                format,
                ty,
                PixelUnpackData::Slice(None),
            ),
        }
        if target != glow::TEXTURE_2D_MULTISAMPLE {
            gl.tex_parameter_i32(target, glow::TEXTURE_MIN_FILTER, glow::NEAREST as i32);
            gl.tex_parameter_i32(target, glow::TEXTURE_MAG_FILTER, glow::NEAREST as i32);
        }
        gl.bind_texture(target, None);
        t
    }
}

/// Attach `t` (of `target`) to a new framebuffer at `at` (with an RGBA8
/// colour texture beside a depth attachment), bind `sampled` to unit 3 as
/// `target`, and return what the check finds with the framebuffer bound.
fn check(target: u32, internal: u32, at: u32, loop_on_purpose: bool) -> Vec<String> {
    let ctx = common::context(common::backend());
    let gl = &*ctx.gl;
    unsafe {
        let attached = make(gl, target, internal);
        let other = make(gl, target, internal);
        let fb = gl.create_framebuffer().unwrap();
        gl.bind_framebuffer(glow::FRAMEBUFFER, Some(fb));
        match target {
            // Face -Y of the cube map, layer 2 of the array.
            glow::TEXTURE_CUBE_MAP => gl.framebuffer_texture_2d(
                glow::FRAMEBUFFER,
                at,
                glow::TEXTURE_CUBE_MAP_NEGATIVE_Y,
                Some(attached),
                0,
            ),
            glow::TEXTURE_2D_ARRAY => {
                gl.framebuffer_texture_layer(glow::FRAMEBUFFER, at, Some(attached), 0, 2)
            }
            _ => gl.framebuffer_texture_2d(glow::FRAMEBUFFER, at, target, Some(attached), 0),
        }
        if at == glow::DEPTH_ATTACHMENT {
            // A depth-only framebuffer: no colour to draw.
            gl.draw_buffer(glow::NONE);
            gl.read_buffer(glow::NONE);
        }
        assert_eq!(
            gl.check_framebuffer_status(glow::FRAMEBUFFER),
            glow::FRAMEBUFFER_COMPLETE,
            "the framebuffer for target {target:#x}"
        );
        gl.active_texture(glow::TEXTURE3);
        let sampled = if loop_on_purpose { attached } else { other };
        gl.bind_texture(target, Some(sampled));
        gl.active_texture(glow::TEXTURE0);
        let found = feedback_loops(gl);
        // Leave a clean context: no loop for the debug check at drop.
        gl.active_texture(glow::TEXTURE3);
        gl.bind_texture(target, None);
        gl.active_texture(glow::TEXTURE0);
        gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        gl.delete_framebuffer(fb);
        gl.delete_texture(attached);
        gl.delete_texture(other);
        ctx.debug.check(gl, "building the loops").unwrap();
        found
    }
}

const CASES: [(u32, u32, u32, &str); 4] = [
    (
        glow::TEXTURE_CUBE_MAP,
        glow::RGBA8,
        glow::COLOR_ATTACHMENT0,
        "GL_TEXTURE_CUBE_MAP",
    ),
    (
        glow::TEXTURE_CUBE_MAP,
        glow::DEPTH_COMPONENT24,
        glow::DEPTH_ATTACHMENT,
        "GL_TEXTURE_CUBE_MAP",
    ),
    (
        glow::TEXTURE_2D_ARRAY,
        glow::RGBA8,
        glow::COLOR_ATTACHMENT0,
        "GL_TEXTURE_2D_ARRAY",
    ),
    (
        glow::TEXTURE_2D_MULTISAMPLE,
        glow::RGBA8,
        glow::COLOR_ATTACHMENT0,
        "GL_TEXTURE_2D_MULTISAMPLE",
    ),
];

#[test]
fn a_cube_map_face_an_array_layer_or_a_multisampled_image_sampled_while_drawn_into_is_caught() {
    for (target, internal, at, name) in CASES {
        let found = check(target, internal, at, true);
        assert_eq!(found.len(), 1, "{name} at {at:#x}: {found:?}");
        assert!(
            found[0].contains(&format!("bound as {name} to texture unit 3")),
            "{found:?}"
        );
    }
}

#[test]
fn another_texture_of_the_same_kind_is_no_loop() {
    for (target, internal, at, name) in CASES {
        let found = check(target, internal, at, false);
        assert!(found.is_empty(), "{name} at {at:#x}: {found:?}");
    }
}
