//! The scene's lights, materials and objects, editable live: each light's
//! type, colour, intensity, position, direction, Kc/Kl/Kq attenuation and
//! cone angles; the light grid's parameters; each material's diffuse and
//! specular colours, shininess, opacity and texture; each object's
//! transform, mesh, material and parent; the camera's lens.

use crate::assets;
use crate::scene::{
    AlphaTest, Camera, DepthFunc, LightGrid, LightKind, Material, MeshSource, Object, Projection,
    Scene, SplitView,
};
use glam::Vec3;
use std::path::PathBuf;

fn vec3(
    ui: &mut egui::Ui,
    label: &str,
    v: &mut Vec3,
    range: std::ops::RangeInclusive<f32>,
) -> bool {
    ui.horizontal(|ui| {
        ui.label(label);
        let mut changed = false;
        for c in [&mut v.x, &mut v.y, &mut v.z] {
            changed |= ui
                .add(egui::DragValue::new(c).range(range.clone()).speed(0.01))
                .changed();
        }
        changed
    })
    .inner
}

fn number(
    ui: &mut egui::Ui,
    label: &str,
    v: &mut f32,
    range: std::ops::RangeInclusive<f32>,
) -> bool {
    ui.horizontal(|ui| {
        ui.label(label);
        ui.add(egui::DragValue::new(v).range(range).speed(0.01))
            .changed()
    })
    .inner
}

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
                        ui.horizontal(|ui| {
                            ui.label("type");
                            for (k, word) in [
                                (LightKind::Directional, "directional"),
                                (LightKind::Point, "point"),
                                (LightKind::Spot, "spot"),
                            ] {
                                changed |= ui.selectable_value(&mut l.kind, k, word).changed();
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
                        changed |= vec3(ui, "specular", &mut m.specular, 0.0..=10.0);
                        changed |= number(ui, "shininess", &mut m.shininess, 1.0..=4096.0);
                        // Below 1 the transparency pass draws it (notes 01 §4.5).
                        changed |= number(ui, "opacity", &mut m.opacity, 0.0..=1.0);
                        changed |= texture(ui, scene, i, m);
                        changed |= material_tests(ui, i, m);
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
                    changed |= object_structure(ui, scene, &mut objects);
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

/// A choice among `names` (index `i`); true when it changed.
fn choose(
    ui: &mut egui::Ui,
    label: &str,
    salt: (&str, usize),
    names: &[String],
    i: &mut usize,
) -> bool {
    let before = *i;
    ui.horizontal(|ui| {
        ui.label(label);
        egui::ComboBox::from_id_salt(salt)
            .selected_text(names.get(*i).map_or("?", String::as_str))
            .show_ui(ui, |ui| {
                for (j, n) in names.iter().enumerate() {
                    ui.selectable_value(i, j, n);
                }
            });
    });
    *i != before
}

/// The name a mesh goes by in the panel.
fn mesh_name(m: &MeshSource) -> String {
    match m {
        MeshSource::Obj(p) => p.file_name().map_or_else(
            || p.display().to_string(),
            |n| n.to_string_lossy().into_owned(),
        ),
        other => format!("{other:?}").to_lowercase(),
    }
}

/// What an object can be made of: the built-in meshes, the scene's OBJ
/// files and those in the assets folder beside the scene.
fn mesh_choices(scene: &Scene) -> Vec<MeshSource> {
    use MeshSource::*;
    let mut v = vec![Sphere, Icosphere, Cube, Plane, Cylinder, Cone, Torus];
    let objs = scene.objects.iter().map(|o| o.mesh.clone());
    let files = assets::assets_beside(&scene.path, "obj")
        .into_iter()
        .map(Obj);
    for m in objs.chain(files) {
        if !v.contains(&m) {
            v.push(m);
        }
    }
    v
}

/// Each object's mesh, material and parent; Some(new objects) when one
/// changed (the demo builds a new renderer: a mesh may need uploading).
pub fn object_structure(ui: &mut egui::Ui, scene: &Scene, objects: &mut [Object]) -> bool {
    let meshes = mesh_choices(scene);
    let mesh_names: Vec<String> = meshes.iter().map(mesh_name).collect();
    let materials: Vec<String> = scene.materials.iter().map(|m| m.name.clone()).collect();
    let mut parents: Vec<String> = vec!["(none)".into()];
    parents.extend(scene.objects.iter().map(|o| o.name.clone()));
    let mut changed = false;
    for (i, o) in objects.iter_mut().enumerate() {
        ui.push_id(("structure", i), |ui| {
            ui.label(&o.name);
            if o.mirror.is_some() {
                ui.label("  a mirror: its mesh stays (it must be flat, or a sphere)");
            } else {
                let mut m = meshes.iter().position(|x| *x == o.mesh).unwrap_or(0);
                if choose(ui, "  mesh", ("mesh", i), &mesh_names, &mut m) {
                    o.mesh = meshes[m].clone();
                    changed = true;
                }
            }
            changed |= choose(
                ui,
                "  material",
                ("material", i),
                &materials,
                &mut o.material,
            );
            let mut p = o.parent.map_or(0, |p| p + 1);
            if choose(ui, "  parent", ("parent", i), &parents, &mut p) {
                o.parent = p.checked_sub(1);
                changed = true;
            }
        });
    }
    changed
}

/// A material's diffuse texture among the scene's textures and the PNGs
/// beside it; true when it changed.
pub fn texture(ui: &mut egui::Ui, scene: &Scene, i: usize, m: &mut Material) -> bool {
    let mut choices: Vec<Option<PathBuf>> = vec![None];
    let used = scene
        .materials
        .iter()
        .filter_map(|m| m.diffuse_texture.clone());
    for p in used.chain(assets::assets_beside(&scene.path, "png")) {
        if !choices.contains(&Some(p.clone())) {
            choices.push(Some(p));
        }
    }
    let names: Vec<String> = choices
        .iter()
        .map(|c| match c {
            None => "(none)".to_string(),
            Some(p) => p
                .file_name()
                .map_or_else(|| p.display().to_string(), |n| n.to_string_lossy().into()),
        })
        .collect();
    let mut k = choices
        .iter()
        .position(|c| *c == m.diffuse_texture)
        .unwrap_or(0);
    if choose(ui, "texture", ("texture", i), &names, &mut k) {
        m.diffuse_texture = choices[k].clone();
        return true;
    }
    false
}

/// A material's own depth test and alpha test (notes 05, "Fragment
/// Tests"); true when one changed.
fn material_tests(ui: &mut egui::Ui, i: usize, m: &mut Material) -> bool {
    let mut changed = false;
    let mut depth: Vec<String> = vec!["(render's)".into()];
    depth.extend(DepthFunc::WORDS.iter().map(|w| w.to_string()));
    let mut d = m
        .depth_func
        .and_then(|f| DepthFunc::ALL.iter().position(|&x| x == f))
        .map_or(0, |k| k + 1);
    if choose(ui, "depth test", ("depth test", i), &depth, &mut d) {
        m.depth_func = d.checked_sub(1).map(|k| DepthFunc::ALL[k]);
        changed = true;
    }
    let alpha: Vec<String> = AlphaTest::WORDS.iter().map(|w| w.to_string()).collect();
    let mut a = AlphaTest::ALL
        .iter()
        .position(|&x| x == m.alpha_test)
        .unwrap_or(0);
    if choose(ui, "alpha test", ("alpha test", i), &alpha, &mut a) {
        m.alpha_test = AlphaTest::ALL[a];
        changed = true;
    }
    changed |= number(ui, "alpha reference", &mut m.alpha_ref, 0.0..=1.0);
    changed
}

/// Each split view's rectangle (fractions of the frame, y up); Some(new
/// views) when one changed.
pub fn views(ui: &mut egui::Ui, scene: &Scene) -> Option<Vec<SplitView>> {
    if scene.views.is_empty() {
        return None;
    }
    let mut views = scene.views.clone();
    let mut changed = false;
    egui::CollapsingHeader::new(format!("Views ({})", views.len()))
        .default_open(false)
        .show(ui, |ui| {
            for v in &mut views {
                ui.horizontal(|ui| {
                    ui.label(format!("{}: x y w h", v.name));
                    for c in &mut v.viewport {
                        changed |= ui
                            .add(egui::DragValue::new(c).range(0.0..=1.0).speed(0.005))
                            .changed();
                    }
                });
            }
        });
    changed.then_some(views)
}
