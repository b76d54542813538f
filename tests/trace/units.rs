//! Texture units never collide (src/frame/units.rs, src/trace/units.rs):
//!
//! * two constants on one unit only where one names the other in `shares`
//!   (and a `shares` names only a constant on the same unit), and the
//!   shadow maps' ranges hold as many units as the scene allows maps;
//! * on every shipped scene's executed frame, on every lighting path, no
//!   draw reads one unit through samplers of two types, and no unit a draw
//!   samples was rebound by another file between its bind and the draw.

use crate::common;
use gloss::frame::units as unit;
use gloss::frame::units::{ALL, Unit};
use gloss::gl::trace::Call;
use gloss::scene::RenderPath;
use gloss::scene::shadows::{MAX_SHADOW_CUBES, MAX_SHADOW_MAPS_2D};
use gloss::trace::units::{Samplers, check, trace_with_samplers, value_of};

fn by_name(name: &str) -> &'static Unit {
    (ALL.iter().find(|u| u.name == name)).unwrap_or_else(|| panic!("no unit constant {name}"))
}

/// Two constants whose units overlap and that do not say they share.
fn undocumented_overlaps(all: &[Unit]) -> Vec<String> {
    let mut out = Vec::new();
    for (i, a) in all.iter().enumerate() {
        for b in &all[i + 1..] {
            let overlap = a.range().any(|u| b.range().contains(&u));
            let said = a.shares.contains(&b.name) || b.shares.contains(&a.name);
            if overlap && !said {
                out.push(format!(
                    "{} (unit {:?}: {}) and {} (unit {:?}: {}) share a unit and neither says so",
                    a.name,
                    a.range(),
                    a.holds.trim(),
                    b.name,
                    b.range(),
                    b.holds.trim()
                ));
            }
        }
    }
    out
}

#[test]
fn no_two_unit_constants_meet_unless_documented_as_sharing() {
    let bad = undocumented_overlaps(ALL);
    assert!(bad.is_empty(), "{}", bad.join("\n"));
    // A `shares` names a constant that exists and is on the same unit.
    for a in ALL {
        for s in a.shares {
            let b = by_name(s);
            assert!(
                a.range().any(|u| b.range().contains(&u)),
                "{} says it shares with {s}, but {:?} and {:?} do not meet",
                a.name,
                a.range(),
                b.range()
            );
        }
    }
    assert_eq!(by_name("SHADOW_MAPS_2D").count as usize, MAX_SHADOW_MAPS_2D);
    assert_eq!(by_name("SHADOW_CUBES").count as usize, MAX_SHADOW_CUBES);
    // The check itself finds a meeting nobody declared.
    let mut moved: Vec<Unit> = ALL.to_vec();
    let ibl = moved
        .iter_mut()
        .find(|u| u.name == "IBL_IRRADIANCE")
        .unwrap();
    ibl.first = by_name("SHADOW_CASCADES").first;
    let bad = undocumented_overlaps(&moved);
    assert_eq!(bad.len(), 1, "{bad:?}");
    assert!(bad[0].contains("IBL_IRRADIANCE") && bad[0].contains("SHADOW_CASCADES"));
}

const PATHS: [RenderPath; 5] = [
    RenderPath::Forward,
    RenderPath::Deferred,
    RenderPath::Volumes,
    RenderPath::Prepass,
    RenderPath::Tiled,
];

#[test]
fn no_draw_of_any_shipped_scene_mixes_or_clobbers_a_unit() {
    let ctx = crate::tracing_context();
    let mut names: Vec<String> = std::fs::read_dir(common::root().join("scenes"))
        .unwrap()
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".toml"))
        .collect();
    names.sort();
    assert!(names.len() > 60, "{names:?}");
    let mut found = Vec::new();
    let mut draws = 0;
    let mut frames = 0;
    for name in &names {
        let base = common::scene(name);
        let mut plans = Vec::new();
        for path in PATHS {
            let mut s = base.clone();
            s.render.path = path;
            s.render.size = (48, 27);
            // A path the scene's frame does not depend on draws the same frame.
            let plan = gloss::techniques::plan(&s).to_string();
            if plans.contains(&plan) {
                continue;
            }
            plans.push(plan);
            frames += 1;
            let (calls, programs) = trace_with_samplers(&ctx, &s)
                .unwrap_or_else(|e| panic!("{name} on {path:?}: {e:#}"));
            draws += calls
                .iter()
                .filter(|c| c.function.starts_with("glDraw"))
                .count();
            for f in check(&calls, &programs) {
                found.push(format!("{name} on {path:?}: {f}"));
            }
        }
    }
    assert!(
        frames > 100 && draws > 1000,
        "only {frames} frames and {draws} draws were checked"
    );
    found.dedup();
    assert!(found.is_empty(), "{}", found.join("\n"));
}

/// `scene`'s frame on `path` as it would be with `sampler`'s unit `from`
/// moved to `to` in the calls `file` makes: its glActiveTexture and the
/// sampler's glUniform1i (and its value at the frame's end).
fn moved(
    scene: &str,
    path: RenderPath,
    file: &str,
    sampler: &str,
    (from, to): (u32, u32),
) -> (Vec<Call>, Samplers) {
    let ctx = crate::tracing_context();
    let mut s = common::scene(scene);
    s.render.path = path;
    s.render.size = (48, 27);
    let (mut calls, mut programs) = trace_with_samplers(&ctx, &s).unwrap();
    let mut changed = 0;
    for c in calls.iter_mut().filter(|c| c.site.file == file) {
        let arg = c.args.first().cloned().unwrap_or_default();
        if c.function == "glActiveTexture" && value_of(&arg) == Some(glow::TEXTURE0 + from) {
            c.args[0] = format!("{:#x}", glow::TEXTURE0 + to);
            changed += 1;
        }
        if c.function == "glUniform1i" && arg == sampler {
            c.args[1] = to.to_string();
            changed += 1;
        }
    }
    for p in programs
        .values_mut()
        .flatten()
        .filter(|p| p.name == sampler)
    {
        p.unit_at_end = to as i32;
    }
    assert!(changed >= 2, "{scene}: {file} made no call to move");
    (calls, programs)
}

#[test]
fn the_frame_check_names_both_sides_of_a_moved_unit() {
    // Sound as they are.
    for (scene, path) in [
        ("parallax.toml", RenderPath::Forward),
        ("ibl.toml", RenderPath::Forward),
    ] {
        let ctx = crate::tracing_context();
        let mut s = common::scene(scene);
        s.render.path = path;
        s.render.size = (48, 27);
        let (calls, programs) = trace_with_samplers(&ctx, &s).unwrap();
        assert_eq!(check(&calls, &programs), Vec::<String>::new(), "{scene}");
    }
    // HEIGHT_MAP onto NORMAL_MAP: the parallax pass's height map is
    // replaced by the material's normal map before the draw reads it.
    let (calls, programs) = moved(
        "parallax.toml",
        RenderPath::Forward,
        "src/techniques/lighting/parallax_mapping.rs",
        "u_height_map",
        (unit::HEIGHT_MAP, unit::NORMAL_MAP),
    );
    let found = check(&calls, &programs);
    assert!(
        found.iter().any(|f| f.contains("parallax_mapping.rs")
            && f.contains("draw_textures.rs")
            && f.contains("u_height_map")),
        "{found:#?}"
    );
    // IBL_IRRADIANCE onto DIFFUSE_TEXTURE: a cube and a 2D sampler on one unit.
    let (calls, programs) = moved(
        "ibl.toml",
        RenderPath::Forward,
        "src/frame/image_based_lighting.rs",
        "u_ibl_irradiance",
        (unit::IBL_IRRADIANCE, unit::DIFFUSE_TEXTURE),
    );
    let found = check(&calls, &programs);
    assert!(
        found.iter().any(|f| f.contains("u_ibl_irradiance")
            && f.contains("image_based_lighting.rs")
            && f.contains("u_diffuse_texture")
            && f.contains("GL_SAMPLER_CUBE")),
        "{found:#?}"
    );
}
