//! A skinned mesh on the CPU (notes 01 §7.1, "Skinned meshes"): the skin in
//! its bind pose, each vertex's joints and weights, the skeleton as a tree of
//! nodes, and the animation clips that move the nodes. `gltf` reads one from
//! a glTF 2.0 file and `gltf_write` writes one; the renderer skins it on the
//! GPU (src/techniques/animation/skinned_meshes.rs) and the CPU reference
//! (`math::skinning`) skins the same vertices with the same joint matrices.
//!
//! A joint's matrix, what the notes call its transform t, takes a vertex
//! from the bind pose to the posed skin in the file's scene space:
//!
//! ```text
//! t_j = global(joint node j) * inverse_bind_j
//! ```
//!
//! (the glTF 2.0 specification, §3.7.3.3 "Joint Hierarchy"): the inverse
//! bind matrix takes the vertex into the joint's space as it was bound, the
//! joint's posed global transform takes it back out where the joint now is,
//! with every node above the joints in place (the mesh node's own
//! transform is not applied: "only the joint transforms are applied to the
//! skinned mesh"). The object's model matrix then places the file's scene.

use crate::geometry::MeshData;
use crate::math::keyframes::Track;
use crate::math::skinning::MAX_INFLUENCES;
use glam::{Mat4, Quat, Vec3};

/// A node of the file's tree: its rest transform (translation, rotation,
/// scale) and its parent.
#[derive(Clone, Debug, PartialEq)]
pub struct SkinNode {
    pub name: String,
    pub parent: Option<usize>,
    pub translation: Vec3,
    pub rotation: Quat,
    pub scale: Vec3,
}

/// What one channel of a clip moves.
#[derive(Clone, Debug, PartialEq)]
pub enum ChannelTrack {
    Translation(Track<Vec3>),
    Rotation(Track<Quat>),
    Scale(Track<Vec3>),
}

/// One animated property of one node.
#[derive(Clone, Debug, PartialEq)]
pub struct Channel {
    pub node: usize,
    pub track: ChannelTrack,
}

/// A named animation: channels that move nodes over the same time line.
#[derive(Clone, Debug, PartialEq)]
pub struct Clip {
    pub name: String,
    pub channels: Vec<Channel>,
}

/// A skin with its skeleton and clips.
#[derive(Clone, Debug)]
pub struct SkinnedMesh {
    /// The skin in its bind pose, in the mesh node's space.
    pub mesh: MeshData,
    /// Per vertex: up to four joints (indices into `joint_nodes`) and their
    /// weights, which sum to 1.
    pub joints: Vec<[u16; MAX_INFLUENCES]>,
    pub weights: Vec<[f32; MAX_INFLUENCES]>,
    /// Every node of the file, parents before or after children.
    pub nodes: Vec<SkinNode>,
    /// The node of each joint, in the skin's order.
    pub joint_nodes: Vec<usize>,
    /// Per joint: bind-pose global transform, inverted.
    pub inverse_bind: Vec<Mat4>,
    /// The node that holds the mesh and the skin.
    pub mesh_node: usize,
    pub clips: Vec<Clip>,
}

impl SkinnedMesh {
    /// The clip named `name`, by index.
    pub fn clip(&self, name: &str) -> Option<usize> {
        self.clips.iter().position(|c| c.name == name)
    }

    /// The first and last key time of `clip` (None: it has no keys).
    pub fn clip_span(&self, clip: usize) -> Option<(f32, f32)> {
        let spans = self.clips[clip].channels.iter().map(|c| match &c.track {
            ChannelTrack::Translation(t) | ChannelTrack::Scale(t) => t.span(),
            ChannelTrack::Rotation(t) => t.span(),
        });
        spans.reduce(|a, b| (a.0.min(b.0), a.1.max(b.1)))
    }

    /// Every node's global transform at `time` in `clip` (None: the rest
    /// pose): the local TRS, with the clip's channels in place of the rest
    /// values, times the parents' up the chain.
    pub fn node_globals(&self, clip: Option<usize>, time: f32) -> Vec<Mat4> {
        let mut local: Vec<(Vec3, Quat, Vec3)> = (self.nodes.iter())
            .map(|n| (n.translation, n.rotation, n.scale))
            .collect();
        if let Some(c) = clip {
            for ch in &self.clips[c].channels {
                let l = &mut local[ch.node];
                match &ch.track {
                    ChannelTrack::Translation(t) => l.0 = t.sample(time),
                    ChannelTrack::Rotation(t) => l.1 = t.sample(time),
                    ChannelTrack::Scale(t) => l.2 = t.sample(time),
                }
            }
        }
        let local: Vec<Mat4> = (local.iter())
            .map(|&(t, r, s)| Mat4::from_scale_rotation_translation(s, r, t))
            .collect();
        let parents: Vec<Option<usize>> = self.nodes.iter().map(|n| n.parent).collect();
        crate::math::chain_globals(&local, &parents)
    }

    /// Each joint's matrix t_j at `time` in `clip` (see the module comment).
    pub fn joint_matrices(&self, clip: Option<usize>, time: f32) -> Vec<Mat4> {
        let g = self.node_globals(clip, time);
        (self.joint_nodes.iter().zip(&self.inverse_bind))
            .map(|(&node, ib)| g[node] * *ib)
            .collect()
    }

    /// The skin posed by `joints` on the CPU, linear blend or dual
    /// quaternions (`math::skinning`): the reference GPU skinning is
    /// checked against, and the mesh `skinning = "cpu"` uploads.
    pub fn skinned(&self, joints: &[Mat4], dual_quaternion: bool) -> MeshData {
        use crate::math::skinning::{DualQuat, dual_quaternion_blend, linear_blend};
        let dq: Vec<DualQuat> = joints.iter().map(DualQuat::from_mat4).collect();
        let mut out = self.mesh.clone();
        for (i, v) in out.vertices.iter_mut().enumerate() {
            let index = self.joints[i].map(usize::from);
            let (p, n) = (Vec3::from(v.position), Vec3::from(v.normal));
            let (p, n) = if dual_quaternion {
                dual_quaternion_blend(&dq, index, self.weights[i], p, n)
            } else {
                linear_blend(joints, index, self.weights[i], p, n)
            };
            v.position = p.to_array();
            v.normal = n.to_array();
        }
        out
    }

    /// Per joint, the box of the bind-pose vertices it moves (weight > 0);
    /// None for a joint that moves none.
    pub fn joint_boxes(&self) -> Vec<Option<(Vec3, Vec3)>> {
        let mut boxes: Vec<Option<(Vec3, Vec3)>> = vec![None; self.joint_nodes.len()];
        for (i, v) in self.mesh.vertices.iter().enumerate() {
            let p = Vec3::from(v.position);
            for k in 0..MAX_INFLUENCES {
                if self.weights[i][k] > 0.0 {
                    let b = &mut boxes[self.joints[i][k] as usize];
                    *b = Some(match *b {
                        None => (p, p),
                        Some((lo, hi)) => (lo.min(p), hi.max(p)),
                    });
                }
            }
        }
        boxes
    }
}

/// A box around the skin posed by `joints`: each joint's box of the
/// vertices it moves, moved by the joint, all together. A linear blend puts
/// every vertex in the convex hull of its joints' images of it, so this box
/// holds the linear-blend skin exactly. A dual-quaternion blend turns a
/// vertex along an arc between those images instead of the chord (that is
/// what keeps a twisted limb's girth), so the box is grown by `grow` times
/// each joint box's half-diagonal to hold the arc.
pub fn posed_bounds(
    boxes: &[Option<(Vec3, Vec3)>],
    joints: &[Mat4],
    grow: f32,
) -> Option<(Vec3, Vec3)> {
    let mut out: Option<(Vec3, Vec3)> = None;
    for (b, m) in boxes.iter().zip(joints) {
        let Some((lo, hi)) = *b else { continue };
        let pad = Vec3::splat((hi - lo).length() * 0.5 * grow);
        for c in crate::math::shadow::corners(lo, hi) {
            let p = m.transform_point3(c);
            if !p.is_finite() {
                continue;
            }
            let (plo, phi) = (p - pad, p + pad);
            out = Some(match out {
                None => (plo, phi),
                Some((a, b)) => (a.min(plo), b.max(phi)),
            });
        }
    }
    out
}
