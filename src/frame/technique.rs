//! What a technique registers, and what its passes are given when they run.
//!
//! A technique is one file under src/techniques/<chapter>/, named as the
//! notes name it. It exports one `Technique` value (its registration) that
//! src/techniques/mod.rs lists in frame order. From a scene, the technique
//! says which passes it adds and which targets they need (no GL: `gloss
//! plan` calls these); the renderer builds the technique's programs once
//! (`create`) and calls `run` for each of its passes in the plan.
//! docs/adding-a-technique.md walks through adding one.

use crate::frame::draw_list::DrawList;
use crate::frame::lights::FrameLights;
use crate::frame::meshes::FrameMeshes;
use crate::frame::pass::Pass;
use crate::frame::shadows::ShadowMaps;
use crate::frame::targets::{TargetDesc, Targets};
use crate::frame::uniforms::FrameUniforms;
use crate::frame::views::View;
use crate::gl::Gl;
use crate::gl::program::{Program, Sources};
use crate::scene::Scene;
use crate::scene::knobs::Knob;
use anyhow::Result;

/// A technique's registration.
pub struct Technique {
    /// As the notes name it, and as its file is named (`light_volumes`).
    pub name: &'static str,
    /// The notes section it implements ("notes 04, Light Volumes").
    pub notes: &'static str,
    /// Its source file, `file!()`.
    pub file: &'static str,
    /// Its shaders under glsl/.
    pub shaders: &'static [&'static str],
    /// A scene under scenes/ that shows it.
    pub scene: &'static str,
    /// Its page under docs/.
    pub docs: &'static str,
    /// The render settings it reads: the demo's panel shows them with it.
    pub knobs: &'static [&'static Knob],
    /// The passes it adds to a frame of `scene` (none: it does not run).
    pub passes: fn(&Scene, &FrameLights) -> Vec<Pass>,
    /// The targets those passes need besides the output (none when it does not run).
    pub targets: fn(&Scene, &FrameLights) -> Vec<TargetDesc>,
    /// Build its programs.
    pub create: fn(&Programs) -> Result<Box<dyn RunPasses>>,
    /// A technique that draws the world more than once (mirrors) orders the
    /// frame: its views, and its own passes interleaved with
    /// `Stage::World(view)`, where every other technique's passes run for
    /// that view. None (every other technique): the frame is the world
    /// drawn once, from the camera. At most one technique orders a frame.
    pub order: Option<fn(&Scene, &FrameLights) -> Option<FrameOrder>>,
    /// When its passes run: once before the views, for every view, or once
    /// after them all.
    pub runs: Runs,
}

/// When a technique's passes run in a frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Runs {
    /// Once, before any view (shadow maps: the light's view of the world
    /// does not change with the camera's).
    BeforeViews,
    /// For every view the world is drawn for, as `order` says.
    PerView,
    /// Once, after every view, on the finished image: the post-processing
    /// chain (notes 01 §9). These passes run in the order of the scene's
    /// `[[post]]` list (`Pass::item` is the entry), not the registry's.
    AfterViews,
}

/// The frame as a technique that draws the world several times orders it.
#[derive(Clone, Debug)]
pub struct FrameOrder {
    pub views: Vec<View>,
    pub stages: Vec<Stage>,
}

#[derive(Clone, Debug)]
pub enum Stage {
    /// The world drawn for view `views[i]`: every world technique's passes.
    World(usize),
    /// One of the ordering technique's own passes (`Pass::view` says for
    /// which view it draws).
    Own(Pass),
}

/// A technique with its programs built: runs one of its passes.
pub trait RunPasses {
    /// Run `pass` (one of those `passes` returned; `pass.step` says which).
    /// A pass sets the GL state it needs and restores it before returning.
    fn run(&self, pass: &Pass, frame: &Frame);

    /// Build what `run` needs for `pass` in `frame` and builds on first use
    /// (the composite's program for the frame's output); the renderer calls
    /// it before `run`, so that a shader that fails is the frame's error.
    /// Most techniques build everything in `create`: nothing to do.
    fn prepare(&self, _pass: &Pass, _frame: &Frame) -> Result<()> {
        Ok(())
    }
}

/// What `create` builds programs with.
pub struct Programs<'a> {
    pub gl: &'a Gl,
    pub sources: &'a Sources,
    /// `#define`s every program gets (MAX_LIGHTS).
    pub defines: &'a [(&'a str, String)],
    /// The frame's lighting variant's `#define`s (src/frame/variant.rs),
    /// which `build_variant` adds.
    pub variant: &'a [(&'a str, String)],
    /// Set when a program was built with `variant`: the renderer then
    /// builds the technique again (or takes it from its cache) when the
    /// variant changes.
    pub variant_used: &'a std::cell::Cell<bool>,
}

/// What `Programs` builds with, owned: for a technique that builds a
/// program on first use rather than in `create`.
pub struct LaterPrograms {
    gl: Gl,
    sources: Sources,
    defines: Vec<(String, String)>,
}

impl LaterPrograms {
    /// `Programs::build_with`, later.
    pub fn build_with(
        &self,
        stages: &[(u32, &str)],
        defines: &[(&str, String)],
    ) -> Result<Program> {
        let all: Vec<(&str, String)> = (self.defines.iter())
            .map(|(k, v)| (k.as_str(), v.clone()))
            .chain(defines.iter().cloned())
            .collect();
        Program::new(&self.gl, &self.sources, stages, &all).map(material_units)
    }
}

/// A program just built, with material.glsl's samplers on their units
/// (`DrawList::setup_program`): every way `Programs` builds ends here.
fn material_units(p: Program) -> Program {
    DrawList::setup_program(&p);
    p
}

impl Programs<'_> {
    /// What these build with, kept for building later (`LaterPrograms`).
    pub fn later(&self) -> LaterPrograms {
        LaterPrograms {
            gl: self.gl.clone(),
            sources: self.sources.clone(),
            defines: (self.defines.iter())
                .map(|(k, v)| (k.to_string(), v.clone()))
                .collect(),
        }
    }

    /// Compile and link `stages` = [(GL_VERTEX_SHADER, "deferred/gbuffer.vert"), ...].
    pub fn build(&self, stages: &[(u32, &str)]) -> Result<Program> {
        Program::new(self.gl, self.sources, stages, self.defines).map(material_units)
    }

    /// `build`, with `#define`s of its own besides the shared ones.
    pub fn build_with(
        &self,
        stages: &[(u32, &str)],
        defines: &[(&str, String)],
    ) -> Result<Program> {
        let all: Vec<(&str, String)> = (self.defines.iter().cloned())
            .chain(defines.iter().cloned())
            .collect();
        Program::new(self.gl, self.sources, stages, &all).map(material_units)
    }

    /// `build`, specialised to the frame's lighting variant: the parts of
    /// glsl/common/lighting.glsl the scene does not need left out.
    pub fn build_variant(&self, stages: &[(u32, &str)]) -> Result<Program> {
        self.build_variant_with(stages, &[])
    }

    /// `build_variant`, with `#define`s of its own besides.
    pub fn build_variant_with(
        &self,
        stages: &[(u32, &str)],
        defines: &[(&str, String)],
    ) -> Result<Program> {
        self.variant_used.set(true);
        let all: Vec<(&str, String)> = (self.variant.iter().cloned())
            .chain(defines.iter().cloned())
            .collect();
        self.build_with(stages, &all)
    }

    /// `build_with`, for a program whose vertex outputs `varyings` are
    /// captured by transform feedback (`Program::with_feedback`).
    pub fn build_feedback(
        &self,
        stages: &[(u32, &str)],
        defines: &[(&str, String)],
        varyings: &[&str],
    ) -> Result<Program> {
        let all: Vec<(&str, String)> = (self.defines.iter().cloned())
            .chain(defines.iter().cloned())
            .collect();
        Program::with_feedback(self.gl, self.sources, stages, &all, varyings).map(material_units)
    }
}

impl Frame<'_> {
    /// The opaque objects this view draws, in the order it draws them:
    /// those inside its frustum (notes 01 §6.3, `render.frustum_culling`),
    /// front to back (§6.2, `render.sort_opaque`). A convex mirror's view
    /// moves each vertex on its own, so it culls nothing.
    pub fn opaque_order(&self) -> Vec<usize> {
        let view = self.uniforms.view * self.view.reflection;
        // The counts the demo shows are the camera's, not a reflection's
        // or a split view's.
        let camera = self.view.reflection == glam::Mat4::IDENTITY && self.view.camera.is_none();
        let seen = self.in_view_stats().map(|(seen, stats)| {
            if camera {
                self.draws.last_cull.set(stats);
            }
            seen
        });
        (self.draws).opaque_order(&view, seen.as_deref(), self.scene.render.sort_opaque)
    }

    /// Which objects reach into this view's frustum (None: every object,
    /// when culling is off or the view is a convex mirror's): the
    /// transparency pass culls with it.
    pub fn in_view(&self) -> Option<Vec<bool>> {
        self.in_view_stats().map(|(seen, _)| seen)
    }

    /// `in_view`, with what the walk did.
    fn in_view_stats(&self) -> Option<(Vec<bool>, crate::frame::culling::CullStats)> {
        let vp = self.uniforms.projection * self.uniforms.view * self.view.reflection;
        (self.scene.render.frustum_culling && self.view.curved.is_none())
            .then(|| self.draws.in_view(&vp))
    }
}

/// What a pass is given: the scene, this frame's values, and the GL objects
/// the renderer owns.
pub struct Frame<'a> {
    pub gl: &'a glow::Context,
    pub scene: &'a Scene,
    /// This pass's view's uniforms (the camera's, or reflected).
    pub uniforms: &'a FrameUniforms,
    /// The view the pass draws for (src/frame/views.rs).
    pub view: &'a View,
    pub draws: &'a DrawList,
    pub lights: &'a FrameLights,
    pub targets: &'a Targets,
    pub meshes: &'a FrameMeshes,
    /// The shadow maps and the `Shadows` block (src/frame/shadows.rs).
    pub shadows: &'a ShadowMaps,
}
