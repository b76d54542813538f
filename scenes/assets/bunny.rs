//! `bunny.obj` from the vendored npm package `bunny` (`bunny/index.js`:
//! `exports.positions=[[x,y,z],...]` and `exports.cells=[[a,b,c],...]` on
//! lines of their own, the
//! Stanford bunny; `bunny/LICENSE.md`): the same vertices and triangles
//! (counter-clockwise seen from outside), standing on y = 0, centred on the
//! y axis, 1 unit tall, with smooth normals.

use anyhow::{Context, Result, bail};
use gloss::geometry::{self, MeshData, Vertex};

/// The numbers of the array after `name=` in `js`, up to the end of its line.
fn numbers(js: &str, name: &str) -> Result<Vec<f64>> {
    let start = js
        .find(&format!("{name}="))
        .with_context(|| format!("bunny/index.js has no {name}"))?;
    let rest = &js[start + name.len() + 1..];
    let end = rest.find([';', '\n']).unwrap_or(rest.len());
    rest[..end]
        .split(['[', ']', ','])
        .filter(|s| !s.trim().is_empty())
        .map(|s| {
            s.trim()
                .parse::<f64>()
                .with_context(|| format!("bad number {s:?} in {name}"))
        })
        .collect()
}

pub fn bunny(js: &str) -> Result<MeshData> {
    let p = numbers(js, "positions")?;
    let c = numbers(js, "cells")?;
    if p.len() % 3 != 0 || c.len() % 3 != 0 {
        bail!("bunny/index.js: partial positions or cells");
    }
    let n = p.len() / 3;
    let at = |i: usize, k: usize| p[3 * i + k];
    let (mut lo, mut hi) = ([f64::MAX; 3], [f64::MIN; 3]);
    for i in 0..n {
        for k in 0..3 {
            lo[k] = lo[k].min(at(i, k));
            hi[k] = hi[k].max(at(i, k));
        }
    }
    let scale = 1.0 / (hi[1] - lo[1]);
    let centre = [(lo[0] + hi[0]) / 2.0, lo[1], (lo[2] + hi[2]) / 2.0];
    let mut m = MeshData {
        vertices: (0..n)
            .map(|i| Vertex {
                position: [0, 1, 2].map(|k| ((at(i, k) - centre[k]) * scale) as f32),
                ..Default::default()
            })
            .collect(),
        indices: c.iter().map(|&i| i as u32).collect(),
        ..Default::default()
    };
    if m.indices.iter().any(|&i| i as usize >= n) {
        bail!("bunny/index.js: a cell names a vertex past {n}");
    }
    geometry::compute_normals(&mut m);
    Ok(m)
}
