//! How many GL objects the owners in this module have made and not yet
//! freed, per kind, on this thread (a context is current on one thread).
//! Tests read it to show that switching techniques and reloading scenes
//! leak nothing; it changes no GL state. `new_buffer`, `new_texture` and
//! `new_vertex_array` make an object and count it, for the owners that make them.

use glow::HasContext;
use std::cell::Cell;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    Program,
    Texture,
    Framebuffer,
    VertexArray,
    Buffer,
    Query,
    Sampler,
}

const KINDS: [(Kind, &str); 7] = [
    (Kind::Program, "programs"),
    (Kind::Texture, "textures"),
    (Kind::Framebuffer, "framebuffers"),
    (Kind::VertexArray, "vertex arrays"),
    (Kind::Buffer, "buffers"),
    (Kind::Query, "queries"),
    (Kind::Sampler, "samplers"),
];

thread_local! {
    static LIVE: [Cell<i64>; 7] = const { [const { Cell::new(0) }; 7] };
}

fn slot(k: Kind) -> usize {
    KINDS
        .iter()
        .position(|(x, _)| *x == k)
        .expect("every kind is listed")
}

pub(crate) fn made(k: Kind) {
    LIVE.with(|l| l[slot(k)].set(l[slot(k)].get() + 1));
}

/// glGenBuffers, counted; the error names the call.
///
/// # Safety
/// A current GL context.
pub(crate) unsafe fn new_buffer(gl: &glow::Context) -> anyhow::Result<glow::Buffer> {
    let b = unsafe { gl.create_buffer() }.map_err(|e| anyhow::anyhow!("glGenBuffers: {e}"))?;
    made(Kind::Buffer);
    Ok(b)
}

/// glGenTextures, counted; the error names the call.
///
/// # Safety
/// A current GL context.
pub(crate) unsafe fn new_texture(gl: &glow::Context) -> anyhow::Result<glow::Texture> {
    let t = unsafe { gl.create_texture() }.map_err(|e| anyhow::anyhow!("glGenTextures: {e}"))?;
    made(Kind::Texture);
    Ok(t)
}

/// glGenVertexArrays, counted; the error names the call.
///
/// # Safety
/// A current GL context.
pub(crate) unsafe fn new_vertex_array(gl: &glow::Context) -> anyhow::Result<glow::VertexArray> {
    let v = unsafe { gl.create_vertex_array() }
        .map_err(|e| anyhow::anyhow!("glGenVertexArrays: {e}"))?;
    made(Kind::VertexArray);
    Ok(v)
}

pub(crate) fn freed(k: Kind) {
    LIVE.with(|l| l[slot(k)].set(l[slot(k)].get() - 1));
}

/// The live objects of each kind, named.
pub fn counts() -> Vec<(&'static str, i64)> {
    LIVE.with(|l| {
        KINDS
            .iter()
            .map(|&(k, name)| (name, l[slot(k)].get()))
            .collect()
    })
}
