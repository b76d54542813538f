//! Bloom against its CPU reference (notes 03, "Blur Pass and Merge Pass";
//! src/image_compare/bloom_reference.rs): what `gloss bench` reports for a
//! scene whose chain blooms, and what tests/post/bloom.rs asserts.
//!
//! The scene is drawn with its chain cascaded (each step its own
//! framebuffer, so every step's image is still there after the frame). The
//! image its first bloom step reads is the input; the CPU reference blooms
//! that input in f64 at full resolution; the step's output is compared
//! with it, in linear light.
//!
//! `bloom_image` runs the chain on an image of the caller's instead of the
//! world's: the image is written into the HDR target after every world pass,
//! so the chain reads it.

use super::headless;
use crate::frame::Runs;
use crate::frame::post::{self, HDR};
use crate::gl::Headless;
use crate::image_compare::bloom_reference::{self, BloomParams};
use crate::renderer::Renderer;
use crate::scene::Scene;
use crate::scene::bloom::Bloom;
use crate::scene::post::{ChainForm, PostPass};
use crate::techniques::ALL;
use anyhow::{Result, anyhow, bail};
use glow::HasContext;
use std::fmt;

/// How far a bloom is from the reference, in linear light. HDR values
/// span 0 to 65504, so each difference is read against the value it
/// should be: |a - r| / (r + mean), the mean of the reference keeping
/// dark pixels from dividing by nearly 0. The output is stored in half
/// floats (RGBA16F, 11 significant bits), so even an exact bloom is off
/// by up to 2^-12 = 2.4e-4 of each value.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BloomError {
    /// The root mean square of |a - r| / (r + mean) over R, G and B of
    /// every pixel.
    pub rms_rel: f64,
    /// The largest |a - r| / (r + mean) of any channel.
    pub max_rel: f64,
    /// The reference's mean over R, G and B.
    pub mean: f64,
}

impl fmt::Display for BloomError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "difference {:.2e} of the value (root mean square), at most {:.2e} (reference mean {:.4})",
            self.rms_rel, self.max_rel, self.mean
        )
    }
}

/// `output` (4 f32 a pixel) against `reference` (4 f64 a pixel), RGB.
pub fn error(output: &[f32], reference: &[f64]) -> BloomError {
    let rgb = |v: &[f64]| -> f64 { v.chunks_exact(4).map(|p| p[0] + p[1] + p[2]).sum() };
    let n = (reference.len() / 4 * 3).max(1) as f64;
    let mean = rgb(reference) / n;
    let floor = if mean > 0.0 { mean } else { 1.0 };
    let (mut sum, mut max) = (0.0, 0.0f64);
    for (o, r) in output.chunks_exact(4).zip(reference.chunks_exact(4)) {
        for c in 0..3 {
            let d = (f64::from(o[c]) - r[c]).abs();
            let d = if d.is_nan() { f64::INFINITY } else { d };
            let rel = d / (r[c].abs() + floor);
            sum += rel * rel;
            max = max.max(rel);
        }
    }
    BloomError {
        rms_rel: (sum / n).sqrt(),
        max_rel: max,
        mean,
    }
}

/// The reference's parameters for a bloom entry.
pub fn params(b: &Bloom) -> BloomParams {
    BloomParams {
        blurs: b.levels.map(|l| (l.sigma, l.radius)),
        weights: b.weights,
    }
}

/// A frame's first bloom step: what it read and what it wrote.
pub struct Bloomed {
    pub width: usize,
    pub height: usize,
    /// The image the bloom read, as the chain held it (half floats).
    pub input: Vec<f32>,
    pub output: Vec<f32>,
    /// The renderer, to read the bloom's levels.
    pub renderer: Renderer,
}

/// `scene` with its chain cascaded, and its first bloom entry's (entry, step).
fn cascaded(scene: &Scene) -> Result<(Scene, usize, usize)> {
    let (entry, step) = (post::entries(scene))
        .find_map(|(i, s, p)| matches!(p, PostPass::Bloom(_)).then_some((i, s)))
        .ok_or_else(|| anyhow!("{}: the chain has no bloom", scene.name))?;
    let mut s = scene.clone();
    s.render.post_chain = ChainForm::Cascaded;
    Ok((s, entry, step))
}

/// Draw `scene` (with `image`, 4 f32 a pixel at the scene's size, in place
/// of the world when given) and read its first bloom step's input and output.
pub fn bloom_image(ctx: &Headless, scene: &Scene, image: Option<&[f32]>) -> Result<Bloomed> {
    let (scene, _, step) = cascaded(scene)?;
    let (w, h) = scene.render.size;
    let (wi, hi) = (w as i32, h as i32);
    if image.is_some_and(|i| i.len() != (w * h * 4) as usize) {
        bail!("bloom_image: the image is not {w}x{h} RGBA");
    }
    let mut r = headless::renderer(ctx, &scene, (w, h))?;
    let hdr = r.targets().get(HDR).colors[0].id;
    let gl = ctx.gl.clone();
    let write = |gl: &glow::Context| {
        if let Some(data) = image {
            upload(gl, hdr, wi, hi, data);
        }
    };
    write(&gl);
    r.render_inspected(&scene.camera.clone(), &mut |pass| {
        if ALL[pass.technique].runs != Runs::AfterViews {
            write(&gl);
        }
    })?;
    let read = |i: post::Image| r.targets().get(i.target).read_rgba_f32(i.texture as u32);
    let input = read(post::reads(&scene, step));
    let output = read(post::writes(&scene, step));
    Ok(Bloomed {
        width: w as usize,
        height: h as usize,
        input,
        output,
        renderer: r,
    })
}

/// glTexSubImage2D of RGBA f32 `data` into `texture` (level 0).
pub fn upload(gl: &glow::Context, texture: glow::Texture, w: i32, h: i32, data: &[f32]) {
    // f32 has no padding: its bytes are the upload.
    let bytes =
        unsafe { std::slice::from_raw_parts(data.as_ptr().cast::<u8>(), size_of_val(data)) };
    unsafe {
        gl.bind_texture(glow::TEXTURE_2D, Some(texture));
        gl.pixel_store_i32(glow::UNPACK_ALIGNMENT, 4);
        gl.tex_sub_image_2d(
            glow::TEXTURE_2D,
            0,
            0,
            0,
            w,
            h,
            glow::RGBA,
            glow::FLOAT,
            glow::PixelUnpackData::Slice(Some(bytes)),
        );
        gl.bind_texture(glow::TEXTURE_2D, None);
    }
}

/// A frame's bloom against the CPU reference of its own input.
pub struct BloomEvaluation {
    pub bloomed: Bloomed,
    pub reference: Vec<f64>,
    pub error: BloomError,
}

/// Draw `scene` and measure its first bloom against the CPU reference.
pub fn evaluate(ctx: &Headless, scene: &Scene, image: Option<&[f32]>) -> Result<BloomEvaluation> {
    let (_, entry, _) = cascaded(scene)?;
    let PostPass::Bloom(b) = &scene.post[entry] else {
        unreachable!("cascaded found a bloom")
    };
    let bloomed = bloom_image(ctx, scene, image)?;
    let reference =
        bloom_reference::bloom(&bloomed.input, bloomed.width, bloomed.height, &params(b))?;
    let error = error(&bloomed.output, &reference);
    Ok(BloomEvaluation {
        bloomed,
        reference,
        error,
    })
}

/// The reference of the last input, kept: every setting of a bench draws
/// the same world, and the reference takes seconds at full size.
#[derive(Default)]
pub struct ReferenceCache {
    key: Option<(Vec<f32>, BloomParams)>,
    reference: Vec<f64>,
}

/// For `gloss bench`: `scene`'s first bloom against the CPU reference of
/// its own input, or None when its chain has no bloom.
pub fn bench_error(
    ctx: &Headless,
    scene: &Scene,
    cache: &mut ReferenceCache,
) -> Result<Option<BloomError>> {
    let Ok((_, entry, _)) = cascaded(scene) else {
        return Ok(None);
    };
    let PostPass::Bloom(b) = &scene.post[entry] else {
        unreachable!("cascaded found a bloom")
    };
    let bloomed = bloom_image(ctx, scene, None)?;
    let key = (bloomed.input.clone(), params(b));
    if cache.key.as_ref() != Some(&key) {
        cache.reference =
            bloom_reference::bloom(&bloomed.input, bloomed.width, bloomed.height, &key.1)?;
        cache.key = Some(key);
    }
    Ok(Some(error(&bloomed.output, &cache.reference)))
}

/// The bench's bloom table: each setting's bloom passes (the sum of their
/// median times) and its error against the reference.
pub fn table(rows: &[(String, f64, BloomError)]) -> String {
    let mut s = String::from(
        "bloom against the CPU reference (f64, full resolution; |a - r| / (r + mean)):\n",
    );
    s.push_str(&format!(
        "  {:<40} {:>12} {:>12} {:>12}\n",
        "setting", "bloom ms", "rms", "max"
    ));
    for (setting, ms, e) in rows {
        s.push_str(&format!(
            "  {setting:<40} {ms:>12.2} {:>12.2e} {:>12.2e}\n",
            e.rms_rel, e.max_rel
        ));
    }
    s
}

/// The sum of the median times of a row's bloom passes.
pub fn bloom_ms(passes: &[(String, super::Stats)]) -> f64 {
    (passes.iter())
        .filter(|(n, _)| n.starts_with("bloom"))
        .map(|(_, s)| s.median)
        .sum()
}
