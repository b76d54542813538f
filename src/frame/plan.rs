//! The frame plan: from a scene, which passes run, in which order, and which
//! render targets they use, decided before any GL work. It is put together
//! from the techniques' own lists (`Technique::passes` and `targets`, in the
//! registry's frame order), `gloss plan SCENE` prints it, and the renderer
//! allocates exactly its targets and runs exactly its passes, one line each.
//!
//! A frame runs only what its scene needs: a technique whose scene does not
//! need it adds no pass (no light pass for a scene with no lights, no stencil
//! work unless the stencil light-volume test is on).

use crate::frame::lights::FrameLights;
// Where the plan's passes are defined (below the techniques that make them);
// re-exported because a pass is read as part of the plan.
use crate::frame::pass::CUBE_FACES;
pub use crate::frame::pass::Pass;
use crate::frame::post;
use crate::frame::targets::{TargetDesc, size_name};
use crate::frame::technique::{FrameOrder, Runs, Stage, Technique};
use crate::frame::views::View;
use crate::math::depth::{DEPTH_BITS, precision_table};
use crate::scene::post::PostPass;
use crate::scene::{Projection, RenderPath, Scene};

#[derive(Clone, Debug, PartialEq)]
pub struct FramePlan {
    pub path: RenderPath,
    pub targets: Vec<TargetDesc>,
    pub passes: Vec<Pass>,
    /// The views the world is drawn for: the camera's first.
    pub views: Vec<View>,
    /// The frame's size as the scene gives it (every target is this size;
    /// the demo's window and `--size` may change it).
    pub size: (u32, u32),
    /// The camera's depth precision (notes 01 §4.4): the smallest eye-space
    /// depth difference the 24-bit depth buffer resolves, (z, dz) at a few
    /// distances (src/math/depth.rs).
    pub depth_precision: DepthPrecision,
    /// The materials' textures (notes 01 §5.3): file, width, height, or the
    /// error reading its header.
    pub textures: Vec<PlanTexture>,
    /// What the scene has that this path does not draw, in words (the
    /// scene's warnings say it too): nothing is dropped in silence.
    pub not_drawn: Vec<String>,
}

/// A texture in the plan: its file name, and its width and height or why
/// they could not be read.
pub type PlanTexture = (String, Result<(u32, u32), String>);

#[derive(Clone, Debug, PartialEq)]
pub struct DepthPrecision {
    pub near: f32,
    pub far: f32,
    pub perspective: bool,
    pub table: Vec<(f64, f64)>,
}

impl DepthPrecision {
    pub fn new(scene: &Scene) -> DepthPrecision {
        let c = &scene.camera;
        let perspective = matches!(c.projection, Projection::Perspective { .. });
        DepthPrecision {
            near: c.near,
            far: c.far,
            perspective,
            table: precision_table(c.near.into(), c.far.into(), perspective, DEPTH_BITS),
        }
    }
}

/// Whether the composite (techniques/deferred/composite.rs) writes straight
/// into an 8-bit output that GL encodes (SRGB8_ALPHA8 with
/// GL_FRAMEBUFFER_SRGB on while it draws): a G-buffer path with no post
/// chain and `render.hardware_srgb`. Every other pass that draws into that
/// output keeps GL_FRAMEBUFFER_SRGB off, so it stores and blends the values
/// its shader encodes exactly as into an RGBA8 output.
pub fn hardware_srgb(scene: &Scene) -> bool {
    use crate::scene::RenderPath::{Deferred, Tiled, Volumes};
    scene.render.hardware_srgb
        && scene.post.is_empty()
        && matches!(scene.render.path, Deferred | Volumes | Tiled)
}

impl FramePlan {
    /// Ask every technique of `registry`, in order, for its passes and targets.
    /// Two techniques may name the same target only if they describe it alike.
    ///
    /// The world techniques' passes run once per `Stage::World` of the
    /// technique that orders the frame (mirrors), or once from the camera.
    pub fn new(scene: &Scene, lights: &FrameLights, registry: &[&Technique]) -> FramePlan {
        let mut targets: Vec<TargetDesc> = Vec::new();
        let ordering = registry.iter().enumerate().find_map(|(i, t)| {
            let order = (t.order?)(scene, lights)?;
            Some((i, order))
        });
        let (director, order) = match ordering {
            Some((i, order)) => (Some(i), order),
            None => (
                None,
                FrameOrder {
                    views: vec![View::camera()],
                    stages: vec![Stage::World(0)],
                },
            ),
        };
        // Passes that run once, before every view (the shadow maps).
        let mut passes = Vec::new();
        for (index, t) in (registry.iter().enumerate()).filter(|(_, t)| t.runs == Runs::BeforeViews)
        {
            let ps = (t.passes)(scene, lights).into_iter();
            passes.extend(ps.map(|p| Pass {
                technique: index,
                ..p
            }));
        }
        let world: Vec<(usize, Vec<Pass>)> = registry
            .iter()
            .enumerate()
            .filter(|&(i, t)| Some(i) != director && t.runs == Runs::PerView)
            .map(|(i, t)| (i, (t.passes)(scene, lights)))
            .collect();
        for stage in order.stages {
            match stage {
                Stage::World(view) => {
                    for (index, ps) in &world {
                        passes.extend(ps.iter().map(|p| Pass {
                            technique: *index,
                            view,
                            ..p.clone()
                        }));
                    }
                }
                Stage::Own(p) => passes.push(Pass {
                    technique: director.expect("only an ordering technique has stages"),
                    ..p
                }),
            }
        }
        // Passes that run once, after every view, on the finished image:
        // the post chain, in the order of the scene's [[post]] entries.
        let mut after = Vec::new();
        for (index, t) in (registry.iter().enumerate()).filter(|(_, t)| t.runs == Runs::AfterViews)
        {
            let ps = (t.passes)(scene, lights).into_iter();
            after.extend(ps.map(|p| Pass {
                technique: index,
                ..p
            }));
        }
        after.sort_by_key(|p| p.item);
        passes.extend(after);
        for t in registry {
            for target in (t.targets)(scene, lights) {
                match targets.iter().find(|d| d.name == target.name) {
                    Some(same) => assert_eq!(
                        same, &target,
                        "{} describes target {} unlike an earlier technique",
                        t.name, target.name
                    ),
                    None => targets.push(target),
                }
            }
        }
        // The world image carries a depth-stencil buffer only when a pass
        // drawing into it needs one: a deferred frame that ends with the
        // composite has no use for it (its depth is the G-buffer's).
        let world = [post::world_target(scene), post::world_image(scene)];
        let world_depth = (passes.iter()).any(|p| world.contains(&p.target) && p.needs_depth);
        targets.extend(post::targets(scene, world_depth));
        let srgb_gamma =
            (scene.post.last()).is_some_and(|p| matches!(p, PostPass::Gamma { srgb: true, .. }));
        let format = if srgb_gamma || hardware_srgb(scene) {
            glow::SRGB8_ALPHA8
        } else {
            glow::RGBA8
        };
        targets.push(TargetDesc::output(
            format,
            scene.post.is_empty() && world_depth,
        ));
        // The composite's program, now that its target is known.
        for p in &mut passes {
            if let (Some(needs), Some(t)) =
                (p.composite, targets.iter().find(|t| t.name == p.target))
            {
                let depth = !matches!(t.depth, crate::frame::targets::Depth::None);
                let srgb = t.colors.first().is_some_and(|c| c.1 == glow::SRGB8_ALPHA8);
                p.programs = vec![needs.at_output(depth, srgb, true).program()];
            }
        }
        FramePlan {
            path: scene.render.path,
            targets,
            passes,
            views: order.views,
            size: scene.render.size,
            depth_precision: DepthPrecision::new(scene),
            textures: textures(scene),
            not_drawn: not_drawn(scene),
        }
    }

    pub fn has_pass(&self, name: &str) -> bool {
        self.passes.iter().any(|p| p.name == name)
    }

    /// Pass `i` named by what it draws, as the timings, the demo's
    /// inspector and `gloss plan` show it: "shadow map (light 0)",
    /// "shadow map (light 1, face +X)" (a point light's cube, one pass per
    /// face), "shadow map (light 1, six faces by gl_Layer)", "forward
    /// (reflection in mirror 'glass')", "forward (view 'top' ...)".
    pub fn title(&self, i: usize) -> String {
        let Some(p) = self.passes.get(i) else {
            return String::new();
        };
        if p.name == "shadow map" {
            return match p.face {
                Some(f) if f < CUBE_FACES.len() => {
                    format!("shadow map (light {}, face {})", p.item, CUBE_FACES[f])
                }
                Some(_) => format!("shadow map (light {}, six faces by gl_Layer)", p.item),
                None => format!("shadow map (light {})", p.item),
            };
        }
        match self.views.get(p.view) {
            Some(v) if p.view > 0 && v.name.starts_with("in ") => {
                format!("{} (reflection {})", p.name, v.name)
            }
            Some(v) if p.view > 0 => format!("{} (view {})", p.name, v.name),
            _ => p.name.to_string(),
        }
    }

    pub fn target(&self, name: &str) -> Option<&TargetDesc> {
        self.targets.iter().find(|t| t.name == name)
    }
}

/// What `scene` has that its path does not draw.
fn not_drawn(scene: &Scene) -> Vec<String> {
    let mut v = Vec::new();
    if scene.tessellation.is_some() && scene.render.path != crate::scene::RenderPath::Forward {
        v.push(format!(
            "the [tessellation] terrain: its pass runs on the forward path only, not on {}",
            scene.render.path.name()
        ));
    }
    v
}

/// The textures the scene's objects sample, each once, with their sizes:
/// every map of their materials, named with what it is.
fn textures(scene: &Scene) -> Vec<PlanTexture> {
    let mut seen: Vec<(std::path::PathBuf, &str)> = Vec::new();
    for o in &scene.objects {
        let m = &scene.materials[o.material];
        let maps = [
            (&m.diffuse_texture, "diffuse"),
            (&m.normal_map, "normal map"),
            (&m.specular_map, "specular map"),
            (&m.alpha_map, "alpha map"),
            (&m.pbr.metallic_roughness, "metallic-roughness map"),
            (&m.pbr.occlusion, "occlusion map"),
            (&m.pbr.emissive_map, "emissive map"),
        ];
        for (p, kind) in maps {
            if let Some(p) = p
                && !seen.iter().any(|(q, _)| q == p)
            {
                seen.push((p.clone(), kind));
            }
        }
    }
    seen.iter()
        .map(|(p, kind)| {
            let file = p.file_name().map_or_else(
                || p.display().to_string(),
                |n| n.to_string_lossy().into_owned(),
            );
            let name = format!("{file} ({kind})");
            let size = crate::gl::image_file::dimensions(p).map_err(|e| format!("{e:#}"));
            (name, size)
        })
        .collect()
}

impl std::fmt::Display for FramePlan {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        writeln!(f, "path: {}", self.path.name())?;
        let (w, h) = self.size;
        if !self.textures.is_empty() {
            writeln!(
                f,
                "textures (RGBA8, with the mip chain made at load, notes 01 §5.3):"
            )?;
        }
        for (name, size) in &self.textures {
            match size {
                Ok((tw, th)) => {
                    let level0 = u64::from(tw * th * 4);
                    let chain = crate::math::texture_mapping::mip_chain_bytes(*tw, *th, 4);
                    writeln!(
                        f,
                        "  {name}  {tw}x{th}: {level0} bytes, {chain} with its {} levels (+{:.0}%)",
                        crate::gl::texture::max_level(*tw as i32, *th as i32) + 1,
                        100.0 * (chain - level0) as f64 / level0 as f64
                    )?;
                }
                Err(e) => writeln!(f, "  {name}  ({e})")?,
            }
        }
        writeln!(f, "render targets ({w}x{h}):")?;
        for t in &self.targets {
            let bytes = size_name(t.bytes(w, h));
            writeln!(
                f,
                "  {:<20} {}  ({bytes})",
                t.name,
                t.attachments().join(", ")
            )?;
        }
        let total: u64 = self.targets.iter().map(|t| t.bytes(w, h)).sum();
        writeln!(f, "  {:<20} {}", "in all", size_name(total))?;
        if self.views.len() > 1 {
            writeln!(f, "views:")?;
            for (i, v) in self.views.iter().enumerate() {
                writeln!(f, "  {i}. {}", v.name)?;
            }
        }
        for what in &self.not_drawn {
            writeln!(f, "not drawn: {what}")?;
        }
        writeln!(f, "passes:")?;
        for (i, p) in self.passes.iter().enumerate() {
            // With several views, say which one each pass draws for.
            let view = if self.views.len() > 1 {
                format!(" (view {})", p.view)
            } else {
                String::new()
            };
            writeln!(
                f,
                "  {}. {:<16} -> {:<20} {}{view}  [{}]",
                i + 1,
                self.title(i),
                p.target,
                p.draws,
                p.code
            )?;
            if let Some(v) = &p.variant {
                writeln!(f, "     shader variant: {v}")?;
            }
            crate::frame::plan_programs::print(f, &p.programs)?;
        }
        let d = &self.depth_precision;
        writeln!(
            f,
            "depth precision ({DEPTH_BITS}-bit, {}, near {}, far {}): smallest resolvable depth difference",
            if d.perspective {
                "perspective: dz = z^2 (f - n) / (f n 2^24)"
            } else {
                "orthographic: dz = (f - n) / 2^24"
            },
            d.near,
            d.far
        )?;
        for (z, dz) in &d.table {
            let z = format!("{}", *z as f32);
            writeln!(f, "  at z = {z:<10} dz = {dz:.3e}")?;
        }
        Ok(())
    }
}
