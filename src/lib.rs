//! gloss: an OpenGL 3.3 core-profile reference renderer for a real-time graphics course.
//!
//! Read it next to the notes in ../shared/notes (see docs/README.md for the map):
//! `gl/` owns GL objects and contexts; each technique has a file named as the
//! notes name it; `plan` decides which passes a scene's frame runs.

pub mod geometry;
pub mod gl;
pub mod math;
