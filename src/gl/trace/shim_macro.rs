//! The macro that turns each line of shims.rs into a recording function.

/// `shims! { glName(arg: Type = Kind, ..) -> Ret; .. }` makes, per line, a
/// slot for the driver's function and an `extern "system"` shim with the
/// same C signature that forwards the call and hands it to `record`;
/// and `lookup(name)`, the shim and slot of a GL function by name.
macro_rules! shims {
    ($( $name:ident ( $( $arg:ident : $ty:ident = $kind:expr ),* ) $( -> $ret:ident )? ; )*) => {
        #[allow(non_snake_case, non_upper_case_globals, unused_imports, clippy::too_many_arguments)]
        mod each {
            use super::super::record::record;
            use super::super::values::{Kind::*, Ptr, Raw};
            use std::ffi::c_void;
            use std::sync::atomic::{AtomicPtr, Ordering};
            $(
                pub mod $name {
                    use super::*;
                    pub static REAL: AtomicPtr<c_void> = AtomicPtr::new(std::ptr::null_mut());
                    pub extern "system" fn shim($( $arg: $ty ),*) $( -> $ret )? {
                        // SAFETY: REAL holds the driver's function of this
                        // name (`wrap` stores it before handing out the shim),
                        // whose C signature this shim's is.
                        let real: extern "system" fn($( $ty ),*) $( -> $ret )? =
                            unsafe { std::mem::transmute(REAL.load(Ordering::Relaxed)) };
                        let args = [$( ($kind, Raw::from($arg)) ),*];
                        let out = real($( $arg ),*);
                        record(stringify!($name), &args, Raw::result(&out));
                        out
                    }
                }
            )*
        }

        /// The shim of GL function `name` and the slot for the driver's own.
        pub fn lookup(name: &str) -> Option<(*const std::ffi::c_void, &'static std::sync::atomic::AtomicPtr<std::ffi::c_void>)> {
            match name {
                $( stringify!($name) => Some((each::$name::shim as *const std::ffi::c_void, &each::$name::REAL)), )*
                _ => None,
            }
        }
    };
}
