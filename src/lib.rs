//! gloss: an OpenGL 3.3 core-profile reference renderer for a real-time graphics course.
//!
//! Read it next to the notes in ../shared/notes (see docs/README.md for the map):
//! `gl/` owns GL objects and contexts; each technique has a file named as the
//! notes name it; `plan` decides which passes a scene's frame runs.

pub mod attenuation;
pub mod bench;
pub mod deferred;
pub mod deferred_lighting;
pub mod deferred_shading;
pub mod demo;
pub mod forward;
pub mod gbuffer;
pub mod geometry;
pub mod gl;
pub mod image_compare;
pub mod light_volumes;
pub mod lighting;
pub mod math;
pub mod plan;
pub mod renderer;
pub mod scene;
