//! What the panel edits beyond values: an object's mesh, material and
//! parent, a material's texture and its depth and alpha tests, the split
//! views' rectangles and the billboards. A new mesh, texture or number of
//! billboards needs a new renderer (src/demo/actions.rs decides).

use super::fields::{number, vec3};
use crate::assets;
use crate::scene::texturing::{TextureFilter, Wrap};
use crate::scene::{
    AlphaTest, BillboardFieldFile, BillboardFile, BillboardKind, Cull, DepthFunc, Material,
    MeshSource, Object, Scene, SplitView, Winding,
};
use glam::Vec3;
use std::path::PathBuf;

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
        MeshSource::GltfPart(part) if part.mesh != crate::scene::gltf_objects::GltfPart::GROUP => {
            let file = part
                .path
                .file_name()
                .map_or_else(String::new, |f| f.to_string_lossy().into_owned());
            format!("{file} mesh {} part {}", part.mesh, part.primitive)
        }
        MeshSource::GltfPart(crate::scene::gltf_objects::GltfPart { path: p, .. })
        | MeshSource::Obj(p)
        | MeshSource::Gltf(p)
        | MeshSource::ObjPart(p, _) => p.file_name().map_or_else(
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
pub(super) fn material_tests(ui: &mut egui::Ui, i: usize, m: &mut Material) -> bool {
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
    let cull: Vec<String> = Cull::WORDS.iter().map(|w| w.to_string()).collect();
    let mut c = Cull::ALL.iter().position(|&x| x == m.cull).unwrap_or(0);
    if choose(ui, "cull faces", ("cull faces", i), &cull, &mut c) {
        m.cull = Cull::ALL[c];
        changed = true;
    }
    let winding: Vec<String> = Winding::WORDS.iter().map(|w| w.to_string()).collect();
    let mut k = Winding::ALL
        .iter()
        .position(|&x| x == m.winding)
        .unwrap_or(0);
    if choose(ui, "front faces wind", ("winding", i), &winding, &mut k) {
        m.winding = Winding::ALL[k];
        changed = true;
    }
    changed
}

/// How a material samples its texture (notes 01 §5): the wrap rule along s
/// and along t, and the filter; true when one changed.
pub(super) fn sampling(ui: &mut egui::Ui, i: usize, m: &mut Material) -> bool {
    let mut changed = false;
    let wraps: Vec<String> = Wrap::WORDS.iter().map(|w| w.to_string()).collect();
    for (axis, label) in [(0, "wrap s (u)"), (1, "wrap t (v)")] {
        let mut k = Wrap::ALL
            .iter()
            .position(|&x| x == m.texturing.wrap[axis])
            .unwrap_or(0);
        if choose(ui, label, (label, i), &wraps, &mut k) {
            m.texturing.wrap[axis] = Wrap::ALL[k];
            changed = true;
        }
    }
    let filters: Vec<String> = TextureFilter::WORDS.iter().map(|w| w.to_string()).collect();
    let mut k = TextureFilter::ALL
        .iter()
        .position(|&x| x == m.texturing.filter)
        .unwrap_or(0);
    if choose(
        ui,
        "material filter",
        ("material filter", i),
        &filters,
        &mut k,
    ) {
        m.texturing.filter = TextureFilter::ALL[k];
        changed = true;
    }
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

/// The `[[billboards]]` (centre, size, kind) and `[[billboard_fields]]`
/// (count, seed, area, ground, heights, aspect, kind); Some((list, fields))
/// when one changed.
pub fn billboards(
    ui: &mut egui::Ui,
    scene: &Scene,
) -> Option<(Vec<BillboardFile>, Vec<BillboardFieldFile>)> {
    if scene.billboard_list.is_empty() && scene.billboard_fields.is_empty() {
        return None;
    }
    let (mut list, mut fields) = (scene.billboard_list.clone(), scene.billboard_fields.clone());
    let mut changed = false;
    let kind = |ui: &mut egui::Ui, k: &mut BillboardKind| {
        ui.horizontal_wrapped(|ui| {
            ui.label("kind");
            let mut c = false;
            for (v, w) in BillboardKind::ALL.iter().zip(BillboardKind::WORDS) {
                c |= ui.selectable_value(k, *v, *w).changed();
            }
            c
        })
        .inner
    };
    egui::CollapsingHeader::new(format!("Billboards ({})", scene.billboards.len()))
        .default_open(false)
        .show(ui, |ui| {
            for (i, b) in list.iter_mut().enumerate() {
                ui.push_id(("billboard", i), |ui| {
                    ui.label(format!("billboard {i}: {}", b.sprite));
                    let mut c = Vec3::from(b.center);
                    if vec3(ui, "  centre", &mut c, -1e4..=1e4) {
                        b.center = c.to_array();
                        changed = true;
                    }
                    for (k, name) in [(0, "  width"), (1, "  height")] {
                        changed |= number(ui, name, &mut b.size[k], 1e-3..=1e3);
                    }
                    changed |= kind(ui, &mut b.kind);
                });
            }
            for (i, g) in fields.iter_mut().enumerate() {
                ui.push_id(("field", i), |ui| {
                    ui.label(format!("field {i}: {}", g.sprite));
                    ui.horizontal(|ui| {
                        ui.label("  count");
                        changed |= ui
                            .add(egui::DragValue::new(&mut g.count).range(0..=20_000))
                            .changed();
                        ui.label("seed");
                        changed |= ui.add(egui::DragValue::new(&mut g.seed)).changed();
                    });
                    ui.horizontal(|ui| {
                        ui.label("  area x0 x1 z0 z1");
                        for c in &mut g.area {
                            changed |= ui.add(egui::DragValue::new(c).speed(0.05)).changed();
                        }
                    });
                    changed |= number(ui, "  ground", &mut g.ground, -1e4..=1e4);
                    ui.horizontal(|ui| {
                        ui.label("  height");
                        for c in &mut g.height {
                            changed |= ui
                                .add(egui::DragValue::new(c).range(1e-3..=1e3).speed(0.01))
                                .changed();
                        }
                    });
                    changed |= number(ui, "  aspect", &mut g.aspect, 1e-3..=100.0);
                    changed |= kind(ui, &mut g.kind);
                });
            }
        });
    changed.then_some((list, fields))
}
