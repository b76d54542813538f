//! Checking a parsed scene file and turning it into a [`Scene`]: every value
//! is validated (errors name the key and what was expected), names are
//! resolved to indices and object matrices are chained through their parents.
//! One function per section of the file, in the order they are checked.

use super::file::SceneFile;
use super::{Material, MeshSource, Object, Scene};
use crate::assets;
use anyhow::{Result, anyhow, bail};
use glam::Vec3;
use std::collections::HashMap;
use std::path::Path;

use super::checks::{finite, non_negative, relative_to};

/// Checks every section of `f` (read from `path`) and builds the [`Scene`].
pub(super) fn resolve(mut f: SceneFile, path: &Path) -> Result<Scene> {
    super::meshes::forget_obj_files();
    // The fields' objects, after the file's own.
    let generated = super::object_fields::expand(&f.object_fields)?;
    let file_objects = f.objects.len();
    f.objects.extend(generated);
    let base = path.parent().unwrap_or(Path::new("."));
    let name = f.name.clone().unwrap_or_else(|| {
        path.file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default()
    });

    let camera = super::views::camera(&f.camera, "camera")?;
    let views = super::views::views(&f, base)?;
    let render = super::render_settings::render_settings(&f)?;
    let lights = super::lights::lights(&f)?;
    let (mut materials, material_index) = materials(&f, base)?;
    let (mut objects, file_warnings, loaded) =
        objects(&f, &material_index, &mut materials, base)
            .map_err(|e| super::object_fields::name_field(e, file_objects, &f))?;
    // Each glTF file's nodes, as children of its entry.
    let gltf = super::gltf_objects::expand(&f.objects, &mut objects, &mut materials, &loaded)?;
    if !gltf.tracks.is_empty() || objects.len() > f.objects.len() {
        super::update_models(&mut objects);
    }
    let mirrors = objects.iter().filter(|o| o.mirror.is_some()).count();
    if mirrors > 0 && !views.is_empty() {
        bail!(
            "views: a scene with [[views]] cannot also have mirrors (each orders the frame its own way)"
        );
    }
    // Each mirror has its own stencil value and one more per level inside it.
    if mirrors * (render.mirror_depth as usize + 1) > 255 {
        bail!(
            "{mirrors} mirrors x (render.mirror_depth {} + 1) stencil values do not fit in 8 stencil bits (255)",
            render.mirror_depth
        );
    }
    if render.mirror_order == super::MirrorOrder::ReflectedFirst
        && (mirrors > 1 || render.mirror_depth > 1)
    {
        bail!(
            "render.mirror_order: \"reflected_first\" draws one mirror and no mirror in a mirror (notes 05, \"Reflected Scene First (issues)\"); this scene has {mirrors} mirrors and mirror_depth = {}: use \"normal_first\"",
            render.mirror_depth
        );
    }
    let (sprites, billboards) =
        super::billboards::expand(&f.billboards, &f.billboard_fields, base)?;
    let post = super::post::chain(&f.post)?;

    let mut animation = super::animation::resolve(&f.animation, &objects)?;
    let moved: std::collections::HashSet<usize> = animation.rest.iter().map(|r| r.0).collect();
    animation.tracks.extend(gltf.tracks);
    animation
        .rest
        .extend(gltf.rest.into_iter().filter(|r| !moved.contains(&r.0)));
    let outlines = super::outlines::resolve(f.outlines.as_ref(), &objects)?;
    if outlines.is_some() && mirrors * (render.mirror_depth as usize + 1) > 127 {
        bail!(
            "outlines: the outline takes the stencil's top bit; {mirrors} mirrors x (render.mirror_depth {} + 1) stencil values do not fit in the 7 bits left (127)",
            render.mirror_depth
        );
    }
    let mut scene = Scene {
        name,
        path: path.to_path_buf(),
        grid_lights: f.light_grid.as_ref().map(|g| g.count),
        light_grid: f.light_grid.clone(),
        camera,
        views,
        render,
        lights,
        area_lights: super::area_lights::resolve(&f.area_lights)?,
        materials,
        objects,
        sprites,
        billboards,
        billboard_list: f.billboards.clone(),
        billboard_fields: f.billboard_fields.clone(),
        post,
        animation,
        tessellation: super::tessellation::resolve(f.tessellation.as_ref(), base)?,
        particles: super::particles::resolve(f.particles.as_ref())?,
        outlines,
        instancing: super::instancing::resolve(f.instancing.as_ref())?,
        clip_planes: super::clip_planes::clip_planes(&f.clip_planes)?,
        sky: super::sky::sky(&f.sky)?,
        skybox: super::skybox::skybox(&f.skybox, f.sky.is_some(), base)?,
        keys_written: Default::default(),
        file_warnings,
    };
    // The instant the file asks for.
    super::skybox::check_reflective(&scene)?;
    scene.set_time(scene.animation.time)?;
    // Mirrors in mirrors: bounded before any view is made.
    super::mirror_views::check(&scene)?;
    Ok(scene)
}

/// Materials (sorted by name so indices are stable); also returns the index
/// of each material by name.
fn materials(f: &SceneFile, base: &Path) -> Result<(Vec<Material>, HashMap<String, usize>)> {
    let mut names: Vec<&String> = f.materials.keys().collect();
    names.sort();
    let mut materials = vec![Material::default()];
    let mut material_index = HashMap::new();
    for n in names {
        let m = &f.materials[n];
        let key = |k: &str| format!("materials.{n}.{k}");
        for (k, v) in [("diffuse", &m.diffuse), ("specular", &m.specular)] {
            non_negative(&key(k), v)?;
            // A surface reflects at most the light it gets, and the
            // G-buffer stores its colours in 8 bits, 0..=1.
            if v.iter().any(|x| *x > 1.0) {
                bail!(
                    "{}: expected reflectances in 0..=1 (a surface reflects at most the light \
                     it gets; the G-buffer stores them in 8 bits), found {v:?}",
                    key(k)
                );
            }
        }
        if !(m.shininess.is_finite() && m.shininess >= 1.0 && m.shininess <= 4096.0) {
            bail!(
                "{}: expected a number in 1..=4096, found {}",
                key("shininess"),
                m.shininess
            );
        }
        if !(m.alpha_ref.is_finite() && (0.0..=1.0).contains(&m.alpha_ref)) {
            bail!(
                "{}: expected a number in 0..=1, found {}",
                key("alpha_ref"),
                m.alpha_ref
            );
        }
        if !(m.opacity.is_finite() && (0.0..=1.0).contains(&m.opacity)) {
            bail!(
                "{}: expected a number in [0, 1] (1 = opaque), found {}",
                key("opacity"),
                m.opacity
            );
        }
        let texture = |k: &str, t: &Option<String>| -> Result<Option<std::path::PathBuf>> {
            let Some(t) = t else { return Ok(None) };
            let p = relative_to(base, t);
            if let Some(why) = assets::not_a_file(&p) {
                bail!("{}: file {} {why}", key(k), p.display());
            }
            Ok(Some(p))
        };
        let diffuse_texture = texture("diffuse_texture", &m.diffuse_texture)?;
        let normal_map = texture("normal_map", &m.normal_map)?;
        let height_map = texture("height_map", &m.height_map)?;
        let height_scale = m.height_scale.unwrap_or(Material::default().height_scale);
        if !(height_scale.is_finite() && (0.0..=1.0).contains(&height_scale)) {
            bail!(
                "{}: expected a depth in 0..=1 texture uv units, found {height_scale}",
                key("height_scale")
            );
        }
        material_index.insert(n.clone(), materials.len());
        materials.push(Material {
            name: n.clone(),
            diffuse: Vec3::from(m.diffuse),
            diffuse_texture,
            normal_map,
            specular: Vec3::from(m.specular),
            shininess: m.shininess,
            microfacet: super::material::microfacet(n, m)?,
            alpha_test: m.alpha_test,
            alpha_ref: m.alpha_ref,
            opacity: m.opacity,
            reflectivity: super::skybox::reflectivity(n, m.reflectivity)?,
            depth_func: m.depth_func,
            cull: m.cull.unwrap_or(super::Cull::Back),
            winding: m.winding.unwrap_or(super::Winding::Ccw),
            texturing: super::material::texturing(n, m)?,
            height_map,
            height_scale,
            ..Material::default()
        });
    }
    Ok((materials, material_index))
}

/// Objects: local matrices first, then parents (in any order, no cycles).
fn objects(
    f: &SceneFile,
    material_index: &HashMap<String, usize>,
    materials: &mut Vec<Material>,
    base: &Path,
) -> Result<(Vec<Object>, Vec<String>, super::skins::Loaded)> {
    let mut locals = Vec::new();
    let mut object_names: HashMap<String, usize> = HashMap::new();
    let mut skins = super::skins::Loaded::default();
    for (i, o) in f.objects.iter().enumerate() {
        let key = |k: &str| format!("objects[{i}].{k}");
        finite(&key("position"), &o.position)?;
        finite(&key("rotation"), &o.rotation)?;
        finite(&key("scale"), &o.scale)?;
        super::camera_limits::within_world(&key("position"), &o.position)?;
        super::camera_limits::within_world(&key("scale"), &o.scale)?;
        let mesh = match o.mesh.as_str() {
            "sphere" => MeshSource::Sphere,
            "icosphere" => MeshSource::Icosphere,
            "cube" => MeshSource::Cube,
            "plane" => MeshSource::Plane,
            "cylinder" => MeshSource::Cylinder,
            "cone" => MeshSource::Cone,
            "torus" => MeshSource::Torus,
            file if assets::has_extension(file, "obj") => {
                let p = relative_to(base, file);
                if let Some(why) = assets::not_a_file(&p) {
                    bail!("{}: file {} {why}", key("mesh"), p.display());
                }
                MeshSource::Obj(p)
            }
            file if assets::has_extension(file, "glb") || assets::has_extension(file, "gltf") => {
                let p = relative_to(base, file);
                if let Some(why) = assets::not_a_file(&p) {
                    bail!("{}: file {} {why}", key("mesh"), p.display());
                }
                let (gltf, warnings) = skins.load(i, &p)?;
                if gltf.skin.is_some() {
                    MeshSource::Gltf(p)
                } else {
                    MeshSource::GltfPart(super::gltf_objects::GltfPart::group(&p, warnings))
                }
            }
            other => bail!(
                "{}: expected one of {} or a path to an .obj, .glb or .gltf file, found \"{other}\"",
                key("mesh"),
                MeshSource::BUILTIN
            ),
        };
        let material = match &o.material {
            None => 0,
            Some(m) => *material_index.get(m).ok_or_else(|| {
                anyhow!(
                    "{}: no material named \"{m}\" in [materials]",
                    key("material")
                )
            })?,
        };
        let name = o.name.clone().unwrap_or_else(|| format!("object{i}"));
        if object_names.insert(name.clone(), i).is_some() {
            bail!("{}: two objects are named \"{name}\"", key("name"));
        }
        let mirror = o
            .mirror
            .as_ref()
            .map(|m| super::mirrors::mirror(&key("mirror"), m, &mesh, base))
            .transpose()?;
        let skin = super::skins::object_skin(i, o, &mesh, &mut skins)?;
        locals.push((name, mesh, material, mirror, skin));
    }
    // Parents by index, then no cycle: one topological walk (a chain of
    // any length in linear time).
    let mut parents = Vec::with_capacity(f.objects.len());
    for (i, o) in f.objects.iter().enumerate() {
        let index = |p: &String| {
            object_names
                .get(p)
                .copied()
                .ok_or_else(|| anyhow!("objects[{i}].parent: no object named \"{p}\""))
        };
        parents.push(o.parent.as_ref().map(index).transpose()?);
    }
    if let Err(i) = super::hierarchy::parents_first(&parents) {
        bail!("objects[{i}].parent: the parent chain is a cycle");
    }
    let mut objects = Vec::new();
    for (i, o) in f.objects.iter().enumerate() {
        let parent = parents[i];
        objects.push(Object {
            name: locals[i].0.clone(),
            mesh: locals[i].1.clone(),
            material: locals[i].2,
            position: Vec3::from(o.position),
            rotation: Vec3::from(o.rotation),
            scale: Vec3::from(o.scale),
            parent,
            model: glam::Mat4::IDENTITY,
            mirror: locals[i].3.clone(),
            orientation: None,
            skin: locals[i].4.clone(),
            light_map: super::light_maps::light_map(i, o.light_map, &locals[i].1)?,
        });
    }
    // An OBJ with its own materials: one object per `usemtl` part.
    let mut extra = Vec::new();
    let mut warnings = Vec::new();
    let mut first = Vec::new();
    let taken = |n: &str| object_names.contains_key(n);
    for (i, o) in objects.iter_mut().enumerate() {
        let MeshSource::Obj(path) = o.mesh.clone() else {
            continue;
        };
        let own = f.objects[i].material.is_none();
        if !own || o.mirror.is_some() {
            continue;
        }
        if o.light_map.is_some() {
            warnings.push(format!(
                "objects[{i}]: an object with a light_map is one mesh: {}'s MTL materials are not used (give it a material)",
                path.display()
            ));
            continue;
        }
        let w =
            super::obj_materials::expand(o, i, &path, materials, &mut first, &mut extra, &taken)
                .map_err(|e| anyhow!("{}: {e:#}", format_args!("objects[{i}].mesh")))?;
        for w in w {
            if !warnings.contains(&w) {
                warnings.push(w);
            }
        }
    }
    objects.extend(extra);
    super::update_models(&mut objects);
    for (i, o) in objects.iter().enumerate() {
        if o.mirror.as_ref().is_some_and(|m| m.curved) {
            if o.curved_mirror().is_none() {
                bail!(
                    "objects[{i}]: a curved mirror must be scaled alike on every axis (a sphere), found scale {}",
                    o.scale
                );
            }
        } else if o.mirror.is_some() && o.mirror_plane().is_none() {
            bail!(
                "objects[{i}]: its scale flattens the mirror's normal to zero: the mirror has no plane"
            );
        }
    }
    Ok((objects, warnings, skins))
}
