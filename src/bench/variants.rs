//! `gloss bench SCENE --vary KEY=V1,V2,... [--vary ...] [--reference KEY=V]`:
//! speed against error for any setting a scene file has, not only the
//! render paths. Each `--vary` names a scene key and the values to try; the
//! settings are every combination, each applied as `--set` would apply it
//! (same parser, same checks). The reference is the scene with the
//! `--reference` keys set (by default, the scene as written).
//!
//! A `--vary` value with ';' in it is one setting of its own, `KEY=V;KEY=V`,
//! measured after the combinations (settings that are no product of lists).
//!
//! For example, the mirror's orders and recursion depths against the
//! deepest reflection:
//!
//! ```text
//! gloss bench scenes/mirrors-recursive.toml --vary render.mirror_order=normal_first \
//!     --vary render.mirror_depth=1,2,3,4 --reference render.mirror_depth=8
//! ```

use super::{BenchArgs, BenchRow, Headless, finish, measure};
use crate::renderer::render_scene;
use crate::scene::Scene;
use anyhow::{Result, anyhow, bail};
use std::path::Path;

/// Every combination of the `--vary` values, as lists of `KEY=VALUE`.
pub fn combinations(vary: &[String]) -> Result<Vec<Vec<String>>> {
    let mut out: Vec<Vec<String>> = vec![vec![]];
    for v in vary {
        let (key, values) = v
            .split_once('=')
            .ok_or_else(|| anyhow!("--vary {v}: expected KEY=V1,V2,..."))?;
        let values: Vec<&str> = values.split(',').map(str::trim).collect();
        if key.trim().is_empty() || values.iter().any(|x| x.is_empty()) {
            bail!("--vary {v}: expected KEY=V1,V2,...");
        }
        out = out
            .into_iter()
            .flat_map(|prefix| {
                values.iter().map(move |x| {
                    let mut c = prefix.clone();
                    c.push(format!("{}={x}", key.trim()));
                    c
                })
            })
            .collect();
    }
    Ok(out)
}

pub(super) fn run(
    args: &BenchArgs,
    scene_path: &Path,
    ctx: &Headless,
    software: bool,
) -> Result<()> {
    // A `--vary` with ';' is one setting (its keys), after the combinations.
    let (cases, vary): (Vec<&String>, Vec<&String>) =
        args.vary.iter().partition(|v| v.contains(';'));
    let vary: Vec<String> = vary.into_iter().cloned().collect();
    let mut combos = combinations(&vary)?;
    for c in cases {
        let keys: Vec<String> = c.split(';').map(|k| k.trim().to_string()).collect();
        if keys.iter().any(|k| !k.contains('=')) {
            bail!("--vary {c}: expected KEY=VALUE;KEY=VALUE... for one setting");
        }
        combos.push(keys);
    }
    let sized = |mut s: Scene| {
        if let Some(size) = args.size {
            s.render.size = size;
        }
        s
    };
    // `--set` first, then the setting's own keys (a later key wins).
    let with_set = |keys: &[String]| [&args.set[..], keys].concat();
    let reference_scene = sized(Scene::load_with(scene_path, &with_set(&args.reference))?);
    // Every setting is checked before anything is measured.
    let scenes: Vec<(String, Scene)> = combos
        .iter()
        .map(|c| {
            Ok((
                c.join(" "),
                sized(Scene::load_with(scene_path, &with_set(c))?),
            ))
        })
        .collect::<Result<_>>()?;
    let (w, h) = reference_scene.render.size;
    eprintln!(
        "gloss bench: {} at {w}x{h} on {}, {} settings against {}, {} warm-up + {} measured frames each",
        scene_path.display(),
        ctx.info.renderer,
        scenes.len(),
        if args.reference.is_empty() {
            "the scene as written".to_string()
        } else {
            args.reference.join(" ")
        },
        args.warmup,
        args.frames
    );
    let reference =
        render_scene(ctx, &reference_scene, crate::renderer::Output::Srgb8)?.read_image();
    let mut rows = Vec::new();
    let (mut blooms, mut cache) = (Vec::new(), super::bloom::ReferenceCache::default());
    for (i, (label, scene)) in scenes.iter().enumerate() {
        let row = BenchRow {
            setting: label.clone(),
            path: scene.render.path.name().to_string(),
            lights: scene.lights.len(),
            cutoff: None,
            ..BenchRow::default()
        };
        let progress = format!("[{}/{}] {label}", i + 1, scenes.len());
        let mut row = measure(ctx, software, args, scene, Some(&reference), row, &progress)?;
        // A scene whose lights cast: its shadows against the exact ones.
        if scene.lights.iter().any(|l| l.shadow.is_some()) {
            row.shadow = Some(super::shadows::evaluate(ctx, scene)?.errors);
        }
        // A chain with a bloom: the bloom against its CPU reference.
        if let Some(e) = super::bloom::bench_error(ctx, scene, &mut cache)? {
            blooms.push((label.clone(), super::bloom::bloom_ms(&row.passes), e));
        }
        rows.push(row);
    }
    eprintln!();
    if !blooms.is_empty() {
        println!("{}", super::bloom::table(&blooms));
    }
    finish(&rows, args)?;
    let floor_ms = super::post::full_screen_ms(ctx, args, &reference_scene)?;
    println!(
        "{}",
        super::floor::table(&rows, floor_ms, reference_scene.render.size)
    );
    if !reference_scene.post.is_empty() {
        println!("{}", super::post::floor_table(ctx, args, &reference_scene)?);
    }
    // What frustum culling (notes 01 §6.3) kept from the camera's passes.
    for (label, scene) in &scenes {
        let c = crate::frame::culling::scene_stats(scene)?;
        if scene.render.frustum_culling && c.culled > 0 {
            println!(
                "{label}: frustum culling drew {} of {} opaque objects, culled {}, in {} sphere and box tests",
                c.drawn, c.objects, c.culled, c.tests
            );
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::combinations;

    #[test]
    fn every_combination_in_order() {
        let c = combinations(&["a=1,2".into(), "b=x,y,z".into()]).unwrap();
        assert_eq!(c.len(), 6);
        assert_eq!(c[0], ["a=1", "b=x"]);
        assert_eq!(c[5], ["a=2", "b=z"]);
        assert!(combinations(&["a".into()]).is_err());
        assert!(combinations(&["a=1,,2".into()]).is_err());
    }
}
