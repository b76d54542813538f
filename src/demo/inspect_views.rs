//! The pass inspector's list of views: every attachment of the frame
//! plan's render targets, each with how it is made visible (`Mode`), the
//! casting lights' shadow maps first, the light volumes' views last. The
//! list comes from the plan, so a technique's targets appear here as soon
//! as it declares them. A view may show one mip level of its texture
//! (`level`); the post chain's images are named by the step that wrote
//! them (src/demo/post_chain.rs). src/demo/inspector.rs draws them.

use super::shadow_views::ShadowView;
use crate::frame::plan::FramePlan;
use crate::frame::post::HDR;
use crate::frame::targets::{Depth, OUTPUT, format_name};
use crate::gl::depth_map;

/// A view of the light volumes (src/demo/volume_views.rs draws them).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VolumeView {
    Wireframe,
    Debug,
    Overdraw,
    /// The stencil light volumes' marks, every light's counted (stencil_marks.rs).
    Marks,
}

impl VolumeView {
    pub fn label(self) -> &'static str {
        match self {
            VolumeView::Wireframe => "light volumes: wireframe in each light's colour",
            VolumeView::Debug => "light volumes: solid red over the albedo (notes 04 debug view)",
            VolumeView::Overdraw => "light volumes: how many cover each pixel (heat map)",
            VolumeView::Marks => {
                "stencil light volumes: step 1's marks of every light, counted (notes 05): the volumes each surface lies inside"
            }
        }
    }
}

/// How an attachment is made visible (glsl/demo/inspect.frag's u_mode).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Mode {
    /// Colour as stored; `encode`: linear colour, sRGB-encode it.
    Color {
        encode: bool,
    },
    Normal,
    Shininess,
    /// One channel (R) in grey, 0 black and 1 white.
    Grey,
    /// HDR light, scaled by the exposure.
    Light,
    Depth,
    /// A count, as a heat map from 0 to `scale`.
    Count {
        scale: f32,
    },
}

/// One view the inspector offers.
#[derive(Clone, Debug, PartialEq)]
pub struct View {
    pub target: &'static str,
    pub attachment: &'static str,
    /// None: the depth-stencil attachment.
    pub color_index: Option<usize>,
    pub format: u32,
    pub mode: Mode,
    /// A view of the light volumes instead of an attachment.
    pub volumes: Option<VolumeView>,
    /// The difference image of "compare with reference" instead of an attachment.
    pub difference: bool,
    /// The stencil values of the depth-stencil attachment (read back: GL 3.3
    /// cannot sample stencil), each value its own colour.
    pub stencil: bool,
    /// A casting light's shadow map instead of an attachment.
    pub shadow: Option<ShadowView>,
    /// The mip level shown (0: the full-size image), stretched over the view.
    pub level: u32,
    /// What the image holds at the end of the frame, for a post chain's
    /// image: "after step 1, tone mapping" (src/demo/post_chain.rs).
    pub written: Option<String>,
}

impl View {
    /// A view of an attachment of `target`, made visible by `mode`.
    pub fn of(
        target: &'static str,
        attachment: &'static str,
        color_index: Option<usize>,
        format: u32,
        mode: Mode,
    ) -> View {
        View {
            target,
            attachment,
            color_index,
            format,
            mode,
            volumes: None,
            difference: false,
            stencil: false,
            shadow: None,
            level: 0,
            written: None,
        }
    }

    /// Whether two views show the same thing. A shadow map stays its
    /// light's map when its resolution changes.
    pub fn same_as(&self, other: &View) -> bool {
        let key = |v: &View| {
            let shadow = v.shadow.map(|s| (s.light, s.face));
            (
                v.target,
                v.attachment,
                v.color_index,
                v.volumes,
                v.difference,
                v.stencil,
                shadow,
                v.level,
            )
        };
        key(self) == key(other)
    }

    /// "gbuffer.normal_shininess (RGBA16F)" and what the view shows.
    pub fn label(&self) -> String {
        if let Some(v) = self.volumes {
            return v.label().to_string();
        }
        if let Some(s) = &self.shadow {
            return s.label();
        }
        if self.difference {
            return "difference to the forward reference, x8".to_string();
        }
        if self.stencil {
            return format!(
                "{}.stencil ({}): each value its own colour, 0 black",
                self.target,
                format_name(self.format)
            );
        }
        if let Some(holds) = holds(self.target, self.attachment) {
            return format!(
                "{}.{} ({}): {holds}",
                self.target,
                self.attachment,
                format_name(self.format)
            );
        }
        let shows = match self.mode {
            Mode::Color { .. } => "colour",
            Mode::Normal => "normal x 0.5 + 0.5",
            Mode::Shininess => "shininess / 256",
            Mode::Grey => "one channel (R) in grey, 0 black, 1 white",
            Mode::Light => "light x exposure",
            Mode::Depth => "depth, linearised",
            Mode::Count { .. } => "count, as a heat map",
        };
        let level = match self.level {
            0 => String::new(),
            l => format!(" level {l}"),
        };
        let written = (self.written.as_deref()).map_or(String::new(), |w| format!(": {w}"));
        format!(
            "{}.{}{level}{written} ({}): {shows}",
            self.target,
            self.attachment,
            format_name(self.format)
        )
    }
}

/// What an attachment holds, by the name its technique gives it in the
/// plan, where that says more than its format: the G-buffer's microfacet
/// triple (notes 03, Geometry Pass) is not light, the SSAO target holds
/// one channel.
pub fn holds(target: &str, attachment: &str) -> Option<&'static str> {
    Some(match attachment {
        "alpha" => "the microfacet triple (alpha, eta, k_s) as r, g, b, stored values",
        "convert" => "gConvert: 1 where gAlpha's element holds a Phong value to convert",
        "ao" => "ambient occlusion, one channel (R), in grey: 0 black, 1 white",
        "albedo" if target == "gbuffer" => "albedo (diffuse colour)",
        "specular" if target == "gbuffer" => "specular colour",
        _ => return None,
    })
}

/// The mode a named attachment is shown in, where its name decides it.
fn mode_of(attachment: &str) -> Option<Mode> {
    match attachment {
        // Stored values, not light: no exposure, no encoding.
        "alpha" | "convert" => Some(Mode::Color { encode: false }),
        // One channel: red alone would read as a colour.
        "ao" => Some(Mode::Grey),
        _ => None,
    }
}

/// Every view of a frame: the shadow map of each casting light (`shadows`:
/// drawn first in the frame), the plan's targets in the plan's order; then,
/// when some light has a volume, the three views of the volumes.
pub fn views(plan: &FramePlan, has_volumes: bool, shadows: &[ShadowView]) -> Vec<View> {
    let map = |s: &ShadowView| View {
        shadow: Some(*s),
        ..View::of("shadow map", "depth", None, depth_map::FORMAT, Mode::Depth)
    };
    // A cube's cross, then each of its faces alone (one per face pass).
    let maps = shadows
        .iter()
        .flat_map(|s| std::iter::once(*s).chain(s.faces()));
    let mut v: Vec<View> = maps.map(|s| map(&s)).collect();
    for t in &plan.targets {
        // A multisampled target (MSAA) cannot be sampled as a sampler2D: its
        // resolved image is the world's target, shown with it.
        if t.samples > 1 {
            continue;
        }
        // A target with mip levels (bloom's): one view per level it has.
        if let Some((first, last)) = t.mips {
            for (i, &(name, format)) in t.colors.iter().enumerate() {
                for level in first..=last {
                    v.push(View {
                        level,
                        ..View::of(t.name, name, Some(i), format, Mode::Light)
                    });
                }
            }
            continue;
        }
        for (i, &(name, format)) in t.colors.iter().enumerate() {
            let color = |mode| View::of(t.name, name, Some(i), format, mode);
            match name {
                "normal_shininess" => {
                    v.push(color(Mode::Normal));
                    v.push(View {
                        attachment: "shininess",
                        ..color(Mode::Shininess)
                    });
                }
                _ if let Some(mode) = mode_of(name) => v.push(color(mode)),
                _ if matches!(format, glow::R8 | glow::R16F | glow::R32F) => {
                    v.push(color(Mode::Grey))
                }
                _ if matches!(format, glow::RGBA16F | glow::RGBA32F) => v.push(color(Mode::Light)),
                _ => v.push(color(Mode::Color {
                    encode: format == glow::SRGB8_ALPHA8,
                })),
            }
        }
        if let Depth::Own(format) = t.depth {
            v.push(View::of(t.name, "depth", None, format, Mode::Depth));
            // The stencil of the target the world is drawn into (the
            // output, or `hdr` when a post chain follows): where mirrors
            // mark their regions.
            if format == glow::DEPTH24_STENCIL8 && [OUTPUT, HDR].contains(&t.name) {
                v.push(View {
                    stencil: true,
                    ..View::of(
                        t.name,
                        "stencil",
                        None,
                        format,
                        Mode::Color { encode: false },
                    )
                });
            }
        }
    }
    if has_volumes {
        // The stencil marks only where the stencil light volumes run.
        let stencil_volumes = (plan.passes.iter()).any(|p| {
            let name = crate::techniques::ALL.get(p.technique).map(|t| t.name);
            name == Some("stencil_light_volumes")
        });
        let marks = stencil_volumes.then_some(VolumeView::Marks);
        for which in [
            VolumeView::Wireframe,
            VolumeView::Debug,
            VolumeView::Overdraw,
        ]
        .into_iter()
        .chain(marks)
        {
            v.push(View {
                volumes: Some(which),
                ..View::of(
                    "light volumes",
                    which.label(),
                    None,
                    0,
                    Mode::Color { encode: false },
                )
            });
        }
    }
    v
}

/// The inspected view, kept by what it shows rather than by its place in the
/// list: adding or removing a caster shifts every view after it. `index` is
/// the panel's choice and `kept` the view it showed last frame (None just
/// after a new choice). Returns the index to show, None when the view has
/// gone, and makes `kept` that view.
pub fn follow(index: Option<usize>, kept: &mut Option<View>, views: &[View]) -> Option<usize> {
    let found = match (index, kept.as_ref()) {
        (None, _) => None,
        (Some(i), Some(k)) if !views.get(i).is_some_and(|v| v.same_as(k)) => {
            views.iter().position(|v| v.same_as(k))
        }
        (Some(i), _) => (i < views.len()).then_some(i),
    };
    *kept = found.map(|i| views[i].clone());
    found
}
