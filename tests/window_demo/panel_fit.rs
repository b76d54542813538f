//! No widget of the panel is clipped at its right edge: a row of choices
//! wider than the panel (the transparency knob's depth_peeling, the depth
//! test's always) wraps inside it rather than running past the edge, where
//! a student cannot click it (src/demo/panel/knob.rs). Checked on the
//! panel's layout (`GLOSS_DEMO_LAYOUT`, src/demo/layout.rs) over technique
//! scenes that together show every knob of the registry and every kind of
//! post-chain entry, at the window's
//! default size; then the depth-peeling and steep-parallax choices are
//! clicked by name and the view compared with `gloss render --set` of the
//! same setting.

use crate::{crate_dir, differing, drive, headless_render, shot};
use gloss::scene::Scene;
use gloss::scene::knobs::{self, Knob};

/// A line of a layout file: a widget's label, kind and rectangle.
struct Widget {
    label: String,
    kind: String,
    rect: [i64; 4],
}

/// The JSON string after `"key":` in `line` (the layout's own escapes undone).
fn string_field(line: &str, key: &str) -> Option<String> {
    let start = line.find(&format!("\"{key}\":\""))? + key.len() + 4;
    let mut out = String::new();
    let mut chars = line[start..].chars();
    while let Some(c) = chars.next() {
        match c {
            '"' => return Some(out),
            '\\' => match chars.next()? {
                'n' => out.push('\n'),
                'u' => {
                    let hex: String = chars.by_ref().take(4).collect();
                    out.push(char::from_u32(u32::from_str_radix(&hex, 16).ok()?)?);
                }
                c => out.push(c),
            },
            c => out.push(c),
        }
    }
    None
}

/// The widgets of a layout file (its first line is the pass and window).
fn widgets(layout: &str) -> Vec<Widget> {
    layout
        .lines()
        .skip(1)
        .map(|l| {
            let rect = l
                .split("\"rect\":[")
                .nth(1)
                .and_then(|r| r.split(']').next());
            let v: Vec<i64> = (rect.unwrap_or_default().split(','))
                .filter_map(|n| n.parse().ok())
                .collect();
            Widget {
                label: string_field(l, "label").unwrap_or_default(),
                kind: string_field(l, "kind").unwrap_or_default(),
                rect: v
                    .try_into()
                    .unwrap_or_else(|_| panic!("no rectangle in {l}")),
            }
        })
        .collect()
}

/// The knobs the panel's Techniques section shows for `scene`: the path,
/// the knobs of every technique in its frame plan, and the switches of
/// techniques switched off (src/demo/panel/mod.rs, `technique_section`).
fn panel_knobs(scene: &Scene) -> Vec<&'static Knob> {
    let plan = gloss::techniques::plan(scene);
    let mut shown = vec![&knobs::PATH];
    for (i, t) in gloss::techniques::ALL.iter().enumerate() {
        if plan.passes.iter().any(|p| p.technique == i) {
            shown.extend(t.knobs.iter().copied());
        }
    }
    for (k, applies) in knobs::SWITCHES {
        if applies(scene) {
            shown.push(k);
        }
    }
    shown
}

/// Technique scenes (the registry's, in its order) that together show
/// every knob any of them shows and every kind of post-chain entry (each
/// kind has its own widgets, src/demo/panel/post_params.rs): each scene
/// kept when it shows one the ones before it did not. With the knobs each
/// one adds.
fn scenes_showing_every_knob() -> Vec<(&'static str, Vec<&'static Knob>)> {
    let mut seen: Vec<&str> = Vec::new();
    let mut posts = Vec::new();
    let mut out = Vec::new();
    for t in gloss::techniques::ALL {
        let scene = Scene::load(&crate_dir().join(t.scene))
            .unwrap_or_else(|e| panic!("{}: {}: {e:#}", t.name, t.scene));
        let new: Vec<&Knob> = (panel_knobs(&scene).into_iter())
            .filter(|k| !seen.contains(&k.key))
            .collect();
        let kinds: Vec<_> = scene.post.iter().map(std::mem::discriminant).collect();
        let new_post = kinds.iter().any(|k| !posts.contains(k));
        if (!new.is_empty() || new_post) && !out.iter().any(|(s, _)| *s == t.scene) {
            seen.extend(new.iter().map(|k| k.key));
            posts.extend(kinds);
            out.push((t.scene, new));
        }
    }
    out
}

/// The widgets of `layout` that run past the panel's scrolling part
/// sideways (where the panel clips them), in words, and the content when it
/// is wider than that part (an unnamed widget past the edge). The
/// thumbnail strip scrolls sideways on its own: its pictures may; the strip
/// may not.
fn clipped(layout: &str) -> Vec<String> {
    let all = widgets(layout);
    let area = |name: &str| {
        all.iter()
            .find(|w| w.label == name && w.kind == "scroll area")
            .map(|w| w.rect)
    };
    let scroll = area("panel scroll").expect("the layout has the panel's scrolling part");
    let strip = area("thumbnail strip");
    let mut out: Vec<String> = (all.iter())
        .filter(|w| !["panel", "view", "Splitter", "content"].contains(&w.kind.as_str()))
        .filter(|w| w.label != "panel scroll")
        .filter(|w| {
            !strip
                .is_some_and(|s| w.kind != "scroll area" && w.rect[1] >= s[1] && w.rect[3] <= s[3])
        })
        .filter(|w| w.rect[0] < scroll[0] || w.rect[2] > scroll[2])
        .map(|w| {
            format!(
                "{} ({}) at x {}..{}, the panel shows {}..{}",
                w.label, w.kind, w.rect[0], w.rect[2], scroll[0], scroll[2]
            )
        })
        .collect();
    // Unnamed widgets too: all that the scrolling part holds fits its width.
    match all.iter().find(|w| w.kind == "content") {
        Some(c) if c.rect[2] > scroll[2] => out.push(format!(
            "the panel's content reaches x {}, past its scrolling part's {}",
            c.rect[2], scroll[2]
        )),
        Some(_) => {}
        None => out.push("the layout has no \"panel content\" line".to_string()),
    }
    out
}

#[test]
fn every_widget_of_the_panel_lies_inside_it_in_scenes_that_show_every_knob_and_post_entry() {
    let scenes = scenes_showing_every_knob();
    // Several windows, each in its own Xvfb run, so that each run stays
    // well inside its time limit on a loaded machine.
    let mut failures = Vec::new();
    for (n, chunk) in scenes.chunks(6).enumerate() {
        let mut script = String::new();
        for (i, (scene, _)) in chunk.iter().enumerate() {
            let path = crate_dir().join(scene);
            // The window at its default size (the scene's beside the
            // panel, fitted to the screen); the layout a few passes in,
            // once the timings and thumbnails are there.
            script.push_str(&format!(
                "start '{}'\np=$(layout_pass); next_pass $((p + 2))\n\
                 cp layout.jsonl layout-{i}.jsonl\ncat gloss.log >> all.log\nquit\n",
                path.display()
            ));
        }
        let Some((dir, _)) = drive(
            &format!("gloss-window-panel-fit-{n}"),
            "1280x1024x24",
            &script,
        ) else {
            return;
        };
        let logs = std::fs::read_to_string(dir.join("all.log")).unwrap_or_default();
        assert!(
            !logs.to_lowercase().contains("error") && !logs.contains("panicked"),
            "the demo reported an error:\n{logs}"
        );
        for (i, (scene, knobs)) in chunk.iter().enumerate() {
            let layout = std::fs::read_to_string(dir.join(format!("layout-{i}.jsonl"))).unwrap();
            // The knobs this scene stands for are in its panel.
            let labels: Vec<String> = widgets(&layout).into_iter().map(|w| w.label).collect();
            for k in knobs {
                assert!(
                    labels.iter().any(|l| l == k.label),
                    "{scene}: the panel does not show the knob {} ({})",
                    k.label,
                    k.key
                );
            }
            let bad = clipped(&layout);
            if !bad.is_empty() {
                failures.push(format!("{scene}:\n    {}", bad.join("\n    ")));
            }
        }
    }
    eprintln!(
        "{} scenes: {:?}",
        scenes.len(),
        scenes.iter().map(|s| s.0).collect::<Vec<_>>()
    );
    assert!(
        failures.is_empty(),
        "widgets run past the panel's right edge, where it clips them:\n{}",
        failures.join("\n")
    );
}

/// The demo's view after clicking the choice `word` of the knob `about` on
/// `scene` at the window's default size (screenshots 1 before, 2 after),
/// and `gloss render --set KEY=WORD` of the same scene at the view's size.
fn click_and_render(
    name: &str,
    scene: &str,
    word: &str,
    about: &str,
    key: &str,
) -> Option<[image::RgbaImage; 3]> {
    let script = format!(
        r#"
        start {scene}
        sleep 2
        key F12; shot 1
        widget "{word}" "{about}" > unscrolled
        scroll_to "{word}" "{about}" > rect
        click_widget "{word}" "{about}"
        toggled "{word}" "{about}" > toggled
        sleep 2
        key F12; shot 2
        quit
    "#
    );
    let (dir, log) = drive(name, "1280x1024x24", &script)?;
    let read = |f: &str| std::fs::read_to_string(dir.join(f)).unwrap_or_default();
    assert_eq!(read("toggled").trim(), "true", "{word} is not selected");
    // Brought into view, the choice lies inside the panel's scrolling part,
    // where it was before: the wheel scrolled the panel down, not sideways.
    let layout = read("layout.jsonl");
    let scroll = crate::layout_rect(&layout, "panel scroll").unwrap();
    let rect = |f: &str| -> Vec<i64> {
        let v = read(f);
        v.split_whitespace().map(|v| v.parse().unwrap()).collect()
    };
    let (r, r0) = (rect("rect"), rect("unscrolled"));
    assert!(
        r[0] >= scroll[0] && r[2] <= scroll[2] && (r[0], r[2]) == (r0[0], r0[2]),
        "{word} at x {}..{} (before scrolling {}..{}): the panel shows {}..{}",
        r[0],
        r[2],
        r0[0],
        r0[2],
        scroll[0],
        scroll[2]
    );
    let (before, after) = (shot(&dir, &log, 1), shot(&dir, &log, 2));
    let (w, h) = after.dimensions();
    let set = format!("{key}={word}");
    let reference = headless_render(&dir, scene, &["--set", &set], (w, h));
    Some([before, after, reference])
}

#[test]
fn the_depth_peeling_choice_clicked_gives_the_depth_peeled_image() {
    let Some([weighted, peeled, reference]) = click_and_render(
        "gloss-window-peel",
        "oit",
        "depth_peeling",
        "transparency",
        "render.transparency",
    ) else {
        return;
    };
    let (changed, off) = (
        differing(&weighted, &peeled, 3),
        differing(&peeled, &reference, 3),
    );
    eprintln!(
        "weighted blended -> depth peeling changes {changed:.4}; against the render {off:.5}"
    );
    // Peeling orders the layers exactly; weighted blended approximates
    // their order: the glass changes where panes overlap.
    assert!(
        changed > 0.005,
        "depth peeling looks like weighted blended: {changed:.4}"
    );
    assert!(
        off < 0.002,
        "{off:.4} of the view differs from `gloss render --set render.transparency=depth_peeling`"
    );
}

#[test]
fn the_steep_parallax_choice_clicked_gives_the_steep_parallax_image() {
    let Some([occlusion, steep, reference]) = click_and_render(
        "gloss-window-steep",
        "parallax",
        "steep",
        "parallax",
        "render.parallax",
    ) else {
        return;
    };
    let (changed, off) = (
        differing(&occlusion, &steep, 3),
        differing(&steep, &reference, 3),
    );
    eprintln!("occlusion -> steep changes {changed:.4}; against the render {off:.5}");
    // Steep parallax stops at the first layer under the height field;
    // occlusion interpolates between the last two: the relief's edges
    // step.
    assert!(changed > 0.001, "steep looks like occlusion: {changed:.4}");
    assert!(
        off < 0.002,
        "{off:.4} of the view differs from `gloss render --set render.parallax=steep`"
    );
}
