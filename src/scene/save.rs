//! "Save as": the scene file as loaded, with the panel's edits written into
//! it (every render knob, the light grid's count, the listed lights, the
//! materials' colours, shininess, opacity and depth test, the objects' transforms, the camera),
//! so that the saved file
//! loads to the same scene. Paths to meshes and textures are rewritten to
//! stay valid from the new file's folder: absolute for files on disk,
//! `embedded:scenes/...` for a shipped scene's assets.

use super::{Camera, Light, LightKind, MeshSource, Projection, Scene, knobs, read_text, shadows};
use crate::assets;
use anyhow::{Context as _, Result, anyhow};
use std::path::Path;

impl Scene {
    /// The TOML text of this scene, as `save_as` writes it.
    pub fn to_toml(&self) -> Result<String> {
        let text = read_text(&self.path)?;
        let mut table: toml::Table = toml::from_str(&text)
            .map_err(|e| anyhow!("{}: {}", self.path.display(), e.to_string().trim_end()))?;
        let render = table
            .entry("render")
            .or_insert_with(|| toml::Value::Table(toml::Table::new()))
            .as_table_mut()
            .ok_or_else(|| anyhow!("{}: render is not a table", self.path.display()))?;
        for k in knobs::ALL {
            let (_, key) = k.key.split_once('.').expect("render.key");
            let v: toml::Table = toml::from_str(&format!("v = {}", k.toml(&self.render)))
                .expect("a knob writes valid TOML");
            render.insert(key.to_string(), v["v"].clone());
        }
        super::ambient_occlusion::save(&self.render, &mut table);
        // The light grid as it is now (the demo edits every parameter).
        if let Some(g) = &self.light_grid {
            let mut grid = toml::Table::new();
            grid.insert("count".into(), toml::Value::Integer(g.count as i64));
            grid.insert("seed".into(), toml::Value::Integer(g.seed as i64));
            grid.insert("area".into(), floats(&g.area));
            grid.insert("height".into(), floats(&g.height));
            grid.insert("intensity".into(), toml::Value::Float(g.intensity.into()));
            grid.insert("attenuation".into(), floats(&g.attenuation));
            table.insert("light_grid".into(), toml::Value::Table(grid));
        }
        // The camera as it is now (the demo saves its current view).
        table.insert("camera".into(), camera_table(&self.camera));
        // The lights the file lists (not the grid's), as they are now.
        let fixed = self.lights.len() - self.grid_lights.unwrap_or(0);
        let lights: Vec<toml::Value> = self.lights[..fixed].iter().map(light_table).collect();
        if !lights.is_empty() {
            table.insert("lights".into(), toml::Value::Array(lights));
        }
        // The materials' colours and shininess, as they are now (index 0 is
        // gloss's default material, not in the file).
        if let Some(materials) = table
            .get_mut("materials")
            .and_then(toml::Value::as_table_mut)
        {
            for m in self.materials.iter().skip(1) {
                if let Some(t) = materials
                    .get_mut(&m.name)
                    .and_then(toml::Value::as_table_mut)
                {
                    t.insert("diffuse".into(), vec3(m.diffuse));
                    // Phong's terms, or notes 03's microfacet triple.
                    match &m.microfacet {
                        None => {
                            t.insert("specular".into(), vec3(m.specular));
                            t.insert("shininess".into(), toml::Value::Float(m.shininess.into()));
                            for k in ["model", "alpha", "eta", "k_s"] {
                                t.remove(k);
                            }
                        }
                        Some(mf) => {
                            t.remove("specular");
                            t.remove("shininess");
                            t.insert("model".into(), "microfacet".into());
                            t.insert("alpha".into(), toml::Value::Float(mf.alpha.into()));
                            t.insert("eta".into(), toml::Value::Float(mf.eta.into()));
                            t.insert("k_s".into(), toml::Value::Float(mf.k_s.into()));
                        }
                    }
                    t.insert("opacity".into(), toml::Value::Float(m.opacity.into()));
                    t.insert("reflectivity".into(), m.reflectivity.into());
                    t.insert("alpha_test".into(), m.alpha_test.name().into());
                    t.insert("alpha_ref".into(), toml::Value::Float(m.alpha_ref.into()));
                    match &m.diffuse_texture {
                        Some(p) => t.insert("diffuse_texture".into(), path(p)),
                        None => t.remove("diffuse_texture"),
                    };
                    match m.depth_func {
                        Some(f) => t.insert("depth_func".into(), f.name().into()),
                        None => t.remove("depth_func"),
                    };
                    match m.winding {
                        crate::scene::Winding::Ccw => t.remove("winding"),
                        w => t.insert("winding".into(), w.name().into()),
                    };
                    match m.cull {
                        crate::scene::Cull::Back => t.remove("cull"),
                        c => t.insert("cull".into(), c.name().into()),
                    };
                    // The sampling the demo edits (notes 01 §5), where not the default.
                    let default = crate::scene::texturing::Texturing::default();
                    if m.texturing.wrap == default.wrap {
                        t.remove("wrap");
                    } else {
                        let [s, w] = m.texturing.wrap.map(|w| toml::Value::from(w.name()));
                        t.insert("wrap".into(), toml::Value::Array(vec![s, w]));
                    }
                    match m.texturing.filter {
                        f if f == default.filter => t.remove("filter"),
                        f => t.insert("filter".into(), f.name().into()),
                    };
                }
            }
        }
        // The objects' local transforms, meshes, materials and parents, as
        // they are now (material 0 is gloss's default, named by no key).
        if let Some(objects) = table.get_mut("objects").and_then(toml::Value::as_array_mut) {
            for (t, o) in objects.iter_mut().zip(&self.objects) {
                if let Some(t) = t.as_table_mut() {
                    t.insert("position".into(), vec3(o.position));
                    t.insert("rotation".into(), vec3(o.rotation));
                    t.insert("scale".into(), vec3(o.scale));
                    let mesh = match &o.mesh {
                        MeshSource::Obj(p) | MeshSource::Gltf(p) | MeshSource::ObjPart(p, _) => {
                            path(p)
                        }
                        MeshSource::GltfPart(part) => path(&part.path),
                        builtin => format!("{builtin:?}").to_lowercase().into(),
                    };
                    t.insert("mesh".into(), mesh);
                    if let Some(s) = &o.skin {
                        t.insert("skinning".into(), s.method.name().into());
                        let clip = s.clip.map_or("none", |c| s.mesh.clips[c].name.as_str());
                        t.insert("clip".into(), clip.into());
                    }
                    match o.material {
                        // The OBJ's own materials (src/scene/obj_materials.rs).
                        _ if matches!(o.mesh, MeshSource::ObjPart(..)) => t.remove("material"),
                        0 => t.remove("material"),
                        i => t.insert("material".into(), self.materials[i].name.clone().into()),
                    };
                    match o.parent {
                        None => t.remove("parent"),
                        Some(p) => t.insert("parent".into(), self.objects[p].name.clone().into()),
                    };
                    if let (Some(m), Some(mt)) = (
                        &o.mirror,
                        t.get_mut("mirror").and_then(toml::Value::as_table_mut),
                    ) {
                        mt.insert("tint".into(), vec3(m.tint));
                        mt.insert(
                            "reflectance".into(),
                            toml::Value::Float(m.reflectance.into()),
                        );
                        mt.insert("infinite".into(), m.infinite.into());
                        mt.insert("covered".into(), m.covered.into());
                    }
                }
            }
        }
        // The billboards and billboard fields, as they are now.
        for (key, list) in [
            ("billboards", toml::Value::try_from(&self.billboard_list)),
            (
                "billboard_fields",
                toml::Value::try_from(&self.billboard_fields),
            ),
        ] {
            match list.context("writing the billboards")? {
                toml::Value::Array(a) if a.is_empty() => table.remove(key),
                v => table.insert(key.into(), v),
            };
        }
        // The post chain, as it is now.
        if self.post.is_empty() {
            table.remove("post");
        } else {
            let entries = self.post.iter().map(|p| toml::Value::Table(p.table()));
            table.insert("post".into(), toml::Value::Array(entries.collect()));
        }
        // The split views' rectangles, as they are now.
        if let Some(views) = table.get_mut("views").and_then(toml::Value::as_array_mut) {
            for (t, v) in views.iter_mut().zip(&self.views) {
                if let Some(t) = t.as_table_mut() {
                    t.insert("viewport".into(), floats(&v.viewport));
                }
            }
        }
        let base = self.path.parent().unwrap_or(Path::new(""));
        let fix = |v: &mut toml::Value| {
            if let Some(s) = v.as_str()
                && !s.starts_with(assets::EMBEDDED)
            {
                let p = base.join(s);
                let p = match p.canonicalize() {
                    Ok(abs) => abs,
                    Err(_) => p,
                };
                *v = toml::Value::String(p.to_string_lossy().into_owned());
            }
        };
        if let Some(materials) = table
            .get_mut("materials")
            .and_then(toml::Value::as_table_mut)
        {
            for (_, m) in materials.iter_mut() {
                for key in ["diffuse_texture", "normal_map", "height_map"] {
                    if let Some(t) = m.get_mut(key) {
                        fix(t);
                    }
                }
            }
        }
        if let Some(objects) = table.get_mut("objects").and_then(toml::Value::as_array_mut) {
            for o in objects {
                if let Some(m) = o
                    .get_mut("mesh")
                    .filter(|m| m.as_str().is_some_and(|s| assets::has_extension(s, "obj")))
                {
                    fix(m);
                }
                if let Some(r) = o.get_mut("mirror").and_then(|m| m.get_mut("roughness")) {
                    fix(r);
                }
            }
        }
        // The skybox's faces.
        let faces = table.get_mut("skybox").and_then(|s| s.get_mut("faces"));
        for f in faces
            .and_then(toml::Value::as_array_mut)
            .into_iter()
            .flatten()
        {
            fix(f);
        }
        // Billboard sprites (`[[billboards]]`, `[[billboard_fields]]`).
        for list in ["billboards", "billboard_fields"] {
            if let Some(items) = table.get_mut(list).and_then(toml::Value::as_array_mut) {
                for b in items {
                    if let Some(s) = b.get_mut("sprite") {
                        fix(s);
                    }
                }
            }
        }
        toml::to_string(&table).context("writing the scene as TOML")
    }

    /// Write `to_toml` to `dest`, through a temporary file so that a failed
    /// write leaves an existing file as it was.
    pub fn save_as(&self, dest: &Path) -> Result<()> {
        let text = self.to_toml()?;
        crate::assets::write::write_file(dest, text.as_bytes())
    }
}

fn vec3(v: glam::Vec3) -> toml::Value {
    toml::Value::Array(
        v.to_array()
            .iter()
            .map(|&x| toml::Value::Float(x.into()))
            .collect(),
    )
}

/// One light as a `[[lights]]` table with every key written out.
fn light_table(l: &Light) -> toml::Value {
    let mut t = toml::Table::new();
    let kind = match l.kind {
        LightKind::Directional => "directional",
        LightKind::Point => "point",
        LightKind::Spot => "spot",
    };
    t.insert("type".into(), toml::Value::String(kind.into()));
    if l.kind != LightKind::Directional {
        t.insert("position".into(), vec3(l.position));
        t.insert(
            "attenuation".into(),
            vec3(glam::Vec3::new(l.kc, l.kl, l.kq)),
        );
    }
    if l.kind != LightKind::Point {
        t.insert("direction".into(), vec3(l.direction));
    }
    t.insert("color".into(), vec3(l.color));
    t.insert("intensity".into(), toml::Value::Float(l.intensity.into()));
    if l.kind == LightKind::Spot {
        t.insert(
            "inner_angle".into(),
            toml::Value::Float(l.inner_angle.into()),
        );
        t.insert(
            "outer_angle".into(),
            toml::Value::Float(l.outer_angle.into()),
        );
    }
    if let Some(s) = &l.shadow {
        t.insert(
            "shadow".into(),
            toml::Value::Table(shadows::shadow_table(s)),
        );
    }
    toml::Value::Table(t)
}

/// The `[camera]` table, every key written out.
fn camera_table(c: &Camera) -> toml::Value {
    let mut t = toml::Table::new();
    let f = |x: f32| toml::Value::Float(x.into());
    match c.projection {
        Projection::Perspective { fov_y_degrees } => {
            t.insert(
                "projection".into(),
                toml::Value::String("perspective".into()),
            );
            t.insert("fov_y".into(), f(fov_y_degrees));
        }
        Projection::Orthographic { half_height } => {
            t.insert(
                "projection".into(),
                toml::Value::String("orthographic".into()),
            );
            t.insert("half_height".into(), f(half_height));
        }
    }
    t.insert("eye".into(), vec3(c.eye));
    t.insert("target".into(), vec3(c.target));
    t.insert("up".into(), vec3(c.up));
    t.insert("near".into(), f(c.near));
    t.insert("far".into(), f(c.far));
    toml::Value::Table(t)
}

/// A TOML array of floats.
fn floats(v: &[f32]) -> toml::Value {
    toml::Value::Array(v.iter().map(|&x| toml::Value::Float(x.into())).collect())
}

/// A path the loader resolved (relative to the working directory, or
/// embedded) as TOML text that stays valid from any folder: absolute, or
/// embedded.
fn path(p: &std::path::Path) -> toml::Value {
    let p = p.canonicalize().unwrap_or_else(|_| p.to_path_buf());
    p.to_string_lossy().into_owned().into()
}
