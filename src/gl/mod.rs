//! Thin owners of OpenGL objects and the three ways gloss gets a context.
//!
//! Every type here creates one GL object and frees it on drop. None of them
//! hides a state change: binding, enabling and blending stay in the technique
//! files, where a student can read them next to the notes. `texture_units`
//! binds a list of textures on their units for the code that names the list,
//! and `gloss trace` lists each of its calls at that code's line.

pub mod buffer;
pub mod cube_map;
pub mod debug;
pub mod depth_map;
pub mod egl;
pub mod framebuffer;
pub mod image_file;
pub mod live;
pub mod mesh;
pub mod mip_target;
pub mod osmesa;
pub mod program;
pub mod query;
pub mod sampler;
pub mod skin_vertices;
pub mod stream;
pub mod texture;
pub mod texture_buffer;
pub mod texture_units;
pub mod trace;
pub mod window;

use anyhow::{Result, bail};
use glow::HasContext;
use std::sync::Arc;

/// The glow function table, shared by every object that must free itself.
pub type Gl = Arc<glow::Context>;

/// Which way the context was made.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Backend {
    /// Headless through EGL (Mesa's software device or a GPU), no display needed.
    Egl,
    /// Headless through Mesa's OSMesa (libOSMesa.so.8 loaded at run time).
    Osmesa,
    /// A window through winit + glutin.
    Window,
}

impl std::fmt::Display for Backend {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Backend::Egl => "egl",
            Backend::Osmesa => "osmesa",
            Backend::Window => "window",
        })
    }
}

/// What the driver says about the context, as `gloss info` prints it.
#[derive(Clone, Debug)]
pub struct GlInfo {
    pub backend: Backend,
    pub version: String,
    pub renderer: String,
    pub vendor: String,
    pub glsl: String,
    pub major: i32,
    pub minor: i32,
    pub core_profile: bool,
    pub debug_context: bool,
    pub khr_debug: bool,
    pub max_uniform_block_size: i32,
    /// GL_MAX_CLIP_DISTANCES: gl_ClipDistance's length (GL 3.3: at least 8).
    pub max_clip_distances: i32,
    /// GL_MAX_VERTEX_UNIFORM_COMPONENTS: what limits a skeleton's joints
    /// in a uniform array (16 a matrix).
    pub max_vertex_uniform_components: i32,
    /// GL_MAX_TEXTURE_MAX_ANISOTROPY (1: no anisotropic filtering).
    pub max_anisotropy: f32,
}

impl GlInfo {
    /// Ask the current context who it is.
    pub fn query(gl: &glow::Context, backend: Backend) -> GlInfo {
        unsafe {
            let major = gl.get_parameter_i32(glow::MAJOR_VERSION);
            let minor = gl.get_parameter_i32(glow::MINOR_VERSION);
            let mask = gl.get_parameter_i32(glow::CONTEXT_PROFILE_MASK);
            let flags = gl.get_parameter_i32(glow::CONTEXT_FLAGS);
            GlInfo {
                backend,
                version: gl.get_parameter_string(glow::VERSION),
                renderer: gl.get_parameter_string(glow::RENDERER),
                vendor: gl.get_parameter_string(glow::VENDOR),
                glsl: gl.get_parameter_string(glow::SHADING_LANGUAGE_VERSION),
                major,
                minor,
                core_profile: mask & glow::CONTEXT_CORE_PROFILE_BIT as i32 != 0,
                debug_context: flags & glow::CONTEXT_FLAG_DEBUG_BIT as i32 != 0,
                khr_debug: gl.supported_extensions().contains("GL_KHR_debug"),
                max_uniform_block_size: gl.get_parameter_i32(glow::MAX_UNIFORM_BLOCK_SIZE),
                max_clip_distances: gl.get_parameter_i32(glow::MAX_CLIP_DISTANCES),
                max_vertex_uniform_components: gl
                    .get_parameter_i32(glow::MAX_VERTEX_UNIFORM_COMPONENTS),
                max_anisotropy: sampler::max_anisotropy(gl),
            }
        }
    }

    /// gloss needs OpenGL 3.3 core: refuse anything older, with a message that says so.
    pub fn require_33_core(&self) -> Result<()> {
        if (self.major, self.minor) < (3, 3) {
            bail!(
                "the {} context is OpenGL {}.{} ({}); gloss needs OpenGL 3.3 core. \
                 Update Mesa (apt-get install libgl1-mesa-dri) or the GPU driver.",
                self.backend,
                self.major,
                self.minor,
                self.version
            );
        }
        if !self.core_profile {
            bail!(
                "the {} context is not a core profile ({}); gloss needs OpenGL 3.3 core",
                self.backend,
                self.version
            );
        }
        Ok(())
    }

    /// Optional 4.x paths (tessellation) check this first.
    pub fn at_least(&self, major: i32, minor: i32) -> bool {
        (self.major, self.minor) >= (major, minor)
    }
}

impl std::fmt::Display for GlInfo {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        writeln!(f, "backend        {}", self.backend)?;
        writeln!(f, "GL_VERSION     {}", self.version)?;
        writeln!(f, "GL_RENDERER    {}", self.renderer)?;
        writeln!(f, "GL_VENDOR      {}", self.vendor)?;
        writeln!(f, "GLSL           {}", self.glsl)?;
        writeln!(
            f,
            "context        {}.{} {}{}",
            self.major,
            self.minor,
            if self.core_profile {
                "core"
            } else {
                "compatibility"
            },
            if self.debug_context { ", debug" } else { "" }
        )?;
        writeln!(
            f,
            "KHR_debug      {}",
            if self.khr_debug { "yes" } else { "no" }
        )?;
        writeln!(f, "max UBO size   {} bytes", self.max_uniform_block_size)?;
        writeln!(
            f,
            "clip distances {} (one for mirrors, the rest for a scene's clip planes)",
            self.max_clip_distances
        )?;
        writeln!(
            f,
            "vertex uniform components {} (skinning: {} joint matrices in a uniform array)",
            self.max_vertex_uniform_components,
            crate::math::skinning::uniform_joint_limit(self.max_vertex_uniform_components)
        )?;
        write!(
            f,
            "max anisotropy {}{}",
            self.max_anisotropy,
            if self.max_anisotropy > 1.0 {
                ""
            } else {
                " (no anisotropic filtering: \"anisotropic\" is trilinear)"
            }
        )
    }
}

/// A headless context (EGL or OSMesa) made current on this thread.
///
/// Keep it alive for as long as any GL object made from `gl` exists: drop
/// the renderer first, then the context.
pub struct Headless {
    pub gl: Gl,
    pub info: GlInfo,
    pub debug: debug::DebugLog,
    // The backend's own handles (EGL display and context, or the OSMesa
    // context and its buffer); dropped last.
    _keep: Box<dyn std::any::Any>,
}

impl Headless {
    /// Make a headless 3.3 core context with the given backend. `debug` asks
    /// for a debug context and installs the KHR_debug callback (or falls back
    /// to glGetError checks where KHR_debug is missing).
    pub fn new(backend: Backend, debug: bool) -> Result<Headless> {
        let (gl, keep) = match backend {
            Backend::Egl => egl::create(debug)?,
            Backend::Osmesa => osmesa::create()?,
            Backend::Window => bail!("the window backend is not headless: use egl or osmesa"),
        };
        Self::finish(gl, keep, backend, debug)
    }

    fn finish(
        mut gl: glow::Context,
        keep: Box<dyn std::any::Any>,
        backend: Backend,
        debug: bool,
    ) -> Result<Headless> {
        let info = GlInfo::query(&gl, backend);
        info.require_33_core()?;
        let log = debug::DebugLog::install(&mut gl, debug);
        Ok(Headless {
            gl: Arc::new(gl),
            info,
            debug: log,
            _keep: keep,
        })
    }
}
