//! A glTF 2.0 scene under one `[[objects]]` entry (`mesh = "x.gltf"` or
//! `"x.glb"`): every node of the file becomes a gloss object, a child of
//! its parent node's object, the top nodes children of the entry's own
//! object, so frustum culling, sorting, shadows and mirrors see each one.
//!
//! ```toml
//! [[objects]]
//! name = "box"
//! mesh = "assets/box_animated.gltf"
//! clip = "spin"        # the node animation played (default: the file's first; "none")
//! material = "red"     # optional: every primitive takes this material instead
//! ```
//!
//! A node's object is named `ENTRY/NODE` (`box/lid`; `ENTRY/node3` for a
//! node without a name, `#3` added when a name repeats). Its local
//! transform is the node's translation, rotation and scale; a node with a
//! mesh draws its first triangle primitive, and each further primitive is
//! a child object of it (`box/lid.1`, ...) at the same place. The entry's
//! object and the nodes without a mesh draw nothing; a node with nothing
//! drawn at or below it (a skin's joints, an empty chain) is no object. A skinned file's
//! entry object is the skin (src/scene/skins.rs), posed in the file's
//! scene space, so the nodes above it stay in place. Node animations play
//! through gloss's keyframe tracks (src/scene/animation.rs), at the
//! scene's time. The materials map onto gloss's (`gltf_material`);
//! docs/gltf.md has the whole mapping and what is left out.

use super::animation::{ObjectTracks, Pose};
use super::file::ObjectFile;
use super::skins::Loaded;
use super::{Material, MeshSource, Object};
use crate::geometry::skin::ChannelTrack;
use crate::geometry::{GltfScene, MeshData, Vertex};
use anyhow::{Result, bail};
use glam::{Mat4, Vec3};
use std::collections::{HashMap, HashSet};
use std::hash::{Hash, Hasher};
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// The most objects all glTF entries of a scene may make together.
pub const MAX_GLTF_OBJECTS: usize = 400_000;

/// One primitive of a glTF file (`mesh`, `primitive`), or a node that draws
/// nothing (`mesh == GltfPart::GROUP`). Equal and hashed by file, mesh and
/// primitive: the draw list uploads each once.
#[derive(Clone)]
pub struct GltfPart {
    pub path: PathBuf,
    pub mesh: usize,
    pub primitive: usize,
    pub data: Arc<MeshData>,
    /// What reading the file warned about (shared by its parts).
    pub warnings: Arc<Vec<String>>,
}

impl GltfPart {
    pub const GROUP: usize = usize::MAX;

    /// A part that draws nothing: one triangle of zero area at the origin
    /// (every object has a mesh; this one covers no pixel and no ray hits it).
    pub fn group(path: &Path, warnings: Arc<Vec<String>>) -> GltfPart {
        let v = Vertex {
            position: [0.0; 3],
            normal: [0.0, 1.0, 0.0],
            uv: [0.0; 2],
            tangent: [1.0, 0.0, 0.0, 1.0],
        };
        GltfPart {
            path: path.to_path_buf(),
            mesh: GltfPart::GROUP,
            primitive: 0,
            data: Arc::new(MeshData {
                vertices: vec![v; 3],
                indices: vec![0, 1, 2],
                colors: Vec::new(),
            }),
            warnings,
        }
    }
}

/// The file and the part, never the triangles (messages quote it).
impl std::fmt::Debug for GltfPart {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        match self.mesh {
            GltfPart::GROUP => write!(f, "{} (a node)", self.path.display()),
            m => write!(
                f,
                "{} mesh {m} primitive {}",
                self.path.display(),
                self.primitive
            ),
        }
    }
}

impl PartialEq for GltfPart {
    fn eq(&self, o: &GltfPart) -> bool {
        (&self.path, self.mesh, self.primitive) == (&o.path, o.mesh, o.primitive)
    }
}
impl Eq for GltfPart {}
impl Hash for GltfPart {
    fn hash<H: Hasher>(&self, h: &mut H) {
        (&self.path, self.mesh, self.primitive).hash(h)
    }
}

/// The tracks that play the files' node animations, and the rest pose of
/// each object they move.
pub(super) struct GltfAnimation {
    pub tracks: Vec<ObjectTracks>,
    pub rest: Vec<(usize, Pose)>,
}

/// Add the objects of every glTF entry (`files[e]` made `objects[e]`) and
/// the materials they use; returns their animation tracks.
pub(super) fn expand(
    files: &[ObjectFile],
    objects: &mut Vec<Object>,
    materials: &mut Vec<Material>,
    loaded: &Loaded,
) -> Result<GltfAnimation> {
    let mut names: HashSet<String> = objects.iter().map(|o| o.name.clone()).collect();
    // (file, its material) -> index in `materials`.
    let mut file_materials: HashMap<(PathBuf, usize), usize> = HashMap::new();
    let mut anim = GltfAnimation {
        tracks: Vec::new(),
        rest: Vec::new(),
    };
    let entries = objects.len().min(files.len());
    for e in 0..entries {
        let path = match &objects[e].mesh {
            MeshSource::Gltf(p) => p.clone(),
            MeshSource::GltfPart(p) if p.mesh == GltfPart::GROUP => p.path.clone(),
            _ => continue,
        };
        let Some(scene) = loaded.get(&path) else {
            continue;
        };
        let key = |k: &str| format!("objects[{e}].{k}");
        if objects.len() + scene.nodes.len() > MAX_GLTF_OBJECTS {
            bail!(
                "{}: the glTF files make more than {MAX_GLTF_OBJECTS} objects in all, the limit",
                key("mesh")
            );
        }
        let mapped = super::gltf_material::materials(&scene, &path);
        let entry_material = objects[e].material;
        let overridden = files[e].material.is_some();
        // Each of the file's materials is added once, when a part uses it
        // (so no unused material is warned about); None: glTF's default.
        let mut material_of = |m: Option<usize>| -> usize {
            if overridden {
                return entry_material;
            }
            let k = m.unwrap_or(scene.materials.len());
            *file_materials.entry((path.clone(), k)).or_insert_with(|| {
                materials.push(mapped[k].clone());
                materials.len() - 1
            })
        };
        if let Some((_, m)) = &scene.skin
            && !overridden
        {
            objects[e].material = material_of(*m);
        }
        let warnings = match &objects[e].mesh {
            MeshSource::GltfPart(p) => p.warnings.clone(),
            _ => objects[e]
                .skin
                .as_ref()
                .map_or_else(Default::default, |s| s.warnings.clone()),
        };
        let entry_name = objects[e].name.clone();
        let prims_of = |i: usize| -> &[crate::geometry::GltfPrimitive] {
            let n = &scene.nodes[i];
            match n.mesh {
                Some(m) if !n.skinned => &scene.meshes[m],
                _ => &[],
            }
        };
        // A node is an object when it or a node below it draws something
        // (a skin's joints alone are posed by the skin).
        let mut keep = vec![false; scene.nodes.len()];
        for &i in scene.order.iter().rev() {
            keep[i] |= !prims_of(i).is_empty();
            if let (true, Some(p)) = (keep[i], scene.nodes[i].parent) {
                keep[p] = true;
            }
        }
        let mut node_object: Vec<Option<usize>> = vec![None; scene.nodes.len()];
        for &i in &scene.order {
            if !keep[i] {
                continue;
            }
            let n = &scene.nodes[i];
            let parent = n.parent.and_then(|p| node_object[p]).unwrap_or(e);
            let prims = prims_of(i);
            let name = unique(&mut names, format!("{entry_name}/{}", n.name), i);
            let part = |k: usize| match prims.get(k) {
                Some(p) => MeshSource::GltfPart(GltfPart {
                    path: path.clone(),
                    mesh: n.mesh.unwrap_or_default(),
                    primitive: k,
                    data: p.data.clone(),
                    warnings: warnings.clone(),
                }),
                None => MeshSource::GltfPart(GltfPart::group(&path, warnings.clone())),
            };
            let material = prims.first().map_or(0, |p| material_of(p.material));
            node_object[i] = Some(objects.len());
            objects.push(object(name.clone(), part(0), material, Some(parent)));
            let o = objects.last_mut().unwrap();
            o.position = n.translation;
            o.orientation = Some(n.rotation);
            o.scale = n.scale;
            for (k, p) in prims.iter().enumerate().skip(1) {
                let sub = unique(&mut names, format!("{name}.{k}"), i);
                let parent = node_object[i];
                objects.push(object(sub, part(k), material_of(p.material), parent));
            }
        }
        node_tracks(e, &files[e], &scene, &node_object, objects, &mut anim)?;
    }
    Ok(anim)
}

/// `base`, or `base#i` when another object has that name.
fn unique(names: &mut HashSet<String>, base: String, i: usize) -> String {
    let name = if names.contains(&base) {
        format!("{base}#{i}")
    } else {
        base
    };
    names.insert(name.clone());
    name
}

fn object(name: String, mesh: MeshSource, material: usize, parent: Option<usize>) -> Object {
    Object {
        name,
        mesh,
        material,
        position: Vec3::ZERO,
        rotation: Vec3::ZERO,
        scale: Vec3::ONE,
        parent,
        model: Mat4::IDENTITY,
        mirror: None,
        orientation: None,
        skin: None,
        light_map: None,
    }
}

/// The clip the entry plays (`clip`, default the file's first) as tracks
/// on its nodes' objects.
fn node_tracks(
    e: usize,
    file: &ObjectFile,
    scene: &GltfScene,
    node_object: &[Option<usize>],
    objects: &[Object],
    anim: &mut GltfAnimation,
) -> Result<()> {
    let clip = match file.clip.as_deref() {
        None => 0,
        Some("none") => return Ok(()),
        Some(name) => match scene.clips.iter().position(|c| c.name == name) {
            Some(c) => c,
            None => {
                let names: Vec<String> = scene
                    .clips
                    .iter()
                    .map(|c| format!("\"{}\"", c.name))
                    .collect();
                bail!(
                    "objects[{e}].clip: {} has no animation named \"{name}\"; it has {} (or \"none\")",
                    file.mesh,
                    if names.is_empty() {
                        "none".to_owned()
                    } else {
                        names.join(", ")
                    }
                );
            }
        },
    };
    let Some(c) = scene.clips.get(clip) else {
        return Ok(());
    };
    let mut by_object: HashMap<usize, ObjectTracks> = HashMap::new();
    for ch in &c.channels {
        let Some(&Some(object)) = node_object.get(ch.node) else {
            continue;
        };
        let t = by_object.entry(object).or_insert_with(|| ObjectTracks {
            object,
            clip: c.name.clone(),
            weight: 1.0,
            position: None,
            rotation: None,
            scale: None,
        });
        match &ch.track {
            ChannelTrack::Translation(k) => t.position = Some(k.clone()),
            ChannelTrack::Rotation(k) => t.rotation = Some(k.clone()),
            ChannelTrack::Scale(k) => t.scale = Some(k.clone()),
        }
    }
    let mut tracks: Vec<ObjectTracks> = by_object.into_values().collect();
    tracks.sort_by_key(|t| t.object);
    for t in &tracks {
        let o = &objects[t.object];
        let rotation = o.orientation.unwrap_or_default();
        let pose = Pose {
            position: o.position,
            rotation,
            scale: o.scale,
        };
        anim.rest.push((t.object, pose));
    }
    anim.tracks.extend(tracks);
    Ok(())
}

/// The file named by a glTF entry, loaded once (None: not a glTF entry).
impl Loaded {
    pub(super) fn get(&self, path: &Path) -> Option<Arc<GltfScene>> {
        self.0.get(path).map(|l| l.0.clone())
    }
}
