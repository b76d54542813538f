//! Billboards (notes 05, "Billboards", "Alpha Test" and "Alpha Test and
//! Billboards"): camera-facing textured quads drawn over the finished
//! opaque image, with the alpha test, plain blending or sorted blending.

// The chapter and its one technique share the notes' name.
#[allow(clippy::module_inception)]
pub mod billboards;
