//! Texture units in an executed frame: replays a traced frame's
//! `glActiveTexture`, `glBindTexture`, `glUseProgram` and `glUniform1i`
//! (for the program's sampler uniforms, whose types GL reports) and, at
//! every draw, finds
//!
//! - two samplers of different types that read one unit (GL forbids it: the
//!   draw would read one of them wrongly, or fail), and
//! - a unit a draw samples that was bound to two different textures, by two
//!   different owners, since the pass began or the last draw that sampled
//!   it: the second bind clobbered the first before its draw. An owner is
//!   a source file with the files in the folder of its name
//!   (src/frame/shadows.rs and src/frame/shadows/cascades.rs are one: the
//!   empty map one binds for the other to replace is no clobber).
//!
//! Each finding names the units' constants (src/frame/units.rs), the pass
//! and technique of the draw, and the source lines of both sides.

use crate::frame::units;
use crate::gl::Headless;
use crate::gl::trace::{self, Call};
use crate::renderer::{Output, render_scene};
use crate::scene::Scene;
use anyhow::Result;
use glow::HasContext;
use std::collections::{BTreeSet, HashMap};

/// A sampler uniform of a program (one element of an array): its name as
/// gloss looks it up, its GLSL type, and its unit when the frame ended.
#[derive(Clone, Debug)]
pub struct Sampler {
    pub name: String,
    pub ty: u32,
    pub unit_at_end: i32,
}

/// The sampler uniforms of every program the frame used, by program name.
pub type Samplers = HashMap<i64, Vec<Sampler>>;

/// One frame of `scene` traced (as `trace_frame`), with the sampler
/// uniforms of every program it used, read while they still exist.
pub fn trace_with_samplers(ctx: &Headless, scene: &Scene) -> Result<(Vec<Call>, Samplers)> {
    let mut r = render_scene(ctx, scene, Output::Srgb8)?;
    trace::start();
    let drawn = r.render(&scene.camera);
    let calls = trace::stop();
    drawn?;
    let mut programs = Samplers::new();
    for c in calls.iter().filter(|c| c.function == "glUseProgram") {
        let Some(id) = c.args.first().and_then(|a| a.parse::<i64>().ok()) else {
            continue;
        };
        if id != 0 {
            (programs.entry(id)).or_insert_with(|| samplers_of(&ctx.gl, id));
        }
    }
    drop(r);
    Ok((calls, programs))
}

/// The sampler uniforms of program `id` (none if it is gone).
fn samplers_of(gl: &glow::Context, id: i64) -> Vec<Sampler> {
    let Some(p) = u32::try_from(id).ok().and_then(std::num::NonZeroU32::new) else {
        return Vec::new();
    };
    let p = glow::NativeProgram(p);
    let mut out = Vec::new();
    unsafe {
        if !gl.is_program(p) {
            return out;
        }
        for i in 0..gl.get_active_uniforms(p) {
            let Some(u) = gl.get_active_uniform(p, i) else {
                continue;
            };
            if target_of(u.utype).is_none() {
                continue;
            }
            let base = u.name.trim_end_matches("[0]");
            for e in 0..u.size.max(1) {
                let name = if u.size > 1 || u.name.ends_with("[0]") {
                    format!("{base}[{e}]")
                } else {
                    base.to_string()
                };
                let Some(loc) = gl.get_uniform_location(p, &name) else {
                    continue;
                };
                let mut v = [0];
                gl.get_uniform_i32(p, &loc, &mut v);
                out.push(Sampler {
                    name,
                    ty: u.utype,
                    unit_at_end: v[0],
                });
            }
        }
    }
    out
}

/// The texture target a sampler type reads.
pub fn target_of(ty: u32) -> Option<u32> {
    Some(match ty {
        glow::SAMPLER_2D
        | glow::SAMPLER_2D_SHADOW
        | glow::INT_SAMPLER_2D
        | glow::UNSIGNED_INT_SAMPLER_2D => glow::TEXTURE_2D,
        glow::SAMPLER_CUBE | glow::SAMPLER_CUBE_SHADOW | glow::INT_SAMPLER_CUBE => {
            glow::TEXTURE_CUBE_MAP
        }
        glow::SAMPLER_2D_ARRAY
        | glow::SAMPLER_2D_ARRAY_SHADOW
        | glow::INT_SAMPLER_2D_ARRAY
        | glow::UNSIGNED_INT_SAMPLER_2D_ARRAY => glow::TEXTURE_2D_ARRAY,
        glow::SAMPLER_BUFFER | glow::INT_SAMPLER_BUFFER | glow::UNSIGNED_INT_SAMPLER_BUFFER => {
            glow::TEXTURE_BUFFER
        }
        glow::SAMPLER_2D_MULTISAMPLE => glow::TEXTURE_2D_MULTISAMPLE,
        glow::SAMPLER_3D => glow::TEXTURE_3D,
        glow::SAMPLER_1D => glow::TEXTURE_1D,
        glow::SAMPLER_2D_RECT => glow::TEXTURE_RECTANGLE,
        _ => return None,
    })
}

/// A shown GL constant back to its value: hex, decimal, or a name the
/// trace knows.
pub fn value_of(shown: &str) -> Option<u32> {
    if let Some(hex) = shown.strip_prefix("0x") {
        return u32::from_str_radix(hex, 16).ok();
    }
    if let Ok(v) = shown.parse::<u32>() {
        return Some(v);
    }
    trace::named_constants()
        .find(|(_, n)| *n == shown)
        .map(|(v, _)| v)
}

/// `unit 4 (LIGHT, TILED_LIGHTS, ...)`: the constants that hold a unit.
pub fn unit_names(unit: u32) -> String {
    let names: Vec<&str> = (units::ALL.iter())
        .filter(|u| u.range().contains(&unit))
        .map(|u| u.name)
        .collect();
    format!("unit {unit} ({})", names.join(", "))
}

fn at(c: &Call) -> String {
    let pass = c.pass.as_ref().map_or_else(
        || "outside any pass".to_string(),
        |p| format!("pass {} ({})", p.pass, p.technique),
    );
    format!("{}:{} in {pass}", c.site.file, c.site.line)
}

/// `src/frame/shadows/cascades.rs` and `src/frame/shadows.rs` are one owner.
fn same_owner(a: &str, b: &str) -> bool {
    let (a, b) = (a.trim_end_matches(".rs"), b.trim_end_matches(".rs"));
    a == b || a.starts_with(&format!("{b}/")) || b.starts_with(&format!("{a}/"))
}

fn type_name(ty: u32) -> &'static str {
    trace::constant_name(ty, "").unwrap_or("a sampler")
}

/// A bind since the last draw that sampled its unit: the texture and the call.
type Bind = (i64, usize);

/// The findings over one traced frame (empty when every draw is sound),
/// each once however many draws repeat it.
pub fn check(calls: &[Call], programs: &Samplers) -> Vec<String> {
    let mut active = 0u32;
    let mut program = 0i64;
    let mut pending: HashMap<(u32, u32), Vec<Bind>> = HashMap::new();
    let mut values: HashMap<(i64, String), (i32, Option<usize>)> = HashMap::new();
    let mut found = BTreeSet::new();
    let mut pass = None;
    for (i, c) in calls.iter().enumerate() {
        // A pass binds what it reads: what the pass before bound is no
        // longer meant for any draw.
        let this_pass = c.pass.as_ref().map(|p| p.number);
        if this_pass != pass {
            pending.clear();
            pass = this_pass;
        }
        let arg = |n: usize| c.args.get(n).map(String::as_str).unwrap_or("");
        match c.function {
            "glActiveTexture" => {
                active = value_of(arg(0)).map_or(0, |v| v - glow::TEXTURE0);
            }
            "glBindTexture" => {
                let (Some(target), Ok(texture)) = (value_of(arg(0)), arg(1).parse::<i64>()) else {
                    continue;
                };
                let binds = pending.entry((active, target)).or_default();
                if texture != 0 {
                    binds.push((texture, i));
                }
            }
            "glUseProgram" => program = arg(0).parse().unwrap_or(0),
            "glUniform1i" => {
                let name = arg(0).to_string();
                let sampler = programs
                    .get(&program)
                    .is_some_and(|s| s.iter().any(|s| s.name == name));
                if let (true, Ok(v)) = (sampler, arg(1).parse::<i32>()) {
                    values.insert((program, name), (v, Some(i)));
                }
            }
            f if f.starts_with("glDraw") && !f.starts_with("glDrawBuffer") => {
                let Some(samplers) = programs.get(&program) else {
                    continue;
                };
                let read: Vec<(&Sampler, u32, Option<usize>)> = (samplers.iter())
                    .map(|s| {
                        let key = (program, s.name.clone());
                        let (v, set) = values.get(&key).copied().unwrap_or((s.unit_at_end, None));
                        (s, v.max(0) as u32, set)
                    })
                    .collect();
                let set_at = |set: Option<usize>| {
                    set.map_or("before the frame".to_string(), |j| at(&calls[j]))
                };
                for (a, (s1, u1, set1)) in read.iter().enumerate() {
                    for (s2, u2, set2) in &read[a + 1..] {
                        if u1 == u2 && s1.ty != s2.ty {
                            found.insert(format!(
                                "{}: a draw at {} reads it as {} `{}` (set at {}) and as {} `{}` (set at {})",
                                unit_names(*u1),
                                at(c),
                                type_name(s1.ty),
                                s1.name,
                                set_at(*set1),
                                type_name(s2.ty),
                                s2.name,
                                set_at(*set2),
                            ));
                        }
                    }
                }
                let sampled: BTreeSet<(u32, u32)> = (read.iter())
                    .filter_map(|(s, u, _)| Some((*u, target_of(s.ty)?)))
                    .collect();
                for key in sampled {
                    let binds = pending.remove(&key).unwrap_or_default();
                    let Some(&(last, j)) = binds.last() else {
                        continue;
                    };
                    let file = |k: usize| calls[k].site.file.as_str();
                    let clobbered = binds
                        .iter()
                        .find(|&&(t, k)| t != last && !same_owner(file(k), file(j)));
                    if let Some(&(t, k)) = clobbered {
                        let readers: Vec<String> = (read.iter())
                            .filter(|(s, u, _)| *u == key.0 && target_of(s.ty) == Some(key.1))
                            .map(|(s, _, _)| format!("`{}`", s.name))
                            .collect();
                        found.insert(format!(
                            "{} ({}): texture {t} bound at {} is replaced by texture {last} bound at {} before a draw at {} reads it as {}",
                            unit_names(key.0),
                            trace::constant_name(key.1, "TextureTarget").unwrap_or("?"),
                            at(&calls[k]),
                            at(&calls[j]),
                            at(c),
                            readers.join(", "),
                        ));
                    }
                }
            }
            _ => {}
        }
    }
    found.into_iter().collect()
}
