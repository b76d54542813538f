//! "Save as": the scene file as loaded, with the panel's edits written into
//! it (every render knob, the light grid's count), so that the saved file
//! loads to the same scene. Paths to meshes and textures are rewritten to
//! stay valid from the new file's folder: absolute for files on disk,
//! `embedded:scenes/...` for a shipped scene's assets.

use super::{Scene, knobs, read_text};
use crate::assets;
use anyhow::{Context as _, Result, anyhow};
use std::path::Path;

impl Scene {
    /// The TOML text of this scene, as `save_as` writes it.
    pub fn to_toml(&self) -> Result<String> {
        let text = read_text(&self.path)?;
        let mut table: toml::Table = toml::from_str(&text)
            .map_err(|e| anyhow!("{}: {}", self.path.display(), e.to_string().trim_end()))?;
        let render = table
            .entry("render")
            .or_insert_with(|| toml::Value::Table(toml::Table::new()))
            .as_table_mut()
            .ok_or_else(|| anyhow!("{}: render is not a table", self.path.display()))?;
        for k in knobs::ALL {
            let (_, key) = k.key.split_once('.').expect("render.key");
            let v: toml::Table = toml::from_str(&format!("v = {}", k.toml(&self.render)))
                .expect("a knob writes valid TOML");
            render.insert(key.to_string(), v["v"].clone());
        }
        if let (Some(n), Some(grid)) = (
            self.grid_lights,
            table
                .get_mut("light_grid")
                .and_then(toml::Value::as_table_mut),
        ) {
            grid.insert("count".into(), toml::Value::Integer(n as i64));
        }
        let base = self.path.parent().unwrap_or(Path::new(""));
        let fix = |v: &mut toml::Value| {
            if let Some(s) = v.as_str()
                && !s.starts_with(assets::EMBEDDED)
            {
                let p = base.join(s);
                let p = match p.canonicalize() {
                    Ok(abs) => abs,
                    Err(_) => p,
                };
                *v = toml::Value::String(p.to_string_lossy().into_owned());
            }
        };
        if let Some(materials) = table
            .get_mut("materials")
            .and_then(toml::Value::as_table_mut)
        {
            for (_, m) in materials.iter_mut() {
                if let Some(t) = m.get_mut("diffuse_texture") {
                    fix(t);
                }
            }
        }
        if let Some(objects) = table.get_mut("objects").and_then(toml::Value::as_array_mut) {
            for o in objects {
                if let Some(m) = o
                    .get_mut("mesh")
                    .filter(|m| m.as_str().is_some_and(|s| s.ends_with(".obj")))
                {
                    fix(m);
                }
            }
        }
        toml::to_string(&table).context("writing the scene as TOML")
    }

    /// Write `to_toml` to `dest`, through a temporary file so that a failed
    /// write leaves an existing file as it was.
    pub fn save_as(&self, dest: &Path) -> Result<()> {
        let text = self.to_toml()?;
        let tmp = dest.with_extension("toml.tmp");
        std::fs::write(&tmp, text)
            .and_then(|()| std::fs::rename(&tmp, dest))
            .map_err(|e| {
                let _ = std::fs::remove_file(&tmp);
                anyhow!("cannot write {}: {e}", dest.display())
            })
    }
}
