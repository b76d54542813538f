//! The scene's lights, materials and objects, editable live: each light's
//! type, colour, intensity, position, direction, Kc/Kl/Kq attenuation,
//! cone angles and shadow knobs (shadow_knobs.rs); the light grid's
//! parameters; each material's diffuse and specular colours, shininess,
//! opacity and texture; each object's transform, mesh, material and
//! parent; the camera's lens.

use super::fields::{number, vec3};
use super::{shadow_knobs, structure};
use crate::scene::material::Microfacet;
use crate::scene::{Camera, LightGrid, LightKind, Object, Projection, Scene};
use glam::Vec3;

/// The lights listed in the scene file, editable; Some(new lights) when one changed.
pub fn lights(ui: &mut egui::Ui, scene: &Scene) -> Option<Vec<crate::scene::Light>> {
    let fixed = scene.lights.len() - scene.grid_lights.unwrap_or(0);
    if fixed == 0 {
        return None;
    }
    let mut lights = scene.lights.clone();
    let mut changed = false;
    egui::CollapsingHeader::new(format!("Lights ({fixed})"))
        .default_open(false)
        .show(ui, |ui| {
            for (i, l) in lights.iter_mut().take(fixed).enumerate() {
                let kind = match l.kind {
                    LightKind::Directional => "directional",
                    LightKind::Point => "point",
                    LightKind::Spot => "spot",
                };
                egui::CollapsingHeader::new(format!("light {i}: {kind}"))
                    .id_salt(("light", i))
                    .show(ui, |ui| {
                        ui.horizontal_wrapped(|ui| {
                            ui.label("type");
                            for (k, word) in [
                                (LightKind::Directional, "directional"),
                                (LightKind::Point, "point"),
                                (LightKind::Spot, "spot"),
                            ] {
                                // A casting light may not move into a full group.
                                let refusal = (l.shadow.is_some())
                                    .then(|| shadow_knobs::refused(&scene.lights, i, k))
                                    .flatten();
                                let button = egui::Button::selectable(l.kind == k, word);
                                let r = ui.add_enabled(refusal.is_none(), button);
                                if r.clicked() && l.kind != k {
                                    l.kind = k;
                                    changed = true;
                                }
                                if let Some(why) = refusal {
                                    r.on_disabled_hover_text(why);
                                }
                            }
                        });
                        changed |= vec3(ui, "colour", &mut l.color, 0.0..=10.0);
                        changed |= number(ui, "intensity", &mut l.intensity, 0.0..=1000.0);
                        if l.kind != LightKind::Directional {
                            changed |= vec3(ui, "position", &mut l.position, -1e4..=1e4);
                            let mut k = Vec3::new(l.kc, l.kl, l.kq);
                            if vec3(ui, "Kc Kl Kq", &mut k, 0.0..=100.0) {
                                (l.kc, l.kl, l.kq) = (k.x, k.y, k.z);
                                changed = true;
                            }
                        }
                        if l.kind != LightKind::Point {
                            changed |= vec3(ui, "direction", &mut l.direction, -1.0..=1.0);
                        }
                        if l.kind == LightKind::Spot {
                            changed |= number(ui, "inner angle", &mut l.inner_angle, 0.0..=88.0);
                            changed |= number(ui, "outer angle", &mut l.outer_angle, 0.0..=88.0);
                        }
                        changed |= shadow_knobs::show(ui, i, l, &scene.lights);
                    });
            }
        });
    changed.then_some(lights)
}

/// The materials, editable; Some(new materials) when one changed.
pub fn materials(ui: &mut egui::Ui, scene: &Scene) -> Option<Vec<crate::scene::Material>> {
    let mut materials = scene.materials.clone();
    let mut changed = false;
    egui::CollapsingHeader::new(format!("Materials ({})", materials.len()))
        .default_open(false)
        .show(ui, |ui| {
            for (i, m) in materials.iter_mut().enumerate() {
                egui::CollapsingHeader::new(&m.name)
                    .id_salt(("material", i))
                    .show(ui, |ui| {
                        changed |= vec3(ui, "diffuse", &mut m.diffuse, 0.0..=10.0);
                        // Phong's terms, or notes 03's microfacet triple.
                        if let Some(mf) = &mut m.microfacet {
                            let (a, e, k) = (Microfacet::ALPHA, Microfacet::ETA, Microfacet::K_S);
                            changed |= number(ui, "alpha", &mut mf.alpha, a.0..=a.1);
                            changed |= number(ui, "eta", &mut mf.eta, e.0..=e.1);
                            changed |= number(ui, "k_s", &mut mf.k_s, k.0..=k.1);
                        } else {
                            changed |= vec3(ui, "specular", &mut m.specular, 0.0..=10.0);
                            changed |= number(ui, "shininess", &mut m.shininess, 1.0..=4096.0);
                        }
                        // Below 1 the transparency pass draws it (notes 01 §4.5).
                        changed |= number(ui, "opacity", &mut m.opacity, 0.0..=1.0);
                        changed |= structure::texture(ui, scene, i, m);
                        changed |= structure::sampling(ui, i, m);
                        changed |= structure::material_tests(ui, i, m);
                    });
            }
        });
    changed.then_some(materials)
}

/// The camera's lens: field of view (or half height), near and far planes;
/// Some(new camera) when one changed. Where it looks from is the orbit's.
pub fn camera(ui: &mut egui::Ui, camera: &Camera) -> Option<Camera> {
    let mut c = camera.clone();
    let mut changed = false;
    egui::CollapsingHeader::new("Camera")
        .default_open(false)
        .show(ui, |ui| {
            match &mut c.projection {
                Projection::Perspective { fov_y_degrees } => {
                    changed |= number(ui, "fov y (degrees)", fov_y_degrees, 1.0..=170.0);
                }
                Projection::Orthographic { half_height } => {
                    changed |= number(ui, "half height", half_height, 1e-3..=1e4);
                }
            }
            changed |= number(ui, "near", &mut c.near, 1e-4..=1e3);
            changed |= number(ui, "far", &mut c.far, 1e-3..=1e6);
        });
    (changed && c.near > 0.0 && c.far > c.near).then_some(c)
}

/// Each object's local transform (its parent's applies on top); Some(new
/// objects) when one changed.
pub fn objects(ui: &mut egui::Ui, scene: &Scene) -> Option<Vec<Object>> {
    let mut objects = scene.objects.clone();
    let mut changed = false;
    egui::CollapsingHeader::new(format!("Objects ({})", objects.len()))
        .default_open(false)
        .show(ui, |ui| {
            for (i, o) in objects.iter_mut().enumerate() {
                egui::CollapsingHeader::new(&o.name)
                    .id_salt(("object", i))
                    .show(ui, |ui| {
                        changed |= vec3(ui, "position", &mut o.position, -1e4..=1e4);
                        changed |= vec3(ui, "rotation (degrees)", &mut o.rotation, -360.0..=360.0);
                        changed |= vec3(ui, "scale", &mut o.scale, -100.0..=100.0);
                        if let Some(m) = &mut o.mirror {
                            changed |= vec3(ui, "mirror tint", &mut m.tint, 0.0..=1.0);
                            changed |= number(ui, "reflectance", &mut m.reflectance, 0.0..=1.0);
                            changed |= ui
                                .checkbox(&mut m.infinite, "infinite (no stencil pass)")
                                .changed();
                            changed |= ui.checkbox(&mut m.covered, "covered by a wall").changed();
                            if m.infinite && m.covered {
                                m.covered = false;
                            }
                        }
                    });
            }
            egui::CollapsingHeader::new("mesh, material, parent")
                .id_salt("object structure")
                .show(ui, |ui| {
                    changed |= structure::object_structure(ui, scene, &mut objects);
                });
        });
    changed.then_some(objects)
}

/// The `[light_grid]`'s seed, area, heights, intensity and attenuation
/// (its count is the slider above); Some(new grid) when one changed.
pub fn light_grid(ui: &mut egui::Ui, scene: &Scene) -> Option<LightGrid> {
    let mut g = scene.light_grid.clone()?;
    let mut changed = false;
    egui::CollapsingHeader::new("Light grid")
        .default_open(false)
        .show(ui, |ui| {
            ui.horizontal(|ui| {
                ui.label("seed");
                changed |= ui.add(egui::DragValue::new(&mut g.seed)).changed();
            });
            ui.horizontal(|ui| {
                ui.label("area x0 x1 z0 z1");
                for c in &mut g.area {
                    changed |= ui.add(egui::DragValue::new(c).speed(0.05)).changed();
                }
            });
            ui.horizontal(|ui| {
                ui.label("height");
                for c in &mut g.height {
                    changed |= ui.add(egui::DragValue::new(c).speed(0.05)).changed();
                }
            });
            changed |= number(ui, "intensity", &mut g.intensity, 0.0..=1000.0);
            let mut k = Vec3::from(g.attenuation);
            if vec3(ui, "Kc Kl Kq", &mut k, 0.0..=100.0) {
                g.attenuation = k.to_array();
                changed = true;
            }
        });
    changed.then_some(g)
}
