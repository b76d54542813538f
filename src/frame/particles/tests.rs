//! The particle system's closed form: who lives, where, and what is sent.

use super::*;

fn fountain() -> Particles {
    Particles {
        count: 1000,
        rate: 100.0,
        lifetime: 2.0,
        speed: 4.0,
        spread: 20.0,
        direction: Vec3::Y,
        gravity: Vec3::new(0.0, -9.8, 0.0),
        emitter: Vec3::new(1.0, 0.0, -1.0),
        size: 0.1,
        color: Vec3::ONE,
        seed: 3,
        ..Particles::default()
    }
}

#[test]
fn the_living_are_those_born_within_a_lifetime() {
    let p = fountain();
    assert!(alive(&p, -1.0).is_empty());
    assert!(alive(&p, f32::NAN).is_empty());
    // At 0 s one particle is born, at 0.5 s fifty-one.
    assert_eq!(alive(&p, 0.0).len(), 1);
    assert_eq!(alive(&p, 0.5).len(), 51);
    // After a lifetime the count stays at rate x lifetime.
    assert_eq!(alive(&p, 10.0).len(), 200);
    // At most `count`.
    let few = Particles {
        count: 50,
        ..fountain()
    };
    assert_eq!(alive(&few, 10.0).len(), 50);
    for q in alive(&p, 10.0) {
        assert!((0.0..1.0).contains(&q.life));
    }
}

#[test]
fn each_particle_follows_its_parabola() {
    let p = fountain();
    // Particle 0 at 0.5 s: emitter + v a + g a^2 / 2.
    let v = velocity(&p, 0);
    let at = alive(&p, 0.5)[0];
    let want = p.emitter + v * 0.5 + p.gravity * 0.125;
    assert!(
        (at.position - want).length() < 1e-5,
        "{} vs {want}",
        at.position
    );
    assert!((at.life - 0.25).abs() < 1e-6);
    // Start speeds are `speed`, inside the cone.
    for i in 0..500 {
        let v = velocity(&p, i);
        assert!((v.length() - 4.0).abs() < 1e-4);
        let angle = v
            .normalize()
            .dot(Vec3::Y)
            .clamp(-1.0, 1.0)
            .acos()
            .to_degrees();
        assert!(angle <= 20.0 + 1e-3, "{angle}");
    }
    // The same seed gives the same particles; another seed, others.
    assert_eq!(alive(&p, 1.3), alive(&p, 1.3));
    let other = Particles {
        seed: 4,
        ..fountain()
    };
    assert_ne!(alive(&p, 1.3), alive(&other, 1.3));
}

#[test]
fn points_take_16_bytes_and_quads_144() {
    let p = fountain();
    let ps = alive(&p, 3.0);
    let mut out = Vec::new();
    pack_points(&ps, &mut out);
    assert_eq!(out.len(), ps.len() * POINT_BYTES);
    let view = crate::math::look_at(Vec3::new(0.0, 2.0, 5.0), Vec3::ZERO, Vec3::Y);
    pack_quads(&ps, &view, 0.1, &mut out);
    assert_eq!(out.len(), ps.len() * QUAD_BYTES);
    // The quad's corners face the camera: they differ from the centre
    // only along the view's right and up.
    let f = |k: usize| f32::from_ne_bytes(out[k * 4..k * 4 + 4].try_into().unwrap());
    let corner = Vec3::new(f(0), f(1), f(2));
    let forward = Vec3::new(-view.x_axis.z, -view.y_axis.z, -view.z_axis.z);
    assert!((corner - ps[0].position).dot(forward).abs() < 1e-5);
    // A point sends 1/9 of a CPU quad's bytes: 89% less.
    assert_eq!(QUAD_BYTES / POINT_BYTES, 9);
}
