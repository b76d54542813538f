//! `[[object_fields]]`: many objects from a few lines, seeded, for the
//! scene management of notes 01 §6 (a 10,000-object city that frustum
//! culling, §6.3, has something to cull, grouped as a scene graph, §6.4):
//!
//! ```toml
//! [[object_fields]]
//! name = "block"                # objects block0, block0.1, ... (default "field")
//! count = 625                   # groups, each a root object
//! children = 15                 # objects on each root, children of it (0: none)
//! seed = 1
//! area = [-150.0, 150.0, -150.0, 150.0]   # xmin, xmax, zmin, zmax
//! mesh = "cube"                 # the root: a plate on y = 0
//! material = "stone"
//! size = [8.0, 0.2]             # the plate: width and depth alike, height
//! child_mesh = "cube"
//! child_material = "brick"
//! child_size = [1.2, 4.0]       # each child: width, and height at most
//! ```
//!
//! Each group stands at a random place in the area, turned by a random
//! angle about y; its children stand on a grid on the plate with random
//! heights (1/4 to 1 of the most). A child is placed in its parent's space
//! with the plate's scale divided out, so that it keeps its own size.
//! The fields' objects come after the file's `[[objects]]`.

use super::file::{ObjectFile, SceneFile};
pub use super::object_field_file::ObjectFieldFile;
use crate::math::lcg::Lcg;
use anyhow::{Result, bail};

/// The most objects all fields together may make.
pub const MAX_FIELD_OBJECTS: usize = 100_000;

/// The objects of every field, as if written in `[[objects]]`.
pub(super) fn expand(fields: &[ObjectFieldFile]) -> Result<Vec<ObjectFile>> {
    let total: usize = (fields.iter())
        .map(|f| f.count.saturating_mul(f.children.saturating_add(1)))
        .fold(0, usize::saturating_add);
    if total > MAX_FIELD_OBJECTS {
        bail!("object_fields: {total} objects in all, the limit is {MAX_FIELD_OBJECTS}");
    }
    let mut out = Vec::with_capacity(total);
    for (k, f) in fields.iter().enumerate() {
        let key = |what: &str| format!("object_fields[{k}].{what}");
        let [x0, x1, z0, z1] = f.area;
        if !f.area.iter().all(|a| a.is_finite()) || x0 > x1 || z0 > z1 {
            bail!(
                "{}: expected [xmin, xmax, zmin, zmax], finite and increasing, found {:?}",
                key("area"),
                f.area
            );
        }
        super::camera_limits::within_world(&key("area"), &f.area)?;
        for (what, s) in [("size", f.size), ("child_size", f.child_size)] {
            if !s.iter().all(|x| x.is_finite() && *x > 0.0 && *x < 1e4) {
                bail!(
                    "{}: expected two sizes in (0, 10000), found {s:?}",
                    key(what)
                );
            }
        }
        let mut rng = Lcg(f
            .seed
            .wrapping_mul(0x9e37_79b9_7f4a_7c15)
            .wrapping_add(k as u64));
        let (plate, depth) = (f.size[0], f.size[1]);
        // The children's grid: the smallest square that holds them.
        let side = (f.children as f32).sqrt().ceil().max(1.0) as usize;
        for g in 0..f.count {
            let root = format!("{}{g}", f.name);
            out.push(object(
                &root,
                &f.mesh,
                &f.material,
                [rng.range(x0, x1), depth * 0.5, rng.range(z0, z1)],
                [0.0, rng.range(0.0, 360.0), 0.0],
                [plate, depth, plate],
                None,
            ));
            let cell = plate / side as f32;
            for c in 0..f.children {
                let (i, j) = ((c % side) as f32, (c / side) as f32);
                let height = f.child_size[1] * rng.range(0.25, 1.0);
                let width = f.child_size[0].min(cell * 0.9);
                // In the plate's space: its scale divided out.
                let x = -plate * 0.5 + cell * (i + 0.5);
                let z = -plate * 0.5 + cell * (j + 0.5);
                let y = depth * 0.5 + height * 0.5;
                out.push(object(
                    &format!("{root}.{c}"),
                    &f.child_mesh,
                    &f.child_material,
                    [x / plate, y / depth, z / plate],
                    [0.0; 3],
                    [width / plate, height / depth, width / plate],
                    Some(root.clone()),
                ));
            }
        }
    }
    Ok(out)
}

fn object(
    name: &str,
    mesh: &str,
    material: &Option<String>,
    position: [f32; 3],
    rotation: [f32; 3],
    scale: [f32; 3],
    parent: Option<String>,
) -> ObjectFile {
    ObjectFile {
        name: Some(name.to_owned()),
        mesh: mesh.to_owned(),
        material: material.clone(),
        position,
        rotation,
        scale,
        parent,
        mirror: None,
        skinning: None,
        clip: None,
        light_map: None,
    }
}

/// An error about object `objects[N]` that a field made (N at or past
/// `file_objects`, the file's own count) names the field's key instead:
/// `objects[700].mesh: ...` becomes `object_fields[0].child_mesh: ...
/// (in object block3.4, which it makes)`.
pub(super) fn name_field(e: anyhow::Error, file_objects: usize, f: &SceneFile) -> anyhow::Error {
    let msg = e.to_string();
    let Some(rest) = msg.strip_prefix("objects[") else {
        return e;
    };
    let digits: String = rest.chars().take_while(char::is_ascii_digit).collect();
    let Some(n) = digits.parse::<usize>().ok().filter(|&n| n >= file_objects) else {
        return e;
    };
    let rest = &rest[digits.len() + 1..];
    // Which field made object n, and whether as a child.
    let mut left = n - file_objects;
    for (k, field) in f.object_fields.iter().enumerate() {
        let made = field.count.saturating_mul(field.children.saturating_add(1));
        if left >= made {
            left -= made;
            continue;
        }
        let child = !left.is_multiple_of(field.children + 1);
        let name = f.objects[n].name.clone().unwrap_or_default();
        let (attr, tail) = match rest.strip_prefix('.') {
            Some(r) => {
                let word: String = r
                    .chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect();
                let tail = r[word.len()..].to_string();
                let word = match (word.as_str(), child) {
                    ("mesh" | "material", true) => format!(".child_{word}"),
                    _ => format!(".{word}"),
                };
                (word, tail)
            }
            None => (String::new(), rest.to_string()),
        };
        let (head, why) = tail.split_once(": ").unwrap_or((&tail, ""));
        return anyhow::anyhow!(
            "object_fields[{k}]{attr}{head} (in object {name}, which it makes): {why}"
        );
    }
    e
}
