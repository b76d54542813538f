//! Notes 05 with the stencil buffer: planar mirrors (src/techniques/stencil/).
//!
//! * the two orders of the slides give the same image;
//! * each reflection, at every depth of a recursion, matches an independent
//!   reference: the scene drawn without mirrors from the camera reflected
//!   through the same mirrors (reflect the viewpoint rather than the world),
//!   mirrored left-right for an odd number of reflections, in the region
//!   the stencil buffer marks for that reflection;
//! * the clip plane keeps what lies behind a mirror out of its reflection,
//!   and the winding fix matters;
//! * several mirrors each have their own stencil value;
//! * `gloss plan` has no stencil pass without a mirror; every mirror pass
//!   restores the GL state; bad mirrors are clear scene errors.
//!
//! Object outlines (LearnOpenGL, Stencil testing): the band's width in
//! pixels against the silhouette projected by hand (object_outlines.rs).
//!
//! Every render runs with GL debug output on and fails on any GL error.

#[path = "../common/mod.rs"]
mod common;

mod functions;
mod mirror;
mod object_outlines;
