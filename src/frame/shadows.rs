//! Shadow maps (notes 01 §8.5; notes 02 "Rendering Cast Shadows"): which
//! lights cast, the depth texture each renders into, the light's view of
//! the world this frame, and the `Shadows` block that every lighting shader
//! reads (glsl/common/shadow.glsl).
//!
//! - A directional or spot light has one 2D map ("1 map for unidirectional
//!   lights"): orthographic for a directional light, perspective for a spot
//!   light, as notes 02 says. Slots 0-3 of the block.
//! - A point light has a cube map ("6 maps for omnidirectional lights").
//!   Slots 4-7. It stores the distance to the light divided by `far`, the
//!   same value whichever face holds it (docs/shadows.md says why that
//!   beats the perspective depth).
//!
//! - A directional light with `shadow.cascades > 1` has a GL_TEXTURE_2D_ARRAY
//!   of cascades instead, and the `Cascades` block (shadows/cascades.rs).
//!
//! The shadow pass (src/techniques/shadows/shadow_map.rs, and
//! cascaded_shadow_maps.rs for the cascades) draws the maps;
//! lighting passes `bind` them and call `shadow_visibility` in their shaders.

use crate::frame::draw_list::DrawList;
use crate::frame::units as unit;
use crate::gl::Gl;
use crate::gl::buffer::Buffer;
use crate::gl::depth_map::DepthMap;
use crate::gl::texture_units::bind_one;
use crate::math::shadow as matrices;
use crate::scene::shadows::{MAX_SHADOW_CUBES, MAX_SHADOW_MAPS_2D};
use crate::scene::{Camera, CubeRender, LightKind, Pcf, Scene, Shadow};
use anyhow::Result;
use glam::{Mat4, Vec3};
use glow::HasContext;

mod block;
mod cascades;
mod sampler;
use block::block_size;
pub use cascades::{CASCADES_BINDING, UNIT_CASCADES, cascade_tints};
pub use sampler::setup_program;

/// The uniform-block binding point of the `Shadows` block.
pub const SHADOWS_BINDING: u32 = 1;
/// Texture units: the 2D maps on 6..10, the cube maps on 10..14
/// (src/frame/units.rs).
pub const UNIT_2D: u32 = unit::SHADOW_MAPS_2D;
pub const UNIT_CUBE: u32 = unit::SHADOW_CUBES;
/// Bytes of one `ShadowMap` in the std140 block: a mat4 and two vec4.
const SHADOW_STRIDE: usize = 96;
const SLOTS: usize = MAX_SHADOW_MAPS_2D + MAX_SHADOW_CUBES;

/// The kinds glsl/common/shadow.glsl tells apart.
pub const ORTHOGRAPHIC: i32 = 0;
pub const PERSPECTIVE: i32 = 1;
pub const CUBE: i32 = 2;
pub const CASCADED: i32 = 3;

/// A light that casts a shadow.
#[derive(Clone, Debug, PartialEq)]
pub struct Caster {
    /// Index of the light in the scene.
    pub light: usize,
    /// Its entry in the `Shadows` block: 0-3 a 2D map, 4-7 a cube map.
    pub slot: usize,
    pub cube: bool,
    pub shadow: Shadow,
}

impl Caster {
    /// Which sampler of its kind reads it (`u_shadow_map[i]`, `u_shadow_cube[i]`).
    pub fn sampler(&self) -> usize {
        self.slot % MAX_SHADOW_MAPS_2D
    }

    /// A directional light's map split into cascades (a 2D array).
    pub fn cascaded(&self) -> bool {
        !self.cube && self.shadow.cascades > 1
    }

    /// The texture unit its map is bound to.
    pub fn unit(&self) -> u32 {
        if self.cascaded() {
            UNIT_CASCADES
        } else if self.cube {
            UNIT_CUBE + self.sampler() as u32
        } else {
            UNIT_2D + self.sampler() as u32
        }
    }
}

/// The scene's casting lights, in light order (the scene's check keeps
/// them within four of each kind).
pub fn casters(scene: &Scene) -> Vec<Caster> {
    let (mut flat, mut cube) = (0, 0);
    let mut out = Vec::new();
    for (light, l) in scene.lights.iter().enumerate() {
        let Some(shadow) = l.shadow else { continue };
        let is_cube = l.kind == LightKind::Point;
        // 2D maps take slots 0..4, cubes 4..8 (the scene's check: four each).
        let (count, first, limit) = if is_cube {
            (&mut cube, MAX_SHADOW_MAPS_2D, MAX_SHADOW_CUBES)
        } else {
            (&mut flat, 0, MAX_SHADOW_MAPS_2D)
        };
        if *count < limit {
            out.push(Caster {
                light,
                slot: first + *count,
                cube: is_cube,
                shadow,
            });
        }
        *count += 1;
    }
    out
}

/// A light's view of the world for one frame.
#[derive(Clone, Debug, PartialEq)]
pub struct LightView {
    /// ORTHOGRAPHIC, PERSPECTIVE or CUBE.
    pub kind: i32,
    /// The light's view-projection (one; six for a cube, in face order).
    pub view_projections: Vec<Mat4>,
    pub near: f32,
    pub far: f32,
    /// A texel's size in world units: the box's width / resolution
    /// (orthographic), or per unit of distance from the light (perspective
    /// and cube: 2 tan(half-angle) / resolution).
    pub texel: f32,
    /// A cascaded map's cascades, one per view-projection (else none).
    pub cascades: Vec<crate::math::cascades::Cascade>,
}

/// Where the light looks this frame. `scene_points` are the corners of
/// every opaque object's box (world); `visible` the corners of the
/// camera's frustum, cut at the scene's far side (from `camera`, whose
/// depths split the cascades). None when there is nothing to cast onto.
pub fn light_view(
    scene: &Scene,
    caster: &Caster,
    scene_points: &[Vec3],
    (visible, camera): (&[Vec3], &Camera),
) -> Option<LightView> {
    let l = &scene.lights[caster.light];
    let s = caster.shadow;
    let res = s.resolution as f32;
    // Spot and point lights: from the light to the farthest corner of the
    // scene; the near plane a thousandth of that (depth clamping in the
    // shadow pass keeps what lies nearer still casting).
    let far = || {
        let d = scene_points.iter().map(|p| p.distance(l.position));
        d.fold(0.0f32, f32::max).max(1e-2) * 1.01
    };
    match l.kind {
        LightKind::Directional if caster.cascaded() => {
            cascades::light_view(l.direction, &s, scene_points, visible, camera)
        }
        LightKind::Directional => {
            let visible = (s.fit == crate::scene::ShadowFit::Visible).then_some(visible);
            let (m, w, h) = matrices::directional_fitted(l.direction, scene_points, visible)?;
            Some(LightView {
                kind: ORTHOGRAPHIC,
                view_projections: vec![m],
                near: 0.0,
                far: 1.0,
                texel: w.max(h) / res,
                cascades: vec![],
            })
        }
        LightKind::Spot => {
            let far = far();
            let m = matrices::spot(l.position, l.direction, l.outer_angle, far * 1e-3, far)?;
            Some(LightView {
                kind: PERSPECTIVE,
                view_projections: vec![m],
                near: far * 1e-3,
                far,
                texel: 2.0 * l.outer_angle.to_radians().tan() / res,
                cascades: vec![],
            })
        }
        LightKind::Point => {
            let far = far();
            Some(LightView {
                kind: CUBE,
                view_projections: matrices::point(l.position, far * 1e-3, far).to_vec(),
                near: far * 1e-3,
                far,
                texel: 2.0 / res,
                cascades: vec![],
            })
        }
    }
}

/// The corners of the camera's view frustum, its far plane pulled in to
/// the farthest of `scene_points` (what the camera can see of the scene).
pub fn visible_corners(camera: &Camera, aspect: f32, scene_points: &[Vec3]) -> Vec<Vec3> {
    let forward = (camera.target - camera.eye).normalize_or_zero();
    let reach = scene_points
        .iter()
        .map(|p| (*p - camera.eye).dot(forward))
        .fold(camera.near * 2.0, f32::max);
    let mut c = camera.clone();
    c.far = c.far.min(reach * 1.01).max(c.near * 1.5);
    let inverse = (c.projection(aspect) * c.view()).inverse();
    matrices::corners(Vec3::NEG_ONE, Vec3::ONE)
        .map(|ndc| inverse.project_point3(ndc))
        .to_vec()
}

/// Every casting light's map, its view this frame, and the `Shadows` block.
pub struct ShadowMaps {
    pub maps: Vec<(Caster, DepthMap)>,
    /// This frame's light views, one per map (None: nothing to draw).
    pub views: Vec<Option<LightView>>,
    /// 1 x 1 maps bound to the samplers no light uses: GL 3.3 wants a
    /// complete texture of the sampler's type on every unit a program reads.
    empty_2d: DepthMap,
    empty_cube: DepthMap,
    /// The cascades' block and, when the GL has the unit, an empty array.
    cascades: cascades::CascadeBlock,
    ubo: Buffer,
    max_lights: usize,
}

impl ShadowMaps {
    /// Allocate a map for every caster of `scene`.
    pub fn new(gl: &Gl, scene: &Scene, max_lights: usize) -> Result<ShadowMaps> {
        let mut maps = Vec::new();
        for c in casters(scene) {
            let size = c.shadow.resolution as i32;
            let map = if c.cascaded() {
                let need = &cascades::UNITS;
                crate::frame::unit_check::check_units(gl, &scene.path, need)?;
                DepthMap::new_array(gl, size, c.shadow.cascades as i32)?
            } else if c.cube {
                let layered = c.shadow.cube == CubeRender::GeometryShader;
                DepthMap::new_cube(gl, size, layered)?
            } else {
                DepthMap::new_2d(gl, size)?
            };
            sampler::as_shadow_sampler(gl, &map, c.shadow.pcf);
            maps.push((c, map));
        }
        let empty_2d = DepthMap::new_2d(gl, 1)?;
        let empty_cube = DepthMap::new_cube(gl, 1, false)?;
        sampler::as_shadow_sampler(gl, &empty_2d, Pcf::None);
        sampler::as_shadow_sampler(gl, &empty_cube, Pcf::None);
        let mut cascades = cascades::CascadeBlock::new(gl)?;
        cascades.needed = cascades::read_by(scene);
        if let Some(a) = &cascades.empty {
            sampler::as_shadow_sampler(gl, a, Pcf::None);
        }
        let ubo = Buffer::new(
            gl,
            glow::UNIFORM_BUFFER,
            block_size(max_lights),
            glow::DYNAMIC_DRAW,
        )?;
        Ok(ShadowMaps {
            views: vec![None; maps.len()],
            maps,
            empty_2d,
            empty_cube,
            cascades,
            ubo,
            max_lights,
        })
    }

    /// Take `scene`'s casters (the demo edits them). The maps stay when
    /// only what the lookup reads changed (the biases, culling, the fit);
    /// a new PCF kernel re-sets the sampler's filter; a new light, kind,
    /// resolution or way of drawing a cube allocates the maps anew.
    pub fn take_casters(&mut self, gl: &Gl, scene: &Scene) -> Result<()> {
        let new = casters(scene);
        self.cascades.needed = cascades::read_by(scene);
        let same_textures = new.len() == self.maps.len()
            && new.iter().zip(&self.maps).all(|(n, (o, _))| {
                let key = |c: &Caster| {
                    let s = c.shadow;
                    (c.light, c.slot, c.cube, s.resolution, s.cube, s.cascades)
                };
                key(n) == key(o)
            });
        if !same_textures {
            *self = ShadowMaps::new(gl, scene, self.max_lights)?;
            return Ok(());
        }
        for (n, (o, map)) in new.into_iter().zip(&mut self.maps) {
            if n.shadow.pcf != o.shadow.pcf {
                sampler::as_shadow_sampler(gl, map, n.shadow.pcf);
            }
            *o = n;
        }
        Ok(())
    }

    /// Fit each light's view to the scene and the camera, and write the
    /// `Shadows` block.
    pub fn update(&mut self, scene: &Scene, draws: &DrawList, camera: &Camera, aspect: f32) {
        let points = draws.world_corners();
        let visible = visible_corners(camera, aspect, &points);
        self.views = (self.maps.iter())
            .map(|(c, _)| light_view(scene, c, &points, (&visible, camera)))
            .collect();
        self.ubo.write(&block::pack(self));
        let cascaded = (self.maps.iter().zip(&self.views)).find(|((c, _), _)| c.cascaded());
        let cascaded = cascaded.and_then(|((c, _), v)| Some((c, v.as_ref()?)));
        self.cascades.write(camera, cascaded);
    }

    /// The lights whose maps are drawn this frame (a caster with nothing to
    /// cast onto has none): the `u_casters` list of the `Shadows` block.
    pub fn casting_lights(&self) -> Vec<usize> {
        (self.maps.iter().zip(&self.views))
            .filter(|(_, v)| v.is_some())
            .map(|((c, _), _)| c.light)
            .collect()
    }

    /// Bind every map to its texture unit (the unused samplers get the
    /// empty maps) and the `Shadows` block to its binding point.
    pub fn bind(&self, gl: &glow::Context) {
        unsafe {
            for i in 0..MAX_SHADOW_MAPS_2D as u32 {
                let (flat, cube) = (self.empty_2d.texture, self.empty_cube.texture);
                bind_one(gl, UNIT_2D + i, glow::TEXTURE_2D, Some(flat));
                bind_one(gl, UNIT_CUBE + i, glow::TEXTURE_CUBE_MAP, Some(cube));
            }
            self.cascades.bind(gl);
            for (c, map) in &self.maps {
                bind_one(gl, c.unit(), map.target, Some(map.texture));
            }
            gl.active_texture(glow::TEXTURE0);
            gl.bind_buffer_base(glow::UNIFORM_BUFFER, SHADOWS_BINDING, Some(self.ubo.id));
        }
    }

    /// The `Cascades` block alone (`on`), or unbound: the deferred paths'
    /// last passes read it for the cascade colours (`cascade_tints`).
    pub fn bind_cascade_block(&self, gl: &glow::Context, on: bool) {
        self.cascades.bind_block(gl, on);
    }

    /// Undo `bind`.
    pub fn unbind(&self, gl: &glow::Context) {
        unsafe {
            for i in 0..MAX_SHADOW_MAPS_2D as u32 {
                bind_one(gl, UNIT_2D + i, glow::TEXTURE_2D, None);
                bind_one(gl, UNIT_CUBE + i, glow::TEXTURE_CUBE_MAP, None);
            }
            self.cascades.unbind(gl);
            gl.active_texture(glow::TEXTURE0);
            gl.bind_buffer_base(glow::UNIFORM_BUFFER, SHADOWS_BINDING, None);
        }
    }
}
