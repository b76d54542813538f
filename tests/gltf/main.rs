//! glTF 2.0 scenes (src/geometry/gltf_scene.rs, src/scene/gltf_objects.rs,
//! docs/gltf.md): files built in code with exact expectations, read as a
//! user's scene would read them; the node transforms, animations, skins and
//! materials checked against the specification's formulas and the CPU, and
//! hostile files refused with clear messages within bounded time and memory.

#[path = "../common/mod.rs"]
mod common;

mod files;
mod hostile;
mod images;
mod maps;
mod materials;
mod reader;
mod samples;
