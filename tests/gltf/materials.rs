//! glTF's metallic-roughness material on gloss's microfacet triple
//! (src/scene/gltf_material.rs, docs/gltf.md), against glTF's BRDF written
//! here from the specification, through the CPU microfacet
//! (src/lighting/microfacet.rs).

use glam::{DVec3, Vec3};
use gloss::geometry::{AlphaMode, GltfMaterial};
use gloss::lighting::microfacet::brdf;
use gloss::scene::gltf_material::{material, microfacet};

/// Rec. 709 luminance.
fn luminance(c: Vec3) -> f32 {
    0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z
}

use std::f64::consts::PI;

/// glTF 2.0's specular BRDF (Appendix B.3): Schlick's Fresnel from F0,
/// GGX with alpha = roughness^2 and the height-correlated visibility
/// V = 1 / (2 (n.l sqrt(n.v^2 (1 - a^2) + a^2) + n.v sqrt(n.l^2 (1 - a^2) + a^2))),
/// written here from the specification, not from gloss's code.
fn gltf_specular(l: DVec3, v: DVec3, n: DVec3, f0: f64, roughness: f64) -> f64 {
    let h = (l + v).normalize();
    let a2 = (roughness * roughness).powi(2);
    let (nl, nv, nh, vh) = (n.dot(l), n.dot(v), n.dot(h), v.dot(h));
    let f = f0 + (1.0 - f0) * (1.0 - vh).powi(5);
    let d = a2 / (PI * (nh * nh * (a2 - 1.0) + 1.0).powi(2));
    let vis =
        0.5 / (nl * (nv * nv * (1.0 - a2) + a2).sqrt() + nv * (nl * nl * (1.0 - a2) + a2).sqrt());
    f * d * vis
}

#[test]
fn metallic_roughness_matches_gltfs_brdf_through_the_cpu_microfacet() {
    let n = DVec3::Z;
    let grey = Vec3::splat(0.7);
    for (metallic, base) in [(0.0, Vec3::new(0.8, 0.3, 0.1)), (0.5, grey), (1.0, grey)] {
        for roughness in [0.2f32, 0.5, 1.0] {
            let m = microfacet(metallic, roughness, base);
            let f0 = 0.04 * (1.0 - metallic as f64) + luminance(base) as f64 * metallic as f64;
            let ours =
                |l: DVec3, v: DVec3| brdf(l, v, n, m.alpha as f64, m.eta as f64, m.k_s as f64);
            // Light from the eye (l = v = h): Fresnel at normal
            // incidence on the microfacet, where the mapping is exact.
            for deg in [0.0f64, 20.0, 45.0, 70.0] {
                let t = deg.to_radians();
                let l = DVec3::new(t.sin(), 0.0, t.cos());
                let v = l;
                let (a, b) = (ours(l, v), gltf_specular(l, v, n, f0, roughness as f64));
                assert!(
                    (a - b).abs() <= 2e-5 * b,
                    "metallic {metallic} roughness {roughness} at {deg}°: {a} vs {b}"
                );
            }
            // Off the mirror direction, v.h >= 0.9: within what
            // Schlick's fit differs from the exact Fresnel there.
            for (tl, tv) in [(10.0f64, 30.0f64), (0.0, 40.0), (30.0, 10.0)] {
                let l = DVec3::new(tl.to_radians().sin(), 0.0, tl.to_radians().cos());
                let v = DVec3::new(0.0, tv.to_radians().sin(), tv.to_radians().cos());
                let h = (l + v).normalize();
                assert!(v.dot(h) >= 0.9);
                let (a, b) = (ours(l, v), gltf_specular(l, v, n, f0, roughness as f64));
                assert!(
                    (a - b).abs() <= 0.03 * b,
                    "metallic {metallic} roughness {roughness} off the eye: {a} vs {b}"
                );
            }
        }
    }
    // A metal has no diffuse; a dielectric keeps its base colour.
    let gm = |metallic: f32| GltfMaterial {
        name: "m".into(),
        base_color: [0.8, 0.3, 0.1, 1.0],
        base_texture: None,
        metallic,
        roughness: 0.5,
        normal_texture: None,
        normal_scale: 1.0,
        metallic_roughness_texture: None,
        occlusion_texture: None,
        occlusion_strength: 1.0,
        emissive: [0.0; 3],
        emissive_texture: None,
        alpha: AlphaMode::Opaque,
        double_sided: false,
    };
    assert_eq!(material(&gm(1.0), "f").diffuse, Vec3::ZERO);
    assert_eq!(material(&gm(0.0), "f").diffuse, Vec3::new(0.8, 0.3, 0.1));
}

/// What a coloured metal loses (docs/gltf.md, "A metal's tint"): gloss's
/// highlight is white with F0 = lum(baseColor), glTF's is F0 = baseColor
/// per channel. Measured through the CPU microfacet against glTF's BRDF
/// per channel, light from the eye at 0-60°: the ratio is lum / F0_c,
/// the table's numbers.
#[test]
fn a_coloured_metals_tint_is_its_luminance_and_the_error_is_measured() {
    let n = DVec3::Z;
    // Metal, base colour, and the relative error per channel the docs give.
    let metals = [
        ("gold", Vec3::new(1.0, 0.766, 0.336), [-0.215, 0.024, 1.335]),
        (
            "copper",
            Vec3::new(0.955, 0.638, 0.538),
            [-0.269, 0.094, 0.298],
        ),
        (
            "silver",
            Vec3::new(0.972, 0.960, 0.915),
            [-0.013, -0.001, 0.048],
        ),
    ];
    for (name, base, documented) in metals {
        let m = microfacet(1.0, 0.5, base);
        for deg in [0.0f64, 30.0, 60.0] {
            let t = deg.to_radians();
            let l = DVec3::new(t.sin(), 0.0, t.cos());
            let ours = brdf(l, l, n, m.alpha as f64, m.eta as f64, m.k_s as f64);
            for (c, want) in [base.x, base.y, base.z].into_iter().zip(documented) {
                let theirs = gltf_specular(l, l, n, c as f64, 0.5);
                let err = (ours - theirs) / theirs;
                assert!(
                    (err - want).abs() < 2e-3,
                    "{name} at {deg}°, F0 {c}: error {err:.4}, documented {want}"
                );
            }
        }
    }
}
