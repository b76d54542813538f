//! Notes 01 §4: the fragment tests that decide where a frame draws, and
//! per-sample processing (MSAA).

pub mod msaa;
pub mod viewports;
