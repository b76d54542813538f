//! Scene files (scenes/*.toml), read with serde + toml.
//!
//! Colours in a scene file are *linear* RGB, the values the lighting
//! equations use; textures are sRGB PNGs and are decoded to linear by the GPU.
//! Paths (meshes, textures) are relative to the scene file. Unknown keys and
//! bad values are errors that name the file, the key and what was expected.

use crate::attenuation;
use crate::math;
use anyhow::{Context as _, Result, anyhow, bail};
use glam::{Mat4, Vec3};
use serde::Deserialize;
use std::collections::HashMap;
use std::path::{Path, PathBuf};

// ---------------------------------------------------------------------------
// The file format, exactly as written in TOML.

#[derive(Deserialize, Debug)]
#[serde(deny_unknown_fields)]
struct SceneFile {
    name: Option<String>,
    camera: CameraFile,
    #[serde(default)]
    render: RenderFile,
    #[serde(default)]
    lights: Vec<LightFile>,
    light_grid: Option<LightGridFile>,
    #[serde(default)]
    materials: HashMap<String, MaterialFile>,
    #[serde(default)]
    objects: Vec<ObjectFile>,
}

#[derive(Deserialize, Debug)]
#[serde(deny_unknown_fields)]
struct CameraFile {
    #[serde(default = "perspective_str")]
    projection: String,
    eye: [f32; 3],
    target: [f32; 3],
    #[serde(default = "up_y")]
    up: [f32; 3],
    #[serde(default = "default_fov")]
    fov_y: f32,
    /// Orthographic: half the height of the view box (width follows the aspect).
    half_height: Option<f32>,
    #[serde(default = "default_near")]
    near: f32,
    #[serde(default = "default_far")]
    far: f32,
}

fn perspective_str() -> String {
    "perspective".into()
}
fn up_y() -> [f32; 3] {
    [0.0, 1.0, 0.0]
}
fn default_fov() -> f32 {
    50.0
}
fn default_near() -> f32 {
    0.1
}
fn default_far() -> f32 {
    100.0
}

#[derive(Deserialize, Debug)]
#[serde(deny_unknown_fields, default)]
struct RenderFile {
    path: String,
    shading: String,
    size: [u32; 2],
    background: [f32; 3],
    ambient: [f32; 3],
    depth_func: String,
    cutoff: f32,
    stencil_volumes: bool,
    accumulation: String,
}

impl Default for RenderFile {
    fn default() -> Self {
        RenderFile {
            path: "forward".into(),
            shading: "phong".into(),
            size: [1280, 720],
            background: [0.0, 0.0, 0.0],
            ambient: [0.03, 0.03, 0.03],
            depth_func: "less".into(),
            cutoff: 5.0 / 256.0,
            stencil_volumes: false,
            accumulation: "rgba16f".into(),
        }
    }
}

#[derive(Deserialize, Debug)]
#[serde(deny_unknown_fields)]
struct LightFile {
    #[serde(rename = "type")]
    kind: String,
    position: Option<[f32; 3]>,
    direction: Option<[f32; 3]>,
    #[serde(default = "white")]
    color: [f32; 3],
    #[serde(default = "one")]
    intensity: f32,
    /// [Kc, Kl, Kq]; notes 04's defaults.
    #[serde(default = "default_attenuation")]
    attenuation: [f32; 3],
    /// Spot cone, degrees from the axis (notes 04: 20 and 30).
    #[serde(default = "spot_inner")]
    inner_angle: f32,
    #[serde(default = "spot_outer")]
    outer_angle: f32,
    #[serde(default)]
    shadow: bool,
}

fn white() -> [f32; 3] {
    [1.0, 1.0, 1.0]
}
fn one() -> f32 {
    1.0
}
fn default_attenuation() -> [f32; 3] {
    [1.0, 0.09, 0.032]
}
fn spot_inner() -> f32 {
    20.0
}
fn spot_outer() -> f32 {
    30.0
}

/// Many point lights placed by a seeded generator (the notes' 256-light example).
#[derive(Deserialize, Debug, Clone)]
#[serde(deny_unknown_fields)]
struct LightGridFile {
    count: usize,
    #[serde(default = "one_u64")]
    seed: u64,
    /// [xmin, xmax, zmin, zmax]
    area: [f32; 4],
    height: [f32; 2],
    #[serde(default = "one")]
    intensity: f32,
    #[serde(default = "default_attenuation")]
    attenuation: [f32; 3],
}

fn one_u64() -> u64 {
    1
}

#[derive(Deserialize, Debug)]
#[serde(deny_unknown_fields)]
struct MaterialFile {
    #[serde(default = "grey")]
    diffuse: [f32; 3],
    diffuse_texture: Option<String>,
    #[serde(default = "spec_default")]
    specular: [f32; 3],
    #[serde(default = "shininess_default")]
    shininess: f32,
}

fn grey() -> [f32; 3] {
    [0.6, 0.6, 0.6]
}
fn spec_default() -> [f32; 3] {
    [0.3, 0.3, 0.3]
}
fn shininess_default() -> f32 {
    32.0
}

#[derive(Deserialize, Debug)]
#[serde(deny_unknown_fields)]
struct ObjectFile {
    name: Option<String>,
    mesh: String,
    material: Option<String>,
    #[serde(default)]
    position: [f32; 3],
    /// Degrees about x, then y, then z.
    #[serde(default)]
    rotation: [f32; 3],
    #[serde(default = "unit_scale")]
    scale: [f32; 3],
    parent: Option<String>,
}

fn unit_scale() -> [f32; 3] {
    [1.0, 1.0, 1.0]
}

// ---------------------------------------------------------------------------
// The scene as the renderer uses it.

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Projection {
    Perspective { fov_y_degrees: f32 },
    Orthographic { half_height: f32 },
}

#[derive(Clone, Debug)]
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

/// Which renderer runs the frame (issue 3 adds the deferred ones).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, clap::ValueEnum)]
pub enum RenderPath {
    /// Every light for every fragment in one pass (notes 04 "forward rendering"): the reference.
    Forward,
    /// G-buffer, then one full-screen pass per light ("our current deferred shader").
    Deferred,
    /// G-buffer, then a volume per light (sphere, cone, full-screen quad), then composite.
    Volumes,
    /// Deferred lighting / light pre-pass (notes 02): diffuse and specular accumulated apart.
    Prepass,
}

impl RenderPath {
    pub fn parse(s: &str) -> Option<RenderPath> {
        Some(match s {
            "forward" => RenderPath::Forward,
            "deferred" => RenderPath::Deferred,
            "volumes" => RenderPath::Volumes,
            "prepass" => RenderPath::Prepass,
            _ => return None,
        })
    }
    pub fn name(self) -> &'static str {
        match self {
            RenderPath::Forward => "forward",
            RenderPath::Deferred => "deferred",
            RenderPath::Volumes => "volumes",
            RenderPath::Prepass => "prepass",
        }
    }
}

/// Notes 01 §8.2 shading modes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Shading {
    /// One colour per triangle (lit at its centroid with its face normal).
    Flat,
    /// Lighting per vertex, interpolated.
    Gouraud,
    /// Lighting per fragment.
    Phong,
}

impl Shading {
    pub fn parse(s: &str) -> Option<Shading> {
        Some(match s {
            "flat" => Shading::Flat,
            "gouraud" => Shading::Gouraud,
            "phong" => Shading::Phong,
            _ => return None,
        })
    }
}

#[derive(Clone, Debug)]
pub struct RenderSettings {
    pub path: RenderPath,
    pub shading: Shading,
    pub size: (u32, u32),
    pub background: Vec3,
    pub ambient: Vec3,
    /// GL_LESS (notes 02: "fails when d >= D") or GL_LEQUAL (notes 01: "passes when z <= D").
    pub depth_func: u32,
    /// Light-volume cutoff, a fraction of the light's brightest channel (notes 04: 5/256).
    pub cutoff: f32,
    /// Light volumes: use the two-sided stencil test to mark lit pixels first.
    pub stencil_volumes: bool,
    /// Internal format of the light accumulation target (RGBA16F or RGBA32F).
    pub accumulation: u32,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LightKind {
    Directional,
    Point,
    Spot,
}

#[derive(Clone, Debug)]
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
    pub shadow: bool,
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
    /// Light-volume radius at `cutoff` (None: no finite volume, e.g. Kl = Kq = 0,
    /// or a directional light).
    pub fn volume_radius(&self, cutoff: f32) -> Option<f32> {
        match self.kind {
            LightKind::Directional => None,
            _ => attenuation::light_volume_radius(self.kc, self.kl, self.kq, self.i_max(), cutoff),
        }
    }
}

#[derive(Clone, Debug)]
pub struct Material {
    pub name: String,
    pub diffuse: Vec3,
    pub diffuse_texture: Option<PathBuf>,
    pub specular: Vec3,
    pub shininess: f32,
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
}

impl MeshSource {
    pub const BUILTIN: &'static str = "sphere, icosphere, cube, plane, cylinder, cone, torus";
}

#[derive(Clone, Debug)]
pub struct Object {
    pub name: String,
    pub mesh: MeshSource,
    pub material: usize,
    /// Model matrix including every parent's.
    pub model: Mat4,
}

#[derive(Clone, Debug)]
pub struct Scene {
    pub name: String,
    pub path: PathBuf,
    pub camera: Camera,
    pub render: RenderSettings,
    pub lights: Vec<Light>,
    pub materials: Vec<Material>,
    pub objects: Vec<Object>,
}

impl Scene {
    /// Read, check and resolve a scene file.
    pub fn load(path: &Path) -> Result<Scene> {
        let text = std::fs::read_to_string(path)
            .with_context(|| format!("cannot read scene file {}", path.display()))?;
        Scene::parse(&text, path)
    }

    /// Parse scene text; `path` names the file in messages and anchors relative paths.
    pub fn parse(text: &str, path: &Path) -> Result<Scene> {
        let file: SceneFile = toml::from_str(text)
            .map_err(|e| anyhow!("{}: {}", path.display(), e.to_string().trim_end()))?;
        resolve(file, path).map_err(|e| anyhow!("{}: {e}", path.display()))
    }

    /// Replace the generated lights with `count` of them (`gloss bench --lights`).
    /// Scenes without a [light_grid] keep their lights.
    pub fn set_light_count(&mut self, count: usize) -> Result<()> {
        let text = std::fs::read_to_string(&self.path)?;
        let file: SceneFile = toml::from_str(&text)?;
        let mut grid = file.light_grid.ok_or_else(|| {
            anyhow!(
                "{}: has no [light_grid] to vary the light count of",
                self.path.display()
            )
        })?;
        grid.count = count;
        let fixed = file.lights.len();
        self.lights.truncate(fixed);
        self.lights.extend(generate_lights(&grid));
        Ok(())
    }

    pub fn aspect(&self) -> f32 {
        self.render.size.0 as f32 / self.render.size.1 as f32
    }
}

fn finite(key: &str, v: &[f32]) -> Result<()> {
    if v.iter().any(|x| !x.is_finite()) {
        bail!("{key}: expected finite numbers, found {v:?}");
    }
    Ok(())
}

fn non_negative(key: &str, v: &[f32]) -> Result<()> {
    finite(key, v)?;
    if v.iter().any(|x| *x < 0.0) {
        bail!("{key}: expected values >= 0, found {v:?}");
    }
    Ok(())
}

fn resolve(f: SceneFile, path: &Path) -> Result<Scene> {
    let base = path.parent().unwrap_or(Path::new("."));
    let name = f.name.clone().unwrap_or_else(|| {
        path.file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default()
    });

    // Camera
    let c = &f.camera;
    finite("camera.eye", &c.eye)?;
    finite("camera.target", &c.target)?;
    finite("camera.up", &c.up)?;
    finite("camera.near/far", &[c.near, c.far])?;
    let eye = Vec3::from(c.eye);
    let target = Vec3::from(c.target);
    let up = Vec3::from(c.up);
    if (target - eye).length() < 1e-6 {
        bail!("camera: eye and target are the same point");
    }
    if (target - eye)
        .normalize()
        .cross(up.normalize_or_zero())
        .length()
        < 1e-6
    {
        bail!("camera.up: must not be parallel to the view direction (or zero)");
    }
    if !(c.near > 0.0 && c.far > c.near) {
        bail!(
            "camera.near/far: expected 0 < near < far, found near = {}, far = {}",
            c.near,
            c.far
        );
    }
    let projection = match c.projection.as_str() {
        "perspective" => {
            if !(c.fov_y > 0.5 && c.fov_y < 179.0) {
                bail!(
                    "camera.fov_y: expected degrees in (0.5, 179), found {}",
                    c.fov_y
                );
            }
            Projection::Perspective {
                fov_y_degrees: c.fov_y,
            }
        }
        "orthographic" => {
            let h = c.half_height.ok_or_else(|| {
                anyhow!("camera.half_height: required for an orthographic camera")
            })?;
            if !(h.is_finite() && h > 0.0) {
                bail!("camera.half_height: expected a positive number, found {h}");
            }
            Projection::Orthographic { half_height: h }
        }
        other => bail!(
            "camera.projection: expected \"perspective\" or \"orthographic\", found \"{other}\""
        ),
    };
    let camera = Camera {
        eye,
        target,
        up,
        projection,
        near: c.near,
        far: c.far,
    };

    // Render settings
    let r = &f.render;
    let render = RenderSettings {
        path: RenderPath::parse(&r.path).ok_or_else(|| {
            anyhow!(
                "render.path: expected forward, deferred, volumes or prepass, found \"{}\"",
                r.path
            )
        })?,
        shading: Shading::parse(&r.shading).ok_or_else(|| {
            anyhow!(
                "render.shading: expected flat, gouraud or phong, found \"{}\"",
                r.shading
            )
        })?,
        size: {
            let [w, h] = r.size;
            if !(1..=8192).contains(&w) || !(1..=8192).contains(&h) {
                bail!("render.size: expected [width, height] in 1..=8192, found [{w}, {h}]");
            }
            (w, h)
        },
        background: {
            non_negative("render.background", &r.background)?;
            Vec3::from(r.background)
        },
        ambient: {
            non_negative("render.ambient", &r.ambient)?;
            Vec3::from(r.ambient)
        },
        depth_func: match r.depth_func.as_str() {
            "less" => glow::LESS,
            "lequal" => glow::LEQUAL,
            other => bail!("render.depth_func: expected \"less\" or \"lequal\", found \"{other}\""),
        },
        cutoff: {
            if !(r.cutoff.is_finite() && r.cutoff > 0.0 && r.cutoff < 1.0) {
                bail!(
                    "render.cutoff: expected a fraction in (0, 1), found {}",
                    r.cutoff
                );
            }
            r.cutoff
        },
        stencil_volumes: r.stencil_volumes,
        accumulation: match r.accumulation.as_str() {
            "rgba16f" => glow::RGBA16F,
            "rgba32f" => glow::RGBA32F,
            other => {
                bail!("render.accumulation: expected \"rgba16f\" or \"rgba32f\", found \"{other}\"")
            }
        },
    };

    // Lights
    let mut lights = Vec::new();
    for (i, l) in f.lights.iter().enumerate() {
        let key = |k: &str| format!("lights[{i}].{k}");
        non_negative(&key("color"), &l.color)?;
        non_negative(&key("intensity"), &[l.intensity])?;
        let [kc, kl, kq] = l.attenuation;
        attenuation::validate_attenuation(kc, kl, kq)
            .map_err(|e| anyhow!("{}: {e}", key("attenuation")))?;
        let kind = match l.kind.as_str() {
            "directional" => LightKind::Directional,
            "point" => LightKind::Point,
            "spot" => LightKind::Spot,
            other => bail!(
                "{}: expected directional, point or spot, found \"{other}\"",
                key("type")
            ),
        };
        let position = match (kind, l.position) {
            (LightKind::Directional, _) => Vec3::ZERO,
            (_, Some(p)) => {
                finite(&key("position"), &p)?;
                Vec3::from(p)
            }
            (_, None) => bail!("{}: required for a {} light", key("position"), l.kind),
        };
        let direction = match (kind, l.direction) {
            (LightKind::Point, _) => Vec3::NEG_Y,
            (_, Some(d)) => {
                finite(&key("direction"), &d)?;
                let d = Vec3::from(d);
                if d.length() < 1e-6 {
                    bail!("{}: must not be zero", key("direction"));
                }
                d.normalize()
            }
            (_, None) => bail!("{}: required for a {} light", key("direction"), l.kind),
        };
        if kind == LightKind::Spot
            && !(l.inner_angle >= 0.0 && l.inner_angle <= l.outer_angle && l.outer_angle < 89.0)
        {
            bail!(
                "{}: expected 0 <= inner_angle <= outer_angle < 89 degrees, found {} and {}",
                key("inner_angle/outer_angle"),
                l.inner_angle,
                l.outer_angle
            );
        }
        lights.push(Light {
            kind,
            position,
            direction,
            color: Vec3::from(l.color),
            intensity: l.intensity,
            kc,
            kl,
            kq,
            inner_angle: l.inner_angle,
            outer_angle: l.outer_angle,
            shadow: l.shadow,
        });
    }
    if let Some(g) = &f.light_grid {
        finite("light_grid.area", &g.area)?;
        finite("light_grid.height", &g.height)?;
        non_negative("light_grid.intensity", &[g.intensity])?;
        let [kc, kl, kq] = g.attenuation;
        attenuation::validate_attenuation(kc, kl, kq)
            .map_err(|e| anyhow!("light_grid.attenuation: {e}"))?;
        if g.count > 100_000 {
            bail!("light_grid.count: at most 100000 lights, found {}", g.count);
        }
        lights.extend(generate_lights(g));
    }

    // Materials (sorted by name so indices are stable)
    let mut names: Vec<&String> = f.materials.keys().collect();
    names.sort();
    let mut materials = vec![Material {
        name: "default".into(),
        diffuse: Vec3::splat(0.6),
        diffuse_texture: None,
        specular: Vec3::splat(0.3),
        shininess: 32.0,
    }];
    let mut material_index = HashMap::new();
    for n in names {
        let m = &f.materials[n];
        let key = |k: &str| format!("materials.{n}.{k}");
        non_negative(&key("diffuse"), &m.diffuse)?;
        non_negative(&key("specular"), &m.specular)?;
        if !(m.shininess.is_finite() && m.shininess >= 1.0 && m.shininess <= 4096.0) {
            bail!(
                "{}: expected a number in 1..=4096, found {}",
                key("shininess"),
                m.shininess
            );
        }
        let diffuse_texture = match &m.diffuse_texture {
            Some(t) => {
                let p = base.join(t);
                if !p.is_file() {
                    bail!(
                        "{}: file {} does not exist",
                        key("diffuse_texture"),
                        p.display()
                    );
                }
                Some(p)
            }
            None => None,
        };
        material_index.insert(n.clone(), materials.len());
        materials.push(Material {
            name: n.clone(),
            diffuse: Vec3::from(m.diffuse),
            diffuse_texture,
            specular: Vec3::from(m.specular),
            shininess: m.shininess,
        });
    }

    // Objects: local matrices first, then parents (in any order, no cycles).
    let mut locals = Vec::new();
    let mut object_names: HashMap<String, usize> = HashMap::new();
    for (i, o) in f.objects.iter().enumerate() {
        let key = |k: &str| format!("objects[{i}].{k}");
        finite(&key("position"), &o.position)?;
        finite(&key("rotation"), &o.rotation)?;
        finite(&key("scale"), &o.scale)?;
        let mesh = match o.mesh.as_str() {
            "sphere" => MeshSource::Sphere,
            "icosphere" => MeshSource::Icosphere,
            "cube" => MeshSource::Cube,
            "plane" => MeshSource::Plane,
            "cylinder" => MeshSource::Cylinder,
            "cone" => MeshSource::Cone,
            "torus" => MeshSource::Torus,
            file if file.ends_with(".obj") => {
                let p = base.join(file);
                if !p.is_file() {
                    bail!("{}: file {} does not exist", key("mesh"), p.display());
                }
                MeshSource::Obj(p)
            }
            other => bail!(
                "{}: expected one of {} or a path to an .obj file, found \"{other}\"",
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
        let [rx, ry, rz] = o.rotation.map(f32::to_radians);
        let [sx, sy, sz] = o.scale;
        let [tx, ty, tz] = o.position;
        // T * Rz * Ry * Rx * S (column vectors: scale first, then rotate x, y, z, then move).
        let local = math::translate(tx, ty, tz)
            * math::rotate_z(rz)
            * math::rotate_y(ry)
            * math::rotate_x(rx)
            * math::scale(sx, sy, sz);
        locals.push((name, mesh, material, local));
    }
    let mut objects = Vec::new();
    for (i, o) in f.objects.iter().enumerate() {
        let mut model = locals[i].3;
        let mut parent = o.parent.clone();
        let mut steps = 0;
        while let Some(p) = parent {
            let &pi = object_names
                .get(&p)
                .ok_or_else(|| anyhow!("objects[{i}].parent: no object named \"{p}\""))?;
            steps += 1;
            if steps > f.objects.len() {
                bail!("objects[{i}].parent: the parent chain is a cycle");
            }
            model = locals[pi].3 * model;
            parent = f.objects[pi].parent.clone();
        }
        objects.push(Object {
            name: locals[i].0.clone(),
            mesh: locals[i].1.clone(),
            material: locals[i].2,
            model,
        });
    }

    Ok(Scene {
        name,
        path: path.to_path_buf(),
        camera,
        render,
        lights,
        materials,
        objects,
    })
}

/// A small deterministic generator (SplitMix64) so scenes need no rand crate
/// and the same seed gives the same lights everywhere.
struct SplitMix(u64);
impl SplitMix {
    fn next_f32(&mut self) -> f32 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 40) as f32 / (1u64 << 24) as f32
    }
}

fn generate_lights(g: &LightGridFile) -> Vec<Light> {
    let mut rng = SplitMix(g.seed);
    let [x0, x1, z0, z1] = g.area;
    (0..g.count)
        .map(|_| {
            let x = x0 + (x1 - x0) * rng.next_f32();
            let z = z0 + (z1 - z0) * rng.next_f32();
            let y = g.height[0] + (g.height[1] - g.height[0]) * rng.next_f32();
            // A saturated hue: one channel full, one random, one low.
            let hue = rng.next_f32() * 6.0;
            let f = hue.fract();
            let color = match hue as u32 {
                0 => Vec3::new(1.0, f, 0.1),
                1 => Vec3::new(1.0 - f, 1.0, 0.1),
                2 => Vec3::new(0.1, 1.0, f),
                3 => Vec3::new(0.1, 1.0 - f, 1.0),
                4 => Vec3::new(f, 0.1, 1.0),
                _ => Vec3::new(1.0, 0.1, 1.0 - f),
            };
            Light {
                kind: LightKind::Point,
                position: Vec3::new(x, y, z),
                direction: Vec3::NEG_Y,
                color,
                intensity: g.intensity,
                kc: g.attenuation[0],
                kl: g.attenuation[1],
                kq: g.attenuation[2],
                inner_angle: 20.0,
                outer_angle: 30.0,
                shadow: false,
            }
        })
        .collect()
}
