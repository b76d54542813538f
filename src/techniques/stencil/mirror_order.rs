//! The frame order of the mirror technique (src/techniques/stencil/mirror.rs;
//! notes 05, "Planar Reflections" to "Normal First Addendum"): which views
//! of the world a frame with mirrors draws, and the mirror's own steps
//! between them, in the order the notes give. Reflected first: one mirror,
//! one reflection. Normal first: every mirror, and the mirrors seen in it,
//! `render.mirror_depth` levels deep, followed only where they can show
//! (src/scene/mirror_views.rs).

use crate::frame::lights::FrameLights;
use crate::frame::plan::Pass;
use crate::frame::post::world_target;
use crate::frame::views::View;
use crate::frame::{FrameOrder, Stage};
use crate::scene::mirror_views::{self, Seen};
use crate::scene::{MirrorOrder, Scene};

/// Where the mirror's passes are run (`gloss plan` names the file).
pub(super) const FILE: &str = "src/techniques/stencil/mirror.rs";

/// Normal first, pass 2: stencil where the mirror passes the depth test.
pub(super) const MARK: u32 = 0;
/// Normal first, pass 3 (first half): depth = far inside the stencil only.
pub(super) const CLEAR_DEPTH: u32 = 1;
/// Reflected first, pass 2: mark the mirror, clear the colour outside it.
pub(super) const STENCIL_AND_CLEAR: u32 = 2;
/// Multiply the reflection by the mirror's tint (stencil region: normal first).
pub(super) const SURFACE: u32 = 3;
/// The same, depth-tested against what is in front (reflected first).
pub(super) const SURFACE_TESTED: u32 = 4;
/// Give a nested region back to its parent's stencil value.
pub(super) const UNMARK: u32 = 5;

/// The frame's views and stages; None without a mirror (no stencil work).
pub(super) fn order(scene: &Scene, _: &FrameLights) -> Option<FrameOrder> {
    let mirrors = scene.mirrors();
    if mirrors.is_empty() {
        return None;
    }
    let r = &scene.render;
    if r.mirror_order == MirrorOrder::ReflectedFirst && mirrors.len() == 1 && r.mirror_depth == 1 {
        reflected_first(scene, mirrors[0])
    } else {
        Some(normal_first(scene, &mirrors))
    }
}

/// The view of the world reflected in `mirror`, seen in `parent`
/// (src/frame/views.rs builds it). None when there is nothing to draw in
/// it: a mirror without a plane, or a mirror seen in a curved one.
fn reflected_view(
    scene: &Scene,
    parent: &View,
    mirror: usize,
    stencil: Option<u8>,
) -> Option<View> {
    let (o, r) = (&scene.objects[mirror], &scene.render);
    if let Some(sphere) = o.curved_mirror() {
        return View::in_curved_mirror(parent, &o.name, sphere, r.mirror_winding, stencil);
    }
    let plane = o.mirror_plane()?;
    View::in_mirror(
        parent,
        &o.name,
        plane,
        r.mirror_clip,
        r.mirror_winding,
        stencil,
    )
}

fn reflected_first(scene: &Scene, m: usize) -> Option<FrameOrder> {
    let camera = View {
        clears: false,
        ..View::camera()
    };
    let reflected = View {
        clears: true,
        ..reflected_view(scene, &camera, m, None)?
    };
    let o = &scene.objects[m];
    let mirror = o.mirror.as_ref()?;
    let mut stages = vec![Stage::World(1)];
    // An infinite mirror, or one framed by a wall, needs no pass 2.
    let stencil = !(mirror.infinite || mirror.covered);
    if stencil {
        let draws = format!("mirror '{}': stencil 1, colour cleared outside it", o.name);
        stages.push(Stage::Own(
            Pass::new("mirror stencil", world_target(scene), draws, FILE)
                .step(STENCIL_AND_CLEAR)
                .about(m, 1),
        ));
    }
    stages.push(Stage::World(0));
    let draws = format!("mirror '{}': tint x reflectance, depth-tested", o.name);
    stages.push(Stage::Own(
        Pass::new("mirror surface", world_target(scene), draws, FILE)
            .step(SURFACE_TESTED)
            .about(m, u32::from(stencil)),
    ));
    Some(FrameOrder {
        views: vec![camera, reflected],
        stages,
    })
}

fn normal_first(scene: &Scene, mirrors: &[usize]) -> FrameOrder {
    let mut order = FrameOrder {
        views: vec![View::camera()],
        stages: vec![Stage::World(0)],
    };
    let levels = scene.render.mirror_depth + 1;
    for (i, &m) in mirrors.iter().enumerate() {
        // Mirror i's own stencil value, and one more per level inside it.
        let at = At {
            parent: 0,
            seen: Some(Seen::camera()),
            level: 1,
            value: 1 + i as u32 * levels,
        };
        visit(scene, mirrors, &mut order, m, at);
    }
    order
}

/// Where a mirror is seen: in view `parent` (what can be seen there:
/// `seen`, None inside a curved mirror, where every mirror is drawn blank),
/// `level` mirrors deep, marked `value`.
#[derive(Clone, Copy)]
struct At {
    parent: usize,
    seen: Option<Seen>,
    level: u32,
    value: u32,
}

/// Mirror `m` seen at `at`. Only the mirrors that can show in its
/// reflection are followed into it (src/scene/mirror_views.rs), and no
/// view is added past `MAX_MIRROR_VIEWS` (the scene refuses such a
/// depth when it is read; the demo may move the camera since).
fn visit(scene: &Scene, mirrors: &[usize], order: &mut FrameOrder, m: usize, at: At) {
    let At {
        parent,
        level,
        value,
        ..
    } = at;
    let name = &scene.objects[m].name;
    let own = |pass: &'static str, step: u32, draws: String| {
        Stage::Own(
            Pass::new(pass, world_target(scene), draws, FILE)
                .step(step)
                .about(m, value)
                .for_view(parent),
        )
    };
    // Where the mirror can show (None: nowhere), and what its reflection can see.
    let rect = match at.seen {
        Some(s) => mirror_views::seen_in(scene, &s, m),
        None => Some(mirror_views::SCREEN),
    };
    let inner = match (at.seen, rect) {
        (Some(s), Some(rect)) => mirror_views::reflected(scene, &s, m, rect),
        _ => None,
    };
    // None: the mirror is drawn blank (marked and tinted, no reflection).
    let view = reflected_view(scene, &order.views[parent], m, Some(value as u8));
    let how = if level == 1 { "" } else { " (increment)" };
    order.stages.push(own(
        "mirror mark",
        MARK,
        format!("mirror '{name}': stencil {value}{how} where it passes the depth test"),
    ));
    let room = order.views.len() <= mirror_views::MAX_MIRROR_VIEWS;
    if let Some(view) =
        view.filter(|_| level <= scene.render.mirror_depth && rect.is_some() && room)
    {
        order.stages.push(own(
            "mirror depth clear",
            CLEAR_DEPTH,
            format!("depth = far where stencil = {value}"),
        ));
        order.views.push(view);
        let k = order.views.len() - 1;
        order.stages.push(Stage::World(k));
        for &c in mirrors.iter().filter(|&&c| c != m) {
            // In a curved mirror's view every mirror is drawn blank, as before.
            if inner.is_some_and(|s| mirror_views::seen_in(scene, &s, c).is_none()) {
                continue;
            }
            let at = At {
                parent: k,
                seen: inner,
                level: level + 1,
                value: value + 1,
            };
            visit(scene, mirrors, order, c, at);
        }
    }
    order.stages.push(own(
        "mirror surface",
        SURFACE,
        format!("mirror '{name}': tint x reflectance where stencil = {value}"),
    ));
    if level > 1 {
        order.stages.push(own(
            "mirror unmark",
            UNMARK,
            format!("stencil {value} -> {} (decrement)", value - 1),
        ));
    }
}
