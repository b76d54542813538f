//! Procedural meshes: the uv sphere and the icosphere, cube, plane, cylinder,
//! cone (the spot-light volume of notes 04) and torus, and the full-screen
//! triangle of the deferred passes (notes 04). Each follows the conventions
//! listed in `geometry` and gets its tangents from `normals`.

use super::MeshData;
use super::tangents::compute_tangents;
use glam::{Vec2, Vec3};
use std::collections::HashMap;
use std::f32::consts::{PI, TAU};

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
///
/// [`light_volume_sphere`]: super::light_volume_sphere
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

#[cfg(test)]
mod tests;
