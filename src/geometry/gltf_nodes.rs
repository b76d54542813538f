//! A glTF file's node tree (glTF 2.0, "Transformations"): each node's rest
//! transform and parent, read once for the whole scene (gltf_scene.rs) and
//! for a skin's joints (gltf.rs), with the limits both keep.

use anyhow::{Result, bail};
use glam::{Quat, Vec3};

/// The most nodes one glTF file may have.
pub const MAX_GLTF_NODES: usize = 262_144;
/// The largest |value| of a node's translation and scale, and of a matrix
/// entry (an inverse bind matrix): gloss's world extent (1e9).
pub const MAX_GLTF_VALUE: f32 = 1e9;

/// A node: its rest transform, parent, and what it holds.
#[derive(Clone, Debug, PartialEq)]
pub struct GltfNode {
    pub name: String,
    pub parent: Option<usize>,
    pub translation: Vec3,
    /// Unit length.
    pub rotation: Quat,
    pub scale: Vec3,
    /// Its mesh, by index into `GltfScene::meshes`.
    pub mesh: Option<usize>,
    /// It holds the skin that `GltfScene::skin` reads.
    pub skinned: bool,
}

/// Every node's rest transform and parent, and the order parents first;
/// a node with two parents, a cycle, a zero quaternion or a value past
/// [`MAX_GLTF_VALUE`] is an error. Linear in the number of nodes.
pub(crate) fn read_nodes(doc: &gltf::Gltf, name: &str) -> Result<(Vec<GltfNode>, Vec<usize>)> {
    let count = doc.nodes().len();
    if count > MAX_GLTF_NODES {
        bail!("{name}: {count} nodes, more than {MAX_GLTF_NODES}, the limit");
    }
    let mut nodes = Vec::with_capacity(count);
    for n in doc.nodes() {
        let i = n.index();
        let (t, r, s) = n.transform().decomposed();
        let (t, s) = (Vec3::from(t), Vec3::from(s));
        let key = |k: &str| format!("{name}: nodes[{i}].{k}");
        let q = Quat::from_array(r);
        if !(t.is_finite() && q.is_finite() && s.is_finite()) {
            bail!(
                "{}: expected finite numbers",
                key("translation/rotation/scale")
            );
        }
        if q.length_squared() < 1e-12 {
            bail!(
                "{}: {r:?} is the zero quaternion, which is no rotation (the identity is [0, 0, 0, 1])",
                key("rotation")
            );
        }
        for (k, v) in [("translation", t), ("scale", s)] {
            if v.abs().max_element() > MAX_GLTF_VALUE {
                bail!(
                    "{}: {v} is past gloss's world limit of {MAX_GLTF_VALUE:e}",
                    key(k)
                );
            }
        }
        nodes.push(GltfNode {
            name: n.name().map_or(format!("node{i}"), str::to_owned),
            parent: None,
            translation: t,
            rotation: q.normalize(),
            scale: s,
            mesh: n.mesh().map(|m| m.index()),
            skinned: n.skin().is_some() && n.mesh().is_some(),
        });
    }
    let mut children: Vec<Vec<usize>> = vec![Vec::new(); count];
    for n in doc.nodes() {
        for c in n.children() {
            if nodes[c.index()].parent.replace(n.index()).is_some() {
                bail!("{name}: node {} has two parents", c.index());
            }
            children[n.index()].push(c.index());
        }
    }
    // Parents first: from the roots down, each node once.
    let mut order = Vec::with_capacity(count);
    let mut stack: Vec<usize> = (0..count).filter(|&i| nodes[i].parent.is_none()).collect();
    stack.reverse();
    while let Some(i) = stack.pop() {
        order.push(i);
        stack.extend(children[i].iter().rev());
    }
    if order.len() != count {
        let mut seen = vec![false; count];
        for &i in &order {
            seen[i] = true;
        }
        let cyclic = seen.iter().position(|s| !s).unwrap_or_default();
        bail!("{name}: node {cyclic} is its own ancestor (the node tree has a cycle)");
    }
    Ok((nodes, order))
}
