//! Meshes that must ENCLOSE the shape they stand for: the sphere of the
//! point-light volumes of notes 04, the face-plane check that proves it, and
//! the bounding radius used to scale volumes. (The spot-light cone lives in
//! `shapes`; its enclosing test is here.)

use super::MeshData;
use super::shapes::icosphere;
use glam::Vec3;

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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::cone;

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
}
