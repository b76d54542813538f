//! The pixel probe in words: what `gloss probe` prints and the demo's
//! panel shows (src/renderer/probe.rs reads the values).

use super::probe::Probe;
use crate::frame::targets::format_name;
use glam::Vec3;

impl std::fmt::Display for Probe {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        let v3 = |v: Vec3| format!("({:.4}, {:.4}, {:.4})", v.x, v.y, v.z);
        let (w, h) = self.size;
        writeln!(
            f,
            "pixel ({}, {}) of the {w}x{h} frame (from the top left)",
            self.x, self.y
        )?;
        for t in &self.targets {
            let v = &t.value[..t.channels];
            let v: Vec<String> = v.iter().map(|c| format!("{c:.4}")).collect();
            writeln!(
                f,
                "  {} ({}): {}",
                t.name,
                format_name(t.format),
                v.join(", ")
            )?;
        }
        match self.depth {
            Some(d) if d < 1.0 => writeln!(f, "  depth: {d:.6}")?,
            Some(_) => writeln!(f, "  depth: 1.0 (nothing drawn here)")?,
            None => writeln!(f, "  depth: none (this frame has no depth buffer)")?,
        }
        if let (Some(v), Some(p)) = (self.view_position, self.world_position) {
            writeln!(f, "  view-space position: {}", v3(v))?;
            writeln!(f, "  world position: {}", v3(p))?;
        }
        if let Some((n, source)) = self.normal {
            writeln!(f, "  normal: {} ({source})", v3(n))?;
        }
        for (target, s) in &self.stencil {
            writeln!(f, "  {target}.stencil: {s}")?;
        }
        for s in &self.shadows {
            writeln!(f, "  {s}")?;
        }
        if let Some(t) = &self.tile {
            writeln!(f, "  {t}")?;
        }
        if let Some(r) = &self.reached {
            let list: Vec<String> = r.iter().map(|l| l.to_string()).collect();
            match list.is_empty() {
                true => writeln!(f, "  lights reaching it: none")?,
                false => writeln!(f, "  lights reaching it: {}", list.join(", "))?,
            }
        }
        for (target, why) in &self.not_read {
            writeln!(f, "  not read: {target} ({why})")?;
        }
        Ok(())
    }
}
