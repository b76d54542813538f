//! The stencil test and its operations (notes 01 §4.3, notes 05 "Stencil
//! Test and Operation": the comparison (ref & mask) OP (stencil & mask),
//! then on stencil fail, depth fail and depth pass one of KEEP, ZERO,
//! REPLACE, INCR, INCR_WRAP, DECR, DECR_WRAP, INVERT, written through the
//! write mask) against a CPU model of the stencil buffer, every pixel read
//! back with glReadPixels(GL_STENCIL_INDEX).
//!
//! The picture: a 16 x 16 framebuffer with a DEPTH24_STENCIL8 attachment.
//! Each pixel starts with its own stencil value (all 256 values, one a
//! pixel, set with scissored glClear), the left half with depth 1 and the
//! right half with depth 0; a triangle over the whole framebuffer at
//! depth 1/2 is drawn with GL_LESS, so it passes the depth test on the left
//! and fails it on the right. Every function (NEVER ... ALWAYS) runs with
//! every operation in each of the three places, references 0 to 255 and
//! value and write masks other than 0xff (64 cases).

use crate::common;
use glow::HasContext;

const FUNCS: [u32; 8] = [
    glow::NEVER,
    glow::LESS,
    glow::LEQUAL,
    glow::GREATER,
    glow::GEQUAL,
    glow::EQUAL,
    glow::NOTEQUAL,
    glow::ALWAYS,
];
const OPS: [u32; 8] = [
    glow::KEEP,
    glow::ZERO,
    glow::REPLACE,
    glow::INCR,
    glow::INCR_WRAP,
    glow::DECR,
    glow::DECR_WRAP,
    glow::INVERT,
];
const SIDE: i32 = 16;

/// The stencil value pixel i starts with: every value 0..=255 once.
fn start(i: usize) -> u8 {
    ((i * 37 + 11) & 255) as u8
}

/// Whether pixel i passes the depth test (its stored depth is 1, the
/// triangle's 1/2, GL_LESS): the left half.
fn depth_passes(i: usize) -> bool {
    (i as i32 % SIDE) < SIDE / 2
}

/// The CPU model: the stencil test (GL 3.3 §4.1.5), its comparison on the
/// masked reference and value.
fn stencil_passes(func: u32, reference: u8, mask: u8, s: u8) -> bool {
    let (r, v) = (reference & mask, s & mask);
    match func {
        glow::NEVER => false,
        glow::LESS => r < v,
        glow::LEQUAL => r <= v,
        glow::GREATER => r > v,
        glow::GEQUAL => r >= v,
        glow::EQUAL => r == v,
        glow::NOTEQUAL => r != v,
        glow::ALWAYS => true,
        _ => unreachable!(),
    }
}

/// The CPU model: an operation's result for stored value `s` (8 bits:
/// INCR and DECR clamp to 0..=255, the _WRAP forms wrap).
fn apply(op: u32, reference: u8, s: u8) -> u8 {
    match op {
        glow::KEEP => s,
        glow::ZERO => 0,
        glow::REPLACE => reference,
        glow::INCR => s.saturating_add(1),
        glow::INCR_WRAP => s.wrapping_add(1),
        glow::DECR => s.saturating_sub(1),
        glow::DECR_WRAP => s.wrapping_sub(1),
        glow::INVERT => !s,
        _ => unreachable!(),
    }
}

/// One case: (function, reference, value mask, write mask, [sfail, dpfail, dppass]).
type Case = (u32, u8, u8, u8, [u32; 3]);

/// What the model says pixel i holds after `c`.
fn model(c: &Case, i: usize) -> u8 {
    let &(func, reference, mask, write, ops) = c;
    let s = start(i);
    let op = if !stencil_passes(func, reference, mask, s) {
        ops[0]
    } else if !depth_passes(i) {
        ops[1]
    } else {
        ops[2]
    };
    (s & !write) | (apply(op, reference, s) & write)
}

fn cases() -> Vec<Case> {
    let references = [0u8, 1, 128, 200, 255, 37, 99, 254];
    let writes = [0xffu8, 0x0f, 0xf0, 0xff, 0x5a, 0xff, 0x81, 0xff];
    let mut v = Vec::new();
    for &func in &FUNCS {
        for k in 0..8 {
            let mask = if k % 2 == 0 { 0xff } else { 0x3c };
            let ops = [OPS[k], OPS[(k + 3) % 8], OPS[(k + 5) % 8]];
            v.push((func, references[k], mask, writes[k], ops));
        }
    }
    v
}

unsafe fn shader(gl: &glow::Context, kind: u32, source: &str) -> glow::Shader {
    unsafe {
        let s = gl.create_shader(kind).unwrap();
        gl.shader_source(s, source);
        gl.compile_shader(s);
        assert!(
            gl.get_shader_compile_status(s),
            "{}",
            gl.get_shader_info_log(s)
        );
        s
    }
}

/// Run every case on the GL; returns each case's stencil buffer, bottom
/// row first.
fn run_on_gl(cases: &[Case]) -> Vec<Vec<u8>> {
    let ctx = common::context(common::backend());
    let gl = &*ctx.gl;
    let mut out = Vec::new();
    unsafe {
        let vs = shader(
            gl,
            glow::VERTEX_SHADER,
            "#version 330 core\nconst vec2 p[3] = vec2[3](vec2(-1.0, -1.0), vec2(3.0, -1.0), vec2(-1.0, 3.0));\nvoid main() { gl_Position = vec4(p[gl_VertexID], 0.0, 1.0); }\n",
        );
        let fs = shader(
            gl,
            glow::FRAGMENT_SHADER,
            "#version 330 core\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n",
        );
        let program = gl.create_program().unwrap();
        gl.attach_shader(program, vs);
        gl.attach_shader(program, fs);
        gl.link_program(program);
        assert!(gl.get_program_link_status(program));
        let vao = gl.create_vertex_array().unwrap();
        let fb = gl.create_framebuffer().unwrap();
        let color = gl.create_renderbuffer().unwrap();
        let depth_stencil = gl.create_renderbuffer().unwrap();
        gl.bind_framebuffer(glow::FRAMEBUFFER, Some(fb));
        for (rb, format, at) in [
            (color, glow::RGBA8, glow::COLOR_ATTACHMENT0),
            (
                depth_stencil,
                glow::DEPTH24_STENCIL8,
                glow::DEPTH_STENCIL_ATTACHMENT,
            ),
        ] {
            gl.bind_renderbuffer(glow::RENDERBUFFER, Some(rb));
            gl.renderbuffer_storage(glow::RENDERBUFFER, format, SIDE, SIDE);
            gl.framebuffer_renderbuffer(glow::FRAMEBUFFER, at, glow::RENDERBUFFER, Some(rb));
        }
        assert_eq!(
            gl.check_framebuffer_status(glow::FRAMEBUFFER),
            glow::FRAMEBUFFER_COMPLETE
        );
        gl.viewport(0, 0, SIDE, SIDE);
        gl.use_program(Some(program));
        gl.bind_vertex_array(Some(vao));
        for &(func, reference, mask, write, ops) in cases {
            // The start: each pixel's own value, depth 1 left and 0 right.
            gl.disable(glow::STENCIL_TEST);
            gl.disable(glow::DEPTH_TEST);
            gl.stencil_mask(0xff);
            gl.depth_mask(true);
            gl.enable(glow::SCISSOR_TEST);
            for i in 0..(SIDE * SIDE) as usize {
                gl.scissor(i as i32 % SIDE, i as i32 / SIDE, 1, 1);
                gl.clear_stencil(start(i) as i32);
                gl.clear(glow::STENCIL_BUFFER_BIT);
            }
            gl.scissor(0, 0, SIDE / 2, SIDE);
            gl.clear_depth_f32(1.0);
            gl.clear(glow::DEPTH_BUFFER_BIT);
            gl.scissor(SIDE / 2, 0, SIDE / 2, SIDE);
            gl.clear_depth_f32(0.0);
            gl.clear(glow::DEPTH_BUFFER_BIT);
            gl.disable(glow::SCISSOR_TEST);
            // The case: the stencil state under test, depth GL_LESS.
            gl.enable(glow::DEPTH_TEST);
            gl.depth_func(glow::LESS);
            gl.depth_mask(false);
            gl.enable(glow::STENCIL_TEST);
            gl.stencil_func(func, reference as i32, mask as u32);
            gl.stencil_op(ops[0], ops[1], ops[2]);
            gl.stencil_mask(write as u32);
            gl.draw_arrays(glow::TRIANGLES, 0, 3);
            // Read the stencil buffer back.
            let mut got = vec![0u8; (SIDE * SIDE) as usize];
            gl.pixel_store_i32(glow::PACK_ALIGNMENT, 1);
            gl.read_pixels(
                0,
                0,
                SIDE,
                SIDE,
                glow::STENCIL_INDEX,
                glow::UNSIGNED_BYTE,
                glow::PixelPackData::Slice(Some(&mut got)),
            );
            gl.pixel_store_i32(glow::PACK_ALIGNMENT, 4);
            out.push(got);
        }
        // Back to the default state.
        gl.disable(glow::STENCIL_TEST);
        gl.disable(glow::DEPTH_TEST);
        gl.depth_mask(true);
        gl.stencil_mask(0xff);
        gl.stencil_func(glow::ALWAYS, 0, 0xff);
        gl.stencil_op(glow::KEEP, glow::KEEP, glow::KEEP);
        gl.depth_func(glow::LESS);
        gl.clear_depth_f32(1.0);
        gl.clear_stencil(0);
        gl.bind_vertex_array(None);
        gl.use_program(None);
        gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        gl.delete_framebuffer(fb);
        gl.delete_renderbuffer(color);
        gl.delete_renderbuffer(depth_stencil);
        gl.delete_vertex_array(vao);
        gl.delete_program(program);
        gl.delete_shader(vs);
        gl.delete_shader(fs);
        ctx.debug.check(gl, "the stencil cases").unwrap();
    }
    out
}

fn name(e: u32) -> &'static str {
    match e {
        glow::NEVER => "NEVER",
        glow::LESS => "LESS",
        glow::LEQUAL => "LEQUAL",
        glow::GREATER => "GREATER",
        glow::GEQUAL => "GEQUAL",
        glow::EQUAL => "EQUAL",
        glow::NOTEQUAL => "NOTEQUAL",
        glow::ALWAYS => "ALWAYS",
        glow::KEEP => "KEEP",
        glow::ZERO => "ZERO",
        glow::REPLACE => "REPLACE",
        glow::INCR => "INCR",
        glow::INCR_WRAP => "INCR_WRAP",
        glow::DECR => "DECR",
        glow::DECR_WRAP => "DECR_WRAP",
        glow::INVERT => "INVERT",
        _ => "?",
    }
}

#[test]
fn every_function_and_operation_with_masks_as_the_cpu_model_says() {
    let cases = cases();
    // The cases cover what they claim: each function, each operation in
    // each of the three places, masks other than 0xff.
    for f in FUNCS {
        assert!(cases.iter().any(|c| c.0 == f && c.2 != 0xff));
        assert!(cases.iter().any(|c| c.0 == f && c.3 != 0xff));
    }
    for op in OPS {
        for place in 0..3 {
            assert!(
                cases.iter().any(|c| c.4[place] == op),
                "{} in place {place}",
                name(op)
            );
        }
    }
    let got = run_on_gl(&cases);
    let mut wrong = Vec::new();
    let mut used = std::collections::BTreeSet::new();
    for (c, buffer) in cases.iter().zip(&got) {
        for (i, &g) in buffer.iter().enumerate() {
            let want = model(c, i);
            if g != want {
                wrong.push(format!(
                    "func {} ref {} mask {:#04x} write {:#04x} ops [{}, {}, {}]: pixel ({}, {}) started {} holds {g}, the model says {want}",
                    name(c.0), c.1, c.2, c.3, name(c.4[0]), name(c.4[1]), name(c.4[2]),
                    i as i32 % SIDE, i as i32 / SIDE, start(i)
                ));
            }
            // Which operation the model applied here, when it changed the value.
            if want != start(i) {
                let s = start(i);
                let op = if !stencil_passes(c.0, c.1, c.2, s) {
                    c.4[0]
                } else if !depth_passes(i) {
                    c.4[1]
                } else {
                    c.4[2]
                };
                used.insert(name(op));
            }
        }
    }
    assert!(
        wrong.is_empty(),
        "{} of {} stencil values differ from the model; first:\n  {}",
        wrong.len(),
        cases.len() * (SIDE * SIDE) as usize,
        wrong[..wrong.len().min(12)].join("\n  ")
    );
    // Every operation but KEEP changed some pixel somewhere.
    assert_eq!(used.len(), 7, "operations that changed a value: {used:?}");
}
