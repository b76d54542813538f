//! The command line of `gloss bench`: which settings to measure, how many
//! frames, and where the CSV and the plot go.

use crate::scene::RenderPath;
use std::path::PathBuf;

#[derive(clap::Args, Debug, Clone)]
pub struct BenchArgs {
    /// The scene to measure (default scenes/many-lights.toml).
    pub scene: Option<PathBuf>,
    /// The command line's `--set KEY=VALUE`s (a global option, not parsed
    /// here): applied to the scene before every setting, the reference's
    /// included.
    #[arg(skip)]
    pub set: Vec<String>,
    /// Render paths, comma-separated (deferred runs both its forms: a pass
    /// per light, and one pass over all the lights).
    /// With --vary the paths are a key like any other
    /// (--vary render.path=forward,tiled): --paths is refused there.
    #[arg(
        long,
        value_delimiter = ',',
        value_enum,
        default_value = "forward,deferred,volumes,prepass,tiled",
        conflicts_with = "vary"
    )]
    pub paths: Vec<RenderPath>,
    /// Light counts (scenes with a [light_grid]); default: the scene's own.
    #[arg(long, value_delimiter = ',')]
    pub lights: Vec<usize>,
    /// Light-volume cutoffs to sweep for the paths that use one (volumes,
    /// prepass, tiled); default: the scene's (5/256). Fractions like 5/256 are accepted.
    #[arg(long, value_delimiter = ',', value_parser = parse_fraction)]
    pub cutoffs: Vec<f32>,
    /// Also measure light volumes with the two-sided stencil test.
    #[arg(long)]
    pub stencil: bool,
    /// WIDTHxHEIGHT (default: the scene's render.size).
    #[arg(long, value_parser = parse_size)]
    pub size: Option<(u32, u32)>,
    /// Measured frames per setting.
    #[arg(long, default_value_t = 20)]
    pub frames: usize,
    /// Unmeasured frames first.
    #[arg(long, default_value_t = 3)]
    pub warmup: usize,
    /// Vary any scene key instead of the render path: KEY=V1,V2,...
    /// (repeatable; every combination is measured). A value with ';' is one
    /// setting of its own, KEY=V;KEY=V, measured after the combinations
    /// (`--vary 'render.path=tiled;render.far_field=4'`). See src/bench/variants.rs.
    #[arg(long, value_name = "KEY=V1,V2")]
    pub vary: Vec<String>,
    /// With --vary: the reference image's settings, KEY=VALUE (repeatable;
    /// default: the scene as written).
    #[arg(long = "reference", value_name = "KEY=VALUE", requires = "vary")]
    pub reference: Vec<String>,
    /// Measure anti-aliasing instead (none, FXAA, MSAA 2/4/8, MSAA 4 +
    /// FXAA) against a 16-sample supersampled reference (src/bench/aa.rs);
    /// default scene scenes/antialiasing.toml.
    #[arg(long, conflicts_with = "vary")]
    pub aa: bool,
    /// Measure texture filtering instead (nearest, bilinear, nearest or
    /// bilinear within a mip level, trilinear, anisotropic) against a
    /// 64-sample supersampled reference (src/bench/filtering.rs); default
    /// scene scenes/texture-filtering.toml.
    #[arg(long, conflicts_with_all = ["vary", "aa"])]
    pub filtering: bool,
    /// Measure screen-space ambient occlusion instead, at 4, 8, 16, 32 and
    /// 64 samples, against its ray-traced CPU reference (src/bench/ssao.rs);
    /// default scene scenes/ambient-occlusion.toml.
    #[arg(long, conflicts_with_all = ["vary", "aa", "filtering"])]
    pub ssao: bool,
    /// Measure image-based lighting instead (render.ibl): the precompute
    /// and the per-frame term, and its maps against Monte Carlo references
    /// (src/bench/ibl.rs); default scene scenes/ibl.toml.
    #[arg(long, conflicts_with_all = ["vary", "aa", "filtering", "ssao"])]
    pub ibl: bool,
    /// Measure how each path's frame time grows with the number of lights
    /// (their radii shrunk so that about as many reach each pixel) and with
    /// the number of pixels, instead (src/bench/scaling.rs).
    #[arg(long, conflicts_with_all = ["vary", "aa"])]
    pub scaling: bool,
    /// Measure the particle system instead, at these particle counts:
    /// points made quads by the geometry shader against quads built on the
    /// CPU, each streamed by a mapped buffer and by glBufferSubData
    /// (src/bench/particles.rs); default scene scenes/particles.toml.
    #[arg(long, value_delimiter = ',', conflicts_with_all = ["vary", "aa", "scaling"])]
    pub particles: Vec<usize>,
    /// Measure skinned meshes instead, at about these many skinned
    /// vertices: the GPU's skinning pass against the CPU reference, linear
    /// blend and dual quaternions (src/bench/skinning.rs); default scene
    /// scenes/skinned-arm.toml.
    #[arg(long, value_delimiter = ',', conflicts_with_all = ["vary", "aa", "scaling", "particles"])]
    pub skinning: Vec<usize>,
    /// Measure instancing instead, at these rock counts: one instanced
    /// draw against one draw per rock (src/bench/instancing.rs); default
    /// scene scenes/instancing.toml.
    #[arg(long, value_delimiter = ',', conflicts_with_all = ["vary", "aa", "scaling", "particles", "skinning"])]
    pub instancing: Vec<usize>,
    /// Where the CSV and the plot go.
    #[arg(long, default_value = "target/bench")]
    pub out: PathBuf,
}

fn parse_fraction(s: &str) -> Result<f32, String> {
    let v = match s.split_once('/') {
        Some((a, b)) => {
            let a: f32 = a
                .trim()
                .parse()
                .map_err(|_| format!("bad number in \"{s}\""))?;
            let b: f32 = b
                .trim()
                .parse()
                .map_err(|_| format!("bad number in \"{s}\""))?;
            a / b
        }
        None => s
            .trim()
            .parse()
            .map_err(|_| format!("bad number \"{s}\""))?,
    };
    if !(v.is_finite() && v > 0.0 && v < 1.0) {
        return Err(format!("cutoff {s}: expected a fraction in (0, 1)"));
    }
    Ok(v)
}

pub fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let (w, h) = s
        .split_once(['x', 'X'])
        .ok_or_else(|| format!("expected WIDTHxHEIGHT, found \"{s}\""))?;
    let w: u32 = w.parse().map_err(|_| format!("bad width in \"{s}\""))?;
    let h: u32 = h.parse().map_err(|_| format!("bad height in \"{s}\""))?;
    if !(1..=8192).contains(&w) || !(1..=8192).contains(&h) {
        return Err(format!("size {w}x{h}: each side must be 1..=8192"));
    }
    Ok((w, h))
}
