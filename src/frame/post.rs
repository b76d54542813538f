//! The post-processing chain's plumbing (notes 01 §9 "Post processing"):
//! "the scene is rendered into a framebuffer" whose texture the following
//! passes read, each "a single quad that fills the screen".
//!
//! With a `[[post]]` list, every view draws the world into `HDR` (linear
//! light in RGBA16F, with its own depth-stencil) instead of the output.
//! The chain then runs as numbered *steps*: a step is one full-screen draw
//! that reads the previous image and writes the next (a separable blur is
//! two steps, horizontal then vertical; bloom's merge is one, its blurs
//! write targets of their own). Step 0 reads `HDR`; the last step writes
//! the output. In between, the two forms of notes 01 §9:
//!
//! - `ping_pong`: "a single framebuffer and two textures are used and each
//!   processing stage samples from one texture and buffers to the other
//!   alternately". Step s draws into texture s % 2 and samples the other.
//!   Only the texture being drawn into is attached (glFramebufferTexture2D
//!   at every step): GL 3.3 §4.4.3 makes sampling *any* texture attached to
//!   the draw framebuffer a feedback loop, whichever draw buffer is chosen.
//! - `cascaded`: "processing stages may be cascaded using multiple
//!   processing render passes into multiple framebuffers": step s draws
//!   into framebuffer `post_{s+1}`, step s + 1 samples it.

use crate::frame::Frame;
use crate::frame::multisample;
use crate::frame::pass::Pass;
use crate::frame::targets::{Depth, OUTPUT, TargetDesc, Targets};
use crate::frame::uniforms::unit;
use crate::gl::program::Program;
use crate::gl::texture::Texture;
use crate::scene::Scene;
use crate::scene::post::{ChainForm, MAX_POST_PASSES, PostPass};
use glam::Mat4;
use glow::HasContext;

// The lit scene's target and format live with the other target names
// (src/frame/targets.rs), below the multisampled twin that also uses them.
pub use crate::frame::targets::{HDR, HDR_FORMAT};
/// The ping-pong form's one framebuffer, with its two textures.
pub const PING_PONG: &str = "post_ping_pong";
/// The most steps a chain has (every entry two steps).
pub const MAX_STEPS: usize = 2 * MAX_POST_PASSES;
/// The cascaded form's framebuffers: step s draws into `CASCADE[s]`.
pub const CASCADE: [&str; MAX_STEPS] = [
    "post_1", "post_2", "post_3", "post_4", "post_5", "post_6", "post_7", "post_8", "post_9",
    "post_10", "post_11", "post_12", "post_13", "post_14", "post_15", "post_16", "post_17",
    "post_18", "post_19", "post_20", "post_21", "post_22", "post_23", "post_24", "post_25",
    "post_26", "post_27", "post_28", "post_29", "post_30", "post_31", "post_32",
];

/// Where every view draws the world: the multisampled twin with MSAA
/// (src/frame/multisample.rs, resolved into `world_image` after the views),
/// else `world_image`.
pub fn world_target(scene: &Scene) -> &'static str {
    if multisample::active(scene) {
        multisample::MSAA
    } else {
        world_image(scene)
    }
}

/// The finished world image (its depth and stencil are the frame's): the
/// output, or `HDR` when a chain follows.
pub fn world_image(scene: &Scene) -> &'static str {
    if scene.post.is_empty() { OUTPUT } else { HDR }
}

/// How many steps (full-screen draws along the chain) an entry takes.
pub fn steps_of(p: &PostPass) -> usize {
    match p {
        PostPass::Blur { .. } | PostPass::Box { .. } => 2,
        _ => 1,
    }
}

/// The steps of the whole chain.
pub fn step_count(scene: &Scene) -> usize {
    scene.post.iter().map(steps_of).sum()
}

/// The chain's entries with the number of their first step.
pub fn entries(scene: &Scene) -> impl Iterator<Item = (usize, usize, &PostPass)> {
    let mut step = 0;
    (scene.post.iter().enumerate()).map(move |(i, p)| {
        let first = step;
        step += steps_of(p);
        (i, first, p)
    })
}

/// An image of the chain: a target's colour texture.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Image {
    pub target: &'static str,
    /// Which of the target's colour textures.
    pub texture: usize,
}

/// What step `s` samples.
pub fn reads(scene: &Scene, s: usize) -> Image {
    if s == 0 {
        return Image {
            target: HDR,
            texture: 0,
        };
    }
    writes(scene, s - 1)
}

/// What step `s` draws into.
pub fn writes(scene: &Scene, s: usize) -> Image {
    if s + 1 == step_count(scene) {
        return Image {
            target: OUTPUT,
            texture: 0,
        };
    }
    match scene.render.post_chain {
        ChainForm::PingPong => Image {
            target: PING_PONG,
            texture: s % 2,
        },
        ChainForm::Cascaded => Image {
            target: CASCADE[s],
            texture: 0,
        },
    }
}

/// The targets the chain needs besides the output: `HDR`, and the
/// ping-pong pair or one framebuffer per inner step. A chain of one step
/// needs neither. Every one is frame-sized and RGBA16F. `HDR` is the world
/// image: it has a depth-stencil buffer when `world_depth` (a pass drawing
/// into it needs one, src/frame/plan.rs).
pub fn targets(scene: &Scene, world_depth: bool) -> Vec<TargetDesc> {
    let steps = step_count(scene);
    if steps == 0 {
        return vec![];
    }
    let mut v = vec![TargetDesc {
        name: HDR,
        samples: 1,
        colors: vec![("color", HDR_FORMAT)],
        depth: if world_depth {
            Depth::Own(glow::DEPTH24_STENCIL8)
        } else {
            Depth::None
        },
        ping_pong: false,
        mips: None,
        downscale: 1,
    }];
    match scene.render.post_chain {
        ChainForm::PingPong if steps > 1 => v.push(TargetDesc {
            name: PING_PONG,
            samples: 1,
            colors: vec![("ping", HDR_FORMAT), ("pong", HDR_FORMAT)],
            depth: Depth::None,
            ping_pong: true,
            mips: None,
            downscale: 1,
        }),
        ChainForm::PingPong => {}
        ChainForm::Cascaded => v.extend(CASCADE[..steps - 1].iter().map(|&name| TargetDesc {
            name,
            samples: 1,
            colors: vec![("color", HDR_FORMAT)],
            depth: Depth::None,
            ping_pong: false,
            mips: None,
            downscale: 1,
        })),
    }
    v
}

/// The texture step `s` samples.
pub fn input<'a>(targets: &'a Targets, scene: &Scene, s: usize) -> &'a Texture {
    let i = reads(scene, s);
    &targets.get(i.target).colors[i.texture]
}

/// "A processing stage renders a single quad that fills the screen" into
/// the image step `s` writes: glBindFramebuffer, and for the ping-pong
/// framebuffer glFramebufferTexture2D of the texture it draws into (the
/// other is detached, so the step can sample it), then glViewport.
pub fn bind_output(gl: &glow::Context, targets: &Targets, scene: &Scene, s: usize) {
    let image = writes(scene, s);
    let fb = targets.get(image.target);
    unsafe {
        gl.bind_framebuffer(glow::FRAMEBUFFER, Some(fb.id));
        if image.target == PING_PONG {
            let t = &fb.colors[image.texture];
            gl.framebuffer_texture_2d(
                glow::FRAMEBUFFER,
                glow::COLOR_ATTACHMENT0,
                glow::TEXTURE_2D,
                Some(t.id),
                0,
            );
        }
        gl.viewport(0, 0, fb.width, fb.height);
    }
}

/// An image's name as `gloss plan` prints it: the target, and for the
/// ping-pong pair which of its textures.
pub fn image_name(targets: &[TargetDesc], image: Image) -> String {
    match targets.iter().find(|t| t.name == image.target) {
        Some(t) if t.colors.len() > 1 => format!("{}.{}", t.name, t.colors[image.texture].0),
        _ => image.target.to_string(),
    }
}

/// "reads hdr, writes post_ping_pong.ping": what step `s` of `scene`'s chain
/// samples and where it draws, for the plan.
pub fn describe(scene: &Scene, s: usize) -> String {
    // Names only: whether HDR has depth does not change them.
    let t = targets(scene, false);
    format!(
        "reads {}, writes {}",
        image_name(&t, reads(scene, s)),
        image_name(&t, writes(scene, s))
    )
}

/// The plan's pass for step `s` of entry `i`: pass `name` of the technique
/// in file `code`, drawing into what step `s` writes, described as `what`
/// (nothing when empty) and what it reads and writes.
pub fn step_pass(
    scene: &Scene,
    name: &'static str,
    what: &str,
    i: usize,
    s: usize,
    code: &'static str,
) -> Pass {
    let io = describe(scene, s);
    let draws = if what.is_empty() {
        io
    } else {
        format!("{what}: {io}")
    };
    Pass::new(name, writes(scene, s).target, draws, code)
        .about(i, s as u32)
        .reading(&[reads(scene, s).target])
}

/// One step of the chain as notes 01 §9 gives it: "a processing stage
/// renders a single quad that fills the screen which is then textured using
/// the colour attachment texture" of the step before.
///
/// 1. Bind the step's output (`bind_output`).
/// 2. Use `p`, bind the previous image on unit::POST_INPUT as `u_image`,
///    and let `set` give the pass's own uniforms.
/// 3. Draw the full-screen triangle (no depth test, no blending: both are
///    off between passes).
/// 4. Unbind the texture, the program and the framebuffer.
pub fn run_step(f: &Frame, p: &Program, s: usize, set: impl FnOnce(&Program)) {
    let gl = f.gl;
    let input = input(f.targets, f.scene, s);
    bind_output(gl, f.targets, f.scene, s);
    unsafe {
        p.use_program();
        gl.active_texture(glow::TEXTURE0 + unit::POST_INPUT);
        gl.bind_texture(glow::TEXTURE_2D, Some(input.id));
        p.set_i32("u_image", unit::POST_INPUT as i32);
        p.set_mat4("u_mvp", &Mat4::IDENTITY);
        set(p);
        f.meshes.fullscreen.draw();

        gl.bind_texture(glow::TEXTURE_2D, None);
        gl.use_program(None);
        gl.bind_framebuffer(glow::FRAMEBUFFER, None);
    }
}
