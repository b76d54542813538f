//! The frame plan: from a scene, decide which passes run and which render
//! targets exist, before any GL work. `gloss plan SCENE` prints it; the
//! renderer creates exactly these targets and runs exactly these passes.
//!
//! A frame runs only what its scene needs: no light pass for a scene with no
//! lights, no stencil work unless the stencil light-volume test is on.

use crate::scene::{LightKind, RenderPath, Scene, Shading};

#[derive(Clone, Debug, PartialEq)]
pub struct Target {
    pub name: &'static str,
    /// Attachments as "name:FORMAT".
    pub attachments: Vec<String>,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Pass {
    pub name: &'static str,
    /// Where the pass writes.
    pub target: &'static str,
    /// What the pass draws, in words (e.g. "12 objects", "256 spheres").
    pub draws: String,
    /// Source file that implements it.
    pub code: &'static str,
}

#[derive(Clone, Debug, PartialEq)]
pub struct FramePlan {
    pub path: RenderPath,
    pub targets: Vec<Target>,
    pub passes: Vec<Pass>,
}

/// G-buffer layout (src/gbuffer.rs; docs/gbuffer.md explains the choice).
pub const GBUFFER_ATTACHMENTS: [&str; 4] = [
    "normal_shininess:RGBA16F",
    "albedo:SRGB8_ALPHA8",
    "specular:SRGB8_ALPHA8",
    "depth_stencil:DEPTH24_STENCIL8",
];

impl FramePlan {
    pub fn new(scene: &Scene) -> FramePlan {
        let r = &scene.render;
        let n_objects = scene.objects.len();
        let count = |k: LightKind| scene.lights.iter().filter(|l| l.kind == k).count();
        let (n_dir, n_point, n_spot) = (
            count(LightKind::Directional),
            count(LightKind::Point),
            count(LightKind::Spot),
        );
        let n_lights = scene.lights.len();
        let accum = if r.accumulation == glow::RGBA32F {
            "RGBA32F"
        } else {
            "RGBA16F"
        };
        let output = Target {
            name: "output",
            attachments: vec![
                "color:RGBA8 (sRGB-encoded)".into(),
                "depth_stencil:DEPTH24_STENCIL8".into(),
            ],
        };
        let gbuffer = Target {
            name: "gbuffer",
            attachments: GBUFFER_ATTACHMENTS.iter().map(|s| s.to_string()).collect(),
        };
        let accumulation = Target {
            name: "light_accumulation",
            attachments: vec![format!("light:{accum}"), "depth_stencil:gbuffer's".into()],
        };
        let gbuffer_pass = Pass {
            name: "gbuffer",
            target: "gbuffer",
            draws: format!("{n_objects} objects"),
            code: "src/gbuffer.rs",
        };
        let mut passes = Vec::new();
        let mut targets = Vec::new();
        match r.path {
            RenderPath::Forward => {
                let mode = match r.shading {
                    Shading::Phong => "Phong shading, per fragment",
                    Shading::Gouraud => "Gouraud shading, per vertex",
                    Shading::Flat => "flat shading, per triangle in a geometry shader",
                };
                targets.push(output);
                passes.push(Pass {
                    name: "forward",
                    target: "output",
                    draws: format!("{n_objects} objects x {n_lights} lights ({mode})"),
                    code: "src/forward.rs",
                });
            }
            RenderPath::Deferred => {
                targets.extend([gbuffer, accumulation, output]);
                passes.push(gbuffer_pass);
                if n_lights > 0 {
                    passes.push(Pass {
                        name: "lighting",
                        target: "light_accumulation",
                        draws: format!("{n_lights} full-screen triangles, one per light, additive"),
                        code: "src/deferred_shading.rs",
                    });
                }
                passes.push(Pass {
                    name: "composite",
                    target: "output",
                    draws: "1 full-screen triangle (ambient + light, sRGB encode)".into(),
                    code: "src/deferred_shading.rs",
                });
            }
            RenderPath::Volumes => {
                targets.extend([gbuffer, accumulation, output]);
                passes.push(gbuffer_pass);
                if n_lights > 0 {
                    let unbounded = scene
                        .lights
                        .iter()
                        .filter(|l| {
                            l.kind != LightKind::Directional && l.volume_radius(r.cutoff).is_none()
                        })
                        .count();
                    let mut parts = Vec::new();
                    if n_point > 0 {
                        parts.push(format!("{} spheres", n_point));
                    }
                    if n_spot > 0 {
                        parts.push(format!("{n_spot} cones"));
                    }
                    if n_dir + unbounded > 0 {
                        parts.push(format!("{} full-screen triangles", n_dir + unbounded));
                    }
                    if unbounded > 0 {
                        parts.push(format!("({unbounded} with no finite radius)"));
                    }
                    passes.push(Pass {
                        name: "lighting",
                        target: "light_accumulation",
                        draws: format!(
                            "{}, front faces culled, additive{}",
                            parts.join(" + "),
                            if r.stencil_volumes {
                                ", stencil-tested"
                            } else {
                                ""
                            }
                        ),
                        code: "src/light_volumes.rs",
                    });
                }
                passes.push(Pass {
                    name: "composite",
                    target: "output",
                    draws: "1 full-screen triangle (ambient + light, sRGB encode)".into(),
                    code: "src/deferred_shading.rs",
                });
            }
            RenderPath::Prepass => {
                // The light pre-pass needs no material in its G-buffer.
                let thin = Target {
                    name: "gbuffer",
                    attachments: vec![
                        GBUFFER_ATTACHMENTS[0].to_string(),
                        GBUFFER_ATTACHMENTS[3].to_string(),
                    ],
                };
                targets.push(thin);
                targets.push(Target {
                    name: "light_accumulation",
                    attachments: vec![
                        format!("diffuse_light:{accum}"),
                        format!("specular_light:{accum}"),
                        "depth_stencil:gbuffer's".into(),
                    ],
                });
                targets.push(output);
                passes.push(Pass {
                    draws: format!("{n_objects} objects (normal + shininess, depth)"),
                    ..gbuffer_pass
                });
                if n_lights > 0 {
                    passes.push(Pass {
                        name: "light pre-pass",
                        target: "light_accumulation",
                        draws: format!(
                            "{n_lights} light volumes, diffuse and specular apart, additive"
                        ),
                        code: "src/deferred_lighting.rs",
                    });
                }
                passes.push(Pass {
                    name: "combine",
                    target: "output",
                    draws: format!(
                        "{n_objects} objects again, GL_LEQUAL against the G-buffer's depth (blitted): material x light, sRGB encode"
                    ),
                    code: "src/deferred_lighting.rs",
                });
            }
        }
        FramePlan {
            path: r.path,
            targets,
            passes,
        }
    }

    pub fn has_pass(&self, name: &str) -> bool {
        self.passes.iter().any(|p| p.name == name)
    }
}

impl std::fmt::Display for FramePlan {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        writeln!(f, "path: {}", self.path.name())?;
        writeln!(f, "render targets:")?;
        for t in &self.targets {
            writeln!(f, "  {:<20} {}", t.name, t.attachments.join(", "))?;
        }
        writeln!(f, "passes:")?;
        for (i, p) in self.passes.iter().enumerate() {
            writeln!(
                f,
                "  {}. {:<16} -> {:<20} {}  [{}]",
                i + 1,
                p.name,
                p.target,
                p.draws,
                p.code
            )?;
        }
        Ok(())
    }
}
