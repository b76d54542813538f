//! Wavefront MTL files (the materials an OBJ's `mtllib` names), parsed by
//! tobj and turned into what gloss draws with: the Phong terms of notes 01
//! §8.3 (c_d = Kd, c_s = Ks, n = Ns), the opacity of §4.5 (d, or 1 - Tr),
//! and the maps: map_Kd (colour, its alpha the alpha test's), map_Ks (a
//! specular map), map_Bump / bump / norm (a tangent-space normal map, notes
//! 01 §8.4, with `-bm` its scale) and map_d (alpha). docs/model_loading.md
//! has the whole mapping and what is dropped, with its warning.
//!
//! A texture path may be written with backslashes, spaces and another case
//! than the file's; a texture that is not there is a warning naming the
//! material and the path, and the material renders without it.

use crate::assets;
use anyhow::{Result, bail};
use std::path::{Path, PathBuf};

/// Largest MTL file read (MTL files are small; this stops /dev/zero).
pub const MAX_MTL_BYTES: u64 = 16 * 1024 * 1024;
/// Most materials one MTL file may define.
pub const MAX_MTL_MATERIALS: usize = 4096;

/// One material of an MTL file, mapped onto gloss's terms.
#[derive(Clone, Debug, PartialEq)]
pub struct MtlMaterial {
    /// `newmtl NAME`.
    pub name: String,
    /// c_d: Kd, clamped to 0..=1 (1 when only map_Kd is given, 0.6 when neither).
    pub diffuse: [f32; 3],
    /// c_s: Ks, clamped to 0..=1 (0 when absent, and for illum 0 and 1).
    pub specular: [f32; 3],
    /// n: Ns, clamped to 1..=4096 (32 when absent).
    pub shininess: f32,
    /// d, or 1 - Tr, clamped to 0..=1 (1: opaque).
    pub opacity: f32,
    /// map_Kd: sRGB colour (its alpha the alpha test's when it has one).
    pub diffuse_map: Option<PathBuf>,
    /// map_Ks: multiplies c_s per texel (linear data).
    pub specular_map: Option<PathBuf>,
    /// map_Bump / bump / norm: a tangent-space normal map (linear data).
    pub normal_map: Option<PathBuf>,
    /// `-bm` of the normal map: its x and y are multiplied by it (1 when absent).
    pub normal_scale: f32,
    /// map_d: the alpha, from its first channel (red, or grey).
    pub alpha_map: Option<PathBuf>,
}

/// The materials of the MTL file at `path`, and what was dropped (each
/// warning names the file and the material).
pub fn load_mtl(path: &Path) -> Result<(Vec<MtlMaterial>, Vec<String>)> {
    let bytes = assets::read(path, MAX_MTL_BYTES, "MTL file")?;
    parse_mtl(&bytes, path)
}

/// `load_mtl` on bytes already read; `path` names the file in messages and
/// anchors the texture paths.
pub fn parse_mtl(bytes: &[u8], path: &Path) -> Result<(Vec<MtlMaterial>, Vec<String>)> {
    let (ours, warnings, _) = parse_both(bytes, path)?;
    Ok((ours, warnings))
}

/// What tobj's OBJ reader wants back from an `mtllib` (always `Ok` here:
/// an error is reported as gloss's own).
pub(crate) type TobjMaterials = tobj::MTLLoadResult;

/// `load_mtl`, with tobj's own materials (for its `usemtl` lookup).
pub(crate) fn load_both(path: &Path) -> Result<(Vec<MtlMaterial>, Vec<String>, TobjMaterials)> {
    let bytes = assets::read(path, MAX_MTL_BYTES, "MTL file")?;
    parse_both(&bytes, path)
}

fn parse_both(bytes: &[u8], path: &Path) -> Result<(Vec<MtlMaterial>, Vec<String>, TobjMaterials)> {
    let name = path.display();
    let Ok(text) = std::str::from_utf8(bytes) else {
        bail!("MTL file {name} is not UTF-8 text");
    };
    let defined = text
        .lines()
        .filter(|l| l.trim_start().starts_with("newmtl"))
        .count();
    if defined > MAX_MTL_MATERIALS {
        bail!("MTL file {name} defines {defined} materials, the limit is {MAX_MTL_MATERIALS}");
    }
    let text = colours_for_tobj(text, &name.to_string())?;
    let parsed = tobj::load_mtl_buf(&mut text.as_bytes());
    let materials = match &parsed {
        Ok((m, _)) => m,
        Err(e) => bail!("malformed MTL file {name}: {}", first_bad_line(&text, *e)),
    };
    let base = path.parent().unwrap_or(Path::new("."));
    let mut warnings = Vec::new();
    let mut out = Vec::new();
    for m in materials {
        out.push(material(m, base, path, &mut warnings)?);
    }
    Ok((out, warnings, parsed))
}

/// The MTL text as tobj can take it: tobj panics on a colour statement
/// (Ka, Kd, Ks, Ke) of fewer than three numbers (found by
/// tests/fuzz/mtl.rs). One number is the MTL specification's grey
/// (`Kd r` is r r r); none or two are an error naming the line.
fn colours_for_tobj(text: &str, name: &str) -> Result<String> {
    let mut out = String::with_capacity(text.len() + 64);
    for (i, line) in text.lines().enumerate() {
        let mut words = line.split_whitespace();
        if let Some(key @ ("Ka" | "Kd" | "Ks" | "Ke")) = words.next() {
            let values: Vec<&str> = words.collect();
            match values.len() {
                1 => {
                    let r = values[0];
                    out.push_str(&format!("{key} {r} {r} {r}\n"));
                    continue;
                }
                0 | 2 => {
                    let shown: String = line.chars().take(80).collect();
                    bail!(
                        "malformed MTL file {name}: line {}: \"{shown}\": expected three numbers (r g b)",
                        i + 1
                    );
                }
                _ => {}
            }
        }
        out.push_str(line);
        out.push('\n');
    }
    Ok(out)
}

/// tobj says what kind of error, not where: find the first line that fails
/// on its own, and quote it.
fn first_bad_line(text: &str, e: tobj::LoadError) -> String {
    for (i, line) in text.lines().enumerate() {
        let one = format!("newmtl probe\n{line}\n");
        if tobj::load_mtl_buf(&mut one.as_bytes()).is_err() {
            let shown: String = line.chars().take(80).collect();
            let key = line.split_whitespace().next().unwrap_or("");
            let expected = match key {
                "Ka" | "Kd" | "Ks" | "Ke" => "expected three numbers (r g b)",
                "Ns" | "Ni" | "d" => "expected a number",
                "illum" => "expected an illumination model, 0 to 10",
                "newmtl" => "expected a material name",
                _ => "expected a file name after the key",
            };
            return format!("line {}: \"{shown}\": {expected} ({e})", i + 1);
        }
    }
    e.to_string()
}

fn material(
    m: &tobj::Material,
    base: &Path,
    file: &Path,
    warnings: &mut Vec<String>,
) -> Result<MtlMaterial> {
    let file_name = file.display();
    let who = format!("MTL file {file_name}, material \"{}\"", m.name);
    let mut warn = |what: String| warnings.push(format!("{who}: {what}"));
    // Any key in any case: tobj matches some keys exactly and keeps the
    // rest as unknown parameters.
    let other = |key: &str| {
        m.unknown_param
            .iter()
            .find(|(k, _)| k.eq_ignore_ascii_case(key))
            .map(|(_, v)| v.as_str())
    };
    let number = |key: &str, v: &str| -> Result<f32> {
        match v.split_whitespace().next().map(str::parse::<f32>) {
            Some(Ok(x)) if x.is_finite() => Ok(x),
            _ => bail!("{who}: {key}: expected a number, found \"{v}\""),
        }
    };
    let colour =
        |key: &str, v: Option<[f32; 3]>, warn: &mut dyn FnMut(String)| {
            v.map(|c| {
            let ok = c.iter().all(|x| x.is_finite() && (0.0..=1.0).contains(x));
            if !ok {
                warn(format!(
                    "{key} {c:?} clamped to 0..=1 (a surface reflects at most the light it gets)"
                ));
            }
            c.map(|x| if x.is_finite() { x.clamp(0.0, 1.0) } else { 0.0 })
        })
        };
    let mut texture = |key: &str, written: Option<&str>| -> (Option<PathBuf>, f32) {
        let Some(written) = written else {
            return (None, 1.0);
        };
        let (rest, bm, ignored) = texture_options(written);
        for o in ignored {
            warn(format!("{key} option {o} is not supported: ignored"));
        }
        if rest.is_empty() {
            warn(format!("{key} names no file: ignored"));
            return (None, 1.0);
        }
        match find_file(base, &rest) {
            Some(p) => (Some(p), bm.unwrap_or(1.0)),
            None => {
                warn(format!(
                    "{key} texture {} not found: the material renders without it",
                    base.join(rest.replace('\\', "/")).display()
                ));
                (None, 1.0)
            }
        }
    };
    let (diffuse_map, _) = texture("map_Kd", m.diffuse_texture.as_deref().or(other("map_Kd")));
    let (specular_map, _) = texture("map_Ks", m.specular_texture.as_deref().or(other("map_Ks")));
    let (normal_map, normal_scale) = texture(
        "map_Bump",
        (m.normal_texture.as_deref())
            .or(other("map_Bump"))
            .or(other("bump"))
            .or(other("norm")),
    );
    let (alpha_map, _) = texture("map_d", m.dissolve_texture.as_deref().or(other("map_d")));
    for (key, given) in [
        ("map_Ka", m.ambient_texture.is_some()),
        ("map_Ns", m.shininess_texture.is_some()),
        ("Ka", m.ambient.is_some_and(|a| a != [0.0; 3])),
        ("Ke", m.emissive.is_some_and(|e| e != [0.0; 3])),
        ("map_Ke", other("map_Ke").is_some()),
        ("refl", other("refl").is_some()),
        ("disp", other("disp").is_some()),
        ("decal", other("decal").is_some()),
    ] {
        if given {
            warn(format!("{key} is not used by gloss: ignored"));
        }
    }
    let mut warn = |w: String| warnings.push(format!("{who}: {w}"));
    let diffuse = colour("Kd", m.diffuse, &mut warn).unwrap_or(if diffuse_map.is_some() {
        [1.0; 3]
    } else {
        [0.6; 3]
    });
    let mut specular = colour("Ks", m.specular, &mut warn).unwrap_or([0.0; 3]);
    match m.illumination_model {
        // Colour on, ambient on / off: no highlight.
        Some(0 | 1) => specular = [0.0; 3],
        None | Some(2) => {}
        Some(i) => warn(format!(
            "illum {i} (reflection, refraction or ray tracing) is drawn as illum 2, Phong with a highlight"
        )),
    }
    let shininess = match m.shininess {
        None => 32.0,
        Some(n) if n.is_finite() => n.clamp(1.0, 4096.0),
        Some(n) => bail!("{who}: Ns: expected a finite number, found {n}"),
    };
    let opacity = match (m.dissolve, other("Tr")) {
        (Some(d), _) if d.is_finite() => d.clamp(0.0, 1.0),
        (Some(d), _) => bail!("{who}: d: expected a number in 0..=1, found {d}"),
        (None, Some(tr)) => 1.0 - number("Tr", tr)?.clamp(0.0, 1.0),
        (None, None) => 1.0,
    };
    if !(normal_scale.is_finite() && normal_scale.abs() <= 100.0) {
        bail!("{who}: -bm: expected a number within ±100, found {normal_scale}");
    }
    Ok(MtlMaterial {
        name: m.name.clone(),
        diffuse,
        specular,
        shininess,
        opacity,
        diffuse_map,
        specular_map,
        normal_map,
        normal_scale,
        alpha_map,
    })
}

/// How many numbers each texture option takes (the MTL specification's
/// "-o u v w" takes one to three).
fn option_arity(o: &str) -> Option<(usize, usize)> {
    Some(match o {
        "-bm" | "-blendu" | "-blendv" | "-cc" | "-clamp" | "-imfchan" | "-texres" | "-type"
        | "-boost" => (1, 1),
        "-mm" => (2, 2),
        "-o" | "-s" | "-t" => (1, 3),
        _ => return None,
    })
}

/// A map statement's value split into the file name (what follows the
/// options, spaces kept), `-bm`'s number, and the options ignored.
pub(crate) fn texture_options(written: &str) -> (String, Option<f32>, Vec<String>) {
    let mut rest = written.trim();
    let mut bm = None;
    let mut ignored = Vec::new();
    while let Some(word) = rest.split_whitespace().next() {
        let Some((least, most)) = option_arity(word) else {
            break;
        };
        let mut after = rest[word.len()..].trim_start();
        let mut values = Vec::new();
        while values.len() < most {
            let Some(v) = after.split_whitespace().next() else {
                break;
            };
            // -clamp and -imfchan take words; the others numbers.
            let is_value =
                v.parse::<f32>().is_ok() || matches!(word, "-clamp" | "-imfchan" | "-type");
            if !is_value || (values.len() >= least && v.parse::<f32>().is_err()) {
                break;
            }
            values.push(v.to_string());
            after = after[v.len()..].trim_start();
        }
        if word == "-bm" {
            bm = values.first().and_then(|v| v.parse::<f32>().ok());
        } else {
            ignored.push(
                format!("{word} {}", values.join(" "))
                    .trim_end()
                    .to_string(),
            );
        }
        rest = after;
    }
    (rest.trim().to_string(), bm, ignored)
}

/// The file `written` names, relative to `base`: backslashes read as
/// slashes, and each part of the path matched in any case when the exact
/// name is not there (models made on Windows name `Body.PNG` for body.png).
pub(crate) fn find_file(base: &Path, written: &str) -> Option<PathBuf> {
    let written = written.trim_matches('"').replace('\\', "/");
    let exact = if Path::new(&written).is_absolute() {
        PathBuf::from(&written)
    } else {
        base.join(&written)
    };
    if assets::is_file(&exact) {
        return Some(exact);
    }
    // Part by part, in any case (on disk; shipped files are named exactly).
    let mut at = if Path::new(&written).is_absolute() {
        PathBuf::from("/")
    } else {
        base.to_path_buf()
    };
    if at.as_os_str().is_empty() {
        // A file named relative to the working directory.
        at = PathBuf::from(".");
    }
    for part in written.split('/').filter(|p| !p.is_empty() && *p != ".") {
        let next = at.join(part);
        if part == ".." || next.exists() {
            at = next;
            continue;
        }
        let found = std::fs::read_dir(&at).ok()?.flatten().find(|e| {
            e.file_name()
                .to_str()
                .is_some_and(|n| n.eq_ignore_ascii_case(part))
        })?;
        at = found.path();
    }
    assets::is_file(&at).then_some(at)
}

#[cfg(test)]
mod tests;
