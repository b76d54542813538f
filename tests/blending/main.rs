//! Blending (src/techniques/blending/): transparent objects.
//!
//! * the back-to-front sort: ties, the camera inside an object's bounding
//!   box, objects behind the camera;
//! * two glass panes over the background equal the over-operator of notes 01
//!   §4.5 computed on the CPU from their Phong colours: in linear light
//!   within 1e-4 (float output), sRGB-encoded within 2/255 (8-bit output);
//!   order matters, and unsorted the wrong order is what comes out;
//! * a transparent object looks the same in every render path (forward vs
//!   each deferred path within DEFERRED_BOUND), the pass is planned only for
//!   a scene with a transparent material, and it restores the GL state.
//!
//! * order-independent transparency (weighted blended, depth peeling): depth
//!   peeling within 1e-4 of the over operator composited on the CPU from the
//!   panes' geometry, weighted blended against depth peeling with stated
//!   bounds, crossed panes that sorting per object gets wrong.
//!
//! Every render runs with GL debug output on and fails on any GL error.

#[path = "../common/mod.rs"]
mod common;

mod order_independent_transparency;
mod transparency;
