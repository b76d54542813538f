//! The glTF scene's assets (scenes/gltf-scene.toml, docs/gltf.md):
//!
//! * `walker.glb`: a skinned figure that walks, written by
//!   `gloss::geometry::write_glb`. Authored z-up, as many exporters write
//!   characters: the vertices and the skeleton stand along +z under an
//!   "armature" node turned -90° about x, which stands them up along +y,
//!   and the mesh node is a child of that armature too. Its boxes (torso,
//!   head, thighs, shins) each follow one joint (pelvis, hips, knees);
//!   the clip "walk" swings the legs and bobs the pelvis, one stride a
//!   second, looping.
//! * `showcase.gltf`: three spheres in glTF's metallic-roughness model
//!   (steel, red plastic, half-metal grey), a grass card whose
//!   texture's alpha cuts its blades out (alphaMode MASK, grass.png), and
//!   a box that spins about y (the "spin" animation, as the Khronos
//!   BoxAnimated sample does), written by `gloss::geometry::GltfBuilder`
//!   with its buffer inline (a data: URI).

use glam::{Mat4, Quat, Vec3};
use gloss::geometry::skin::{Channel, ChannelTrack, Clip, SkinNode, SkinnedMesh};
use gloss::geometry::{GltfBuilder, MeshData, compute_tangents, cube, uv_sphere};
use gloss::math::keyframes::{Interpolation, Track};

fn node(name: &str, parent: Option<usize>, t: Vec3, r: Quat) -> SkinNode {
    SkinNode {
        name: name.into(),
        parent,
        translation: t,
        rotation: r,
        scale: Vec3::ONE,
    }
}

/// A box of half-size `h` centred at `c` (z-up), every vertex on joint `j`.
fn part(m: &mut MeshData, joints: &mut Vec<[u16; 4]>, c: Vec3, h: Vec3, j: u16) {
    let b = cube();
    let base = m.vertices.len() as u32;
    for mut v in b.vertices {
        v.position = (Vec3::from(v.position) * h + c).to_array();
        m.vertices.push(v);
        joints.push([j, 0, 0, 0]);
    }
    m.indices.extend(b.indices.iter().map(|i| i + base));
}

fn keys<T: gloss::math::keyframes::Keyed>(
    node: usize,
    times: &[f32],
    v: &[T],
    f: fn(Track<T>) -> ChannelTrack,
) -> Channel {
    let track = Track::new("walker", times.to_vec(), v.to_vec(), Interpolation::Linear)
        .expect("valid keys");
    Channel {
        node,
        track: f(track),
    }
}

pub fn walker() -> SkinnedMesh {
    // Joints (z-up): pelvis at z = 1, hips 0.15 to each side, knees 0.45 below.
    let turn = Quat::from_rotation_x(-std::f32::consts::FRAC_PI_2);
    let nodes = vec![
        node("armature", None, Vec3::ZERO, turn),
        node("pelvis", Some(0), Vec3::new(0.0, 0.0, 1.0), Quat::IDENTITY),
        node("hip.L", Some(1), Vec3::new(0.15, 0.0, 0.0), Quat::IDENTITY),
        node("hip.R", Some(1), Vec3::new(-0.15, 0.0, 0.0), Quat::IDENTITY),
        node(
            "knee.L",
            Some(2),
            Vec3::new(0.0, 0.0, -0.45),
            Quat::IDENTITY,
        ),
        node(
            "knee.R",
            Some(3),
            Vec3::new(0.0, 0.0, -0.45),
            Quat::IDENTITY,
        ),
        node("body", Some(0), Vec3::ZERO, Quat::IDENTITY),
    ];
    let joint_nodes = vec![1, 2, 3, 4, 5];
    let mut mesh = MeshData::default();
    let mut joints = Vec::new();
    let parts = [
        (Vec3::new(0.0, 0.0, 1.35), Vec3::new(0.22, 0.12, 0.35), 0),
        (Vec3::new(0.0, 0.0, 1.85), Vec3::new(0.12, 0.12, 0.13), 0),
        (Vec3::new(0.15, 0.0, 0.78), Vec3::new(0.08, 0.08, 0.21), 1),
        (Vec3::new(-0.15, 0.0, 0.78), Vec3::new(0.08, 0.08, 0.21), 2),
        (Vec3::new(0.15, 0.0, 0.3), Vec3::new(0.07, 0.07, 0.24), 3),
        (Vec3::new(-0.15, 0.0, 0.3), Vec3::new(0.07, 0.07, 0.24), 4),
        (Vec3::new(0.15, -0.06, 0.04), Vec3::new(0.07, 0.13, 0.04), 3),
        (
            Vec3::new(-0.15, -0.06, 0.04),
            Vec3::new(0.07, 0.13, 0.04),
            4,
        ),
    ];
    for (c, h, j) in parts {
        part(&mut mesh, &mut joints, c, h, j);
    }
    for source in compute_tangents(&mut mesh) {
        joints.push(joints[source]);
    }
    let weights = vec![[1.0, 0.0, 0.0, 0.0]; joints.len()];
    // Bind pose: the joints' globals, the mesh node (the armature's child)
    // at the armature: inverse_bind_j = inverse(global_j) * global(body).
    let local = |n: &SkinNode| Mat4::from_rotation_translation(n.rotation, n.translation);
    let mut global = vec![Mat4::IDENTITY; nodes.len()];
    for (i, n) in nodes.iter().enumerate() {
        global[i] = n.parent.map_or(Mat4::IDENTITY, |p| global[p]) * local(n);
    }
    let inverse_bind = (joint_nodes.iter())
        .map(|&j| global[j].inverse() * global[6])
        .collect();
    let t = [0.0, 0.25, 0.5, 0.75, 1.0];
    let swing = |deg: [f32; 5]| deg.map(|d| Quat::from_rotation_x(d.to_radians()));
    let clip = Clip {
        name: "walk".into(),
        channels: vec![
            keys(
                2,
                &t,
                &swing([25.0, 0.0, -25.0, 0.0, 25.0]),
                ChannelTrack::Rotation,
            ),
            keys(
                3,
                &t,
                &swing([-25.0, 0.0, 25.0, 0.0, -25.0]),
                ChannelTrack::Rotation,
            ),
            keys(
                4,
                &t,
                &swing([0.0, 0.0, 40.0, 0.0, 0.0]),
                ChannelTrack::Rotation,
            ),
            keys(
                5,
                &t,
                &swing([40.0, 0.0, 0.0, 0.0, 40.0]),
                ChannelTrack::Rotation,
            ),
            keys(
                1,
                &t,
                &[0.0, 0.04, 0.0, 0.04, 0.0].map(|z| Vec3::new(0.0, 0.0, 1.0 + z)),
                ChannelTrack::Translation,
            ),
        ],
    };
    SkinnedMesh {
        mesh,
        joints,
        weights,
        nodes,
        joint_nodes,
        inverse_bind,
        mesh_node: 6,
        clips: vec![clip],
    }
}

pub fn showcase() -> String {
    let mut b = GltfBuilder::default();
    let sphere = uv_sphere(16, 32);
    let materials = [
        r#"{"name":"steel","pbrMetallicRoughness":{"baseColorFactor":[0.9,0.9,0.9,1],"metallicFactor":1.0,"roughnessFactor":0.35}}"#,
        r#"{"name":"red plastic","pbrMetallicRoughness":{"baseColorFactor":[0.7,0.06,0.04,1],"metallicFactor":0.0,"roughnessFactor":0.45}}"#,
        r#"{"name":"grey","pbrMetallicRoughness":{"baseColorFactor":[0.6,0.6,0.6,1],"metallicFactor":0.5,"roughnessFactor":0.8}}"#,
        r#"{"name":"grass","alphaMode":"MASK","alphaCutoff":0.5,"doubleSided":true,"pbrMetallicRoughness":{"baseColorTexture":{"index":0},"metallicFactor":0.0,"roughnessFactor":0.9}}"#,
        r#"{"name":"box","pbrMetallicRoughness":{"baseColorFactor":[0.3,0.53,0.8,1],"metallicFactor":0.0,"roughnessFactor":0.6}}"#,
    ];
    for m in materials {
        b.materials.push(m.into());
    }
    b.textures.push(r#"{"source":0,"sampler":0}"#.into());
    b.images.push(r#"{"uri":"grass.png"}"#.into());
    b.samplers.push(r#"{"wrapS":33071,"wrapT":33071}"#.into());
    for (k, x) in [-1.6f32, 0.0, 1.6].iter().enumerate() {
        let mesh = b.mesh(&sphere, Some(k));
        b.nodes.push(format!(
            r#"{{"name":"sphere {k}","mesh":{mesh},"translation":[{x},0.6,-1.2],"scale":[0.6,0.6,0.6]}}"#
        ));
    }
    // The grass card: a unit quad (x, y in -1..1) facing +z.
    let mut card = gloss::geometry::plane(2.0, 2.0, 1);
    for v in &mut card.vertices {
        let p = Vec3::from(v.position);
        v.position = [p.x, -p.z, 0.0];
        v.normal = [0.0, 0.0, 1.0];
    }
    compute_tangents(&mut card);
    let mesh = b.mesh(&card, Some(3));
    b.nodes.push(format!(
        r#"{{"name":"grass","mesh":{mesh},"translation":[-2.6,0.7,0.4],"scale":[0.7,0.7,0.7],"rotation":[0,0.2588,0,0.9659]}}"#
    ));
    let mesh = b.mesh(&cube(), Some(4));
    b.nodes
        .push(r#"{"name":"turntable","translation":[2.6,0.35,0.4],"children":[5]}"#.into());
    b.nodes.push(format!(
        r#"{{"name":"box","mesh":{mesh},"scale":[0.35,0.35,0.35]}}"#
    ));
    let times = b.floats(&[0.0, 1.0, 2.0, 3.0, 4.0], 1, "SCALAR");
    let turn: Vec<f32> = (0..5)
        .flat_map(|k| Quat::from_rotation_y(k as f32 * std::f32::consts::FRAC_PI_2).to_array())
        .collect();
    let turn = b.floats(&turn, 4, "VEC4");
    b.animations.push(format!(
        r#"{{"name":"spin","channels":[{{"sampler":0,"target":{{"node":5,"path":"rotation"}}}}],"samplers":[{{"input":{times},"output":{turn},"interpolation":"LINEAR"}}]}}"#
    ));
    b.gltf()
}
