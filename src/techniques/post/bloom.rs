//! Bloom (notes 03, "Blur Pass and Merge Pass"): "the blur pass executes 4
//! blurs each with a horizon blur pass and a vertical blur pass", blur k
//! "saved into a mipmap of the temporary frame buffer" (level k), and "the
//! merge pass merges the above 4 blur results and the original image with
//! the weighted factors using the Spencer model":
//!
//! ```text
//! 0.8843 g(x) + 0.1 g(6.2, x) + 0.012 g(24.9, x) + 0.0027 g(81.0, x) + 0.001 g(263, x)
//! ```
//!
//! For each blur k (bloom_levels.rs has where each runs and its kernel):
//! 1. downsample: the chain's image, sanitised (NaN 0, +inf 65504, negative
//!    0), box-averaged into level k of `BLOOM_LEVELS` (2^k x 2^k pixels a texel);
//! 2. horizontal blur: level k of `BLOOM_LEVELS` into level k of `BLOOM_TEMP`;
//! 3. vertical blur: level k of `BLOOM_TEMP` back into level k of `BLOOM_LEVELS`.
//!
//! Then 4. merge: the original and the four levels (bilinear upsample),
//! weighted, into the image the chain's step writes (src/frame/post.rs).
//! No pass samples the texture it draws into: each blur reads one texture
//! and writes the other's level.
//!
//! The kernels are `math::gaussian`'s, uploaded as a uniform block of
//! (offset, weight) taps: direct (one texel each) or linear (the
//! linear-filtering trick, one bilinear fetch per pair of texels).
//! `src/image_compare/bloom_reference.rs` is the CPU reference the tests
//! hold it to.
//!
//! GL state: the taps' uniform block at `TAPS_BINDING`, textures on units
//! 0-4; all unbound after, with the program and the framebuffer.

use super::bloom_levels::{self, BLOOM_FULL, BLOOM_FULL_TEMP, BLOOM_LEVELS, BLOOM_TEMP, Blur};
use crate::frame::lights::FrameLights;
use crate::frame::plan::Pass;
use crate::frame::post::{self, entries, step_pass};
use crate::frame::targets::{Depth, TargetDesc};
use crate::frame::uniforms::unit;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::buffer::Buffer;
use crate::gl::program::Program;
use crate::scene::Scene;
use crate::scene::bloom::{Bloom, BloomScheme};
use crate::scene::post::PostPass;
use anyhow::Result;
use glam::{Mat4, Vec2};
use glow::HasContext;

pub const BLOOM: Technique = Technique {
    name: "bloom",
    notes: "notes 03, Blur Pass and Merge Pass",
    file: file!(),
    shaders: &[
        "common/fullscreen.vert",
        "post/finite.glsl",
        "post/bloom_downsample.frag",
        "post/bloom_blur.frag",
        "post/bloom_merge.frag",
    ],
    scene: "scenes/bloom.toml",
    docs: "docs/post/bloom.md",
    knobs: &[],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::AfterViews,
};

/// The uniform-block binding of the blur's taps (`BloomTaps`).
pub const TAPS_BINDING: u32 = 2;
/// The most taps a side the block holds (two a vec4, 1024 vec4).
pub const MAX_TAPS: usize = 2048;
/// The merge's step: blur k's three passes are steps 3k .. 3k + 2 (k = 0..4,
/// a blur whose level does not exist has none), the merge comes last.
const MERGE_STEP: u32 = 12;
/// Texture units of the merge's four blurs (the image is unit::POST_INPUT).
const BLUR_UNITS: [u32; 4] = [
    unit::BLOOM_BLURS,
    unit::BLOOM_BLURS + 1,
    unit::BLOOM_BLURS + 2,
    unit::BLOOM_BLURS + 3,
];
/// The format of the levels: the chain's own.
const FORMAT: u32 = post::HDR_FORMAT;

/// The bloom entries of the chain: (entry, step, settings).
fn blooms(scene: &Scene) -> impl Iterator<Item = (usize, usize, &Bloom)> {
    entries(scene).filter_map(|(i, step, p)| match p {
        PostPass::Bloom(b) => Some((i, step, b)),
        _ => None,
    })
}

fn size(scene: &Scene) -> (i32, i32) {
    (scene.render.size.0 as i32, scene.render.size.1 as i32)
}

fn passes(scene: &Scene, _: &FrameLights) -> Vec<Pass> {
    let (w, h) = size(scene);
    let mut v = Vec::new();
    for (i, step, b) in blooms(scene) {
        let blurs = bloom_levels::blurs(b, w, h);
        for blur in &blurs {
            let s = 3 * blur.index as u32;
            let at = bloom_levels::describe(blur);
            let k = blur.index + 1;
            v.push(
                Pass::new(
                    "bloom downsample",
                    blur.target,
                    format!(
                        "blur{k}, {at}: {0}x{0} box of the sanitised image",
                        blur.block()
                    ),
                    file!(),
                )
                .reading(&[crate::frame::post::reads(scene, step).target])
                .step(s)
                .level(blur.level)
                .about(i, step as u32),
            );
            v.push(
                Pass::new("bloom blur h", blur.temp, format!("blur{k}, {at}"), file!())
                    .reading(&[blur.target])
                    .step(s + 1)
                    .level(blur.level)
                    .about(i, step as u32),
            );
            v.push(
                Pass::new(
                    "bloom blur v",
                    blur.target,
                    format!("blur{k}, {at}"),
                    file!(),
                )
                .reading(&[blur.temp])
                .step(s + 2)
                .level(blur.level)
                .about(i, step as u32),
            );
        }
        let missing = (blurs.len()..4)
            .map(|k| format!("blur{}", k + 1))
            .collect::<Vec<_>>();
        let clamp = match (missing.is_empty(), blurs.last()) {
            (true, _) => String::new(),
            (false, Some(last)) => format!(
                " ({} not at {w}x{h}: level {} stands in)",
                missing.join(", "),
                last.level
            ),
            (false, None) => format!(" (no mip level at {w}x{h}: the original stands in)"),
        };
        let weights = b.weights.map(|x| x.to_string()).join(" + ");
        v.push(
            step_pass(
                scene,
                "bloom merge",
                &format!("weights {weights}{clamp}"),
                i,
                step,
                file!(),
            )
            .reading(&blurs.iter().map(|b| b.target).take(1).collect::<Vec<_>>())
            .step(MERGE_STEP),
        );
    }
    v
}

fn mip_target(name: &'static str, first: u32, last: u32) -> TargetDesc {
    TargetDesc {
        name,
        samples: 1,
        colors: vec![("color", FORMAT)],
        depth: Depth::None,
        ping_pong: false,
        mips: Some((first, last)),
        downscale: 1,
    }
}

fn targets(scene: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    let (w, h) = size(scene);
    let mut v = Vec::new();
    let mut add = |d: TargetDesc| {
        if !v.contains(&d) {
            v.push(d);
        }
    };
    for (_, _, b) in blooms(scene) {
        match b.scheme {
            BloomScheme::Mips => {
                let last = bloom_levels::last_level(w, h);
                if last >= 1 {
                    add(mip_target(BLOOM_LEVELS, 1, last));
                    add(mip_target(BLOOM_TEMP, 1, last));
                }
            }
            BloomScheme::Full => {
                for name in BLOOM_FULL {
                    add(mip_target(name, 0, 0));
                }
                add(mip_target(BLOOM_FULL_TEMP, 0, 0));
            }
        }
    }
    v
}

struct BloomPasses {
    downsample: Program,
    blur: Program,
    merge: Program,
    /// The taps of the blur being drawn (std140: two (offset, weight) a vec4).
    taps: Buffer,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    let vert = (glow::VERTEX_SHADER, "common/fullscreen.vert");
    let blur = p.build(&[vert, (glow::FRAGMENT_SHADER, "post/bloom_blur.frag")])?;
    blur.bind_uniform_block("BloomTaps", TAPS_BINDING);
    Ok(Box::new(BloomPasses {
        downsample: p.build(&[vert, (glow::FRAGMENT_SHADER, "post/bloom_downsample.frag")])?,
        blur,
        merge: p.build(&[vert, (glow::FRAGMENT_SHADER, "post/bloom_merge.frag")])?,
        taps: Buffer::new(p.gl, glow::UNIFORM_BUFFER, MAX_TAPS * 8, glow::DYNAMIC_DRAW)?,
    }))
}

impl RunPasses for BloomPasses {
    fn run(&self, pass: &Pass, f: &Frame) {
        let PostPass::Bloom(b) = &f.scene.post[pass.item] else {
            unreachable!("the plan gives bloom its own entries")
        };
        let step = pass.value as usize;
        let input = post::input(f.targets, f.scene, step);
        // The blurs as the targets were made (a resized frame may have fewer levels).
        let blurs: Vec<Blur> = bloom_levels::blurs(b, input.width, input.height)
            .into_iter()
            .filter(|x| {
                f.targets
                    .mip(x.target)
                    .and_then(|t| t.level(x.level))
                    .is_some()
            })
            .collect();
        if pass.step == MERGE_STEP {
            return self.merge(f, step, b, &blurs);
        }
        let index = (pass.step / 3) as usize;
        // A frame resized below the plan's size may lack the blur's level.
        let Some(blur) = blurs.iter().find(|x| x.index == index) else {
            return;
        };
        match pass.step % 3 {
            0 => self.downsample(f, input.id, blur),
            1 => self.blur(f, blur, blur.target, blur.temp, Vec2::X),
            _ => self.blur(f, blur, blur.temp, blur.target, Vec2::Y),
        }
    }
}

impl BloomPasses {
    /// 1. The sanitised image, box-averaged into the blur's level.
    fn downsample(&self, f: &Frame, input: glow::Texture, blur: &Blur) {
        let (gl, p) = (f.gl, &self.downsample);
        let level = f
            .targets
            .mip(blur.target)
            .and_then(|t| t.level(blur.level))
            .expect("filtered in run");
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(level.framebuffer));
            gl.viewport(0, 0, level.width, level.height);
            p.use_program();
            gl.active_texture(glow::TEXTURE0 + unit::POST_INPUT);
            gl.bind_texture(glow::TEXTURE_2D, Some(input));
            p.set_i32("u_image", unit::POST_INPUT as i32);
            p.set_i32("u_block", blur.block() as i32);
            p.set_mat4("u_mvp", &Mat4::IDENTITY);
            f.meshes.fullscreen.draw();

            gl.bind_texture(glow::TEXTURE_2D, None);
            gl.use_program(None);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }

    /// 2. and 3. One direction of the separable blur: `from`'s level into `to`'s.
    fn blur(&self, f: &Frame, blur: &Blur, from: &str, to: &str, direction: Vec2) {
        let (gl, p) = (f.gl, &self.blur);
        let source = f.targets.mip(from).expect("planned");
        let level = f
            .targets
            .mip(to)
            .and_then(|t| t.level(blur.level))
            .expect("filtered in run");
        self.taps.write(&std140_taps(&blur.taps));
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(level.framebuffer));
            gl.viewport(0, 0, level.width, level.height);
            p.use_program();
            gl.bind_buffer_base(glow::UNIFORM_BUFFER, TAPS_BINDING, Some(self.taps.id));
            gl.active_texture(glow::TEXTURE0 + unit::POST_INPUT);
            gl.bind_texture(glow::TEXTURE_2D, Some(source.texture.id));
            p.set_i32("u_image", unit::POST_INPUT as i32);
            p.set_i32("u_lod", (blur.level - source.first()) as i32);
            p.set_i32("u_tap_count", blur.taps.len().min(MAX_TAPS) as i32);
            p.set_bool("u_linear", blur.linear);
            p.set_vec2("u_direction", direction);
            p.set_mat4("u_mvp", &Mat4::IDENTITY);
            f.meshes.fullscreen.draw();

            gl.bind_texture(glow::TEXTURE_2D, None);
            gl.bind_buffer_base(glow::UNIFORM_BUFFER, TAPS_BINDING, None);
            gl.use_program(None);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }

    /// 4. The Spencer merge, into the chain's next image.
    fn merge(&self, f: &Frame, step: usize, b: &Bloom, blurs: &[Blur]) {
        let gl = f.gl;
        post::run_step(f, &self.merge, step, |p| unsafe {
            let mut lod = [0.0f32; 4];
            let mut block = [1.0f32; 4];
            for i in 0..4 {
                let Some(src) = bloom_levels::merge_source(blurs, i) else {
                    continue;
                };
                let t = f.targets.mip(src.target).expect("planned");
                gl.active_texture(glow::TEXTURE0 + BLUR_UNITS[i]);
                gl.bind_texture(glow::TEXTURE_2D, Some(t.texture.id));
                p.set_i32(&format!("u_blur{i}"), BLUR_UNITS[i] as i32);
                lod[i] = (src.level - t.first()) as f32;
                block[i] = src.block() as f32;
            }
            gl.active_texture(glow::TEXTURE0 + unit::POST_INPUT);
            p.set_f32_array("u_lod", &lod);
            p.set_f32_array("u_block", &block);
            p.set_f32_array("u_weight", &b.weights.map(|w| w as f32));
            p.set_bool("u_has_blurs", !blurs.is_empty());
        });
        unsafe {
            for u in BLUR_UNITS {
                gl.active_texture(glow::TEXTURE0 + u);
                gl.bind_texture(glow::TEXTURE_2D, None);
            }
            gl.active_texture(glow::TEXTURE0);
        }
    }
}

/// The taps as the `BloomTaps` block holds them: (offset, weight, offset,
/// weight) a vec4, f32 (at most `MAX_TAPS`).
pub fn std140_taps(taps: &[(f64, f64)]) -> Vec<u8> {
    let mut bytes = Vec::with_capacity(taps.len().div_ceil(2) * 16);
    for &(offset, weight) in taps.iter().take(MAX_TAPS) {
        bytes.extend((offset as f32).to_ne_bytes());
        bytes.extend((weight as f32).to_ne_bytes());
    }
    bytes.resize(bytes.len().div_ceil(16) * 16, 0);
    bytes
}
