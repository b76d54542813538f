//! OSMesa headless backend (being written).
use anyhow::{Result, bail};
pub fn create() -> Result<(glow::Context, Box<dyn std::any::Any>)> {
    bail!("the OSMesa backend is not built yet")
}
