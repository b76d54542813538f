//! Static lighting (notes 01 §8.2: "combining texture with a light map. No
//! real time updates. No additional computation."): an object's diffuse
//! light, baked on the CPU when the scene loads into a texture over the
//! mesh's own uvs, which the forward pass multiplies by the material's
//! colour instead of running its light loop.
//!
//! Baking, texel by texel: each triangle is rasterised in uv space (texel
//! centre (x + 1/2, y + 1/2) / size, v up as GL's textures run); for a
//! texel it covers, the barycentric weights give the surface point P and
//! normal N, and the texel holds the Phong diffuse light there, summed over
//! the scene's lights: radiance x attenuation x N . L (`phong_light`, the
//! shaders' CPU twin), times 0 where a shadow ray from P to the light hits
//! a triangle (`SceneTriangles`, when `shadows` is on). Texels no triangle
//! covers take their nearest covered neighbour's value, a few texels out,
//! so that bilinear filtering at a chart's edge does not blend in black.
//!
//! Light maps hold only the view-independent diffuse light: specular
//! highlights move with the eye and cannot be baked.

use super::phong_light;
use super::shadow_reference::{LightRay, SceneTriangles};
use crate::geometry::MeshData;
use crate::math;
use crate::scene::Scene;
use glam::{DVec2, Mat3, Vec3};

/// A baked light map: linear RGB irradiance, row 0 at v = 0.
#[derive(Clone, Debug)]
pub struct LightMap {
    pub size: u32,
    pub texels: Vec<[f32; 3]>,
    /// Texels more than one triangle covered (overlapping uvs: the map
    /// holds the last).
    pub overlaps: usize,
}

/// How far (in texels) the baked texels are spread into the uncovered ones.
pub const DILATION: u32 = 4;

/// Bake object `object` of `scene` (mesh `mesh`, its model matrix from the
/// scene) into a `size` x `size` map; `occluders` casts the shadow rays.
pub fn bake(
    scene: &Scene,
    object: usize,
    mesh: &MeshData,
    size: u32,
    occluders: Option<&SceneTriangles>,
) -> LightMap {
    let o = &scene.objects[object];
    let normal_matrix = math::normal_matrix(&o.model).unwrap_or_else(|| Mat3::from_mat4(o.model));
    let n = size as usize;
    let mut texels = vec![[0.0f32; 3]; n * n];
    let mut covered = vec![false; n * n];
    let mut overlaps = 0;
    for t in mesh.indices.chunks_exact(3) {
        let v = [0, 1, 2].map(|k| &mesh.vertices[t[k] as usize]);
        let uv = v.map(|v| DVec2::new(f64::from(v.uv[0]), f64::from(v.uv[1])) * f64::from(size));
        let lo = uv[0].min(uv[1]).min(uv[2]).floor().max(DVec2::ZERO);
        let hi = uv[0]
            .max(uv[1])
            .max(uv[2])
            .ceil()
            .min(DVec2::splat(f64::from(size)));
        for y in lo.y as usize..hi.y as usize {
            for x in lo.x as usize..hi.x as usize {
                let p = DVec2::new(x as f64 + 0.5, y as f64 + 0.5);
                let Some(b) = math::interpolation::barycentric(p, uv) else {
                    continue;
                };
                if b.iter().any(|&w| w < -1e-9) {
                    continue;
                }
                let mix = |f: &dyn Fn(&crate::geometry::Vertex) -> [f32; 3]| {
                    let [a, bb, c] = v.map(|v| Vec3::from(f(v)));
                    a * b[0] as f32 + bb * b[1] as f32 + c * b[2] as f32
                };
                let local = mix(&|v| v.position);
                let world = o.model.transform_point3(local);
                let normal = (normal_matrix * mix(&|v| v.normal)).try_normalize();
                let Some(normal) = normal else { continue };
                let i = y * n + x;
                if covered[i] {
                    // On an edge two triangles share, the first keeps it;
                    // strictly inside a second triangle, the uvs overlap.
                    if b.iter().all(|&w| w > 1e-6) {
                        overlaps += 1;
                    } else {
                        continue;
                    }
                }
                covered[i] = true;
                texels[i] = irradiance(scene, world, normal, occluders).to_array();
            }
        }
    }
    dilate(&mut texels, &mut covered, n);
    LightMap {
        size,
        texels,
        overlaps,
    }
}

/// The diffuse light reaching a surface point with normal `n` from every
/// light of the scene (before the material's colour), as the forward
/// pass's light loop adds it.
pub fn irradiance(scene: &Scene, p: Vec3, n: Vec3, occluders: Option<&SceneTriangles>) -> Vec3 {
    let mut e = Vec3::ZERO;
    for l in &scene.lights {
        if occluders.is_some_and(|s| s.occluded(p, LightRay::of(l))) {
            continue;
        }
        // The view direction only matters to the specular term.
        e += phong_light(l, p, n, n, 1.0).0;
    }
    e
}

/// Spread covered texels into uncovered neighbours, `DILATION` rings out.
fn dilate(texels: &mut [[f32; 3]], covered: &mut [bool], n: usize) {
    for _ in 0..DILATION {
        let (before, was) = (texels.to_vec(), covered.to_vec());
        for y in 0..n {
            for x in 0..n {
                if was[y * n + x] {
                    continue;
                }
                let near = [(0, 1), (2, 1), (1, 0), (1, 2)]
                    .iter()
                    .find_map(|&(dx, dy)| {
                        let (nx, ny) = ((x + dx).checked_sub(1)?, (y + dy).checked_sub(1)?);
                        (nx < n && ny < n && was[ny * n + nx]).then(|| before[ny * n + nx])
                    });
                if let Some(t) = near {
                    texels[y * n + x] = t;
                    covered[y * n + x] = true;
                }
            }
        }
    }
}
