//! The frame: what every technique uses, and nothing above it.
//!
//! - `plan`: which passes a scene's frame runs and which targets they use,
//!   put together from the techniques' own lists (`gloss plan` prints it).
//! - `technique`: what a technique registers (its passes, targets, programs).
//! - `draw_list`: the scene's objects on the GPU, ready to draw.
//! - `lights`: what each light derives from the scene (volume radius, volume
//!   mesh) and the std140 block the shaders read: computed once, here.
//! - `uniforms`: per-frame values; `units`: the texture units, named once;
//!   `unit_check`: that the GL has the units past the 16 GL 3.3 promises
//!   that a scene's key asks for (gl::texture_units binds textures on them).
//! - `forward_pass`: the clip distances and per-frame uniforms the passes
//!   that light objects the forward way set up alike.
//! - `gbuffer`: the G-buffer's layout, written by one technique and read by many.
//! - `targets`: the render targets the plan names, allocated and sized.
//! - `meshes`: the meshes every screen or volume pass draws.
//! - `multisample`: the world's multisampled twin (MSAA on the forward path).
//! - `timing`: pass times around glFinish.
//! - `post`: the post chain's steps, what each reads and writes.
//! - `views`: the camera's view and the reflected views mirrors add.
//! - `clusters`: tiled shading's light binning on the CPU: each light's
//!   bounding sphere into screen tiles and depth slices (no GL).
//! - `variant`: which parts of the lighting model a scene's lighting
//!   passes compile (shaders specialised to the frame).
//! - `check`: what `gloss plan` checks without a GL context (the files the
//!   renderer loads, the light count), with the renderer's own functions.

pub mod alpha_maps;
pub mod billboards;
pub mod budget;
pub mod check;
pub mod clusters;
pub mod culling;
pub mod draw_list;
pub mod draw_textures;
pub mod environment;
pub mod forward_pass;
pub mod gbuffer;
pub mod gbuffer_slim;
pub mod image_based_lighting;
pub mod light_halves;
pub mod light_maps;
pub mod lights;
pub mod ltc_area_lights;
pub mod material_variant;
pub mod meshes;
pub mod multisample;
pub mod particles;
pub mod pass;
pub mod plan;
pub mod plan_graph;
pub mod plan_programs;
pub mod post;
pub mod shadows;
pub mod skins;
pub mod targets;
pub mod technique;
pub mod texturing;
pub mod timing;
pub mod uniforms;
pub mod unit_check;
pub mod units;
pub mod variant;
pub mod views;

pub use technique::{Frame, FrameOrder, Programs, RunPasses, Runs, Stage, Technique};
