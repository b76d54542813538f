//! gloss: an OpenGL 3.3 core-profile reference renderer for a real-time graphics course.
//!
//! The modules are layers; imports only run downwards (tests/architecture.rs
//! checks it, docs/architecture.md explains it):
//!
//! | layer | modules | holds |
//! |---|---|---|
//! | 0 | `math`, `image_compare` | notes 01 §2 transforms; image metrics |
//! | 1 | `geometry` | procedural shapes, OBJ loading, normals and tangents |
//! | 2 | `gl` | thin owners of GL objects, and the contexts |
//! | 3 | `scene` | scene types, the TOML format, validation |
//! | 4 | `lighting` | CPU twins of the shader formulas (Phong, attenuation) |
//! | 5 | `frame` | the plan, draw list, lights, targets, uniforms, timing |
//! | 6 | `techniques` | one file per technique, by chapter, and the registry |
//! | 7 | `renderer` | runs the plan |
//! | 8 | `bench`, `demo`, `trace` | the tools |
//! | 9 | `cli` | the command line as clap parses it; `src/main.rs` runs it |

pub mod assets;
pub mod bench;
pub mod cli;
pub mod demo;
pub mod frame;
pub mod geometry;
pub mod gl;
pub mod image_compare;
pub mod lighting;
pub mod math;
pub mod renderer;
pub mod scene;
pub mod techniques;
pub mod trace;
