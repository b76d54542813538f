//! The `[particles]` table: a particle fountain (notes 01 §3.2,
//! src/frame/particles.rs simulates it, src/techniques/vertex_geometry/
//! particles.rs draws it).
//!
//! ```toml
//! [particles]
//! count = 10000              # at most this many alive
//! rate = 2000.0              # born a second
//! lifetime = 2.5             # seconds
//! speed = 5.0                # start speed
//! spread = 15.0              # degrees about direction
//! direction = [0, 1, 0]
//! gravity = [0, -9.8, 0]
//! emitter = [0, 0, 0]
//! size = 0.08                # a quad's side, world units
//! color = [1.0, 0.6, 0.2]
//! seed = 1
//! blend = "additive"         # or "alpha_test"
//! expand = "geometry_shader" # or "cpu": the quads built on the CPU, for comparison
//! stream = "map"             # or "subdata": how each frame's buffer is written
//! ```
//!
//! The particles' time is the animation's (`[animation] time`, `--time`).

use super::camera_limits::within_world;
use super::checks::{finite, non_negative};
use anyhow::{Result, bail};
use glam::Vec3;
use serde::Deserialize;

#[derive(Deserialize, Debug, Clone, Default)]
#[serde(deny_unknown_fields, default)]
pub(super) struct ParticlesFile {
    count: Option<u32>,
    rate: Option<f32>,
    lifetime: Option<f32>,
    speed: Option<f32>,
    spread: Option<f32>,
    direction: Option<[f32; 3]>,
    gravity: Option<[f32; 3]>,
    emitter: Option<[f32; 3]>,
    size: Option<f32>,
    color: Option<[f32; 3]>,
    seed: Option<u32>,
    blend: Option<String>,
    expand: Option<String>,
    stream: Option<String>,
}

/// The most particles alive at once.
pub const MAX_PARTICLES: u32 = 4_000_000;

/// How particles are blended into the image.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum ParticleBlend {
    /// glBlendFunc(GL_ONE, GL_ONE), no depth writes: order does not matter.
    #[default]
    Additive,
    /// A disc cut out by the alpha test, depth-tested and written like any opaque object.
    AlphaTest,
}

/// The checked table.
#[derive(Clone, Debug, PartialEq)]
pub struct Particles {
    pub count: u32,
    pub rate: f32,
    pub lifetime: f32,
    pub speed: f32,
    pub spread: f32,
    pub direction: Vec3,
    pub gravity: Vec3,
    pub emitter: Vec3,
    pub size: f32,
    pub color: Vec3,
    pub seed: u32,
    pub blend: ParticleBlend,
    /// Quads made by the geometry shader from points (true), or on the CPU.
    pub geometry_shader: bool,
    /// The buffer written through glMapBufferRange (true) or glBufferSubData.
    pub map: bool,
}

impl Default for Particles {
    fn default() -> Particles {
        Particles {
            count: 10_000,
            rate: 2000.0,
            lifetime: 2.5,
            speed: 5.0,
            spread: 15.0,
            direction: Vec3::Y,
            gravity: Vec3::new(0.0, -9.8, 0.0),
            emitter: Vec3::ZERO,
            size: 0.08,
            color: Vec3::new(1.0, 0.6, 0.2),
            seed: 1,
            blend: ParticleBlend::Additive,
            geometry_shader: true,
            map: true,
        }
    }
}

fn word<'a>(key: &str, v: &'a Option<String>, words: [&'a str; 2]) -> Result<bool> {
    match v.as_deref() {
        None => Ok(true),
        Some(w) if w == words[0] => Ok(true),
        Some(w) if w == words[1] => Ok(false),
        Some(w) => bail!(
            "particles.{key}: expected \"{}\" or \"{}\", found \"{w}\"",
            words[0],
            words[1]
        ),
    }
}

pub(super) fn resolve(f: Option<&ParticlesFile>) -> Result<Option<Particles>> {
    let Some(f) = f else { return Ok(None) };
    let d = Particles::default();
    let count = f.count.unwrap_or(d.count);
    if !(1..=MAX_PARTICLES).contains(&count) {
        bail!("particles.count: expected 1..={MAX_PARTICLES} particles, found {count}");
    }
    let positive = |key: &str, v: Option<f32>, default: f32| -> Result<f32> {
        let v = v.unwrap_or(default);
        if !(v.is_finite() && v > 0.0) {
            bail!("particles.{key}: expected a number > 0, found {v}");
        }
        within_world(&format!("particles.{key}"), &[v])?;
        Ok(v)
    };
    let vec = |key: &str, v: Option<[f32; 3]>, default: Vec3| -> Result<Vec3> {
        let v = v.map_or(default, Vec3::from);
        finite(&format!("particles.{key}"), &v.to_array())?;
        within_world(&format!("particles.{key}"), &v.to_array())?;
        Ok(v)
    };
    let direction = vec("direction", f.direction, d.direction)?;
    if direction.length() < 1e-6 {
        bail!("particles.direction: expected a direction, found {direction}");
    }
    let spread = f.spread.unwrap_or(d.spread);
    if !(0.0..=180.0).contains(&spread) {
        bail!("particles.spread: expected 0..=180 degrees, found {spread}");
    }
    let speed = f.speed.unwrap_or(d.speed);
    non_negative("particles.speed", &[speed])?;
    within_world("particles.speed", &[speed])?;
    let color = vec("color", f.color, d.color)?;
    non_negative("particles.color", &color.to_array())?;
    Ok(Some(Particles {
        count,
        rate: positive("rate", f.rate, d.rate)?,
        lifetime: positive("lifetime", f.lifetime, d.lifetime)?,
        speed,
        spread,
        direction,
        gravity: vec("gravity", f.gravity, d.gravity)?,
        emitter: vec("emitter", f.emitter, d.emitter)?,
        size: positive("size", f.size, d.size)?,
        color,
        seed: f.seed.unwrap_or(d.seed),
        blend: if word("blend", &f.blend, ["additive", "alpha_test"])? {
            ParticleBlend::Additive
        } else {
            ParticleBlend::AlphaTest
        },
        geometry_shader: word("expand", &f.expand, ["geometry_shader", "cpu"])?,
        map: word("stream", &f.stream, ["map", "subdata"])?,
    }))
}
