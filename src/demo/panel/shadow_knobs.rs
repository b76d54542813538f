//! A light's shadow knobs (notes 01 §8.5 "Shadow mapping", §8.5.1 "Issues";
//! docs/shadows.md says what each does): "casts shadows", then the map's
//! resolution, the constant, slope-scaled and normal-offset biases,
//! front-face culling, the PCF kernel, and a directional light's fit or a
//! point light's way of drawing its cube.
//!
//! A scene holds at most `MAX_SHADOW_MAPS_2D` casting directional and spot
//! lights and `MAX_SHADOW_CUBES` casting point lights (a texture unit each;
//! the scene loader refuses more): "casts shadows" on a light past that is
//! refused with a message, and so is a casting light's change of type into
//! a full group.

use crate::scene::shadows::{MAX_CASCADES, MAX_SHADOW_CUBES, MAX_SHADOW_MAPS_2D, RESOLUTIONS};
use crate::scene::{CascadeSplit, CubeRender, Light, LightKind, Pcf, Shadow, ShadowFit};

/// The colour of the refusal message (the panel's error colour).
const REFUSED: egui::Color32 = egui::Color32::from_rgb(255, 110, 90);

/// How many lights of each group cast: (directional and spot, point).
fn casting(lights: &[Light], except: Option<usize>) -> (usize, usize) {
    let on = |(i, l): &(usize, &Light)| l.shadow.is_some() && Some(*i) != except;
    let cube = |l: &Light| l.kind == LightKind::Point;
    let mut n = (0, 0);
    for (_, l) in lights.iter().enumerate().filter(on) {
        if cube(l) {
            n.1 += 1;
        } else {
            n.0 += 1;
        }
    }
    n
}

/// Why light `i` may not cast as a light of `kind` beside the others of
/// `lights` (None: it may).
pub fn refused(lights: &[Light], i: usize, kind: LightKind) -> Option<String> {
    let (flat, cube) = casting(lights, Some(i));
    if kind == LightKind::Point && cube >= MAX_SHADOW_CUBES {
        Some(format!(
            "{cube} point lights cast shadows already: at most {MAX_SHADOW_CUBES} may (a cube-map texture unit each)"
        ))
    } else if kind != LightKind::Point && flat >= MAX_SHADOW_MAPS_2D {
        Some(format!(
            "{flat} directional and spot lights cast shadows already: at most {MAX_SHADOW_MAPS_2D} may (a 2D-map texture unit each)"
        ))
    } else {
        None
    }
}

/// The scene loader's limit, checked on lights the panel edited: the
/// loader's words when there are too many casters.
pub fn too_many_casters(lights: &[Light]) -> Option<String> {
    let (flat, cube) = casting(lights, None);
    (flat > MAX_SHADOW_MAPS_2D || cube > MAX_SHADOW_CUBES).then(|| {
        format!(
            "lights: {flat} directional or spot and {cube} point lights cast shadows; at most {MAX_SHADOW_MAPS_2D} and {MAX_SHADOW_CUBES} may (one texture unit each)"
        )
    })
}

/// Light `i`'s shadow knobs; `before` are the scene's lights as they were
/// before this frame's edits. True when one changed.
pub fn show(ui: &mut egui::Ui, i: usize, l: &mut Light, before: &[Light]) -> bool {
    let mut changed = false;
    let mut on = l.shadow.is_some();
    let refusal = if on { None } else { refused(before, i, l.kind) };
    let r = ui.add_enabled(
        refusal.is_none(),
        egui::Checkbox::new(&mut on, "casts shadows"),
    );
    if r.changed() {
        l.shadow = on.then(Shadow::default);
        changed = true;
    }
    if let Some(why) = refusal {
        ui.colored_label(REFUSED, why);
    }
    let kind = l.kind;
    let Some(s) = &mut l.shadow else {
        return changed;
    };
    ui.horizontal(|ui| {
        ui.label("resolution");
        egui::ComboBox::from_id_salt(("shadow resolution", i))
            .selected_text(format!("{0} x {0}", s.resolution))
            .show_ui(ui, |ui| {
                for n in RESOLUTIONS {
                    let word = format!("{n} x {n}");
                    changed |= ui.selectable_value(&mut s.resolution, n, word).changed();
                }
            });
    });
    changed |= drag(ui, "bias (world units)", &mut s.bias, 1.0);
    changed |= drag(ui, "slope bias", &mut s.slope_bias, 20.0);
    changed |= drag(ui, "normal offset (texels)", &mut s.normal_offset, 20.0);
    changed |= ui
        .checkbox(&mut s.cull_front, "cull front faces (store back faces)")
        .changed();
    changed |= combo(
        ui,
        ("shadow pcf", i),
        "PCF",
        &mut s.pcf,
        Pcf::ALL,
        Pcf::name,
    );
    if kind == LightKind::Directional {
        let (all, name) = (ShadowFit::ALL, ShadowFit::name);
        changed |= combo(ui, ("shadow fit", i), "fit to", &mut s.fit, all, name);
        changed |= cascades(ui, i, s, before);
    }
    if kind == LightKind::Point {
        let (all, name) = (CubeRender::ALL, CubeRender::name);
        changed |= combo(ui, ("shadow cube", i), "cube faces", &mut s.cube, all, name);
    }
    changed
}

/// A directional light's cascades (docs/shadows/cascaded_shadow_maps.md):
/// the count (1: one map), the split, the practical split's lambda, the
/// stable fit, the blend band and the cascade colours. Only one light may
/// cascade (the loader's rule): a second is refused with a message.
fn cascades(ui: &mut egui::Ui, i: usize, s: &mut Shadow, before: &[Light]) -> bool {
    let other = (before.iter().enumerate())
        .any(|(j, l)| j != i && l.shadow.is_some_and(|s| s.cascades > 1));
    let mut changed = false;
    ui.horizontal(|ui| {
        ui.label("cascades");
        let enabled = !other || s.cascades > 1;
        let slider = egui::Slider::new(&mut s.cascades, 1..=MAX_CASCADES);
        changed |= ui.add_enabled(enabled, slider).changed();
    });
    if other && s.cascades <= 1 {
        ui.colored_label(
            REFUSED,
            "another directional light cascades already: at most one may",
        );
    }
    // Each layer is a full map: keep to the loader's 512 MiB.
    while u64::from(s.cascades) * u64::from(s.resolution).pow(2) > 1 << 27 {
        s.resolution /= 2;
    }
    if s.cascades <= 1 {
        return changed;
    }
    let (all, name) = (CascadeSplit::ALL, CascadeSplit::name);
    changed |= combo(ui, ("cascade split", i), "split", &mut s.split, all, name);
    if s.split == CascadeSplit::Practical {
        changed |= ui
            .add(egui::Slider::new(&mut s.lambda, 0.0..=1.0).text("lambda (log weight)"))
            .changed();
    }
    changed |= ui
        .checkbox(&mut s.stable, "stable cascades (texel-snapped)")
        .changed();
    changed |= ui
        .add(egui::Slider::new(&mut s.blend, 0.0..=0.5).text("blend band"))
        .changed();
    changed |= ui
        .checkbox(&mut s.cascade_colors, "cascade colours")
        .changed();
    changed
}

/// A value that must stay >= 0 (the loader refuses a negative bias), on
/// a logarithmic slider from 0 to `max` (a bias is tuned by its order of
/// magnitude); a larger value from the file stays as it is until moved.
fn drag(ui: &mut egui::Ui, label: &str, v: &mut f32, max: f32) -> bool {
    ui.horizontal(|ui| {
        ui.label(label);
        let slider = egui::Slider::new(v, 0.0..=max.max(*v))
            .logarithmic(true)
            .smallest_positive(1e-5);
        ui.add(slider).changed()
    })
    .inner
}

/// A choice among `all`, each shown by `name`.
fn combo<T: Copy + PartialEq, const N: usize>(
    ui: &mut egui::Ui,
    id: (&str, usize),
    label: &str,
    v: &mut T,
    all: [T; N],
    name: fn(T) -> &'static str,
) -> bool {
    let mut changed = false;
    ui.horizontal(|ui| {
        ui.label(label);
        egui::ComboBox::from_id_salt(id)
            .selected_text(name(*v))
            .show_ui(ui, |ui| {
                for c in all {
                    changed |= ui.selectable_value(v, c, name(c)).changed();
                }
            });
    });
    changed
}
