//! `arm.glb`: a skinned arm for notes 01 §7.1, written as a binary glTF 2.0
//! file by `gloss::geometry::write_glb`.
//!
//! The skin is a capped tube along +x, 3 long and 0.18 thick, 41 rings of
//! 20 vertices. Three joints in a chain: shoulder at x = 0, elbow at x = 1,
//! wrist at x = 2 (the hand reaches to x = 3). A vertex near a joint is
//! shared by the two bones that meet there: across the 0.6 around the joint
//! its weights go smoothly from the parent bone to the child, and they
//! always sum to 1. uv: u along the arm, v around it.
//!
//! Two clips, linear keys:
//! * `wave`: over 2 s the shoulder lifts 30°, the elbow bends 90° and the
//!   wrist 40°, and over 2 s more all come back;
//! * `twist`: over 2 s the elbow turns the forearm about its own axis, 0° to
//!   180° (keys every 90°, so each step is the shortest arc). At 180° linear
//!   blending squashes the tube at the elbow to its axis (the "candy
//!   wrapper"); dual quaternions keep its girth.

use glam::{Mat4, Quat, Vec2, Vec3};
use gloss::geometry::skin::{Channel, ChannelTrack, Clip, SkinNode, SkinnedMesh};
use gloss::geometry::{MeshData, Vertex, compute_tangents};
use gloss::math::keyframes::{Interpolation, Track};

const RINGS: usize = 41;
const SIDES: usize = 20;
const LENGTH: f32 = 3.0;
const RADIUS: f32 = 0.18;
/// The joints' places along x, and how far each side of a joint the blend reaches.
const JOINTS: [f32; 3] = [0.0, 1.0, 2.0];
const BLEND: f32 = 0.3;

/// Weights at x: (joint, weight) of the bone the vertex is on, and of the
/// one it blends into near a joint.
fn weights_at(x: f32) -> ([u16; 4], [f32; 4]) {
    for (j, &b) in JOINTS.iter().enumerate().skip(1) {
        if (x - b).abs() < BLEND {
            let s = (x - (b - BLEND)) / (2.0 * BLEND);
            let s = s * s * (3.0 - 2.0 * s);
            return ([j as u16 - 1, j as u16, 0, 0], [1.0 - s, s, 0.0, 0.0]);
        }
    }
    let j = JOINTS.iter().rposition(|&b| x >= b).unwrap_or(0) as u16;
    ([j, 0, 0, 0], [1.0, 0.0, 0.0, 0.0])
}

fn tube() -> (MeshData, Vec<[u16; 4]>, Vec<[f32; 4]>) {
    let mut m = MeshData::default();
    let (mut joints, mut weights) = (Vec::new(), Vec::new());
    let mut push = |m: &mut MeshData, p: Vec3, n: Vec3, uv: Vec2| {
        m.vertices.push(Vertex {
            position: p.to_array(),
            normal: n.to_array(),
            uv: uv.to_array(),
            tangent: [1.0, 0.0, 0.0, 1.0],
        });
        let (j, w) = weights_at(p.x);
        joints.push(j);
        weights.push(w);
        (m.vertices.len() - 1) as u32
    };
    for r in 0..RINGS {
        let x = LENGTH * r as f32 / (RINGS - 1) as f32;
        for s in 0..=SIDES {
            let a = std::f32::consts::TAU * s as f32 / SIDES as f32;
            let n = Vec3::new(0.0, a.cos(), a.sin());
            let uv = Vec2::new(x / LENGTH, s as f32 / SIDES as f32);
            push(&mut m, Vec3::new(x, 0.0, 0.0) + n * RADIUS, n, uv);
        }
    }
    let row = (SIDES + 1) as u32;
    for r in 0..RINGS as u32 - 1 {
        for s in 0..SIDES as u32 {
            let (a, b) = (r * row + s, (r + 1) * row + s);
            // Counter-clockwise seen from outside.
            m.indices.extend_from_slice(&[a, a + 1, b + 1, a, b + 1, b]);
        }
    }
    // Caps: a fan at each end, facing -x and +x.
    for (x, nx) in [(0.0f32, -1.0f32), (LENGTH, 1.0)] {
        let n = Vec3::new(nx, 0.0, 0.0);
        let centre = push(
            &mut m,
            Vec3::new(x, 0.0, 0.0),
            n,
            Vec2::new(x / LENGTH, 0.5),
        );
        let first = m.vertices.len() as u32;
        for s in 0..SIDES {
            let a = std::f32::consts::TAU * s as f32 / SIDES as f32;
            let p = Vec3::new(x, a.cos() * RADIUS, a.sin() * RADIUS);
            push(&mut m, p, n, Vec2::new(x / LENGTH, 0.5));
        }
        for s in 0..SIDES as u32 {
            let (a, b) = (first + s, first + (s + 1) % SIDES as u32);
            if nx < 0.0 {
                m.indices.extend_from_slice(&[centre, b, a]);
            } else {
                m.indices.extend_from_slice(&[centre, a, b]);
            }
        }
    }
    compute_tangents(&mut m);
    (m, joints, weights)
}

fn node(name: &str, parent: Option<usize>, x: f32) -> SkinNode {
    SkinNode {
        name: name.to_owned(),
        parent,
        translation: Vec3::new(x, 0.0, 0.0),
        rotation: Quat::IDENTITY,
        scale: Vec3::ONE,
    }
}

/// Keys every `step` seconds from 0.
fn rotation(node: usize, axis: Vec3, step: f32, degrees: &[f32]) -> Channel {
    let times = (0..degrees.len()).map(|i| i as f32 * step).collect();
    let values = (degrees.iter())
        .map(|d| Quat::from_axis_angle(axis, d.to_radians()))
        .collect();
    let track = Track::new("arm", times, values, Interpolation::Linear).expect("valid keys");
    Channel {
        node,
        track: ChannelTrack::Rotation(track),
    }
}

pub fn arm() -> SkinnedMesh {
    let (mesh, joints, weights) = tube();
    SkinnedMesh {
        mesh,
        joints,
        weights,
        nodes: vec![
            node("arm", None, 0.0),
            node("shoulder", Some(0), JOINTS[0]),
            node("elbow", Some(1), JOINTS[1] - JOINTS[0]),
            node("wrist", Some(2), JOINTS[2] - JOINTS[1]),
        ],
        joint_nodes: vec![1, 2, 3],
        inverse_bind: JOINTS
            .iter()
            .map(|&x| Mat4::from_translation(Vec3::new(-x, 0.0, 0.0)))
            .collect(),
        mesh_node: 0,
        clips: vec![
            Clip {
                name: "wave".into(),
                channels: vec![
                    rotation(1, Vec3::Z, 2.0, &[0.0, 30.0, 0.0]),
                    rotation(2, Vec3::Z, 2.0, &[0.0, 90.0, 0.0]),
                    rotation(3, Vec3::Z, 2.0, &[0.0, 40.0, 0.0]),
                ],
            },
            Clip {
                name: "twist".into(),
                channels: vec![rotation(2, Vec3::X, 1.0, &[0.0, 90.0, 180.0])],
            },
        ],
    }
}
