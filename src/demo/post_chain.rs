//! The demo's side of the post chain (notes 01 §9 "Post processing";
//! docs/post.md): the panel's edits of the `[[post]]` list, checked by the
//! scene loader's own rules before they run, and the chain's images named
//! in the inspector by the step that wrote them.
//!
//! An edited chain is written out as the scene file would have it
//! (`PostPass::table`, the tables "save as" writes) and read back with
//! `scene::post::chain`, so the panel can make no chain that a file could
//! not: gamma last, at most `MAX_POST_PASSES` entries, every value in its
//! range. A refused chain leaves the scene, and the renderer, as they were.

use super::inspector::View;
use crate::frame::Runs;
use crate::frame::plan::FramePlan;
use crate::frame::post::{self, HDR, Image};
use crate::scene::Scene;
use crate::scene::post::{PASS_NAMES, PostPass, chain};
use crate::techniques;
use crate::techniques::post::bloom_levels;
use anyhow::{Result, anyhow};

/// How a refused chain's message begins (the panel shows it in its "Post
/// chain" section too).
pub const REFUSED: &str = "post chain refused, the old one keeps running";

/// `scene` with the edited chain `edited`, checked as the scene loader
/// checks a file's `[[post]]` list; an error names the entry and the key
/// and says that the old chain keeps running.
pub fn checked(scene: &Scene, edited: &[PostPass]) -> Result<Scene> {
    let tables: Vec<toml::Table> = edited.iter().map(PostPass::table).collect();
    let post = chain(&tables).map_err(|e| anyhow!("{REFUSED}: {e:#}"))?;
    let mut scene = scene.clone();
    scene.post = post;
    Ok(scene)
}

/// A new entry of pass `name` (one of `PASS_NAMES`), with the parameters a
/// file must give set to a value to start from: a Reinhard tone map, a
/// blur of sigma 2, a box of radius 2, the sharpen kernel.
pub fn new_pass(name: &str, index: usize) -> Result<PostPass> {
    let mut t = toml::Table::new();
    t.insert("pass".into(), name.into());
    match name {
        "tonemap" => t.insert("operator".into(), "reinhard".into()),
        "blur" => t.insert("sigma".into(), 2.0.into()),
        "box" => t.insert("radius".into(), 2.into()),
        "kernel" => t.insert("kernel".into(), "sharpen".into()),
        _ => None,
    };
    PostPass::parse(&t, index)
}

/// `chain` with a new entry of pass `name` before its final gamma (at the
/// end when it has none).
pub fn with_added(chain: &[PostPass], name: &str) -> Result<Vec<PostPass>> {
    debug_assert!(PASS_NAMES.contains(&name));
    let at = match chain.last() {
        Some(PostPass::Gamma { .. }) => chain.len() - 1,
        _ => chain.len(),
    };
    let mut v = chain.to_vec();
    v.insert(at, new_pass(name, at)?);
    Ok(v)
}

/// What each image of `scene`'s chain holds at the end of the frame, as the
/// inspector names it: `hdr` "the world, read by step 1"; an inner image
/// "after step 3 of 4, blur 2/2", the last step that drew into it (a
/// ping-pong texture is drawn into by every other step; the inspector shows
/// what the last one left). Steps are counted from 1, as the panel lists them.
pub fn name_steps(views: &mut [View], scene: &Scene, plan: &FramePlan) {
    let steps = post::step_count(scene);
    if steps == 0 {
        return;
    }
    for v in views.iter_mut().filter(|v| v.shadow.is_none()) {
        let Some(texture) = v.color_index else {
            continue;
        };
        let image = Image {
            target: v.target,
            texture,
        };
        if image.target == HDR {
            v.written = Some("the world, read by step 1".into());
            continue;
        }
        if let Some(s) = (0..steps).rev().find(|&s| post::writes(scene, s) == image) {
            v.written = Some(format!(
                "after step {} of {steps}, {}",
                s + 1,
                step_name(scene, plan, s)
            ));
        }
    }
    name_bloom(views, scene);
}

/// Bloom's images, by the blur that left them: a level of `bloom_levels`
/// "blur 2 of 4, sigma 24.9 full-resolution pixels", the same level of
/// `bloom_temp` "blur 2's horizontal pass" (src/techniques/post/bloom_levels.rs).
fn name_bloom(views: &mut [View], scene: &Scene) {
    let (w, h) = (scene.render.size.0 as i32, scene.render.size.1 as i32);
    for b in scene.post.iter().filter_map(|p| match p {
        PostPass::Bloom(b) => Some(b),
        _ => None,
    }) {
        let blurs = bloom_levels::blurs(b, w, h);
        for v in views.iter_mut() {
            let on = |t: &str, x: &bloom_levels::Blur| t == v.target && x.level == v.level;
            if let Some(x) = blurs.iter().rev().find(|x| on(x.target, x)) {
                let sigma = b.levels[x.index].sigma;
                v.written = Some(format!(
                    "blur {} of 4, sigma {sigma} full-resolution pixels",
                    x.index + 1
                ));
            } else if let Some(x) = blurs.iter().rev().find(|x| on(x.temp, x)) {
                v.written = Some(format!("blur {}'s horizontal pass", x.index + 1));
            }
        }
    }
}

/// Step `s`'s name: its pass in the plan ("tone mapping"), or its entry's
/// pass, and for an entry of several steps which one ("blur 2/2").
pub fn step_name(scene: &Scene, plan: &FramePlan, s: usize) -> String {
    let Some((i, first, p)) = post::entries(scene)
        .filter(|&(_, first, _)| first <= s)
        .last()
    else {
        return format!("step {}", s + 1);
    };
    let planned = plan.passes.iter().find(|q| {
        techniques::ALL
            .get(q.technique)
            .is_some_and(|t| t.runs == Runs::AfterViews)
            && q.item == i
            && q.value as usize == s
    });
    let name = planned.map_or(p.name(), |q| q.name);
    match post::steps_of(p) {
        1 => name.to_string(),
        n => format!("{name} {}/{n}", s - first + 1),
    }
}
