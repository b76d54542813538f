//! `gloss trace`'s recording GL layer: every GL function glow loads is
//! replaced, when tracing is on, by a shim (shims.rs, generated from glow's
//! own signatures) that records the call, its arguments as GL names, the
//! line of gloss's source that made it and the pass it belongs to, and then
//! calls the driver's function. Nothing changes in the code that draws: the
//! layer sits between glow and the driver, so what it lists is what the
//! frame executed.
//!
//! 1. `enable()` before the context is made: the loaders (egl.rs,
//!    osmesa.rs) pass each function pointer through `wrap`.
//! 2. `start()`, draw the frame, `stop()` returns the calls in order.
//! 3. The renderer names each pass with `enter_pass` / `leave_pass`.

mod names;
mod record;
#[macro_use]
mod shim_macro;
mod shims;
mod values;

pub use record::{Call, PassLabel, Site, enter_pass, leave_pass, program_defines, start, stop};
pub use values::constant_name;

use std::ffi::c_void;
use std::sync::atomic::{AtomicBool, Ordering};

static WRAP: AtomicBool = AtomicBool::new(false);

/// Make every context created from now on record its calls when asked
/// (`start`). Call it before the context is made.
pub fn enable() {
    WRAP.store(true, Ordering::SeqCst);
}

/// The function the loader hands glow for `name`: the driver's `real`
/// unless tracing is enabled and `name` has a shim. A missing function
/// stays missing (null), so glow still sees it as not loaded.
pub fn wrap(name: &str, real: *const c_void) -> *const c_void {
    if !WRAP.load(Ordering::SeqCst) || real.is_null() {
        return real;
    }
    match shims::lookup(name) {
        Some((shim, slot)) => {
            slot.store(real as *mut c_void, Ordering::SeqCst);
            shim
        }
        None => real,
    }
}

/// Every constant gloss's source names (for the test that the name table
/// is complete): `(value, "GL_NAME")`.
pub fn named_constants() -> impl Iterator<Item = (u32, &'static str)> {
    names::NAMES.iter().map(|(v, n, _)| (*v, *n))
}
