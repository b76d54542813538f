//! The scene's objects on the GPU: each object's mesh, model and normal
//! matrices and material, with the meshes and textures they share uploaded
//! once. A geometry pass (forward, G-buffer, combine) loops over `items`,
//! making its own GL state changes per object (glFrontFace, the diffuse
//! texture) in its own file; this module only sets uniforms. The opaque
//! passes skip the `transparent` items; the transparency pass draws them.

use crate::frame::alpha_maps::with_alpha_map;
use crate::frame::billboards::BillboardDraws;
use crate::frame::culling::{CullStats, CullTree, mesh_bounds};
use crate::frame::skins::SkinDraw;
use crate::frame::texturing::TextureSamplers;
use crate::gl::Gl;
use crate::gl::mesh::Mesh;
use crate::gl::program::Program;
use crate::gl::texture::{Sampling, Texture};
use crate::math;
use crate::math::frustum::Frustum;
use crate::scene::material::Microfacet;
use crate::scene::texturing::Texturing;
use crate::scene::{Cull, DepthFunc, MeshSource, Scene, Winding};
use anyhow::Result;
use glam::{Mat3, Mat4, Vec3};
use std::cell::{Cell, RefCell};
use std::collections::HashMap;
use std::path::PathBuf;

/// One object ready to draw.
pub struct DrawItem {
    pub mesh: usize,
    /// Index into the scene's materials.
    pub material: usize,
    pub model: Mat4,
    pub normal_matrix: Mat3,
    /// Its front faces wind clockwise on screen: the model matrix mirrors
    /// (negative determinant), or, not both, the material's winding is
    /// "cw" (notes 01 §3.4). `View::front_face` gives the pass its glFrontFace.
    pub mirrored: bool,
    pub diffuse: Vec3,
    pub specular: Vec3,
    pub shininess: f32,
    /// Notes 03's microfacet triple (None: the Phong terms above).
    pub microfacet: Option<crate::scene::material::Microfacet>,
    pub texture: Option<usize>,
    /// The material's normal map (notes 01 §8.4), if it has one.
    pub normal_map: Option<usize>,
    /// The normal map's x and y are multiplied by it (`Material::normal_scale`).
    pub normal_scale: f32,
    /// The material's specular map, if it has one (`Material::specular_map`).
    pub specular_map: Option<usize>,
    /// glTF's metallic-roughness, occlusion and emissive maps and their
    /// factors (`Material::pbr`); the height map of parallax mapping and
    /// the depth of its relief (`Material::height_scale`).
    pub pbr_maps: [Option<usize>; 3],
    pub pbr: crate::scene::material::PbrMaps,
    pub height_map: Option<usize>,
    pub height_scale: f32,
    /// The object's baked light map (notes 01 §8.2), if it has one.
    pub light_map: Option<usize>,
    /// How the texture is sampled, and the uv transform (notes 01 §5).
    pub texturing: Texturing,
    /// A mirror: the mirror technique draws it (stencil/mirror.rs), the world's passes skip it.
    pub mirror: bool,
    /// A mirror's roughening texture (linear greyscale), if it has one.
    pub roughness: Option<usize>,
    /// The material's alpha test (notes 05): `AlphaTest::code` and the reference.
    pub alpha_test: i32,
    pub alpha_ref: f32,
    /// The material's opacity (alpha, notes 01 §4.5).
    pub opacity: f32,
    /// How much of the environment it mirrors (src/frame/environment.rs).
    pub reflectivity: f32,
    /// Opacity < 1: the opaque passes skip it, the transparency pass draws it.
    pub transparent: bool,
    /// The material's own depth test (None: `render.depth_func`).
    pub depth_func: Option<DepthFunc>,
    /// The material's face culling (notes 01 §3.4).
    pub cull: Cull,
    /// The mesh's box centre in its own space (the transparency pass sorts by `model * centre`'s depth).
    pub centre: Vec3,
    /// Index into `DrawList::skins` for a skinned object.
    pub skin: Option<usize>,
}

/// Every object of the scene, with the meshes and textures they share.
pub struct DrawList {
    pub items: Vec<DrawItem>,
    pub meshes: Vec<Mesh>,
    pub textures: Vec<Texture>,
    /// The materials' sampler objects and the mip-colour twins (src/frame/texturing.rs).
    pub samplers: TextureSamplers,
    /// Each mesh's axis-aligned box in its own space (lo, hi).
    pub bounds: Vec<(Vec3, Vec3)>,
    /// The scene's billboards (src/frame/billboards.rs).
    pub billboards: BillboardDraws,
    /// The skinned objects (src/frame/skins.rs), each with its own mesh.
    pub skins: Vec<SkinDraw>,
    /// The environment cube map (src/frame/environment.rs).
    pub environment: super::environment::Environment,
    /// The LTC tables of the `[[area_lights]]` (src/frame/ltc_area_lights.rs).
    pub ltc: Option<super::ltc_area_lights::LtcTables>,
    /// The objects' boxes through the graph, for culling (src/frame/culling.rs); each one's parent.
    cull_tree: CullTree,
    parents: Vec<Option<usize>>,
    /// The camera's last culled walk (set by `Frame::opaque_order`).
    pub last_cull: Cell<CullStats>,
    /// The shadow passes' culling of the casters, summed over their faces.
    pub shadow_cull: Cell<CullStats>,
    /// The tiled pass's last lists for the camera's view (the pixel probe's).
    pub tiled_lists: RefCell<Option<(super::clusters::Grid, super::clusters::Bins)>>,
}

impl DrawList {
    pub fn new(gl: &Gl, scene: &Scene) -> Result<DrawList> {
        let mut meshes = Vec::new();
        let mut mesh_index: HashMap<MeshSource, usize> = HashMap::new();
        let mut textures = Vec::new();
        // Keyed by file and colour space: one PNG may be both.
        let mut texture_index: HashMap<(PathBuf, bool), usize> = HashMap::new();
        let mut with_alpha: HashMap<(Option<PathBuf>, PathBuf), usize> = HashMap::new();
        let mut items = Vec::new();
        let mut bounds = Vec::new();
        let mut skins = Vec::new();
        // Static lighting: the light maps, baked now (src/frame/light_maps.rs).
        let mut light_maps = crate::frame::light_maps::bake_light_maps(gl, scene)?;
        for (object, o) in scene.objects.iter().enumerate() {
            let mesh = match mesh_index.get(&o.mesh) {
                // A skinned object poses its own copy of the skin.
                _ if o.skin.is_some() => {
                    let s = o.skin.as_ref().unwrap();
                    skins.push(SkinDraw::new(gl, items.len(), s)?);
                    bounds.push(mesh_bounds(&s.mesh.mesh));
                    meshes.push(Mesh::upload_dynamic(gl, &s.mesh.mesh)?);
                    meshes.len() - 1
                }
                Some(&i) => i,
                None => {
                    let data = crate::scene::meshes::mesh_data(&o.mesh)?;
                    bounds.push(mesh_bounds(&data));
                    meshes.push(Mesh::upload(gl, &data)?);
                    mesh_index.insert(o.mesh.clone(), meshes.len() - 1);
                    meshes.len() - 1
                }
            };
            let m = &scene.materials[o.material];
            let combined = (m.alpha_map.as_ref())
                .map(|a| with_alpha_map(gl, &mut textures, &mut with_alpha, m, a))
                .transpose()?; // an MTL's map_d: one texture, the diffuse with that alpha
            let mut load = |p: &PathBuf, srgb: bool| -> Result<usize> {
                if let Some(&i) = texture_index.get(&(p.clone(), srgb)) {
                    return Ok(i);
                }
                textures.push(Texture::load(gl, p, srgb, Sampling::TRILINEAR_REPEAT)?);
                texture_index.insert((p.clone(), srgb), textures.len() - 1);
                Ok(textures.len() - 1)
            };
            let texture = (combined.map(Ok))
                .or_else(|| m.diffuse_texture.as_ref().map(|p| load(p, true)))
                .transpose()?;
            // Data, not colour: normal, specular and height maps and glTF's
            // metallic-roughness and occlusion are linear (GL_RGBA8); emission is colour.
            let [normal, specular, height, metal_rough, occlusion, emissive] = [
                (&m.normal_map, false),
                (&m.specular_map, false),
                (&m.height_map, false),
                (&m.pbr.metallic_roughness, false),
                (&m.pbr.occlusion, false),
                (&m.pbr.emissive_map, true),
            ]
            .map(|(p, srgb)| p.as_ref().map(|p| load(p, srgb)).transpose());
            let (normal_map, specular_map, height_map) = (normal?, specular?, height?);
            let pbr_maps = [metal_rough?, occlusion?, emissive?];
            let roughness = (o.mirror.as_ref().and_then(|m| m.roughness.as_ref()))
                .map(|p| load(p, false)) // a rough mirror's roughness map: data
                .transpose()?;
            items.push(DrawItem {
                mesh,
                material: o.material,
                model: o.model,
                normal_matrix: normal_matrix(&o.model),
                mirrored: (Mat3::from_mat4(o.model).determinant() < 0.0)
                    != (m.winding == Winding::Cw),
                diffuse: m.diffuse,
                specular: m.specular,
                shininess: m.shininess,
                microfacet: m.microfacet,
                texture,
                normal_map,
                normal_scale: m.normal_scale,
                specular_map,
                pbr_maps,
                pbr: m.pbr.clone(),
                height_map,
                height_scale: m.height_scale,
                light_map: light_maps[object].take().map(|t| {
                    textures.push(t);
                    textures.len() - 1
                }),
                texturing: m.texturing,
                mirror: o.mirror.is_some(),
                roughness,
                alpha_test: m.alpha_test.code(),
                alpha_ref: m.alpha_ref,
                opacity: m.opacity,
                reflectivity: m.reflectivity,
                transparent: m.is_transparent(),
                depth_func: m.depth_func,
                cull: m.cull,
                centre: (bounds[mesh].0 + bounds[mesh].1) * 0.5,
                skin: o.skin.as_ref().map(|_| skins.len() - 1),
            });
        }
        let textured: Vec<Texturing> = scene
            .materials
            .iter()
            .filter(|m| m.is_textured())
            .map(|m| m.texturing)
            .collect();
        let samplers = TextureSamplers::new(gl, &textured, &textures)?;
        let mut list = DrawList {
            items,
            meshes,
            textures,
            samplers,
            bounds,
            billboards: BillboardDraws::new(gl, scene)?,
            skins,
            environment: super::environment::Environment::new(gl, scene)?,
            ltc: super::ltc_area_lights::LtcTables::for_scene(gl, scene)?,
            cull_tree: CullTree::default(),
            parents: scene.objects.iter().map(|o| o.parent).collect(),
            last_cull: Cell::default(),
            shadow_cull: Cell::default(),
            tiled_lists: RefCell::default(),
        };
        list.pose_skins(scene);
        list.grow_cull_tree();
        Ok(list)
    }

    /// The culling tree again, from the models and boxes as they are now.
    fn grow_cull_tree(&mut self) {
        let models: Vec<Mat4> = self.items.iter().map(|d| d.model).collect();
        let local: Vec<(Vec3, Vec3)> = self.items.iter().map(|d| self.bounds[d.mesh]).collect();
        self.cull_tree = CullTree::new(&models, &local, &self.parents);
    }

    /// Pose every skinned object at the scene's time (on the CPU, skin it
    /// too; see src/frame/skins.rs) and take its posed box.
    fn pose_skins(&mut self, scene: &Scene) {
        for s in &mut self.skins {
            if let Some(skin) = &scene.objects[s.item].skin {
                s.skin = skin.clone();
            }
            let d = &mut self.items[s.item];
            let time = scene.animation.time;
            let b = s.pose(time, scene.render.skinning_on, &self.meshes[d.mesh]);
            self.bounds[d.mesh] = b;
            d.centre = (b.0 + b.1) * 0.5;
        }
    }

    /// Take the objects' model matrices and the materials' colours and
    /// shininess again (the demo edits them); meshes and textures stay.
    /// `scene` has the objects this list was made from, in the same order.
    pub fn update_values(&mut self, scene: &Scene) {
        for (d, o) in self.items.iter_mut().zip(&scene.objects) {
            d.model = o.model;
            d.normal_matrix = normal_matrix(&o.model);
            d.mirrored = (Mat3::from_mat4(o.model).determinant() < 0.0)
                != (scene.materials[d.material].winding == Winding::Cw);
            let m = &scene.materials[d.material];
            d.diffuse = m.diffuse;
            d.specular = m.specular;
            d.shininess = m.shininess;
            d.microfacet = m.microfacet;
            d.alpha_test = m.alpha_test.code();
            d.alpha_ref = m.alpha_ref;
            d.normal_scale = m.normal_scale;
            d.pbr = m.pbr.clone();
            d.opacity = m.opacity;
            d.reflectivity = m.reflectivity;
            d.cull = m.cull;
            d.transparent = m.is_transparent();
            d.depth_func = m.depth_func;
        }
        self.pose_skins(scene);
        self.grow_cull_tree();
    }

    /// The corners of every opaque object's box, in world space: what a
    /// shadow map must hold (src/frame/shadows.rs).
    pub fn world_corners(&self) -> Vec<Vec3> {
        let opaque = self.items.iter().filter(|d| !d.transparent);
        opaque
            .flat_map(|d| {
                let (lo, hi) = self.bounds[d.mesh];
                math::shadow::corners(lo, hi).map(|c| d.model.transform_point3(c))
            })
            .filter(|p| p.is_finite())
            .collect()
    }

    /// The opaque items the world passes draw (not transparent, not
    /// mirrors): front to back by the eye-space depth of their centres in
    /// `view` when `sorted` (notes 01 §6.2: the depth test then rejects
    /// hidden fragments before they are shaded), else in the scene's order.
    /// A big object's centre says little about its nearest point: a floor
    /// under everything sorts by its middle. With `seen` (from `in_view`),
    /// only the objects inside the view's frustum (notes 01 §6.3).
    pub fn opaque_order(&self, view: &Mat4, seen: Option<&[bool]>, sorted: bool) -> Vec<usize> {
        let mut order: Vec<usize> = (0..self.items.len())
            .filter(|&i| self.is_opaque_world(i) && seen.is_none_or(|s| s[i]))
            .collect();
        if sorted {
            let depth = |i: usize| {
                let d = &self.items[i];
                -view.transform_point3(d.model.transform_point3(d.centre)).z
            };
            order.sort_by(|&a, &b| depth(a).total_cmp(&depth(b)));
        }
        order
    }

    /// Which objects (perhaps partly) lie inside the frustum of the
    /// view-projection matrix `vp` (notes 01 §6.3), and what the walk did
    /// over the opaque ones the world passes draw.
    pub fn in_view(&self, vp: &Mat4) -> (Vec<bool>, CullStats) {
        let wanted: Vec<bool> = (0..self.items.len())
            .map(|i| self.is_opaque_world(i))
            .collect();
        (self.cull_tree).visible(&Frustum::from_view_projection(vp), &wanted)
    }

    /// Which shadow casters (every object but the transparent ones) may
    /// reach the shadow map of light view-projection `vp` (notes 01 §6.3
    /// applied to §8.5): the light's frustum without its near plane, since
    /// the shadow pass clamps depth and a caster between the light and the
    /// near plane still casts.
    pub fn casters_in(&self, vp: &Mat4) -> (Vec<bool>, CullStats) {
        let wanted: Vec<bool> = self.items.iter().map(|d| !d.transparent).collect();
        let frustum = Frustum::from_view_projection(vp).without_near();
        self.cull_tree.visible(&frustum, &wanted)
    }

    /// Drawn by the opaque world passes: not transparent, not a mirror.
    fn is_opaque_world(&self, i: usize) -> bool {
        !self.items[i].transparent && !self.items[i].mirror
    }

    pub fn mesh(&self, d: &DrawItem) -> &Mesh {
        &self.meshes[d.mesh]
    }

    /// glUniform* for one object's transform and material (program `p` in use).
    pub fn set_object_uniforms(&self, p: &Program, d: &DrawItem) {
        p.set_mat4("u_model", &d.model);
        p.set_mat3("u_normal_matrix", &d.normal_matrix);
        p.set_f32("u_mirror", if d.mirrored { -1.0 } else { 1.0 });
        p.set_vec3("u_diffuse", d.diffuse);
        p.set_vec3("u_specular", d.specular);
        p.set_f32("u_reflectivity", d.reflectivity);
        // A microfacet surface's shininess is its lobe's Blinn-Phong
        // equivalent: what the far field's error bound reads from the G-buffer.
        let shininess = d
            .microfacet
            .map_or(d.shininess, |m| m.equivalent_shininess());
        p.set_f32("u_shininess", shininess);
        let m = d.microfacet.unwrap_or(Microfacet {
            alpha: 1.0,
            eta: 1.0,
            k_s: 0.0,
        });
        p.set_bool("u_microfacet", d.microfacet.is_some());
        p.set_f32("u_microfacet_alpha", m.alpha);
        p.set_f32("u_microfacet_eta", m.eta);
        p.set_f32("u_microfacet_k_s", m.k_s);
        p.set_bool("u_has_diffuse_texture", d.texture.is_some());
        let (scale, offset) = (d.texturing.uv_scale, d.texturing.uv_offset);
        p.set_vec4(
            "u_uv_transform",
            glam::Vec4::new(scale[0], scale[1], offset[0], offset[1]),
        );
        let mirrors = Mat3::from_mat4(d.model).determinant() < 0.0;
        p.set_f32("u_tangent_sign", if mirrors { -1.0 } else { 1.0 });
        p.set_i32("u_alpha_test", d.alpha_test);
        p.set_f32("u_alpha_ref", d.alpha_ref);
    }
}

/// The normal matrix (notes 01 §8.1.1): transpose(inverse(mat3(model))).
/// For a singular model matrix (a zero scale flattens the object) the
/// inverse does not exist; the cofactor matrix, det x inverse-transpose, is
/// still defined and gives the flattened surface's normal, so use that.
pub fn normal_matrix(model: &Mat4) -> Mat3 {
    match math::normal_matrix(model) {
        Some(n) => n,
        None => math::cofactor(model),
    }
}
