//! The check that this GL has the fixed texture units (src/frame/units.rs)
//! a scene's key asks for. GL 3.3 promises a fragment shader 16 texture
//! units; image-based lighting, the shadow cascades, the LTC tables and the
//! G-buffer's microfacet triple sit past them (`GL_MAX_TEXTURE_IMAGE_UNITS`
//! is 32 on llvmpipe), so a scene that asks for them on a GL with fewer
//! gets an error naming its key before anything is drawn. Binding textures
//! on those units is src/gl/texture_units.rs.

use anyhow::{Result, bail};
use glow::HasContext;
use std::path::Path;

/// What a scene asks of the fixed units past those every GL has: the key
/// as the user writes it, what it reads there, its units, and the setting
/// that does without them.
#[derive(Clone, Copy, Debug)]
pub struct UnitsNeeded<'a> {
    /// `render.ibl`, `[[area_lights]]`.
    pub key: &'a str,
    /// "its maps", "the LTC tables".
    pub reads: &'a str,
    pub units: &'a [u32],
    /// "set render.ibl = false".
    pub instead: &'a str,
}

/// `GL_MAX_TEXTURE_IMAGE_UNITS`: the units a fragment shader can read.
pub fn fragment_units(gl: &glow::Context) -> i32 {
    unsafe { gl.get_parameter_i32(glow::MAX_TEXTURE_IMAGE_UNITS) }
}

/// Whether a GL with `have` fragment texture units has every unit of
/// `need`; if not, an error that names the key, the units and the setting
/// that does without.
pub fn units_fit(have: i32, need: &UnitsNeeded) -> Result<()> {
    let missing = need.units.iter().any(|&u| i64::from(u) >= i64::from(have));
    if !missing {
        return Ok(());
    }
    let units: Vec<String> = need.units.iter().map(u32::to_string).collect();
    let (word, units) = match units.as_slice() {
        [one] => ("unit", one.clone()),
        [first @ .., last] => ("units", format!("{} and {last}", first.join(", "))),
        [] => ("units", String::new()),
    };
    bail!(
        "{} reads {} from texture {word} {units}, but this GL has {have} fragment texture \
         units (0 to {}): {}",
        need.key,
        need.reads,
        have - 1,
        need.instead
    );
}

/// `units_fit` against this GL, the error prefixed with the scene's file.
pub fn check_units(gl: &glow::Context, scene_file: &Path, need: &UnitsNeeded) -> Result<()> {
    units_fit(fragment_units(gl), need)
        .map_err(|e| anyhow::anyhow!("{}: {e}", scene_file.display()))
}
