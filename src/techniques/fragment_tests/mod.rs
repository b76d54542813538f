//! Notes 01 §4: the fragment tests that decide where a frame draws.

pub mod viewports;
