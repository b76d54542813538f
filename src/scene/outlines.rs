//! `[outlines]`: objects drawn with an outline around them (LearnOpenGL,
//! 4.advanced_opengl "Stencil testing"; src/techniques/stencil/object_outlines.rs):
//!
//! ```toml
//! [outlines]
//! objects = ["ball", "box"]     # by name, as [[objects]] names them
//! color = [1.0, 0.55, 0.05]     # linear RGB, each 0..=1
//! ```
//!
//! The outline's width in pixels and whether outlines are drawn at all are
//! render settings (`render.outline_width`, `render.outlines`): the demo's
//! panel switches them.

use super::Object;
use anyhow::{Result, bail};
use glam::Vec3;
use serde::Deserialize;

#[derive(Deserialize, Debug, Clone, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct OutlinesFile {
    pub objects: Vec<String>,
    #[serde(default = "orange")]
    pub color: [f32; 3],
}

fn orange() -> [f32; 3] {
    [1.0, 0.55, 0.05]
}

/// The outlined objects (indices into `Scene::objects`, in the order the
/// file names them) and the outline's colour.
#[derive(Debug, Clone, PartialEq)]
pub struct Outlines {
    pub objects: Vec<usize>,
    pub color: Vec3,
}

/// The widths `render.outline_width` takes, in pixels.
pub const OUTLINE_WIDTHS: std::ops::RangeInclusive<u32> = 1..=64;

pub(super) fn resolve(file: Option<&OutlinesFile>, objects: &[Object]) -> Result<Option<Outlines>> {
    let Some(f) = file else {
        return Ok(None);
    };
    if f.objects.is_empty() {
        bail!("outlines.objects: expected the names of one or more objects, found an empty list");
    }
    let mut list = Vec::with_capacity(f.objects.len());
    for (k, name) in f.objects.iter().enumerate() {
        let Some(i) = objects.iter().position(|o| &o.name == name) else {
            bail!("outlines.objects[{k}]: no object named \"{name}\"");
        };
        if objects[i].mirror.is_some() {
            bail!(
                "outlines.objects[{k}]: \"{name}\" is a mirror; the mirror's stencil regions and an outline cannot share its surface"
            );
        }
        if list.contains(&i) {
            bail!("outlines.objects[{k}]: \"{name}\" is listed twice");
        }
        list.push(i);
    }
    if f.color
        .iter()
        .any(|c| !c.is_finite() || !(0.0..=1.0).contains(c))
    {
        bail!(
            "outlines.color: expected linear RGB with each channel in 0..=1, found {:?}",
            f.color
        );
    }
    Ok(Some(Outlines {
        objects: list,
        color: Vec3::from(f.color),
    }))
}
