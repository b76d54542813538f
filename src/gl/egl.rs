//! Headless OpenGL 3.3 core through EGL with no display (../shared/stack-facts.md).
//!
//! glutin has no surfaceless-platform constructor, so this uses the EGL
//! *device* platform (EGL_EXT_platform_device): pick Mesa's software device
//! (EGL_MESA_device_software) or, on a GPU machine, a hardware device; ask for
//! a config with no surface type; make the context current with no surface;
//! render into our own framebuffer objects.

use anyhow::{Context as _, Result, anyhow};
use glutin::api::egl::{context::PossiblyCurrentContext, device::Device, display::Display};
use glutin::config::{Api, ConfigSurfaceTypes, ConfigTemplateBuilder};
use glutin::context::{ContextApi, ContextAttributesBuilder, GlProfile, Version};
use glutin::display::GlDisplay;
use std::ffi::CString;

struct EglKeep {
    _context: PossiblyCurrentContext,
    _display: Display,
}

const INSTALL_HINT: &str = "install the EGL loader and Mesa's drivers: \
     apt-get install libegl1 libegl-mesa0 libgl1-mesa-dri";

/// Create the context and load glow from it.
pub fn create(debug: bool) -> Result<(glow::Context, Box<dyn std::any::Any>)> {
    let devices: Vec<Device> = Device::query_devices()
        .map_err(|e| anyhow!("EGL is not available ({e}); {INSTALL_HINT}"))?
        .collect();
    if devices.is_empty() {
        return Err(anyhow!("EGL found no device; {INSTALL_HINT}"));
    }
    // Prefer a hardware device when the machine has one (timings then mean
    // something); otherwise Mesa's software rasterizer, llvmpipe.
    let software = |d: &Device| d.extensions().contains("EGL_MESA_device_software");
    let device = devices
        .iter()
        .find(|d| !software(d) && d.drm_render_device_node_path().is_some())
        .or_else(|| devices.iter().find(|d| software(d)))
        .unwrap_or(&devices[0]);

    let display = unsafe { Display::with_device(device, None) }
        .map_err(|e| anyhow!("could not open the EGL device display ({e}); {INSTALL_HINT}"))?;
    let template = ConfigTemplateBuilder::new()
        .with_surface_type(ConfigSurfaceTypes::empty())
        .with_api(Api::OPENGL)
        .build();
    let config = unsafe { display.find_configs(template) }
        .map_err(|e| anyhow!("EGL has no OpenGL config ({e}); {INSTALL_HINT}"))?
        .next()
        .ok_or_else(|| anyhow!("EGL has no OpenGL config without surfaces; {INSTALL_HINT}"))?;
    let attributes = ContextAttributesBuilder::new()
        .with_context_api(ContextApi::OpenGl(Some(Version::new(3, 3))))
        .with_profile(GlProfile::Core)
        .with_debug(debug)
        .build(None);
    let context = unsafe { display.create_context(&config, &attributes) }.map_err(|e| {
        anyhow!("could not create an OpenGL 3.3 core context through EGL ({e}); {INSTALL_HINT}")
    })?;
    let context = context
        .make_current_surfaceless()
        .context("could not make the EGL context current without a surface")?;
    let gl = unsafe {
        glow::Context::from_loader_function(|name| {
            let c_name = CString::new(name).expect("GL names have no NUL");
            super::trace::wrap(name, display.get_proc_address(&c_name) as *const _)
        })
    };
    Ok((
        gl,
        Box::new(EglKeep {
            _context: context,
            _display: display,
        }),
    ))
}
