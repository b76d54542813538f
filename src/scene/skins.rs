//! Skinned objects in a scene (notes 01 §7.1): an object whose mesh is a
//! glTF file gets the file's skin, skeleton and clips, loaded once per
//! file and shared, with the object's own method and clip:
//!
//! ```toml
//! [[objects]]
//! mesh = "assets/arm.glb"
//! skinning = "dual_quaternion"   # or "linear" (the default)
//! clip = "twist"                 # default: the file's first; "none": the rest pose
//! ```
//!
//! The scene's time (`[animation] time`, `--time`, the demo's clock) is the
//! clip's time; `render.skinning_on` says whether the GPU's skinning pass or
//! the CPU reference poses the skin.

use super::file::ObjectFile;
use super::{MeshSource, Scene, SkinMethod};
use crate::geometry::skin::SkinnedMesh;
use crate::geometry::{GltfScene, load_gltf_scene};
use anyhow::{Result, anyhow, bail};
use glam::Mat4;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// One object's skin.
#[derive(Clone, Debug)]
pub struct ObjectSkin {
    /// The file's skin, skeleton and clips (shared by the objects that use
    /// the same file).
    pub mesh: Arc<SkinnedMesh>,
    pub method: SkinMethod,
    /// The clip that poses it (None: the rest pose).
    pub clip: Option<usize>,
    /// What loading the file warned about (weights renormalised, ...).
    pub warnings: Arc<Vec<String>>,
}

impl PartialEq for ObjectSkin {
    fn eq(&self, other: &ObjectSkin) -> bool {
        Arc::ptr_eq(&self.mesh, &other.mesh)
            && self.method == other.method
            && self.clip == other.clip
    }
}

impl ObjectSkin {
    /// The joint matrices at `time` (seconds into the clip).
    pub fn joint_matrices(&self, time: f32) -> Vec<Mat4> {
        self.mesh.joint_matrices(self.clip, time)
    }

    /// The clip's name, or "rest pose".
    pub fn clip_name(&self) -> &str {
        self.clip
            .map_or("rest pose", |c| self.mesh.clips[c].name.as_str())
    }
}

/// The glTF files read so far while resolving a scene, each with its
/// warnings.
#[derive(Default)]
pub(super) struct Loaded(pub(super) HashMap<PathBuf, (Arc<GltfScene>, Arc<Vec<String>>)>);

impl Loaded {
    /// The file at `path` (for `objects[i].mesh`), read once.
    pub(super) fn load(
        &mut self,
        i: usize,
        path: &Path,
    ) -> Result<(Arc<GltfScene>, Arc<Vec<String>>)> {
        if let Some(l) = self.0.get(path) {
            return Ok(l.clone());
        }
        let scene = load_gltf_scene(path).map_err(|e| anyhow!("objects[{i}].mesh: {e:#}"))?;
        let warnings = Arc::new(scene.warnings.clone());
        let l = (Arc::new(scene), warnings);
        self.0.insert(path.to_path_buf(), l.clone());
        Ok(l)
    }
}

/// The skin of `objects[i]` (None: its mesh is no skinned glTF file, and
/// it must then not set `skinning`; `clip` is also for a static glTF file's
/// node animations).
pub(super) fn object_skin(
    i: usize,
    o: &ObjectFile,
    mesh: &MeshSource,
    loaded: &mut Loaded,
) -> Result<Option<ObjectSkin>> {
    let MeshSource::Gltf(path) = mesh else {
        let gltf = matches!(mesh, MeshSource::GltfPart(_));
        if o.skinning.is_some() || (o.clip.is_some() && !gltf) {
            bail!(
                "objects[{i}]: `skinning` and `clip` are for a skinned mesh (a .glb or .gltf file; `clip` also plays a glTF file's node animations), not mesh \"{}\"",
                o.mesh
            );
        }
        return Ok(None);
    };
    let (scene, warnings) = loaded.load(i, path)?;
    let Some((skinned, _)) = scene.skin.clone() else {
        bail!("objects[{i}].mesh: {} has no skin", path.display());
    };
    let clip = match o.clip.as_deref() {
        None => (!skinned.clips.is_empty()).then_some(0),
        Some("none") => None,
        Some(name) => match skinned.clip(name) {
            Some(c) => Some(c),
            None => {
                let names: Vec<String> = skinned
                    .clips
                    .iter()
                    .map(|c| format!("\"{}\"", c.name))
                    .collect();
                bail!(
                    "objects[{i}].clip: {} has no animation named \"{name}\"; it has {} (or \"none\": the rest pose)",
                    path.display(),
                    if names.is_empty() {
                        "none".to_owned()
                    } else {
                        names.join(", ")
                    }
                );
            }
        },
    };
    Ok(Some(ObjectSkin {
        mesh: skinned,
        method: o.skinning.unwrap_or(SkinMethod::Linear),
        clip,
        warnings,
    }))
}

impl Scene {
    /// The objects that are skinned, by index.
    pub fn skinned_objects(&self) -> Vec<usize> {
        (0..self.objects.len())
            .filter(|&i| self.objects[i].skin.is_some())
            .collect()
    }

    /// The span of the skinned objects' clips (None: no skinned object plays one).
    pub fn skin_span(&self) -> Option<(f32, f32)> {
        (self.objects.iter())
            .filter_map(|o| o.skin.as_ref())
            .filter_map(|s| s.clip.and_then(|c| s.mesh.clip_span(c)))
            .reduce(|a, b| (a.0.min(b.0), a.1.max(b.1)))
    }
}
