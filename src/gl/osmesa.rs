//! Headless OpenGL 3.3 core through Mesa's OSMesa (../shared/stack-facts.md).
//!
//! `libOSMesa.so.8` is loaded at run time with libloading, so gloss builds and
//! runs on machines without it (the EGL backend is the default; OSMesa was
//! removed from Mesa in 25.1 and is only the fallback). The context is made
//! current on a tiny buffer of our own: gloss renders into its own FBOs and
//! never draws to OSMesa's buffer.

use anyhow::{Result, anyhow, bail};
use libloading::Library;
use std::ffi::{CString, c_char, c_int, c_uint, c_void};

// From Mesa's include/GL/osmesa.h.
const OSMESA_FORMAT: c_int = 0x22;
const OSMESA_DEPTH_BITS: c_int = 0x30;
const OSMESA_STENCIL_BITS: c_int = 0x31;
const OSMESA_ACCUM_BITS: c_int = 0x32;
const OSMESA_PROFILE: c_int = 0x33;
const OSMESA_CORE_PROFILE: c_int = 0x34;
const OSMESA_CONTEXT_MAJOR_VERSION: c_int = 0x36;
const OSMESA_CONTEXT_MINOR_VERSION: c_int = 0x37;
const GL_RGBA: c_int = 0x1908;
const GL_UNSIGNED_BYTE: c_uint = 0x1401;

/// The library's soname; the unversioned `libOSMesa.so` comes only with the -dev package.
const LIBRARY: &str = "libOSMesa.so.8";
const INSTALL_HINT: &str = "OSMesa is not installed: apt-get install libosmesa6";

/// Size of the buffer the context is made current on (RGBA8).
const BUFFER_SIZE: i32 = 16;

type OsMesaContext = *mut c_void;
type CreateContextAttribs = unsafe extern "C" fn(*const c_int, OsMesaContext) -> OsMesaContext;
type DestroyContext = unsafe extern "C" fn(OsMesaContext);
type MakeCurrent = unsafe extern "C" fn(OsMesaContext, *mut c_void, c_uint, c_int, c_int) -> u8;
type GetCurrentContext = unsafe extern "C" fn() -> OsMesaContext;
type GetProcAddress = unsafe extern "C" fn(*const c_char) -> *const c_void;

/// The library, the context and its buffer, kept alive by `Headless`.
struct OsMesaKeep {
    context: OsMesaContext,
    destroy: DestroyContext,
    make_current: MakeCurrent,
    get_current: GetCurrentContext,
    // Read by OSMesa through the raw pointer handed to OSMesaMakeCurrent.
    buffer: Box<[u8]>,
    // Declared last: the function pointers above point into it, so it is
    // unloaded after the context is gone.
    _library: Library,
}

impl Drop for OsMesaKeep {
    fn drop(&mut self) {
        unsafe {
            // Unbind first if the context is current on this thread (gallium
            // OSMesa accepts a null context with a null buffer as "release").
            if (self.get_current)() == self.context {
                (self.make_current)(std::ptr::null_mut(), std::ptr::null_mut(), 0, 0, 0);
            }
            (self.destroy)(self.context);
        }
    }
}

/// Copy a symbol's address out of the library as a plain function pointer.
///
/// Safety: `T` must be the symbol's C signature. The caller keeps `library`
/// loaded for as long as the pointer is used.
unsafe fn symbol<T: Copy>(library: &Library, name: &str) -> Result<T> {
    let c_name = CString::new(name).map_err(|_| anyhow!("symbol name {name:?} has a NUL"))?;
    let sym = unsafe { library.get::<T>(c_name.as_bytes_with_nul()) }.map_err(|e| {
        anyhow!(
            "{LIBRARY} has no {name} ({e}); it is too old or not Mesa's OSMesa. \
             apt-get install libosmesa6"
        )
    })?;
    Ok(*sym)
}

/// Create the context, make it current on this thread and load glow from it.
///
/// OSMesa has no debug-context attribute; `DebugLog::install` still turns on
/// KHR_debug output, which Mesa allows in any context.
pub fn create() -> Result<(glow::Context, Box<dyn std::any::Any>)> {
    let library = unsafe { Library::new(LIBRARY) }.map_err(|e| anyhow!("{INSTALL_HINT} ({e})"))?;
    let (create_attribs, destroy, make_current, get_current, get_proc) = unsafe {
        (
            symbol::<CreateContextAttribs>(&library, "OSMesaCreateContextAttribs")?,
            symbol::<DestroyContext>(&library, "OSMesaDestroyContext")?,
            symbol::<MakeCurrent>(&library, "OSMesaMakeCurrent")?,
            symbol::<GetCurrentContext>(&library, "OSMesaGetCurrentContext")?,
            symbol::<GetProcAddress>(&library, "OSMesaGetProcAddress")?,
        )
    };

    let attribs: [c_int; 15] = [
        OSMESA_FORMAT,
        GL_RGBA,
        OSMESA_DEPTH_BITS,
        24,
        OSMESA_STENCIL_BITS,
        8,
        OSMESA_ACCUM_BITS,
        0,
        OSMESA_PROFILE,
        OSMESA_CORE_PROFILE,
        OSMESA_CONTEXT_MAJOR_VERSION,
        3,
        OSMESA_CONTEXT_MINOR_VERSION,
        3,
        0,
    ];
    let context = unsafe { create_attribs(attribs.as_ptr(), std::ptr::null_mut()) };
    if context.is_null() {
        bail!(
            "OSMesa could not create an OpenGL 3.3 core context (RGBA, depth 24, stencil 8); \
             this Mesa is too old or its OSMesa lacks core profiles: apt-get install libosmesa6 \
             libgl1-mesa-dri, or use --backend egl"
        );
    }
    let mut keep = OsMesaKeep {
        context,
        destroy,
        make_current,
        get_current,
        buffer: vec![0u8; (BUFFER_SIZE * BUFFER_SIZE * 4) as usize].into_boxed_slice(),
        _library: library,
    };
    let ok = unsafe {
        make_current(
            context,
            keep.buffer.as_mut_ptr().cast(),
            GL_UNSIGNED_BYTE,
            BUFFER_SIZE,
            BUFFER_SIZE,
        )
    };
    if ok == 0 {
        // `keep` destroys the context on the way out.
        bail!("OSMesaMakeCurrent failed on a {BUFFER_SIZE}x{BUFFER_SIZE} RGBA8 buffer");
    }
    let gl = unsafe {
        glow::Context::from_loader_function(|name| match CString::new(name) {
            Ok(c_name) => super::trace::wrap(name, get_proc(c_name.as_ptr())),
            Err(_) => std::ptr::null(),
        })
    };
    Ok((gl, Box::new(keep)))
}

#[cfg(test)]
mod tests {
    use crate::gl::framebuffer::Framebuffer;
    use crate::gl::{Backend, Headless};
    use glow::HasContext;

    /// Skip (with a note) when libOSMesa.so.8 is absent; CI installs it.
    fn osmesa_installed() -> bool {
        let present = unsafe { libloading::Library::new(super::LIBRARY) }.is_ok();
        if !present {
            eprintln!("skipping: {}", super::INSTALL_HINT);
        }
        present
    }

    #[test]
    fn osmesa_clears_an_fbo_and_reads_it_back() {
        if !osmesa_installed() {
            return;
        }
        let ctx = Headless::new(Backend::Osmesa, true).expect("OSMesa context");
        assert!(ctx.info.core_profile, "{}", ctx.info);
        assert!(ctx.info.at_least(3, 3), "{}", ctx.info);
        let fb = Framebuffer::new(&ctx.gl, "test", 8, 4, &[glow::RGBA8], None).expect("fbo");
        unsafe {
            ctx.gl.bind_framebuffer(glow::FRAMEBUFFER, Some(fb.id));
            ctx.gl.viewport(0, 0, 8, 4);
            ctx.gl.clear_color(1.0, 0.5, 0.0, 1.0);
            ctx.gl.clear(glow::COLOR_BUFFER_BIT);
            ctx.gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
        ctx.debug.check(&ctx.gl, "clear").expect("no GL errors");
        let img = fb.read_rgba8_top_down(0);
        let px = img.get_pixel(3, 2).0;
        assert_eq!(px[0], 255);
        assert!((127..=128).contains(&px[1]), "{px:?}");
        assert_eq!((px[2], px[3]), (0, 255));
        ctx.debug.check(&ctx.gl, "read back").expect("no GL errors");
        drop(fb);
    }

    /// EGL and OSMesa must agree on the version they give a 3.3 core request
    /// (4.5 on Mesa; 3.3 under MESA_GL_VERSION_OVERRIDE=3.3 as .ci/run sets).
    #[test]
    fn osmesa_and_egl_report_the_same_version() {
        if !osmesa_installed() {
            return;
        }
        let (osmesa, osmesa_core) = {
            let ctx = Headless::new(Backend::Osmesa, false).expect("OSMesa context");
            ((ctx.info.major, ctx.info.minor), ctx.info.core_profile)
        };
        let (egl, egl_core) = {
            let ctx = Headless::new(Backend::Egl, false).expect("EGL context");
            ((ctx.info.major, ctx.info.minor), ctx.info.core_profile)
        };
        assert_eq!(osmesa, egl, "OSMesa and EGL give different GL versions");
        assert!(osmesa_core && egl_core);
        if std::env::var("MESA_GL_VERSION_OVERRIDE").as_deref() == Ok("3.3") {
            assert_eq!(osmesa, (3, 3));
        }
    }
}
