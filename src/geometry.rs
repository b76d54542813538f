//! CPU-side meshes: the interleaved vertex layout, procedural shapes, OBJ loading
//! and tangent generation. `gl::mesh` uploads a `MeshData` into a VAO.
//!
//! Conventions for every mesh made here:
//!
//! * right-handed model space, y up; front faces wind counter-clockwise seen
//!   from outside (GL's default `glFrontFace(GL_CCW)`), normals point outward
//!   and have unit length;
//! * uv (0, 0) is the bottom-left of a texture: v grows upward, as GL samples
//!   textures that `gl::texture` flipped on load;
//! * `tangent.xyz` is the unit direction of increasing u, perpendicular to the
//!   normal; `tangent.w` (+1 or -1) is the handedness, so the bitangent of
//!   notes 01 §8.4 is `B = cross(N, T) * tangent.w` (direction of increasing v).
//!   Every procedural mesh has w = +1.

use anyhow::{Context, Result, anyhow, bail};
use glam::{Vec2, Vec3};
use std::collections::HashMap;
use std::f32::consts::{PI, TAU};
use std::io::Read;
use std::path::Path;

/// One interleaved vertex: position, normal, uv, tangent (xyz + handedness w).
/// 48 bytes; attribute locations 0..3 in every shader.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Vertex {
    pub position: [f32; 3],
    pub normal: [f32; 3],
    pub uv: [f32; 2],
    pub tangent: [f32; 4],
}

/// An indexed triangle list.
#[derive(Clone, Debug, Default)]
pub struct MeshData {
    pub vertices: Vec<Vertex>,
    pub indices: Vec<u32>,
}

impl MeshData {
    /// Number of triangles (`indices.len() / 3`).
    pub fn triangle_count(&self) -> usize {
        self.indices.len() / 3
    }

    fn push(&mut self, position: Vec3, normal: Vec3, uv: Vec2) -> u32 {
        self.vertices.push(Vertex {
            position: position.to_array(),
            normal: normal.to_array(),
            uv: uv.to_array(),
            tangent: [1.0, 0.0, 0.0, 1.0],
        });
        (self.vertices.len() - 1) as u32
    }

    /// Two triangles for the quad a, b, c, d given counter-clockwise.
    fn quad(&mut self, a: u32, b: u32, c: u32, d: u32) {
        self.indices.extend_from_slice(&[a, b, c, a, c, d]);
    }

    /// A `(columns + 1) x (rows + 1)` grid of vertices from `f(u, v)` ->
    /// (position, normal), u and v in 0..1, stitched into counter-clockwise
    /// quads (u to the right, v up as seen from the front). The seam column
    /// is duplicated so it can carry u = 1.
    fn grid(&mut self, columns: u32, rows: u32, f: impl Fn(f32, f32) -> (Vec3, Vec3)) {
        let base = self.vertices.len() as u32;
        for i in 0..=rows {
            for j in 0..=columns {
                let uv = Vec2::new(j as f32 / columns as f32, i as f32 / rows as f32);
                let (p, n) = f(uv.x, uv.y);
                self.push(p, n, uv);
            }
        }
        let at = |j: u32, i: u32| base + i * (columns + 1) + j;
        for i in 0..rows {
            for j in 0..columns {
                self.quad(at(j, i), at(j + 1, i), at(j + 1, i + 1), at(j, i + 1));
            }
        }
    }
}

// Parameter ranges: small enough that indices fit in u32 and memory stays
// sane, large enough for anything a scene wants. Out-of-range values are
// clamped, never a panic.
const MAX_GRID: u32 = 1024;
const MAX_SEGMENTS: u32 = 4096;
const MAX_ICO_SUBDIVISIONS: u32 = 7;

/// A unit sphere (radius 1, centred) of `stacks` rings from pole to pole and
/// `slices` segments around y. Poles on ±y; u goes around (seam at -z, u = 0.5
/// faces +z), v from 0 at the south pole to 1 at the north pole.
/// `stacks` is clamped to 2..=1024, `slices` to 3..=1024.
/// (stacks + 1) * (slices + 1) vertices, 6 * slices * (stacks - 1) indices.
pub fn uv_sphere(stacks: u32, slices: u32) -> MeshData {
    let stacks = stacks.clamp(2, MAX_GRID);
    let slices = slices.clamp(3, MAX_GRID);
    let mut m = MeshData::default();
    for i in 0..=stacks {
        for j in 0..=slices {
            let v = i as f32 / stacks as f32;
            let mut u = j as f32 / slices as f32;
            if i == 0 || i == stacks {
                // One pole vertex per slice, its u in the middle of the slice.
                u = (j as f32 + 0.5) / slices as f32;
            }
            let p = sphere_point(u, v);
            m.push(p, p, Vec2::new(u, v));
        }
    }
    let at = |j: u32, i: u32| i * (slices + 1) + j;
    for i in 0..stacks {
        for j in 0..slices {
            let (a, b, c, d) = (at(j, i), at(j + 1, i), at(j + 1, i + 1), at(j, i + 1));
            // Skip the triangle that would collapse onto a pole.
            if i != 0 {
                m.indices.extend_from_slice(&[a, b, c]);
            }
            if i != stacks - 1 {
                m.indices.extend_from_slice(&[a, c, d]);
            }
        }
    }
    compute_tangents(&mut m);
    m
}

/// The point of the unit sphere at texture coordinate (u, v): longitude
/// 2πu measured from -z, v = 0 south pole, v = 1 north pole. dP/du points
/// along +x at u = 0.5 (the +z side), so tangents come out with w = +1.
fn sphere_point(u: f32, v: f32) -> Vec3 {
    let (st, ct) = turn(u);
    let (sp, cp) = (PI * (1.0 - v)).sin_cos();
    // Exact poles: sin(π) is not exactly 0 in f32.
    let sp = if v <= 0.0 || v >= 1.0 { 0.0 } else { sp };
    Vec3::new(-sp * st, cp, -sp * ct)
}

/// (sin, cos) of the angle 2πt, with t = 1 giving exactly the same values
/// as t = 0, so the vertices duplicated along a u seam coincide exactly.
fn turn(t: f32) -> (f32, f32) {
    (TAU * t.fract()).sin_cos()
}

/// Inverse of `sphere_point` for a unit vector: (u, v), u in [0, 1).
fn sphere_uv(p: Vec3) -> Vec2 {
    let u = (-p.x).atan2(-p.z) / TAU;
    let u = if u < 0.0 { u + 1.0 } else { u };
    let v = 1.0 - p.y.clamp(-1.0, 1.0).acos() / PI;
    Vec2::new(u.min(1.0), v)
}

/// A geodesic unit sphere: an icosahedron whose triangles are each split in
/// four `subdivisions` times (clamped to 0..=7), new vertices pushed out to
/// radius 1: 20 * 4^s triangles. Every vertex lies ON the unit sphere, so the faces
/// cut inside it; see [`light_volume_sphere`] for a mesh that encloses it.
/// uvs use the same longitude/latitude mapping as [`uv_sphere`]; vertices are
/// duplicated along the u seam and at the poles so no triangle wraps.
pub fn icosphere(subdivisions: u32) -> MeshData {
    let subdivisions = subdivisions.min(MAX_ICO_SUBDIVISIONS);
    let t = (1.0 + 5.0f32.sqrt()) / 2.0;
    let mut positions: Vec<Vec3> = [
        (-1.0, t, 0.0),
        (1.0, t, 0.0),
        (-1.0, -t, 0.0),
        (1.0, -t, 0.0),
        (0.0, -1.0, t),
        (0.0, 1.0, t),
        (0.0, -1.0, -t),
        (0.0, 1.0, -t),
        (t, 0.0, -1.0),
        (t, 0.0, 1.0),
        (-t, 0.0, -1.0),
        (-t, 0.0, 1.0),
    ]
    .iter()
    .map(|&(x, y, z)| Vec3::new(x, y, z).normalize())
    .collect();
    let mut faces: Vec<[u32; 3]> = vec![
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    for _ in 0..subdivisions {
        let mut midpoints: HashMap<(u32, u32), u32> = HashMap::new();
        let mut mid = |a: u32, b: u32, positions: &mut Vec<Vec3>| -> u32 {
            *midpoints.entry((a.min(b), a.max(b))).or_insert_with(|| {
                let p = (positions[a as usize] + positions[b as usize]).normalize();
                positions.push(p);
                (positions.len() - 1) as u32
            })
        };
        let mut next = Vec::with_capacity(faces.len() * 4);
        for [a, b, c] in faces {
            let ab = mid(a, b, &mut positions);
            let bc = mid(b, c, &mut positions);
            let ca = mid(c, a, &mut positions);
            next.extend_from_slice(&[[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]);
        }
        faces = next;
    }

    // Give every triangle corner a uv, splitting vertices where the same
    // position needs two different u (the seam, the poles).
    let mut m = MeshData::default();
    let mut remap: HashMap<(u32, u32), u32> = HashMap::new();
    for face in faces {
        let p = face.map(|i| positions[i as usize]);
        let mut uv = p.map(sphere_uv);
        let pole = p.map(|q| q.x.abs() < 1e-6 && q.z.abs() < 1e-6);
        let others: Vec<usize> = (0..3).filter(|&k| !pole[k]).collect();
        let (lo, hi) = others.iter().fold((f32::MAX, f32::MIN), |(lo, hi), &k| {
            (lo.min(uv[k].x), hi.max(uv[k].x))
        });
        if hi - lo > 0.5 {
            for &k in &others {
                if uv[k].x < 0.5 {
                    uv[k].x += 1.0;
                }
            }
        }
        let mean_u = others.iter().map(|&k| uv[k].x).sum::<f32>() / others.len().max(1) as f32;
        for k in 0..3 {
            if pole[k] {
                uv[k].x = mean_u;
            }
        }
        for k in 0..3 {
            let key = (face[k], uv[k].x.to_bits());
            let index = *remap
                .entry(key)
                .or_insert_with(|| m.push(p[k], p[k], uv[k]));
            m.indices.push(index);
        }
    }
    compute_tangents(&mut m);
    m
}

/// The sphere mesh for point-light volumes (notes 04): [`icosphere`]`(2)`
/// scaled up so that it ENCLOSES the unit sphere.
///
/// An icosphere's vertices lie on the unit sphere, so its flat faces cut
/// inside it: a volume scaled to the light radius would miss the fragments
/// near the edge of the light, and their light would go missing. Here the
/// distance from the origin to every face plane is computed exactly (in f64),
/// and positions are divided by the smallest one (plus one part in a million
/// so f32 rounding cannot put a plane back inside). Every face plane is then
/// at distance >= 1, so scaling this mesh by the light radius covers the whole
/// sphere of influence; the vertices end up at radius about 1.018.
pub fn light_volume_sphere() -> MeshData {
    let mut m = icosphere(2);
    let min_distance = face_planes(&m)
        .map(|(_, d)| d)
        .fold(f64::INFINITY, f64::min);
    let s = ((1.0 + 1e-6) / min_distance) as f32;
    for v in &mut m.vertices {
        v.position = (Vec3::from(v.position) * s).to_array();
    }
    m
}

/// (unit outward normal, distance from the origin) of every triangle's plane,
/// in f64. Degenerate triangles are skipped.
fn face_planes(m: &MeshData) -> impl Iterator<Item = (glam::DVec3, f64)> + '_ {
    m.indices.chunks_exact(3).filter_map(move |t| {
        let p = |i: u32| {
            m.vertices
                .get(i as usize)
                .map(|v| Vec3::from(v.position).as_dvec3())
        };
        let (a, b, c) = (p(t[0])?, p(t[1])?, p(t[2])?);
        let n = (b - a).cross(c - a).try_normalize()?;
        Some((n, n.dot(a)))
    })
}

/// A cube of side 2 centred on the origin, with per-face normals and each face
/// mapped to the whole 0..1 uv square (upright when the face is seen from
/// outside with +y up; the top and bottom faces have u along +x).
/// 24 vertices, 36 indices.
pub fn cube() -> MeshData {
    let mut m = MeshData::default();
    // (outward normal, direction of increasing u); v runs along cross(n, u).
    let faces = [
        (Vec3::X, Vec3::NEG_Z),
        (Vec3::NEG_X, Vec3::Z),
        (Vec3::Y, Vec3::X),
        (Vec3::NEG_Y, Vec3::X),
        (Vec3::Z, Vec3::X),
        (Vec3::NEG_Z, Vec3::NEG_X),
    ];
    for (n, t) in faces {
        let b = n.cross(t);
        let [a, bb, c, d] =
            [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)].map(|(s, r): (f32, f32)| {
                m.push(
                    n + t * s + b * r,
                    n,
                    Vec2::new((s + 1.0) / 2.0, (r + 1.0) / 2.0),
                )
            });
        m.quad(a, bb, c, d);
    }
    compute_tangents(&mut m);
    m
}

/// A flat plane in y = 0 facing +y, `size_x` by `size_z`, centred on the
/// origin, split into `divisions` x `divisions` quads (clamped to 1..=1024).
/// u runs 0..1 along +x and v 0..1 along -z (away from a viewer on +z), so
/// the tangent is +x with w = +1. (divisions + 1)^2 vertices.
pub fn plane(size_x: f32, size_z: f32, divisions: u32) -> MeshData {
    let d = divisions.clamp(1, MAX_GRID);
    let mut m = MeshData::default();
    m.grid(d, d, |u, v| {
        (
            Vec3::new((u - 0.5) * size_x, 0.0, (0.5 - v) * size_z),
            Vec3::Y,
        )
    });
    compute_tangents(&mut m);
    m
}

/// A closed cylinder of radius 1 around the y axis from y = -1 to y = 1,
/// `segments` around (clamped to 3..=4096). The side has smooth normals and u
/// around (seam at -z, as [`uv_sphere`]), v up; the caps are separate
/// vertices with flat normals ±y and a planar uv disc.
pub fn cylinder(segments: u32) -> MeshData {
    let n = segments.clamp(3, MAX_SEGMENTS);
    let mut m = MeshData::default();
    m.grid(n, 1, |u, v| {
        let (s, c) = turn(u);
        let radial = Vec3::new(-s, 0.0, -c);
        (radial + Vec3::Y * (2.0 * v - 1.0), radial)
    });
    for (y, normal) in [(1.0f32, Vec3::Y), (-1.0, Vec3::NEG_Y)] {
        // Seen from outside (from ±y): u along +x, v along -z on the top cap
        // and along +z on the bottom cap.
        let uv_of = |p: Vec3| Vec2::new(0.5 + 0.5 * p.x, 0.5 - 0.5 * p.z * y);
        let centre = m.push(Vec3::new(0.0, y, 0.0), normal, Vec2::splat(0.5));
        let ring: Vec<u32> = (0..n)
            .map(|j| {
                let (s, c) = turn(j as f32 / n as f32);
                let p = Vec3::new(-s, y, -c);
                m.push(p, normal, uv_of(p))
            })
            .collect();
        for j in 0..n as usize {
            let (a, b) = (ring[j], ring[(j + 1) % n as usize]);
            // The ring turns counter-clockwise seen from +y.
            if y > 0.0 {
                m.indices.extend_from_slice(&[centre, a, b]);
            } else {
                m.indices.extend_from_slice(&[centre, b, a]);
            }
        }
    }
    compute_tangents(&mut m);
    m
}

/// The spot-light volume of notes 04 ("load a cone geometry"): apex at the
/// origin, axis along -z, base cap at z = -1, `segments` around (clamped to
/// 3..=4096).
///
/// It CIRCUMSCRIBES the true cone of half-angle 45° (radius 1 at z = -1):
/// the base vertices sit at radius 1 / cos(π / segments), so each flat side
/// touches the true cone along a line through the apex instead of cutting
/// inside it, and every point of the true cone lies inside this mesh.
/// Scale x and y by tan(outer angle) * range and z by range (then rotate -z
/// onto the spot direction) to cover a spot light; an inscribed cone would
/// lose light along the edges between the base vertices.
///
/// The sides carry the true cone's smooth normals ((cos θ, sin θ, 1) / √2,
/// the apex duplicated per segment), u around and v from 0 at the base to 1
/// at the apex. The base cap faces -z.
pub fn cone(segments: u32) -> MeshData {
    let n = segments.clamp(3, MAX_SEGMENTS);
    let r = 1.0 / (PI / n as f32).cos();
    let mut m = MeshData::default();
    let angle = |k: f32| TAU * (k / n as f32).fract();
    let side_normal = |a: f32| Vec3::new(a.cos(), a.sin(), 1.0) / 2.0f32.sqrt();
    let base: Vec<u32> = (0..=n)
        .map(|j| {
            let a = angle(j as f32);
            let p = Vec3::new(r * a.cos(), r * a.sin(), -1.0);
            m.push(p, side_normal(a), Vec2::new(j as f32 / n as f32, 0.0))
        })
        .collect();
    for j in 0..n {
        let mid = j as f32 + 0.5;
        let apex = m.push(
            Vec3::ZERO,
            side_normal(angle(mid)),
            Vec2::new(mid / n as f32, 1.0),
        );
        m.indices
            .extend_from_slice(&[base[j as usize], base[j as usize + 1], apex]);
    }
    // Base cap, facing -z: seen from -z, u runs along -x and v along +y.
    let centre = m.push(Vec3::new(0.0, 0.0, -1.0), Vec3::NEG_Z, Vec2::splat(0.5));
    let ring: Vec<u32> = (0..n)
        .map(|j| {
            let a = angle(j as f32);
            let (x, y) = (r * a.cos(), r * a.sin());
            let uv = Vec2::new(0.5 - 0.5 * x / r, 0.5 + 0.5 * y / r);
            m.push(Vec3::new(x, y, -1.0), Vec3::NEG_Z, uv)
        })
        .collect();
    for j in 0..n as usize {
        m.indices
            .extend_from_slice(&[centre, ring[(j + 1) % n as usize], ring[j]]);
    }
    compute_tangents(&mut m);
    m
}

/// A torus around the y axis: the tube's centre circle has radius `major`,
/// the tube radius `minor`; `seg_major` segments around y and `seg_minor`
/// around the tube (each clamped to 3..=1024). u goes around y (seam at -z),
/// v around the tube starting on the outer equator.
/// (seg_major + 1) * (seg_minor + 1) vertices.
pub fn torus(major: f32, minor: f32, seg_major: u32, seg_minor: u32) -> MeshData {
    let sm = seg_major.clamp(3, MAX_GRID);
    let sn = seg_minor.clamp(3, MAX_GRID);
    let mut m = MeshData::default();
    m.grid(sm, sn, |u, v| {
        let (st, ct) = turn(u);
        let (sp, cp) = turn(v);
        let radial = Vec3::new(-st, 0.0, -ct);
        let normal = radial * cp + Vec3::Y * sp;
        (radial * major + normal * minor, normal)
    });
    compute_tangents(&mut m);
    m
}

/// One triangle that covers the whole screen when drawn with an identity
/// MVP: clip-space corners (-1, -1), (3, -1), (-1, 3) at z = 0, counter-
/// clockwise, normal +z. Its uvs are (0, 0), (2, 0), (0, 2), so the visible
/// part has uv 0..1 with (0, 0) at the bottom-left of the screen. Used for
/// the directional light and post-processing passes (notes 04).
pub fn fullscreen_triangle() -> MeshData {
    let mut m = MeshData::default();
    for (x, y) in [(-1.0, -1.0), (3.0, -1.0), (-1.0, 3.0)] {
        m.push(
            Vec3::new(x, y, 0.0),
            Vec3::Z,
            Vec2::new((x + 1.0) / 2.0, (y + 1.0) / 2.0),
        );
    }
    m.indices.extend_from_slice(&[0, 1, 2]);
    compute_tangents(&mut m);
    m
}

/// The radius of the smallest origin-centred sphere that contains every
/// vertex (the largest vertex distance from the model-space origin); 0 for
/// an empty mesh. Use it to scale light volumes and for culling.
pub fn bounding_radius(mesh: &MeshData) -> f32 {
    mesh.vertices
        .iter()
        .map(|v| Vec3::from(v.position).length())
        .filter(|r| r.is_finite())
        .fold(0.0, f32::max)
}

/// Replaces every normal by the area-weighted average of the normals of the
/// triangles around it (notes 01 §8.1: the cross product of two edges, whose
/// length is twice the triangle's area, so big triangles count more).
///
/// Vertices at exactly the same position share their normal even when they
/// are separate vertices (split for a uv seam), so seams do not show as
/// creases; give the file normals if you want hard edges. A vertex touched by
/// no usable triangle keeps its normal if it is a usable one, otherwise gets
/// +y. Out-of-range indices are ignored.
pub fn compute_normals(mesh: &mut MeshData) {
    let key = |p: [f32; 3]| p.map(|c| if c == 0.0 { 0 } else { c.to_bits() });
    let mut sums: HashMap<[u32; 3], Vec3> = HashMap::new();
    for t in mesh.indices.chunks_exact(3) {
        let Some(v) = t
            .iter()
            .map(|&i| mesh.vertices.get(i as usize))
            .collect::<Option<Vec<_>>>()
        else {
            continue;
        };
        let p = v.iter().map(|v| Vec3::from(v.position)).collect::<Vec<_>>();
        let n = (p[1] - p[0]).cross(p[2] - p[0]);
        if !n.is_finite() {
            continue;
        }
        for corner in v {
            *sums.entry(key(corner.position)).or_insert(Vec3::ZERO) += n;
        }
    }
    for v in &mut mesh.vertices {
        let sum = sums.get(&key(v.position)).copied().unwrap_or(Vec3::ZERO);
        let n = sum
            .try_normalize()
            .or_else(|| Vec3::from(v.normal).try_normalize())
            .unwrap_or(Vec3::Y);
        v.normal = n.to_array();
    }
}

/// Computes `tangent` for every vertex from the uv layout (notes 01 §8.4):
/// for each triangle, the direction in which u grows across it
/// (dP/du = (e1 * dv2 - e2 * dv1) / det, with edges e1, e2 and uv deltas), and
/// likewise dP/dv. Both are summed per vertex, weighted by the triangle's uv
/// area (so a triangle with zero uv area adds nothing), then the tangent is
/// made perpendicular to the normal (Gram-Schmidt: T - N (N.T)), normalised,
/// and w is set to +1 if cross(N, T) points along dP/dv and -1 if it points
/// against it (mirrored uvs).
///
/// A vertex with no usable uv direction (zero uv area, all uvs equal, no uvs
/// at all, or non-finite data) gets some unit vector perpendicular to its
/// normal instead, and w = +1: never NaN. Normals should be set first.
pub fn compute_tangents(mesh: &mut MeshData) {
    let count = mesh.vertices.len();
    let mut tan = vec![Vec3::ZERO; count];
    let mut bit = vec![Vec3::ZERO; count];
    for t in mesh.indices.chunks_exact(3) {
        let (Some(a), Some(b), Some(c)) = (
            mesh.vertices.get(t[0] as usize),
            mesh.vertices.get(t[1] as usize),
            mesh.vertices.get(t[2] as usize),
        ) else {
            continue;
        };
        let e1 = Vec3::from(b.position) - Vec3::from(a.position);
        let e2 = Vec3::from(c.position) - Vec3::from(a.position);
        let d1 = Vec2::from(b.uv) - Vec2::from(a.uv);
        let d2 = Vec2::from(c.uv) - Vec2::from(a.uv);
        let det = d1.x * d2.y - d2.x * d1.y;
        // (e1 d2.y - e2 d1.y) = det * dP/du: multiplying by sign(det) instead
        // of dividing by det weights each triangle by its uv area.
        let sign = if det < 0.0 { -1.0 } else { 1.0 };
        let t_dir = (e1 * d2.y - e2 * d1.y) * sign;
        let b_dir = (e2 * d1.x - e1 * d2.x) * sign;
        if !t_dir.is_finite() || !b_dir.is_finite() {
            continue;
        }
        for &i in t {
            tan[i as usize] += t_dir;
            bit[i as usize] += b_dir;
        }
    }
    for (i, v) in mesh.vertices.iter_mut().enumerate() {
        let n = Vec3::from(v.normal).try_normalize().unwrap_or(Vec3::Y);
        let t = tan[i];
        let ortho = t - n * n.dot(t);
        // Relative test: T almost parallel to N leaves only rounding noise.
        let usable = ortho.is_finite() && ortho.length() > 1e-6 * t.length();
        let (tangent, w) = match ortho.try_normalize().filter(|_| usable) {
            Some(tangent) => {
                let w = if n.cross(tangent).dot(bit[i]) < 0.0 {
                    -1.0
                } else {
                    1.0
                };
                (tangent, w)
            }
            None => (any_perpendicular(n), 1.0),
        };
        v.tangent = [tangent.x, tangent.y, tangent.z, w];
    }
}

/// A unit vector perpendicular to the unit vector `n`: +x made perpendicular
/// to n (or +y when n is close to ±x). For a +y normal this is +x.
fn any_perpendicular(n: Vec3) -> Vec3 {
    let a = if n.x.abs() < 0.9 { Vec3::X } else { Vec3::Y };
    (a - n * n.dot(a)).try_normalize().unwrap_or(Vec3::X)
}

/// Largest OBJ file `load_obj` reads.
pub const MAX_OBJ_BYTES: u64 = 256 * 1024 * 1024;
/// Most vertices `load_obj` accepts (after splitting by position/uv/normal).
pub const MAX_OBJ_VERTICES: usize = 16_000_000;

/// Loads a Wavefront OBJ through tobj (polygons triangulated, one index per
/// vertex), merging all its objects and groups into one mesh. Materials are
/// ignored. Objects without normals in the file get smooth normals
/// ([`compute_normals`]); tangents are always computed. A file without uvs
/// loads with uv (0, 0) everywhere (and arbitrary tangents).
///
/// Refuses, with an error naming the file: a missing or unreadable file, one
/// over 256 MiB (checked before reading) or with more than 16 million
/// vertices, malformed content, no triangles, NaN or infinite numbers, and
/// face indices out of range.
pub fn load_obj(path: &Path) -> Result<MeshData> {
    load_obj_limited(path, MAX_OBJ_BYTES, MAX_OBJ_VERTICES)
}

fn load_obj_limited(path: &Path, max_bytes: u64, max_vertices: usize) -> Result<MeshData> {
    let name = path.display();
    let meta = std::fs::metadata(path).with_context(|| format!("cannot open OBJ file {name}"))?;
    if !meta.is_file() {
        bail!("OBJ file {name} is not a regular file");
    }
    if meta.len() > max_bytes {
        bail!(
            "OBJ file {name} is too large: {} bytes, the limit is {max_bytes} bytes",
            meta.len()
        );
    }
    let mut bytes = Vec::with_capacity(meta.len() as usize);
    std::fs::File::open(path)
        .and_then(|f| f.take(max_bytes + 1).read_to_end(&mut bytes))
        .with_context(|| format!("cannot read OBJ file {name}"))?;
    if bytes.len() as u64 > max_bytes {
        bail!("OBJ file {name} is too large: it grew past {max_bytes} bytes while being read");
    }
    // Cheap count before tobj allocates anything per vertex.
    let positions = bytes
        .split(|&b| b == b'\n')
        .filter(|l| {
            l.trim_ascii_start().starts_with(b"v ") || l.trim_ascii_start().starts_with(b"v\t")
        })
        .count();
    if positions > max_vertices {
        bail!(
            "OBJ file {name} is too large: {positions} vertex positions, the limit is {max_vertices}"
        );
    }

    let options = tobj::LoadOptions {
        triangulate: true,
        single_index: true,
        ignore_points: true,
        ignore_lines: true,
    };
    let (models, _materials) = tobj::load_obj_buf(&mut bytes.as_slice(), &options, |_| {
        Ok((Vec::new(), Default::default()))
    })
    .map_err(|e| anyhow!("malformed OBJ file {name}: {}", describe_tobj_error(&e)))?;

    let mut mesh = MeshData::default();
    for model in &models {
        let m = &model.mesh;
        let object = &model.name;
        if m.positions.len() % 3 != 0 {
            bail!("malformed OBJ file {name}: object '{object}' has a partial position");
        }
        let n = m.positions.len() / 3;
        if mesh.vertices.len() + n > max_vertices {
            bail!(
                "OBJ file {name} is too large: more than {max_vertices} vertices after splitting by uv and normal"
            );
        }
        let finite = |values: &[f32], what: &str| -> Result<()> {
            match values.iter().position(|x| !x.is_finite()) {
                Some(_) => bail!("OBJ file {name}: object '{object}' has a NaN or infinite {what}"),
                None => Ok(()),
            }
        };
        finite(&m.positions, "vertex position")?;
        finite(&m.normals, "normal")?;
        finite(&m.texcoords, "texture coordinate")?;
        if m.indices.len() % 3 != 0 {
            bail!("malformed OBJ file {name}: object '{object}' has a partial triangle");
        }
        if let Some(&bad) = m.indices.iter().find(|&&i| i as usize >= n) {
            bail!(
                "OBJ file {name}: object '{object}' has face index {bad} out of range ({n} vertices)"
            );
        }
        let has_normals = m.normals.len() == m.positions.len();
        let has_uvs = m.texcoords.len() == 2 * n;
        let mut part = MeshData {
            vertices: (0..n)
                .map(|i| Vertex {
                    position: [
                        m.positions[3 * i],
                        m.positions[3 * i + 1],
                        m.positions[3 * i + 2],
                    ],
                    normal: if has_normals {
                        [m.normals[3 * i], m.normals[3 * i + 1], m.normals[3 * i + 2]]
                    } else {
                        [0.0; 3]
                    },
                    uv: if has_uvs {
                        [m.texcoords[2 * i], m.texcoords[2 * i + 1]]
                    } else {
                        [0.0; 2]
                    },
                    tangent: [1.0, 0.0, 0.0, 1.0],
                })
                .collect(),
            indices: m.indices.clone(),
        };
        if !has_normals {
            compute_normals(&mut part);
        }
        let offset = mesh.vertices.len() as u32;
        for mut v in part.vertices {
            // File normals of zero length fall back to +y rather than NaN.
            v.normal = Vec3::from(v.normal)
                .try_normalize()
                .unwrap_or(Vec3::Y)
                .to_array();
            mesh.vertices.push(v);
        }
        mesh.indices.extend(part.indices.iter().map(|i| i + offset));
    }
    if mesh.indices.len() < 3 {
        bail!("OBJ file {name} contains no triangles");
    }
    compute_tangents(&mut mesh);
    Ok(mesh)
}

fn describe_tobj_error(e: &tobj::LoadError) -> String {
    use tobj::LoadError as E;
    match e {
        E::FaceVertexOutOfBounds | E::FaceTexCoordOutOfBounds | E::FaceNormalOutOfBounds => {
            format!("{e} (face index out of range)")
        }
        E::ReadError => "read error (not UTF-8 text?)".to_string(),
        _ => e.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::PathBuf;

    /// Everything every mesh must satisfy: indices in range and whole
    /// triangles, finite data, unit normals, unit tangents perpendicular to the
    /// normal with w = ±1, and counter-clockwise winding seen from outside:
    /// each triangle's edge cross product points the same way as the average
    /// of its vertex normals.
    fn check_mesh(name: &str, m: &MeshData) {
        assert_eq!(m.indices.len() % 3, 0, "{name}: partial triangle");
        assert!(!m.indices.is_empty(), "{name}: no triangles");
        for (i, v) in m.vertices.iter().enumerate() {
            let all = v
                .position
                .iter()
                .chain(&v.normal)
                .chain(&v.uv)
                .chain(&v.tangent);
            assert!(
                all.clone().all(|x| x.is_finite()),
                "{name}: vertex {i} not finite: {v:?}"
            );
            let n = Vec3::from(v.normal);
            assert!(
                (n.length() - 1.0).abs() < 1e-4,
                "{name}: vertex {i} normal {n}"
            );
            let t = Vec3::new(v.tangent[0], v.tangent[1], v.tangent[2]);
            assert!(
                (t.length() - 1.0).abs() < 1e-4,
                "{name}: vertex {i} tangent {t}"
            );
            assert!(
                t.dot(n).abs() < 1e-4,
                "{name}: vertex {i} tangent not perpendicular"
            );
            assert!(v.tangent[3].abs() == 1.0, "{name}: vertex {i} handedness");
        }
        for (k, t) in m.indices.chunks_exact(3).enumerate() {
            assert!(
                t.iter().all(|&i| (i as usize) < m.vertices.len()),
                "{name}: index range"
            );
            let v = [t[0], t[1], t[2]].map(|i| m.vertices[i as usize]);
            let p = v.map(|v| Vec3::from(v.position));
            let face = (p[1] - p[0]).cross(p[2] - p[0]);
            let avg: Vec3 = v.iter().map(|v| Vec3::from(v.normal)).sum();
            assert!(face.length() > 0.0, "{name}: triangle {k} degenerate");
            assert!(
                face.dot(avg) > 0.0,
                "{name}: triangle {k} winds clockwise seen from outside"
            );
        }
    }

    fn procedural() -> Vec<(&'static str, MeshData)> {
        vec![
            ("uv_sphere", uv_sphere(12, 24)),
            ("uv_sphere_min", uv_sphere(0, 0)),
            ("icosphere0", icosphere(0)),
            ("icosphere3", icosphere(3)),
            ("light_volume_sphere", light_volume_sphere()),
            ("cube", cube()),
            ("plane", plane(4.0, 2.0, 3)),
            ("cylinder", cylinder(16)),
            ("cone", cone(16)),
            ("cone3", cone(3)),
            ("torus", torus(1.0, 0.25, 32, 12)),
            ("fullscreen_triangle", fullscreen_triangle()),
        ]
    }

    #[test]
    fn procedural_meshes_are_well_formed() {
        for (name, m) in procedural() {
            check_mesh(name, &m);
        }
    }

    #[test]
    fn procedural_counts() {
        let s = uv_sphere(12, 24);
        assert_eq!(s.vertices.len(), 13 * 25);
        assert_eq!(s.indices.len(), 6 * 24 * 11);
        assert_eq!(icosphere(0).triangle_count(), 20);
        assert_eq!(icosphere(2).triangle_count(), 320);
        assert_eq!(icosphere(100).triangle_count(), 20 * 4usize.pow(7));
        let c = cube();
        assert_eq!((c.vertices.len(), c.indices.len()), (24, 36));
        let p = plane(1.0, 1.0, 4);
        assert_eq!((p.vertices.len(), p.indices.len()), (25, 96));
        let cy = cylinder(16);
        assert_eq!(cy.vertices.len(), 2 * 17 + 2 * (16 + 1));
        assert_eq!(cy.triangle_count(), 2 * 16 + 2 * 16);
        let co = cone(16);
        assert_eq!(co.vertices.len(), 17 + 16 + 17);
        assert_eq!(co.triangle_count(), 32);
        let t = torus(1.0, 0.25, 32, 12);
        assert_eq!(
            (t.vertices.len(), t.triangle_count()),
            (33 * 13, 2 * 32 * 12)
        );
        let f = fullscreen_triangle();
        assert_eq!((f.vertices.len(), f.indices.len()), (3, 3));
    }

    #[test]
    fn procedural_shapes_have_the_documented_size() {
        for v in uv_sphere(8, 8)
            .vertices
            .iter()
            .chain(&icosphere(2).vertices)
        {
            assert!((Vec3::from(v.position).length() - 1.0).abs() < 1e-5);
        }
        assert!((bounding_radius(&cube()) - 3.0f32.sqrt()).abs() < 1e-6);
        assert!((bounding_radius(&cylinder(8)) - 2.0f32.sqrt()).abs() < 1e-6);
        assert_eq!(bounding_radius(&MeshData::default()), 0.0);
        assert!((bounding_radius(&torus(2.0, 0.5, 8, 8)) - 2.5).abs() < 1e-5);
        for v in &plane(4.0, 2.0, 2).vertices {
            assert_eq!(v.position[1], 0.0);
            assert!(v.position[0].abs() <= 2.0 && v.position[2].abs() <= 1.0);
            assert!(v.uv.iter().all(|&x| (0.0..=1.0).contains(&x)));
        }
        for v in &cylinder(8).vertices {
            assert!(v.position[1].abs() <= 1.0);
        }
    }

    #[test]
    fn sphere_uvs_do_not_wrap_and_tangents_run_east() {
        for (name, m) in [
            ("icosphere", icosphere(3)),
            ("uv_sphere", uv_sphere(16, 32)),
        ] {
            for t in m.indices.chunks_exact(3) {
                let u = [t[0], t[1], t[2]].map(|i| m.vertices[i as usize].uv[0]);
                let span = u.iter().fold(f32::MIN, |a, &b| a.max(b))
                    - u.iter().fold(f32::MAX, |a, &b| a.min(b));
                assert!(span < 0.5, "{name}: triangle wraps around the u seam");
            }
            for v in &m.vertices {
                let p = Vec3::from(v.position);
                if p.y.abs() < 0.9 {
                    // dP/du points east: (z, 0, -x), +x on the +z side.
                    let east = Vec3::new(p.z, 0.0, -p.x).normalize();
                    let t = Vec3::new(v.tangent[0], v.tangent[1], v.tangent[2]);
                    assert!(t.dot(east) > 0.95, "{name}: tangent {t} at {p}");
                }
            }
        }
    }

    #[test]
    fn fullscreen_triangle_covers_clip_space() {
        let f = fullscreen_triangle();
        let pos: Vec<[f32; 3]> = f.vertices.iter().map(|v| v.position).collect();
        assert_eq!(
            pos,
            vec![[-1.0, -1.0, 0.0], [3.0, -1.0, 0.0], [-1.0, 3.0, 0.0]]
        );
        // uv is linear in position: clip (-1,-1) -> (0,0) and (1,1) -> (1,1).
        for v in &f.vertices {
            assert_eq!(
                v.uv,
                [(v.position[0] + 1.0) / 2.0, (v.position[1] + 1.0) / 2.0]
            );
        }
    }

    #[test]
    fn light_volume_sphere_encloses_unit_sphere() {
        let m = light_volume_sphere();
        assert_eq!(m.triangle_count(), 320);
        let mut count = 0;
        for (n, d) in face_planes(&m) {
            assert!(
                d >= 1.0,
                "face plane at distance {d} cuts the unit sphere (normal {n})"
            );
            assert!(d <= 1.1, "face plane at distance {d}: volume much too big");
            count += 1;
        }
        assert_eq!(count, 320);
        let r = bounding_radius(&m);
        assert!(r > 1.0 && r < 1.1, "vertex radius {r}");
    }

    #[test]
    fn cone_circumscribes_true_cone() {
        for segments in [3, 8, 16, 32] {
            let m = cone(segments);
            let planes: Vec<_> = face_planes(&m).collect();
            // Apex at the origin, base cap at z = -1.
            assert!(
                m.vertices
                    .iter()
                    .all(|v| v.position[2] <= 0.0 && v.position[2] >= -1.0)
            );
            assert!(
                m.vertices
                    .iter()
                    .any(|v| Vec3::from(v.position) == Vec3::ZERO)
            );
            // Sample the true cone (radius -z, z in -1..0), boundary included.
            let mut state = 12345u32;
            let mut rand = || {
                state = state.wrapping_mul(1664525).wrapping_add(1013904223);
                (state >> 8) as f64 / (1u32 << 24) as f64
            };
            for k in 0..20000 {
                let z = -rand();
                let r = if k % 2 == 0 { -z } else { -z * rand().sqrt() };
                let a = std::f64::consts::TAU * rand();
                let p = glam::DVec3::new(r * a.cos(), r * a.sin(), z);
                for (n, d) in &planes {
                    assert!(
                        n.dot(p) <= d + 1e-6,
                        "cone({segments}): {p} of the true cone is outside face plane {n}, {d}"
                    );
                }
            }
            // An inscribed cone would fail: the mid-edge point of the base
            // circle touches the side plane exactly.
            let touching = planes.iter().filter(|(n, _)| n.z > 0.0).all(|(n, d)| {
                (d.abs() < 1e-6) && (n.z - std::f64::consts::FRAC_1_SQRT_2).abs() < 1e-5
            });
            assert!(
                touching,
                "cone({segments}): sides are not tangent to the true cone"
            );
        }
    }

    #[test]
    fn plane_tangent_is_plus_x() {
        for v in &plane(3.0, 5.0, 4).vertices {
            assert_eq!(v.normal, [0.0, 1.0, 0.0]);
            let t = v.tangent;
            assert!((t[0] - 1.0).abs() < 1e-6 && t[1].abs() < 1e-6 && t[2].abs() < 1e-6);
            assert_eq!(t[3], 1.0);
        }
    }

    #[test]
    fn tangents_follow_u_and_handedness() {
        // Procedural meshes are right-handed: cross(N, T) runs along +v.
        for (name, m) in procedural() {
            assert!(
                m.vertices.iter().all(|v| v.tangent[3] == 1.0),
                "{name}: w != +1"
            );
        }
        // Mirroring u flips the handedness.
        let mut p = plane(1.0, 1.0, 1);
        for v in &mut p.vertices {
            v.uv[0] = 1.0 - v.uv[0];
        }
        compute_tangents(&mut p);
        for v in &p.vertices {
            assert!((v.tangent[0] + 1.0).abs() < 1e-6 && v.tangent[3] == -1.0);
        }
    }

    fn triangle(uvs: [[f32; 2]; 3]) -> MeshData {
        let p = [[0.0, 0.0, 0.0], [1.0, 0.0, -0.2], [0.3, 0.1, -1.0]];
        let mut m = MeshData {
            vertices: (0..3)
                .map(|i| Vertex {
                    position: p[i],
                    uv: uvs[i],
                    ..Default::default()
                })
                .collect(),
            indices: vec![0, 1, 2],
        };
        compute_normals(&mut m);
        compute_tangents(&mut m);
        m
    }

    fn assert_tangent_ok(m: &MeshData) {
        for v in &m.vertices {
            assert!(v.tangent.iter().all(|x| x.is_finite()), "NaN tangent {v:?}");
            let t = Vec3::new(v.tangent[0], v.tangent[1], v.tangent[2]);
            assert!((t.length() - 1.0).abs() < 1e-5);
            assert!(t.dot(Vec3::from(v.normal)).abs() < 1e-5);
            assert!(v.tangent[3] == 1.0 || v.tangent[3] == -1.0);
        }
    }

    #[test]
    fn degenerate_uvs_give_finite_tangents() {
        // Missing uvs (all zero), all uvs equal, zero uv area (collinear uvs).
        assert_tangent_ok(&triangle([[0.0; 2]; 3]));
        assert_tangent_ok(&triangle([[0.3, 0.7]; 3]));
        assert_tangent_ok(&triangle([[0.0, 0.0], [0.5, 0.5], [1.0, 1.0]]));
        assert_tangent_ok(&triangle([[f32::NAN, 0.0], [0.5, 0.5], [1.0, 0.0]]));
        // A degenerate triangle (zero area) and a vertex no triangle uses.
        let mut m = triangle([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]);
        m.vertices.push(Vertex::default());
        m.vertices[1].position = m.vertices[0].position;
        m.vertices[2].position = m.vertices[0].position;
        compute_normals(&mut m);
        compute_tangents(&mut m);
        assert_tangent_ok(&m);
        // Out-of-range indices are ignored, not a panic.
        m.indices.extend_from_slice(&[0, 1, 99]);
        compute_normals(&mut m);
        compute_tangents(&mut m);
        assert_tangent_ok(&m);
    }

    #[test]
    fn compute_normals_area_weighted_and_welded() {
        // Recomputing the sphere's normals gives back (almost) the radius.
        let mut s = icosphere(3);
        compute_normals(&mut s);
        for v in &s.vertices {
            assert!(Vec3::from(v.normal).dot(Vec3::from(v.position)) > 0.999);
        }
        // uv-seam duplicates share the same normal.
        let mut u = uv_sphere(8, 8);
        compute_normals(&mut u);
        let (first, last) = (&u.vertices[9 * 4], &u.vertices[9 * 4 + 8]);
        assert_eq!(first.position, last.position);
        assert_eq!(first.normal, last.normal);
        // Area weighting: a big triangle on the xz plane outweighs a small one
        // on the xy plane sharing vertex 0.
        let mut m = MeshData {
            vertices: [
                [0.0, 0.0, 0.0],
                [10.0, 0.0, 0.0],
                [0.0, 0.0, -10.0],
                [0.0, 0.1, 0.0],
                [-0.1, 0.0, 0.0],
            ]
            .iter()
            .map(|&p| Vertex {
                position: p,
                ..Default::default()
            })
            .collect(),
            indices: vec![0, 1, 2, 0, 3, 4],
        };
        compute_normals(&mut m);
        compute_tangents(&mut m);
        let n0 = Vec3::from(m.vertices[0].normal);
        assert!(n0.y > 0.99 && n0.z > 0.0, "{n0}");
        check_mesh("weighted", &m);
    }

    // --- OBJ loading ---------------------------------------------------------

    fn temp_obj(name: &str, contents: &[u8]) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("gloss-geometry-tests-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join(name);
        std::fs::write(&path, contents).unwrap();
        path
    }

    fn load_err(name: &str, contents: &str) -> String {
        let path = temp_obj(name, contents.as_bytes());
        let err = load_obj(&path).expect_err("should fail");
        let msg = format!("{err:#}");
        assert!(msg.contains(name), "error does not name the file: {msg}");
        msg
    }

    const QUAD: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n";

    #[test]
    fn load_obj_quad_without_normals() {
        let path = temp_obj(
            "quad.obj",
            format!("{QUAD}o a\nf 1/1 2/2 3/3 4/4\n").as_bytes(),
        );
        let m = load_obj(&path).unwrap();
        assert_eq!((m.vertices.len(), m.indices.len()), (4, 6));
        check_mesh("quad.obj", &m);
        for v in &m.vertices {
            assert_eq!(v.normal, [0.0, 0.0, 1.0]);
            assert_eq!(v.tangent, [1.0, 0.0, 0.0, 1.0]);
        }
    }

    #[test]
    fn load_obj_merges_models_and_keeps_file_normals() {
        let text = format!("{QUAD}vn 0 0 2\no a\nf 1/1/1 2/2/1 3/3/1\no b\nf 1/1 3/3 4/4\n");
        let m = load_obj(&temp_obj("two.obj", text.as_bytes())).unwrap();
        assert_eq!(m.triangle_count(), 2);
        check_mesh("two.obj", &m);
        // The first object's file normal (normalised); no uvs -> still finite.
        assert_eq!(m.vertices[0].normal, [0.0, 0.0, 1.0]);
        let m = load_obj(&temp_obj(
            "nouv.obj",
            b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
        ))
        .unwrap();
        check_mesh("nouv.obj", &m);
    }

    #[test]
    fn load_obj_missing_file() {
        let path = std::env::temp_dir().join("gloss-no-such-dir/missing.obj");
        let msg = format!("{:#}", load_obj(&path).unwrap_err());
        assert!(
            msg.contains("cannot open OBJ file") && msg.contains("missing.obj"),
            "{msg}"
        );
    }

    #[test]
    fn load_obj_malformed() {
        let msg = load_err("malformed.obj", "v 1.0 abc 2.0\nf 1 1 1\n");
        assert!(
            msg.contains("malformed OBJ file") && msg.contains("position parse error"),
            "{msg}"
        );
        let msg = load_err("badface.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 two 3\n");
        assert!(
            msg.contains("malformed OBJ file") && msg.contains("face parse error"),
            "{msg}"
        );
        let path = temp_obj("binary.obj", &[0xff, 0xfe, 0x00, 0x76, 0x20, 0x31, 0x0a]);
        let msg = format!("{:#}", load_obj(&path).unwrap_err());
        assert!(
            msg.contains("malformed OBJ file") && msg.contains("binary.obj"),
            "{msg}"
        );
    }

    #[test]
    fn load_obj_no_triangles() {
        let msg = load_err("empty.obj", "");
        assert!(msg.contains("contains no triangles"), "{msg}");
        let msg = load_err("lines.obj", "v 0 0 0\nv 1 0 0\nl 1 2\np 1\n");
        assert!(msg.contains("contains no triangles"), "{msg}");
    }

    #[test]
    fn load_obj_non_finite() {
        let msg = load_err("nan.obj", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        assert!(msg.contains("NaN or infinite vertex position"), "{msg}");
        let msg = load_err("inf.obj", "v 0 0 0\nv 1 0 0\nv 0 inf 0\nf 1 2 3\n");
        assert!(msg.contains("NaN or infinite vertex position"), "{msg}");
        let msg = load_err(
            "nanvt.obj",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt NaN 0\nf 1/1 2/1 3/1\n",
        );
        assert!(msg.contains("NaN or infinite texture coordinate"), "{msg}");
    }

    #[test]
    fn load_obj_index_out_of_range() {
        let msg = load_err("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n");
        assert!(msg.contains("face index out of range"), "{msg}");
        let msg = load_err(
            "rangevt.obj",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/5 3/1\n",
        );
        assert!(msg.contains("face index out of range"), "{msg}");
    }

    #[test]
    fn load_obj_too_large() {
        // The real limits are 256 MiB and 16M vertices; the same checks run
        // here with small limits so the test files stay small.
        let path = temp_obj("big.obj", format!("{QUAD}f 1 2 3 4\n").as_bytes());
        let msg = format!(
            "{:#}",
            load_obj_limited(&path, 16, MAX_OBJ_VERTICES).unwrap_err()
        );
        assert!(
            msg.contains("big.obj") && msg.contains("too large") && msg.contains("bytes"),
            "{msg}"
        );
        let msg = format!(
            "{:#}",
            load_obj_limited(&path, MAX_OBJ_BYTES, 3).unwrap_err()
        );
        assert!(
            msg.contains("big.obj")
                && msg.contains("too large")
                && msg.contains("vertex positions"),
            "{msg}"
        );
        // 3 positions but 6 vertices once split by uv.
        let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 1\nf 1/1 2/1 3/1\nf 1/2 3/2 2/2\n";
        let path = temp_obj("split.obj", text.as_bytes());
        let msg = format!(
            "{:#}",
            load_obj_limited(&path, MAX_OBJ_BYTES, 5).unwrap_err()
        );
        assert!(
            msg.contains("split.obj") && msg.contains("after splitting"),
            "{msg}"
        );
        assert!(load_obj_limited(&path, MAX_OBJ_BYTES, 6).is_ok());
    }

    #[test]
    fn committed_assets_load() {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/assets");
        for name in ["knot.obj", "rock.obj"] {
            let path = dir.join(name);
            if !path.exists() {
                continue; // generated by `cargo run --release --example gen_assets`
            }
            let m = load_obj(&path).unwrap();
            check_mesh(name, &m);
            assert!(m.triangle_count() > 50);
        }
    }
}
