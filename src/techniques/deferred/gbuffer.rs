//! The geometry pass: fill the G-buffer (notes 01 §8.6.2 step 1 "Fill
//! G-Buffer"; notes 02 "G-Buffers"). Like a forward pass, but each fragment
//! writes what lighting will need instead of a colour: normal and shininess,
//! diffuse albedo, specular colour, and depth. The layout is in
//! src/frame/gbuffer.rs. The light pre-pass fills a thin G-buffer (normal,
//! shininess and depth only): the fragment shader's other outputs are dropped.
//!
//! With `render.gbuffer = "octahedral"` the normal attachment is packed
//! (src/frame/gbuffer.rs): the shader writes the octahedral normal in
//! 12 + 12 bits and, per object, the index of its shininess in the scene's
//! table (`u_shininess_code`), instead of xyz and shininess in half floats.
//!
//! The alpha test (notes 05, "Alpha Test": an OBJ's cut-out leaves) has a
//! `discard`, which a software rasteriser pays for even where `u_alpha_test`
//! says "always" (the test runs, and a shader that may discard gets no early
//! depth test). So with `render.specialize` an object whose material tests
//! nothing is drawn with a program built with `NO_ALPHA_TEST`, an
//! alpha-tested one with the program that tests, switched between in the
//! objects' own order (the same images). `render.specialize = false`: every
//! object with the program that tests.
//!
//! GL state: sets glDepthFunc(render.depth_func, or the material's
//! depth_func per object where it differs), depth writes, back-face
//! culling, glFrontFace per object, GL_FRAMEBUFFER_SRGB (albedo and specular
//! are encoded as they are stored); restores all of them.

use crate::frame::draw_list::DrawList;
use crate::frame::gbuffer;
use crate::frame::gbuffer::MaterialVariant;
use crate::frame::gbuffer_slim;
use crate::frame::lights::FrameLights;
use crate::frame::material_variant::{alpha_programs, tests_alpha};
use crate::frame::plan::Pass;
use crate::frame::plan_programs::PlanProgram;
use crate::frame::targets::{Depth, TargetDesc};
use crate::frame::technique::LaterPrograms;
use crate::frame::uniforms::unit;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::program::Program;
use crate::scene::knobs;
use crate::scene::material::GBufferNormals;
use crate::scene::texturing::Interpolation;
use crate::scene::{RenderPath, Scene};
use anyhow::Result;
use glow::HasContext;
use std::cell::OnceCell;
use std::collections::BTreeSet;

pub const GBUFFER: Technique = Technique {
    name: "gbuffer",
    notes: "notes 01 §8.6.2 step 1; notes 02, G-Buffers",
    file: file!(),
    shaders: &["deferred/gbuffer.vert", "deferred/gbuffer.frag"],
    scene: "scenes/deferred-shading.toml",
    docs: "docs/deferred/gbuffer.md",
    knobs: &[
        &knobs::DEPTH_FUNC,
        &knobs::GBUFFER_NORMALS,
        &knobs::GBUFFER_SLIM,
    ],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::PerView,
};

/// Which G-buffer the scene's path fills: None (forward), full, or thin.
fn layout(scene: &Scene) -> Option<bool> {
    match scene.render.path {
        RenderPath::Forward => None,
        RenderPath::Deferred | RenderPath::Volumes | RenderPath::Tiled => Some(false),
        RenderPath::Prepass => Some(true),
    }
}

fn passes(scene: &Scene, lights: &FrameLights) -> Vec<Pass> {
    let n = scene.opaque_objects();
    // Which normal encoding, and the bytes a pixel the G-buffer takes.
    let Some(t) = targets(scene, lights).pop() else {
        return vec![];
    };
    let Depth::Own(depth) = t.depth else {
        return vec![];
    };
    let table = gbuffer::shininess_table(scene).len();
    let normal = if gbuffer::octahedral(scene) {
        format!("octahedral normal RGBA8, {table} shininess values")
    } else if scene.render.gbuffer == GBufferNormals::Octahedral {
        let why = gbuffer::kept_by(scene).unwrap_or_default();
        format!("normal RGBA16F, not octahedral: {why}")
    } else {
        "normal RGBA16F".to_string()
    };
    let bytes = gbuffer::bytes_per_pixel(&t.colors, depth);
    let what = match layout(scene) {
        Some(true) => "normal + shininess, depth; ",
        _ => "",
    };
    // The slim G-buffer's missing attachment, or why the full one keeps it.
    let specular = match (gbuffer_slim::constant_specular(scene), layout(scene)) {
        (Some(c), _) => format!(
            "no specular attachment: every material's is ({:.2}, {:.2}, {:.2}); ",
            c.x, c.y, c.z
        ),
        (None, Some(false)) => gbuffer_slim::kept_by(scene)
            .map(|why| format!("specular attachment kept: {why}; "))
            .unwrap_or_default(),
        _ => String::new(),
    };
    // Its program: the layout, the normal's encoding (the target's, as
    // `needs` reads it) and the materials' variant.
    let thin = layout(scene) == Some(true);
    let material = MaterialVariant::of(scene);
    let packed = gbuffer::octahedral(scene);
    // One program for the objects that test no alpha, one for those that do
    // (`with_alpha_test`), in that order.
    let programs = (alpha_programs(scene).into_iter())
        .map(|a| {
            let role = if a {
                "G-buffer, alpha test"
            } else {
                "G-buffer"
            };
            PlanProgram::new(role, defines(thin, packed, material, a))
        })
        .collect();
    vec![
        Pass::new(
            "gbuffer",
            gbuffer::NAME,
            format!("{n} objects ({what}{specular}{normal}; {bytes} bytes/px)"),
            file!(),
        )
        .with_programs(programs),
    ]
}

fn targets(scene: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    let depth = gbuffer::depth_format(scene);
    let material = gbuffer::material_attachments(scene);
    let octahedral = gbuffer::octahedral(scene);
    let slim = gbuffer_slim::constant_specular(scene).is_some();
    (layout(scene).map(|thin| gbuffer::target(thin, octahedral, slim, depth, &material)))
        .into_iter()
        .collect()
}

/// The pass's shaders.
const STAGES: [(u32, &str); 2] = [
    (glow::VERTEX_SHADER, "deferred/gbuffer.vert"),
    (glow::FRAGMENT_SHADER, "deferred/gbuffer.frag"),
];

struct GBufferPass {
    build: LaterPrograms,
    /// The programs, by [`program_index`], each built the first frame that
    /// needs it: full or thin (the light pre-pass's: the material triple at
    /// locations 1 and 2), the normal as xyz or packed (OCTAHEDRAL_NORMALS),
    /// and the material code the scene's materials need
    /// (`gbuffer::MaterialVariant`: 8 of them), with or without the alpha
    /// test.
    programs: [OnceCell<Program>; 64],
}

/// What a program is built for: thin, packed normal, the material variant,
/// and whether it runs the alpha test.
type Needs = (bool, bool, MaterialVariant, bool);

/// Which program: thin, packed normal, the material variant, the alpha test.
fn program_index((thin, packed, material, alpha): Needs) -> usize {
    usize::from(alpha) * 32 + usize::from(thin) * 16 + usize::from(packed) * 8 + material.index()
}

/// What `f` needs for an object that tests no alpha: (thin, packed normal,
/// material variant, the alpha test only if `render.specialize` is off).
fn needs(f: &Frame) -> Needs {
    let target = f.targets.get(gbuffer::NAME);
    let thin = layout(f.scene) == Some(true);
    let packed = target.colors[0].internal_format == gbuffer::OCTAHEDRAL.1;
    (
        thin,
        packed,
        MaterialVariant::of(f.scene),
        !f.scene.render.specialize,
    )
}

/// `frame`'s needs for an object whose material's alpha test is
/// `alpha_test` (`DrawItem::alpha_test`).
fn with_alpha_test((thin, packed, material, alpha): Needs, alpha_test: i32) -> Needs {
    (thin, packed, material, tests_alpha(!alpha, alpha_test))
}

/// The `#define`s of the program for (thin, packed normal, material
/// variant, alpha test): what the pass builds, and what the plan names.
fn defines(
    thin: bool,
    packed: bool,
    material: MaterialVariant,
    alpha: bool,
) -> Vec<(&'static str, String)> {
    let mut defines = material.defines();
    if !alpha {
        defines.push(("NO_ALPHA_TEST", "1".into()));
    }
    if thin {
        defines.push(("THIN_GBUFFER", "1".into()));
    }
    if packed {
        defines.push(("OCTAHEDRAL_NORMALS", "1".into()));
    }
    defines
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    Ok(Box::new(GBufferPass {
        build: p.later(),
        programs: std::array::from_fn(|_| OnceCell::new()),
    }))
}

impl GBufferPass {
    /// The program for `needs`, built now if no frame has needed it yet.
    fn program(&self, needs: Needs) -> Result<&Program> {
        let i = program_index(needs);
        if let Some(p) = self.programs[i].get() {
            return Ok(p);
        }
        let (thin, packed, material, alpha) = needs;
        let program = (self.build).build_with(&STAGES, &defines(thin, packed, material, alpha))?;
        Ok(self.programs[i].get_or_init(|| program))
    }

    /// Put the program for `needs` in use with the pass's uniforms; None
    /// (and a warning) if it could not be built. Built by `prepare`, which
    /// the renderer calls first.
    fn use_program(&self, f: &Frame, needs: Needs) -> Option<&Program> {
        let p = match self.program(needs) {
            Ok(p) => p,
            Err(e) => {
                eprintln!("warning: the G-buffer pass did not draw: {e:#}");
                return None;
            }
        };
        let (target, u) = (f.targets.get(gbuffer::NAME), f.uniforms);
        p.use_program();
        p.set_mat4("u_view_projection", &u.view_projection);
        // How gAlpha and gConvert hold the microfacet triple (notes 03).
        p.set_i32("u_gbuffer_material", gbuffer::material_layout(target).1);
        p.set_i32("u_diffuse_texture", unit::DIFFUSE_TEXTURE as i32);
        p.set_i32("u_normal_map", unit::NORMAL_MAP as i32);
        p.set_i32("u_specular_map", unit::SPECULAR_MAP as i32);
        // Texture coordinates and vertex colours perspective-correct or
        // affine (notes 01 §4.1, §5.1).
        let affine = f.scene.render.interpolation == Interpolation::Affine;
        p.set_bool("u_affine", affine);
        f.view.set_uniforms(p, f.uniforms.eye, &f.scene.clip_planes);
        Some(p)
    }
}

impl RunPasses for GBufferPass {
    /// The programs the objects' alpha tests need (a transparent object's
    /// too: one more program at most).
    fn prepare(&self, _: &Pass, f: &Frame) -> Result<()> {
        let tests: BTreeSet<i32> = f.draws.items.iter().map(|d| d.alpha_test).collect();
        let frame = needs(f);
        for t in tests {
            self.program(with_alpha_test(frame, t))?;
        }
        Ok(())
    }

    fn run(&self, _: &Pass, f: &Frame) {
        let target = f.targets.get(gbuffer::NAME);
        let frame = needs(f);
        let (_, packed, _, _) = frame;
        let table = gbuffer::shininess_table(f.scene);
        let gl = f.gl;
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(target.id));
            let (x, y, w, h) = f.view.rect(target.width, target.height);
            gl.viewport(x, y, w, h);
            gl.clear_color(0.0, 0.0, 0.0, 0.0);
            gl.enable(glow::DEPTH_TEST);
            gl.depth_func(f.scene.render.depth_func.gl());
            gl.depth_mask(true);
            let depth = target.depth_stencil.as_ref().map(|d| d.internal_format);
            if depth.is_some_and(gbuffer::has_stencil) {
                gl.clear(
                    glow::COLOR_BUFFER_BIT | glow::DEPTH_BUFFER_BIT | glow::STENCIL_BUFFER_BIT,
                );
            } else {
                gl.clear(glow::COLOR_BUFFER_BIT | glow::DEPTH_BUFFER_BIT);
            }
            gl.enable(glow::CULL_FACE);
            gl.cull_face(glow::BACK);
            // Linear albedo and specular are encoded to sRGB as they are stored.
            gl.enable(glow::FRAMEBUFFER_SRGB);
            // A reflected view (stencil/mirror.rs) cuts what lies behind its mirror.
            if f.view.clips() {
                gl.enable(glow::CLIP_DISTANCE0);
            }
            // Edges only (notes 01 §3.3-3.4: what the clipper makes of each triangle).
            if f.scene.render.wireframe {
                gl.polygon_mode(glow::FRONT_AND_BACK, glow::LINE);
            }
            // The scene's clip planes (notes 01 §3.3), GL_CLIP_DISTANCE1 on.
            for i in 0..f.scene.clip_planes.len() as u32 {
                gl.enable(glow::CLIP_DISTANCE1 + i);
            }

            // The program in use, and what it was built for.
            let mut current: Option<(Needs, Option<&Program>)> = None;
            gl.active_texture(glow::TEXTURE0 + unit::DIFFUSE_TEXTURE);
            let mut depth_func = f.scene.render.depth_func;
            // Transparent objects are drawn later, sorted (blending/transparency.rs);
            // mirrors by the mirror technique (stencil/mirror.rs).
            for i in f.opaque_order() {
                let d = &f.draws.items[i];
                // The program its alpha test needs, put in use when it changes.
                let want = with_alpha_test(frame, d.alpha_test);
                if current.map(|c| c.0) != Some(want) {
                    current = Some((want, self.use_program(f, want)));
                }
                let Some((_, Some(p))) = current else {
                    continue;
                };
                // The material's face culling (notes 01 §3.4): back faces
                // (the default), front faces, both, or none.
                match d.cull.gl() {
                    Some(face) => {
                        gl.enable(glow::CULL_FACE);
                        gl.cull_face(face);
                    }
                    None => gl.disable(glow::CULL_FACE),
                }
                // A material may test depth its own way (notes 05, "Depth Test and Operation").
                let func = d.depth_func.unwrap_or(f.scene.render.depth_func);
                if func != depth_func {
                    gl.depth_func(func.gl());
                    depth_func = func;
                }
                // A mirroring model matrix, or a reflected view, turns
                // counter-clockwise triangles clockwise.
                gl.front_face(f.view.front_face(d.mirrored));
                // Its texture and normal map, with the sampler that says how
                // to read them (notes 01 §5: wrap rules, filter; §8.4).
                f.draws.bind_textures(gl, p, d, &f.scene.render);
                f.draws.set_object_uniforms(p, d);
                if packed {
                    // The index of its shininess (as set_object_uniforms sets it).
                    let s = d
                        .microfacet
                        .map_or(d.shininess, |m| m.equivalent_shininess());
                    p.set_f32(
                        "u_shininess_code",
                        gbuffer::shininess_code(&table, s) as f32,
                    );
                }
                f.draws.mesh(d).draw();
            }

            gl.front_face(glow::CCW);
            gl.polygon_mode(glow::FRONT_AND_BACK, glow::FILL);
            gl.disable(glow::CLIP_DISTANCE0);
            for i in 0..f.scene.clip_planes.len() as u32 {
                gl.disable(glow::CLIP_DISTANCE1 + i);
            }
            DrawList::unbind_textures(gl);
            gl.bind_texture(glow::TEXTURE_2D, None);
            gl.active_texture(glow::TEXTURE0);
            gl.disable(glow::FRAMEBUFFER_SRGB);
            gl.use_program(None);
            gl.cull_face(glow::BACK);
            gl.disable(glow::CULL_FACE);
            gl.disable(glow::DEPTH_TEST);
            gl.depth_func(glow::LESS);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }
}
