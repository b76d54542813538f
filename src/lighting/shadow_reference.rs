//! The exact answer shadow mapping approximates (notes 01 §8.5): a surface
//! point is in shadow from a light when a triangle of the scene lies on the
//! segment from the point to the light (to infinity along `-direction` for a
//! directional light). No depth map, no resolution, no bias: a ray against
//! every caster's triangles, through a bounding volume hierarchy (`bvh`,
//! written by hand: the Rust BVH crates build on nalgebra, not glam).
//!
//! For each pixel the surface point comes from the depth buffer: the pixel
//! centre and its window depth d are mapped back to normalised device
//! coordinates and through the inverse view-projection,
//! ```text
//! ndc = ((x + 0.5) / w * 2 - 1, (y + 0.5) / h * 2 - 1, d * 2 - 1, 1)
//! p   = inverse(P V) ndc,  world point = p.xyz / p.w
//! ```
//! (x, y from the bottom-left, as glReadPixels gives rows).
//!
//! Self-shadowing: the point read back lies a little off its surface (depth
//! is quantised), so its own triangle could shadow it. The ray starts
//! `epsilon` along (`EPSILON_PER_SIZE` = 1e-4 times the scene's size, the
//! diagonal of the box around its casters) and a triangle within `epsilon`
//! of the start point never counts: a surface does not shadow itself. The
//! price is that an occluder closer than `epsilon` to the point (at a contact)
//! is missed, a band far thinner than a pixel in the shadow scenes.
//!
//! Alpha-tested casters (a leaf's cut-out) block a ray only where their
//! texel passes the material's alpha test (shadow_reference/cutouts.rs).
//!
//! Also the analytic case of the tests: a sphere's shadow on a plane from a
//! point light, a conic section, in closed form.

mod cutouts;

use super::bvh::Bvh;
use super::triangle::Triangle;
use crate::image_compare::shadow_metrics::Visibility;
use crate::scene::meshes::mesh_data;
use crate::scene::{Light, LightKind, MeshSource, Scene};
use anyhow::Result;
use glam::{Mat4, Vec3, Vec4};
use std::collections::HashMap;

/// The self-hit epsilon, as a fraction of the scene's size.
pub const EPSILON_PER_SIZE: f32 = 1e-4;

/// Where the light is seen from a surface point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightRay {
    /// A point or spot light at this position: the segment up to it.
    Position(Vec3),
    /// A directional light shining along this direction: the ray along
    /// `-direction`, to infinity.
    Direction(Vec3),
}

impl LightRay {
    pub fn of(light: &Light) -> LightRay {
        match light.kind {
            LightKind::Directional => LightRay::Direction(light.direction),
            LightKind::Point | LightKind::Spot => LightRay::Position(light.position),
        }
    }
}

/// Every shadow caster of a scene, in world space, in a BVH.
pub struct SceneTriangles {
    bvh: Bvh,
    /// The alpha-tested casters (cutouts.rs).
    cutouts: cutouts::Cutouts,
    /// World-space self-hit distance (module header).
    pub epsilon: f32,
}

impl SceneTriangles {
    /// The triangles of every object that casts a shadow: all but those
    /// whose material is transparent (opacity < 1) or alpha-tests with no
    /// texture and fails everywhere, each mesh moved to the world by its
    /// object's model matrix. An alpha-tested caster blocks a ray only
    /// where its texel passes the test (cutouts.rs).
    pub fn new(scene: &Scene) -> Result<SceneTriangles> {
        let mut meshes = HashMap::<&MeshSource, _>::new();
        let mut triangles = Vec::new();
        let mut cutouts = cutouts::Cutouts::default();
        let mut textures = HashMap::<usize, Option<usize>>::new();
        for o in &scene.objects {
            let material = &scene.materials[o.material];
            if material.is_transparent() {
                continue;
            }
            let texture = match textures.get(&o.material) {
                Some(&t) => t,
                None => {
                    let t = cutouts::AlphaTexture::of(material)?.map(|t| cutouts.add_texture(t));
                    textures.insert(o.material, t);
                    t
                }
            };
            if texture.is_none() && !cutouts::passes_untextured(material) {
                continue;
            }
            if !meshes.contains_key(&o.mesh) {
                meshes.insert(&o.mesh, mesh_data(&o.mesh)?);
            }
            let m = &meshes[&o.mesh];
            let world: Vec<Vec3> = m
                .vertices
                .iter()
                .map(|v| o.model.transform_point3(Vec3::from(v.position)))
                .collect();
            let (scale, offset) = (material.texturing.uv_scale, material.texturing.uv_offset);
            let uv = |i: u32| {
                let t = m.vertices[i as usize].uv;
                glam::Vec2::new(t[0] * scale[0] + offset[0], t[1] * scale[1] + offset[1])
            };
            for t in m.indices.chunks_exact(3) {
                let tri = Triangle {
                    a: world[t[0] as usize],
                    b: world[t[1] as usize],
                    c: world[t[2] as usize],
                };
                if let Some(k) = texture {
                    cutouts.add_triangle(&tri, k, [uv(t[0]), uv(t[1]), uv(t[2])]);
                }
                triangles.push(tri);
            }
        }
        let mut s = SceneTriangles::from_triangles(triangles);
        s.cutouts = cutouts;
        Ok(s)
    }

    /// The same from world-space triangles.
    pub fn from_triangles(triangles: Vec<Triangle>) -> SceneTriangles {
        let bvh = Bvh::new(triangles);
        let size = bvh.bounds().map_or(0.0, |(lo, hi)| (hi - lo).length());
        SceneTriangles {
            bvh,
            cutouts: cutouts::Cutouts::default(),
            epsilon: (EPSILON_PER_SIZE * size).max(1e-6),
        }
    }

    pub fn triangle_count(&self) -> usize {
        self.bvh.triangles().len()
    }

    /// The hierarchy itself (for closest-hit queries).
    pub fn bvh(&self) -> &Bvh {
        &self.bvh
    }

    /// Whether a caster lies between the surface point `from` and the light:
    /// a hit at `epsilon < t < distance to the light - epsilon` (to infinity
    /// for a directional light) on a triangle farther than `epsilon` from
    /// `from`.
    pub fn occluded(&self, from: Vec3, to_light: LightRay) -> bool {
        let eps = self.epsilon;
        let (dir, t_max) = match to_light {
            LightRay::Position(p) => {
                let d = p - from;
                let len = d.length();
                if len <= 2.0 * eps {
                    return false;
                }
                (d / len, len - eps)
            }
            LightRay::Direction(d) => match (-d).try_normalize() {
                Some(d) => (d, f32::INFINITY),
                None => return false,
            },
        };
        self.bvh.any_hit(from, dir, eps, t_max, |t| {
            t.distance(from) > eps && self.cutouts.blocks(t, from, dir)
        })
    }

    /// Lit or shadowed, per pixel, from light `light` of `scene`: `depth` is
    /// the window depth (0..1, `width x height`, rows bottom-up as
    /// glReadPixels gives them), `inverse_view_projection` the camera's
    /// inverse(P V). Depth 1 (nothing drawn) is `Background`. The result has
    /// the same layout as `depth`. Whether the pixel faces the light is not
    /// decided here: the GL mask leaves out pixels the light does not reach.
    /// Panics if `depth` is not `width * height` long or `light` is out of range.
    pub fn reference_mask(
        &self,
        scene: &Scene,
        light: usize,
        depth: &[f32],
        inverse_view_projection: Mat4,
        width: usize,
        height: usize,
    ) -> Vec<Visibility> {
        assert_eq!(depth.len(), width * height, "depth is not width x height");
        let ray = LightRay::of(&scene.lights[light]);
        let mut out = vec![Visibility::Background; depth.len()];
        if width == 0 {
            return out;
        }
        // Rows split among the cores (scoped threads, no crate).
        let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
        let rows_per = height.div_ceil(threads).max(1);
        std::thread::scope(|s| {
            for (chunk, rows) in out.chunks_mut(rows_per * width).enumerate() {
                s.spawn(move || {
                    for (i, v) in rows.iter_mut().enumerate() {
                        let (x, y) = (i % width, chunk * rows_per + i / width);
                        let d = depth[y * width + x];
                        if d >= 1.0 || d.is_nan() {
                            continue;
                        }
                        let p = pixel_world_point(x, y, d, inverse_view_projection, width, height);
                        *v = if self.occluded(p, ray) {
                            Visibility::Shadowed
                        } else {
                            Visibility::Lit
                        };
                    }
                });
            }
        });
        out
    }
}

/// The world point pixel (x, y) (from the bottom-left) shows at window
/// depth `depth` (module header).
pub fn pixel_world_point(
    x: usize,
    y: usize,
    depth: f32,
    inverse_view_projection: Mat4,
    width: usize,
    height: usize,
) -> Vec3 {
    let ndc = Vec4::new(
        (x as f32 + 0.5) / width as f32 * 2.0 - 1.0,
        (y as f32 + 0.5) / height as f32 * 2.0 - 1.0,
        depth * 2.0 - 1.0,
        1.0,
    );
    let p = inverse_view_projection * ndc;
    p.truncate() / p.w
}

/// Every pixel's world point, in the layout of `depth` (pixels that show the
/// background land on the far plane).
pub fn world_points(
    depth: &[f32],
    inverse_view_projection: Mat4,
    width: usize,
    height: usize,
) -> Vec<Vec3> {
    (0..depth.len())
        .map(|i| {
            let (x, y) = (i % width, i / width);
            pixel_world_point(x, y, depth[i], inverse_view_projection, width, height)
        })
        .collect()
}

/// Distance from `p` to the segment from `a` to `b`.
pub fn segment_distance(p: Vec3, a: Vec3, b: Vec3) -> f32 {
    let ab = b - a;
    let t = ((p - a).dot(ab) / ab.length_squared().max(f32::MIN_POSITIVE)).clamp(0.0, 1.0);
    (a + ab * t - p).length()
}

/// The analytic shadow of a sphere (centre, radius) from a point light: a
/// point (on the floor y = 0 in the tests) is shadowed exactly when the
/// segment from it to the light passes within `radius` of the centre. On a
/// plane the shadowed points fill a conic section (an ellipse when the light
/// is above the top of the sphere).
pub fn sphere_shadow_on_plane(
    light: Vec3,
    centre: Vec3,
    radius: f32,
    point_on_floor: Vec3,
) -> bool {
    segment_distance(centre, point_on_floor, light) < radius
}

#[cfg(test)]
mod tests;
