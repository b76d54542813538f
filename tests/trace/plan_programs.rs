//! `gloss plan` names every program a pass draws with (src/frame/plan_programs.rs):
//! the G-buffer's material variant, the composite's, forward's lighting
//! variant (VARIANT_FORWARD_GLTF among its defines), deferred shading's
//! (both forms), the light pre-pass's combine (with and without the alpha
//! test) and the shadow pass's
//! depth-only and alpha-test caster programs. Here the plan's defines are
//! compared with those of the programs each pass of an executed frame put in
//! use (glUseProgram in the pass), read back from the recording layer, which
//! notes the `#define`s of every shader source the driver was given: the
//! test fails if the plan or a pass drifts from the other.
//!
//! The demo's switches that change the set (render.specialize, the path,
//! render.ibl, render.normal_mapping, through `Renderer::set_render_settings`)
//! give a next frame that draws with the programs the new plan names.
//!
//! And the shadow passes build their caster programs on first use
//! (src/techniques/shadows/casters.rs): a frame without alpha-tested casters
//! has no alpha-test caster program at all (counted among the GL's live
//! programs by their uniforms: `u_light_view_projection` is a caster
//! program's alone, `u_alpha_ref` the alpha test's).

use crate::common;
use gloss::frame::plan::FramePlan;
use gloss::gl::Headless;
use gloss::gl::program::Sources;
use gloss::gl::trace::{self, Call};
use gloss::renderer::{Output, Renderer};
use gloss::scene::Scene;
use glow::HasContext;
use std::collections::{BTreeMap, BTreeSet};

type Defines = Vec<(String, String)>;

/// The first frame of `s`, traced: the calls, the plan, and the renderer
/// (whose programs are still alive).
fn first_frame(ctx: &Headless, s: &Scene) -> (Vec<Call>, FramePlan, Renderer) {
    let (w, h) = s.render.size;
    let mut r = Renderer::with_output(
        &ctx.gl,
        &ctx.debug,
        s,
        &Sources::Embedded,
        w as i32,
        h as i32,
        Output::Srgb8,
    )
    .unwrap();
    trace::start();
    let drawn = r.render(&s.camera);
    let calls = trace::stop();
    drawn.unwrap();
    let plan = r.plan.clone();
    (calls, plan, r)
}

/// Sorted, without MAX_LIGHTS (every program has it; the plan names the rest).
fn sorted(defines: impl IntoIterator<Item = (String, String)>) -> Defines {
    let mut d: Defines = (defines.into_iter())
        .filter(|(k, _)| k != "MAX_LIGHTS")
        .collect();
    d.sort();
    d
}

/// The defines of the programs each pass (by its number) put in use.
fn used_by_pass(calls: &[Call]) -> BTreeMap<usize, BTreeSet<Defines>> {
    let mut out: BTreeMap<usize, BTreeSet<Defines>> = BTreeMap::new();
    for c in calls.iter().filter(|c| c.function == "glUseProgram") {
        let (Some(pass), Some(id)) = (&c.pass, c.args.first().and_then(|a| a.parse().ok())) else {
            continue;
        };
        if id == 0 {
            continue;
        }
        let defines = trace::program_defines(id)
            .unwrap_or_else(|| panic!("program {id} ({}): made unseen", pass.title));
        (out.entry(pass.number).or_default()).insert(sorted(defines));
    }
    out
}

/// Every pass of `s` whose plan names its programs: the plan's defines
/// equal the used programs'; the printed plan shows each. Returns the names
/// of the passes checked, and the programs' roles.
fn check(ctx: &Headless, what: &str, s: &Scene) -> (BTreeSet<String>, BTreeSet<String>) {
    let (calls, plan, _r) = first_frame(ctx, s);
    compare(what, s, &calls, &plan)
}

/// `check` for a frame of `s` already traced.
fn compare(
    what: &str,
    s: &Scene,
    calls: &[Call],
    plan: &FramePlan,
) -> (BTreeSet<String>, BTreeSet<String>) {
    let used = used_by_pass(calls);
    let printed = plan.to_string();
    let mut checked = BTreeSet::new();
    let mut roles = BTreeSet::new();
    for (i, p) in plan.passes.iter().enumerate() {
        if p.programs.is_empty() {
            continue;
        }
        let named: BTreeSet<Defines> = (p.programs.iter())
            .map(|g| sorted(g.defines.iter().map(|(k, v)| (k.to_string(), v.clone()))))
            .collect();
        let frame = used.get(&(i + 1)).cloned().unwrap_or_default();
        // Frustum culling may leave a shadow map without the casters of
        // one of its programs (the plan names what the scene's casters
        // need, and the pass builds that); without it, every one is used.
        let culled = s.render.frustum_culling && p.name.contains("shadow map");
        assert!(
            named == frame || (culled && frame.is_subset(&named) && !frame.is_empty()),
            "{what}: pass {} ({}): the plan names {named:#?}, the frame used {frame:#?}",
            i + 1,
            plan.title(i)
        );
        for g in &p.programs {
            let line = format!("program ({}):", g.role);
            assert!(printed.contains(&line), "{what}: no {line} in\n{printed}");
            for (k, _) in &g.defines {
                assert!(printed.contains(k), "{what}: {k} not printed in\n{printed}");
            }
            roles.insert(g.role.to_string());
        }
        checked.insert(p.name.to_string());
    }
    (checked, roles)
}

fn scene(name: &str, edit: impl Fn(&mut Scene)) -> Scene {
    let mut s = common::scene(&format!("{name}.toml"));
    s.render.size = (64, 36);
    edit(&mut s);
    s
}

#[test]
fn the_plan_names_the_defines_of_every_program_the_frame_uses() {
    use gloss::scene::{CubeRender, RenderPath};
    let ctx = crate::tracing_context();
    let deferred = |s: &mut Scene| s.render.path = RenderPath::Deferred;
    let general = |s: &mut Scene| s.render.specialize = false;
    let layered = |s: &mut Scene| {
        for l in &mut s.lights {
            if let Some(sh) = &mut l.shadow {
                sh.cube = CubeRender::GeometryShader;
            }
        }
    };
    let cases: Vec<(&str, Scene)> = vec![
        ("default", scene("default", |_| {})),
        ("default, deferred", scene("default", deferred)),
        ("gltf-scene", scene("gltf-scene", |_| {})),
        ("gltf-scene, deferred", scene("gltf-scene", deferred)),
        ("ibl", scene("ibl", |_| {})),
        ("ibl, deferred", scene("ibl", deferred)),
        ("ambient-occlusion", scene("ambient-occlusion", |_| {})),
        ("deferred-shading", scene("deferred-shading", |_| {})),
        (
            "deferred-shading, single pass",
            scene("deferred-shading", |s| {
                s.render.deferred_lights = gloss::scene::DeferredLights::SinglePass
            }),
        ),
        ("light-prepass", scene("light-prepass", |_| {})),
        ("light-prepass, general", scene("light-prepass", general)),
        (
            "ibl, light pre-pass",
            scene("ibl", |s| s.render.path = RenderPath::Prepass),
        ),
        (
            "ambient-occlusion, light pre-pass",
            scene("ambient-occlusion", |s| s.render.path = RenderPath::Prepass),
        ),
        (
            "model-loading, light pre-pass",
            scene("model-loading", |s| s.render.path = RenderPath::Prepass),
        ),
        (
            "model-loading (alpha-tested leaves)",
            scene("model-loading", |_| {}),
        ),
        ("model-loading, general", scene("model-loading", general)),
        ("shadows-directional", scene("shadows-directional", |_| {})),
        ("shadows-point", scene("shadows-point", |_| {})),
        ("shadows-point, gl_Layer", scene("shadows-point", layered)),
        ("cascaded-shadows", scene("cascaded-shadows", |_| {})),
    ];
    let mut passes = BTreeSet::new();
    let mut roles = BTreeSet::new();
    for (what, s) in &cases {
        let (p, r) = check(&ctx, what, s);
        passes.extend(p);
        roles.extend(r);
        // Every caster drawn into every map: the plan's programs exactly.
        let mut all = s.clone();
        all.render.frustum_culling = false;
        check(&ctx, &format!("{what}, no frustum culling"), &all);
    }
    // Every kind of pass the plan names programs for was checked.
    for pass in [
        "gbuffer",
        "composite",
        "forward",
        "shadow map",
        "cascaded shadow map",
        "lighting",
        "combine",
    ] {
        assert!(passes.contains(pass), "no {pass} pass checked: {passes:?}");
    }
    for role in [
        "depth only",
        "alpha test",
        "G-buffer",
        "composite",
        "Phong",
        "per light",
        "single pass",
        "combine",
        "combine, alpha test",
    ] {
        assert!(roles.contains(role), "no {role} program checked: {roles:?}");
    }
}

/// The live programs of the GL that draw casters into a shadow map: (depth
/// only, with the alpha test).
fn caster_programs(gl: &glow::Context, calls_seen: i64) -> (usize, usize) {
    let (mut depth_only, mut alpha) = (0, 0);
    for id in 1..=calls_seen {
        let Some(p) = u32::try_from(id).ok().and_then(std::num::NonZeroU32::new) else {
            continue;
        };
        let p = glow::NativeProgram(p);
        unsafe {
            if !gl.is_program(p) {
                continue;
            }
            let names: Vec<String> = (0..gl.get_active_uniforms(p))
                .filter_map(|i| gl.get_active_uniform(p, i))
                .map(|u| u.name)
                .collect();
            if !names
                .iter()
                .any(|n| n.starts_with("u_light_view_projection"))
            {
                continue;
            }
            if names.iter().any(|n| n == "u_alpha_ref") {
                alpha += 1;
            } else {
                depth_only += 1;
            }
        }
    }
    (depth_only, alpha)
}

#[test]
fn a_frame_builds_only_the_caster_programs_it_draws_with() {
    let ctx = crate::tracing_context();
    let cases = [
        // (scene, specialised: depth-only programs, alpha-test programs)
        ("shadows-directional", true, 1, 0),
        ("shadows-spot", true, 1, 0),
        ("cascaded-shadows", true, 1, 0),
        ("shadows-point", true, 1, 0),
        // A sun (2D map) and a lamp (cube), both casting leaves.
        ("model-loading", true, 2, 2),
        ("shadows-directional", false, 0, 1),
    ];
    for (name, specialize, depth_only, alpha) in cases {
        let s = scene(name, |s| s.render.specialize = specialize);
        let (_, _, r) = first_frame(&ctx, &s);
        // The highest program name GL has handed out so far.
        let highest = unsafe { ctx.gl.create_program() }.unwrap();
        let highest = i64::from(highest.0.get());
        unsafe { ctx.gl.delete_program(highest_program(highest)) };
        let got = caster_programs(&ctx.gl, highest);
        assert_eq!(
            got,
            (depth_only, alpha),
            "{name} (specialize {specialize}): (depth-only, alpha-test) caster programs"
        );
        drop(r);
    }
}

fn highest_program(id: i64) -> glow::NativeProgram {
    glow::NativeProgram(std::num::NonZeroU32::new(id as u32).unwrap())
}

/// Every program the plan names, as a set of define lists.
fn named(plan: &FramePlan) -> BTreeSet<(&'static str, Defines)> {
    (plan.passes.iter().flat_map(|p| p.programs.iter()))
        .map(|g| {
            let d = sorted(g.defines.iter().map(|(k, v)| (k.to_string(), v.clone())));
            (g.role, d)
        })
        .collect()
}

/// The demo's switches (`Renderer::set_render_settings`, what its panel
/// calls) that change a pass's programs: the next frame draws with the
/// programs the new plan names, built then.
#[test]
fn a_switch_that_changes_the_programs_gets_those_the_plan_names() {
    use gloss::scene::{RenderPath, RenderSettings};
    let ctx = crate::tracing_context();
    type Switch = (&'static str, fn(&mut RenderSettings));
    let cases: [(&str, RenderPath, &[Switch]); 3] = [
        (
            "model-loading",
            RenderPath::Deferred,
            &[
                ("general", |r| r.specialize = false),
                ("specialised", |r| r.specialize = true),
                ("forward", |r| r.path = RenderPath::Forward),
                ("deferred", |r| r.path = RenderPath::Deferred),
            ],
        ),
        (
            "ibl",
            RenderPath::Deferred,
            &[
                ("IBL off", |r| r.ibl = false),
                ("IBL on", |r| r.ibl = true),
                ("forward", |r| r.path = RenderPath::Forward),
            ],
        ),
        (
            "bump-mapping",
            RenderPath::Deferred,
            &[
                ("normal mapping off", |r| r.normal_mapping = false),
                ("normal mapping on", |r| r.normal_mapping = true),
            ],
        ),
    ];
    for (name, path, switches) in cases {
        let mut s = scene(name, |s| {
            s.render.path = path;
            s.render.frustum_culling = false;
        });
        let (calls, plan, mut r) = first_frame(&ctx, &s);
        compare(name, &s, &calls, &plan);
        let mut before = named(&plan);
        for (what, switch) in switches {
            switch(&mut s.render);
            r.set_render_settings(s.render.clone()).unwrap();
            trace::start();
            let drawn = r.render(&s.camera);
            let calls = trace::stop();
            drawn.unwrap();
            let what = format!("{name}, then {what}");
            compare(&what, &s, &calls, &r.plan);
            let after = named(&r.plan);
            assert_ne!(before, after, "{what}: no program changed");
            before = after;
        }
    }
}
