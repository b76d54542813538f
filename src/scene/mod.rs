//! Scene files (scenes/*.toml), read with serde + toml.
//!
//! Colours in a scene file are *linear* RGB, the values the lighting
//! equations use; textures are sRGB PNGs and are decoded to linear by the GPU.
//! Paths (meshes, textures) are relative to the scene file. Unknown keys and
//! bad values are errors that name the file, the key and what was expected.
//!
//! This folder: the scene types the renderer uses (here), the file format as
//! written in TOML (`file`), checking it and turning it into a [`Scene`]
//! (`resolve`), the seeded many-lights generator (`light_grid`), and the
//! triangles behind each mesh source (`meshes`).

mod alpha_test;
pub mod ambient_occlusion;
pub mod animation;
pub mod area_lights;
mod billboards;
pub mod bloom;
pub mod camera_limits;
mod checks;
pub mod clip_planes;
mod far_field;
mod file;
pub mod fxaa;
pub mod gltf_material;
pub mod gltf_objects;
pub mod hierarchy;
pub mod instancing;
pub mod knobs;
mod light_data;
mod light_grid;
mod light_maps;
mod lights;
pub mod material;
pub mod meshes;
pub mod mirror_views;
mod mirrors;
pub mod obj_materials;
mod object_field_file;
pub mod object_fields;
pub mod outlines;
mod overrides;
pub mod particles;
pub mod post;
mod post_entry;
mod render_settings;
mod resolve;
mod save;
mod settings;
pub mod shadows;
pub mod skins;
pub mod sky;
pub mod skybox;
pub mod tessellation;
mod text;
pub mod texturing;
mod views;
mod warnings;

pub use alpha_test::BILLBOARD_ALPHA_TEST;
pub use billboards::{Billboard, BillboardFieldFile, BillboardFile, MAX_BILLBOARDS};
pub use light_data::LightData;
pub use light_grid::LightGrid;
pub use light_maps::{LightMapSettings, MAX_LIGHT_MAP};
pub use lights::validate_attenuation;
pub use material::Material;
pub use mirrors::{Mirror, flat};
pub use render_settings::RenderSettings;
pub use settings::Parallax;
pub use settings::Transparency;
pub use settings::{
    Accumulation, AlphaTest, BillboardKind, BillboardMode, Cull, DeferredLights, DepthFunc,
    Falloff, JointStorage, MirrorOrder, RenderPath, Shading, SkinMethod, SkinningOn, Winding,
};
pub use shadows::{CascadeSplit, CubeRender, Pcf, Shadow, ShadowFit};
pub use text::MAX_MESSAGE_CHARS;
pub use views::{SplitView, check_viewport};

use crate::assets;
use crate::math;
use anyhow::{Context as _, Result, anyhow};
use file::SceneFile;
use glam::{Mat4, Vec3};
use resolve::resolve;
use serde::Deserialize as _;
use std::path::{Path, PathBuf};

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Projection {
    Perspective { fov_y_degrees: f32 },
    Orthographic { half_height: f32 },
}

#[derive(Clone, Debug, PartialEq)]
pub struct Camera {
    pub eye: Vec3,
    pub target: Vec3,
    pub up: Vec3,
    pub projection: Projection,
    pub near: f32,
    pub far: f32,
}

impl Camera {
    pub fn view(&self) -> Mat4 {
        math::look_at(self.eye, self.target, self.up)
    }
    pub fn projection(&self, aspect: f32) -> Mat4 {
        match self.projection {
            Projection::Perspective { fov_y_degrees } => {
                math::perspective(fov_y_degrees.to_radians(), aspect, self.near, self.far)
            }
            Projection::Orthographic { half_height } => {
                let hw = half_height * aspect;
                math::orthographic(-hw, hw, -half_height, half_height, self.near, self.far)
            }
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LightKind {
    Directional,
    Point,
    Spot,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Light {
    pub kind: LightKind,
    pub position: Vec3,
    /// Unit direction the light shines in (directional, spot).
    pub direction: Vec3,
    pub color: Vec3,
    pub intensity: f32,
    pub kc: f32,
    pub kl: f32,
    pub kq: f32,
    pub inner_angle: f32,
    pub outer_angle: f32,
    /// Casts shadows (notes 01 §8.5) with these knobs.
    pub shadow: Option<Shadow>,
    /// Lmax of notes 01's linear attenuation a = 1 - d / Lmax
    /// (`render.falloff = "linear"`); None: the volume radius at the cutoff.
    pub range: Option<f32>,
}

impl Light {
    /// colour x intensity, what the shader multiplies by.
    pub fn radiance(&self) -> Vec3 {
        self.color * self.intensity
    }
    /// The brightest channel, I_max in notes 04.
    pub fn i_max(&self) -> f32 {
        self.radiance().max_element()
    }
}

/// Where a mesh comes from.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum MeshSource {
    Sphere,
    Icosphere,
    Cube,
    Plane,
    Cylinder,
    Cone,
    Torus,
    Obj(PathBuf),
    /// Part k of an OBJ file: the faces of its k-th material
    /// (src/scene/obj_materials.rs).
    ObjPart(PathBuf, usize),
    /// A skinned mesh in a glTF 2.0 file (src/scene/skins.rs).
    Gltf(PathBuf),
    /// One primitive of a glTF 2.0 file's mesh, or a node that draws
    /// nothing (src/scene/gltf_objects.rs).
    GltfPart(gltf_objects::GltfPart),
}

impl MeshSource {
    pub const BUILTIN: &'static str = "sphere, icosphere, cube, plane, cylinder, cone, torus";
}

#[derive(Clone, Debug, PartialEq)]
pub struct Object {
    pub name: String,
    pub mesh: MeshSource,
    pub material: usize,
    /// The local transform as the file writes it: position, rotation
    /// (degrees about x, y, z) and scale.
    pub position: Vec3,
    pub rotation: Vec3,
    pub scale: Vec3,
    /// Index of the parent object (resolved, never a cycle).
    pub parent: Option<usize>,
    /// Model matrix including every parent's (`update_models`).
    pub model: Mat4,
    /// Set when the object is a planar mirror.
    pub mirror: Option<Mirror>,
    /// A rotation that replaces `rotation`'s angles: an animation track's
    /// (src/scene/animation.rs). None: the file's angles.
    pub orientation: Option<glam::Quat>,
    /// A skinned mesh's skin, skeleton, clip and method (mesh = a glTF file).
    pub skin: Option<skins::ObjectSkin>,
    /// Static lighting (notes 01 §8.2): the light map to bake at load.
    pub light_map: Option<LightMapSettings>,
}

impl Object {
    /// T * Rz * Ry * Rx * S (column vectors: scale first, then rotate about
    /// x, y, z, then move), notes 01 §2.6.
    pub fn local(&self) -> Mat4 {
        let r = self.rotation * (std::f32::consts::PI / 180.0);
        let (p, s) = (self.position, self.scale);
        if let Some(q) = self.orientation {
            // An animated rotation: T * R(q) * S.
            return math::translate(p.x, p.y, p.z)
                * Mat4::from_quat(q)
                * math::scale(s.x, s.y, s.z);
        }
        math::translate(p.x, p.y, p.z)
            * math::rotate_z(r.z)
            * math::rotate_y(r.y)
            * math::rotate_x(r.x)
            * math::scale(s.x, s.y, s.z)
    }
}

pub use hierarchy::update_models;

#[derive(Clone, Debug)]
pub struct Scene {
    pub name: String,
    pub path: PathBuf,
    pub camera: Camera,
    /// `[[views]]`: the frame split into rectangles, each its own camera
    /// (empty: one view, the camera's).
    pub views: Vec<SplitView>,
    pub render: RenderSettings,
    pub lights: Vec<Light>,
    /// `[[area_lights]]`: rectangles lit with LTC (forward path).
    pub area_lights: Vec<area_lights::AreaLight>,
    /// The `[light_grid]` that generated the last `grid_lights` lights.
    pub light_grid: Option<LightGrid>,
    /// How many of `lights` a `[light_grid]` generated (None: the scene has none).
    pub grid_lights: Option<usize>,
    pub materials: Vec<Material>,
    pub objects: Vec<Object>,
    /// Billboard sprites (RGBA PNGs), each once, and the billboards (notes 05).
    pub sprites: Vec<PathBuf>,
    pub billboards: Vec<Billboard>,
    /// The `[[billboards]]` and `[[billboard_fields]]` they came from, as
    /// written (`set_billboards` makes `billboards` again).
    pub billboard_list: Vec<BillboardFile>,
    pub billboard_fields: Vec<BillboardFieldFile>,
    /// `[[post]]`: the post-processing chain, in order (empty: none; the
    /// lit scene is the output).
    pub post: Vec<post::PostPass>,
    /// `[animation]`: keyframe tracks and the instant shown.
    pub animation: animation::Animation,
    /// `[tessellation]`: a terrain the GL 4.0 tessellator divides.
    pub tessellation: Option<tessellation::Tessellation>,
    /// `[particles]`: a particle fountain, drawn as points a geometry shader
    /// turns into quads.
    pub particles: Option<particles::Particles>,
    /// `[outlines]`: objects outlined with the stencil buffer
    /// (src/techniques/stencil/object_outlines.rs).
    pub outlines: Option<outlines::Outlines>,
    /// `[instancing]`: a field of rocks drawn with instanced arrays
    /// (src/techniques/vertex_geometry/instancing.rs).
    pub instancing: Option<instancing::Instancing>,
    /// `[[clip_planes]]`: world-space planes (n, -n . p), |n| = 1; what lies
    /// on the side n points away from is cut away (gl_ClipDistance[1..]).
    pub clip_planes: Vec<glam::Vec4>,
    /// `[sky]`: the Preetham sun-sky behind the world (notes 03, Sun Sky).
    pub sky: Option<sky::SkySettings>,
    /// `[skybox]`: the cube map behind the world (notes 03, Implementation).
    pub skybox: Option<skybox::Environment>,
    /// Every key the file and `--set` wrote, dotted (`render.cutoff`,
    /// `lights[0].shadow.cube`): `warnings` names those with no effect.
    pub keys_written: std::collections::BTreeSet<String>,
    /// What loading the scene's model files left out (an OBJ's missing
    /// textures, unknown MTL keys), one line each; `warnings` adds them.
    pub file_warnings: Vec<String>,
}

impl Scene {
    /// The indices of the objects that are mirrors, in file order.
    pub fn mirrors(&self) -> Vec<usize> {
        (0..self.objects.len())
            .filter(|&i| self.objects[i].mirror.is_some())
            .collect()
    }
}

/// The largest scene file gloss reads (scene files are small; this stops a
/// wrong path such as /dev/zero from filling the memory).
pub const MAX_SCENE_BYTES: u64 = 4 << 20;

fn read_text(path: &Path) -> Result<String> {
    let bytes = assets::read(path, MAX_SCENE_BYTES, "scene file")?;
    String::from_utf8(bytes.into_owned()).with_context(|| {
        format!(
            "cannot read scene file {}: it is not UTF-8 text",
            path.display()
        )
    })
}

/// A message about the scene file at `path`: its name, then the message,
/// cut to `text::MAX_MESSAGE_CHARS` (a value quoted from a hostile file can
/// be megabytes long).
fn at(path: &Path, e: impl std::fmt::Display) -> anyhow::Error {
    anyhow!("{}: {}", path.display(), text::quoted(&e.to_string()))
}

impl Scene {
    /// Read, check and resolve a scene file (on disk, or a shipped one:
    /// src/assets.rs).
    pub fn load(path: &Path) -> Result<Scene> {
        Scene::parse(&read_text(path)?, path)
    }

    /// `load`, with `KEY=VALUE` overrides applied to the file's text as if
    /// written in it (`--set render.cutoff=0.01`; see `knobs`).
    pub fn load_with(path: &Path, overrides: &[String]) -> Result<Scene> {
        Scene::parse_with(&read_text(path)?, path, overrides)
    }

    /// `parse`, with `KEY=VALUE` overrides. VALUE is TOML (`0.01`, `true`,
    /// `[0.1, 0.1, 0.1]`, `"volumes"`); a bare word is taken as a string.
    pub fn parse_with(text: &str, path: &Path, overrides: &[String]) -> Result<Scene> {
        if overrides.is_empty() {
            return Scene::parse(text, path);
        }
        let mut table: toml::Table = toml::from_str(text).map_err(|e| at(path, e))?;
        for o in overrides {
            overrides::apply_override(&mut table, o).map_err(|e| {
                let o = text::short(o, 200);
                anyhow!("{}", text::quoted(&format!("--set {o}: {e}")))
            })?;
        }
        text::floats_in_f32_range(&table, "").map_err(|e| at(path, e))?;
        let keys_written = text::written_keys(&table);
        let file = SceneFile::deserialize(toml::Value::Table(table)).map_err(|e| {
            let all: Vec<String> = overrides.iter().map(|o| text::short(o, 200)).collect();
            let with = format!("with --set {}: {e}", all.join(" --set "));
            anyhow!("{} {}", path.display(), text::quoted(&with))
        })?;
        let mut scene = resolve(file, path).map_err(|e| at(path, e))?;
        scene.keys_written = keys_written;
        Ok(scene)
    }

    /// Parse scene text; `path` names the file in messages and anchors relative paths.
    /// Every message names the file and is at most `text::MAX_MESSAGE_CHARS`
    /// characters after the name, whatever the file holds.
    pub fn parse(text: &str, path: &Path) -> Result<Scene> {
        let table = toml::from_str::<toml::Table>(text).ok();
        if let Some(table) = &table {
            text::floats_in_f32_range(table, "").map_err(|e| at(path, e))?;
        }
        let file: SceneFile = toml::from_str(text).map_err(|e| at(path, e))?;
        let mut scene = resolve(file, path).map_err(|e| at(path, e))?;
        scene.keys_written = table.map(|t| text::written_keys(&t)).unwrap_or_default();
        Ok(scene)
    }

    /// Replace the generated lights with `count` of them (`gloss bench --lights`).
    /// Scenes without a `[light_grid]` keep their lights.
    pub fn set_light_count(&mut self, count: usize) -> Result<()> {
        let grid = self.light_grid.clone().ok_or_else(|| {
            anyhow!(
                "{}: has no [light_grid] to vary the light count of",
                self.path.display()
            )
        })?;
        self.set_light_grid(LightGrid { count, ..grid })
    }

    /// How many objects the opaque passes draw (their material's opacity is 1).
    pub fn opaque_objects(&self) -> usize {
        self.objects
            .iter()
            .filter(|o| !self.materials[o.material].is_transparent())
            .count()
    }

    pub fn aspect(&self) -> f32 {
        self.render.size.0 as f32 / self.render.size.1 as f32
    }
}
