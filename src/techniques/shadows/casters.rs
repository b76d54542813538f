//! Drawing the casters into a shadow map (notes 01 §8.5, first pass), for
//! shadow_map.rs and cascaded_shadow_maps.rs, with two programs: an opaque
//! caster needs depth alone (the fragment shader of 8922fc1: empty for a 2D
//! map, the distance for a cube), an alpha-tested caster (notes 05 "Alpha
//! Test": an OBJ's cut-out leaves) its material's alpha test
//! (glsl/shadows/shadow_alpha.glsl). A software rasteriser pays for the
//! test's code even where `u_alpha_test` says "always", so with
//! `render.specialize` the opaque casters are drawn with the program built
//! with `DEPTH_ONLY` and the alpha-tested ones, after them, with the general
//! one; a frame without alpha-tested casters never uses the general program,
//! and never builds it: each program is built the first frame that draws
//! with it (`CasterPrograms::prepare`), and `gloss plan` names the ones a
//! shadow pass draws with (`plan_programs`), from the same rule (`CasterProgram::of`).
//! With `render.specialize = false` every caster is drawn with the general
//! program, in the scene's order. Either way the map holds the same depths
//! (GL_LESS keeps the nearest, whatever the order).

use crate::frame::Frame;
use crate::frame::Programs;
use crate::frame::draw_list::DrawItem;
use crate::frame::plan_programs::PlanProgram;
use crate::frame::technique::LaterPrograms;
use crate::frame::uniforms::unit;
use crate::gl::program::Program;
use crate::scene::{AlphaTest, Cull, Scene};
use anyhow::Result;
use glow::HasContext;
use std::cell::OnceCell;

/// Which program draws a caster.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum CasterProgram {
    /// Built with `DEPTH_ONLY`: no alpha test, no texture coordinates.
    DepthOnly,
    /// The general program: the alpha test behind `u_alpha_test`.
    AlphaTest,
}

impl CasterProgram {
    /// The program for a caster whose material's alpha test is
    /// `alpha_test` (`AlphaTest::code`): with `render.specialize`, depth
    /// only for an opaque caster, the test for an alpha-tested one; without
    /// it, the general program for every caster. The one rule: the frame
    /// sorts its casters by it, the plan names the programs by it.
    pub fn of(specialize: bool, alpha_test: i32) -> CasterProgram {
        if specialize && alpha_test == AlphaTest::Always.code() {
            CasterProgram::DepthOnly
        } else {
            CasterProgram::AlphaTest
        }
    }

    /// In the order a pass draws with them.
    const ALL: [CasterProgram; 2] = [CasterProgram::DepthOnly, CasterProgram::AlphaTest];

    fn defines(self) -> &'static [(&'static str, &'static str)] {
        match self {
            CasterProgram::DepthOnly => &[("DEPTH_ONLY", "1")],
            CasterProgram::AlphaTest => &[],
        }
    }

    fn role(self) -> &'static str {
        match self {
            CasterProgram::DepthOnly => "depth only",
            CasterProgram::AlphaTest => "alpha test",
        }
    }
}

/// The caster programs a shadow pass of `scene` draws with, in the order
/// it draws: those of its opaque objects (transparent ones cast no shadow
/// here). Frustum culling may leave a program's casters out of a map;
/// the pass builds what the scene's casters need all the same.
pub(super) fn needed(scene: &Scene) -> Vec<CasterProgram> {
    let casting = (scene.objects.iter())
        .map(|o| &scene.materials[o.material])
        .filter(|m| !m.is_transparent());
    let used: Vec<CasterProgram> = casting
        .map(|m| CasterProgram::of(scene.render.specialize, m.alpha_test.code()))
        .collect();
    (CasterProgram::ALL.into_iter())
        .filter(|c| used.contains(c))
        .collect()
}

/// The programs a shadow pass of `scene` draws with, as the plan names them,
/// for stages built with `defines` (`CasterPrograms::new`'s).
pub(super) fn plan_programs(scene: &Scene, defines: &[(&'static str, String)]) -> Vec<PlanProgram> {
    (needed(scene).into_iter())
        .map(|c| PlanProgram::new(c.role(), all_defines(defines, c)))
        .collect()
}

fn all_defines(stage: &[(&'static str, String)], c: CasterProgram) -> Vec<(&'static str, String)> {
    (stage.iter().cloned())
        .chain(c.defines().iter().map(|(k, v)| (*k, v.to_string())))
        .collect()
}

/// The general program (the alpha test behind `u_alpha_test`) and the
/// depth-only one, from the same stages, each built the first frame that
/// draws with it (`prepare`): a frame without alpha-tested casters builds
/// no alpha-test program.
pub(super) struct CasterPrograms {
    build: LaterPrograms,
    stages: Vec<(u32, &'static str)>,
    defines: Vec<(&'static str, String)>,
    /// By `CasterProgram` (`ALL`'s order).
    programs: [OnceCell<Program>; 2],
}

impl CasterPrograms {
    /// `stages` with `defines`, and with `DEPTH_ONLY` besides: built later.
    pub fn new(
        p: &Programs,
        stages: &[(u32, &'static str)],
        defines: &[(&'static str, String)],
    ) -> Self {
        CasterPrograms {
            build: p.later(),
            stages: stages.to_vec(),
            defines: defines.to_vec(),
            programs: [OnceCell::new(), OnceCell::new()],
        }
    }

    /// Program `c`, built now if no frame has drawn with it yet.
    fn get(&self, c: CasterProgram) -> Result<&Program> {
        let cell = &self.programs[c as usize];
        if let Some(p) = cell.get() {
            return Ok(p);
        }
        let program = (self.build).build_with(&self.stages, &all_defines(&self.defines, c))?;
        Ok(cell.get_or_init(|| program))
    }

    /// Build the programs a shadow pass of `scene` draws with (`needed`).
    pub fn prepare(&self, scene: &Scene) -> Result<()> {
        needed(scene)
            .into_iter()
            .try_for_each(|c| self.get(c).map(|_| ()))
    }
}

/// Every opaque object (mirrors too: they are solid); transparent ones cast
/// no shadow here. With `render.frustum_culling`, only the casters inside
/// the frustum of one of `faces` (the light's view-projections this draw
/// reaches; notes 01 §6.3), counted in `DrawList::shadow_cull`.
/// With `cull_front`, a two-sided material (`cull = "none"`: a leaf's
/// quad) is drawn without culling, so that it casts from either side.
/// `setup` sets the pass's uniforms on each program as it is put in use.
pub(super) fn draw_casters(
    gl: &glow::Context,
    programs: &CasterPrograms,
    f: &Frame,
    faces: &[glam::Mat4],
    cull_front: bool,
    setup: &dyn Fn(&Program),
) {
    let mut keep = vec![true; f.draws.items.len()];
    if f.scene.render.frustum_culling {
        let mut any = vec![false; keep.len()];
        let mut total = f.draws.shadow_cull.get();
        for vp in faces {
            let (seen, stats) = f.draws.casters_in(vp);
            for (a, s) in any.iter_mut().zip(seen) {
                *a |= s;
            }
            total.objects += stats.objects;
            total.drawn += stats.drawn;
            total.culled += stats.culled;
            total.tests += stats.tests;
        }
        f.draws.shadow_cull.set(total);
        keep = any;
    }
    let casters: Vec<&DrawItem> = (f.draws.items.iter().zip(keep))
        .filter(|(d, k)| *k && !d.transparent)
        .map(|(d, _)| d)
        .collect();
    // 1. The opaque casters: depth only (with render.specialize).
    // 2. The alpha-tested casters: the test, then depth.
    for c in CasterProgram::ALL {
        let these: Vec<&DrawItem> = (casters.iter().copied())
            .filter(|d| CasterProgram::of(f.scene.render.specialize, d.alpha_test) == c)
            .collect();
        if these.is_empty() {
            continue;
        }
        match programs.get(c) {
            Ok(p) => draw(
                gl,
                p,
                c == CasterProgram::AlphaTest,
                f,
                &these,
                cull_front,
                setup,
            ),
            Err(e) => eprintln!("warning: a shadow map's casters were not drawn: {e:#}"),
        }
    }
}

/// `casters` with `p`; `general`: `p` has the alpha test (its uniforms are set).
fn draw(
    gl: &glow::Context,
    p: &Program,
    general: bool,
    f: &Frame,
    casters: &[&DrawItem],
    cull_front: bool,
    setup: &dyn Fn(&Program),
) {
    p.use_program();
    setup(p);
    let mut bound = false;
    for d in casters {
        unsafe { gl.front_face(if d.mirrored { glow::CW } else { glow::CCW }) };
        if cull_front {
            match d.cull {
                Cull::None => unsafe { gl.disable(glow::CULL_FACE) },
                _ => unsafe { gl.enable(glow::CULL_FACE) },
            }
        }
        p.set_mat4("u_model", &d.model);
        if !general {
            f.draws.mesh(d).draw();
            continue;
        }
        // 2. An alpha-tested caster runs its material's alpha test on its
        // diffuse texture (glsl/shadows/shadow_alpha.glsl): a leaf casts a
        // leaf, not its quad.
        p.set_i32("u_alpha_test", d.alpha_test);
        if d.alpha_test != AlphaTest::Always.code() {
            let texture = d.texture.map(|t| f.draws.textures[t].id);
            p.set_f32("u_alpha_ref", d.alpha_ref);
            p.set_bool("u_has_diffuse_texture", texture.is_some());
            let (scale, offset) = (d.texturing.uv_scale, d.texturing.uv_offset);
            p.set_vec4(
                "u_uv_transform",
                glam::Vec4::new(scale[0], scale[1], offset[0], offset[1]),
            );
            unsafe {
                gl.active_texture(glow::TEXTURE0 + unit::DIFFUSE_TEXTURE);
                gl.bind_texture(glow::TEXTURE_2D, texture);
                gl.bind_sampler(unit::DIFFUSE_TEXTURE, f.draws.sampler(d, &f.scene.render));
            }
            bound = true;
        }
        f.draws.mesh(d).draw();
    }
    if bound {
        unsafe {
            gl.bind_texture(glow::TEXTURE_2D, None);
            gl.bind_sampler(unit::DIFFUSE_TEXTURE, None);
            gl.active_texture(glow::TEXTURE0);
        }
    }
}
