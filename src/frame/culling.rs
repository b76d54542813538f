//! Frustum culling through the scene graph (notes 01 §6.3 and §6.4): each
//! object's bounding box and sphere in world space, and each subtree's box
//! (the object's and all its descendants'). A frame walks the tree from
//! the roots (`CullTree::visible`):
//!
//! - a subtree whose box is outside the frustum is culled whole, with one
//!   test however many objects it holds;
//! - a subtree whose box is inside is drawn whole, with no more tests;
//! - otherwise the object's own sphere is tested, then its box (the cheap
//!   test first, the tighter second), and the walk goes on to its children.
//!
//! No GL here: the draw list keeps a tree for the renderer, and `gloss
//! plan` builds one from the scene (`scene_stats`).

use crate::geometry::MeshData;
use crate::math::frustum::{Containment, Frustum, transform_aabb};
use crate::scene::{MeshSource, Scene};
use anyhow::Result;
use glam::{Mat4, Vec3};
use std::collections::HashMap;

/// What one walk did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CullStats {
    /// Objects walked over (the opaque ones a pass would draw).
    pub objects: usize,
    pub drawn: usize,
    pub culled: usize,
    /// Sphere and box tests made.
    pub tests: usize,
}

#[derive(Clone, Debug, Default)]
pub struct CullTree {
    children: Vec<Vec<usize>>,
    roots: Vec<usize>,
    /// Each object's world box, and sphere (centre, radius).
    own: Vec<(Vec3, Vec3)>,
    sphere: Vec<(Vec3, f32)>,
    /// The box around each object and its descendants.
    subtree: Vec<(Vec3, Vec3)>,
}

impl CullTree {
    /// From each object's model matrix, its mesh's box in its own space,
    /// and its parent.
    pub fn new(models: &[Mat4], local: &[(Vec3, Vec3)], parents: &[Option<usize>]) -> CullTree {
        let n = models.len();
        let mut children = vec![Vec::new(); n];
        let mut roots = Vec::new();
        for (i, p) in parents.iter().enumerate() {
            match p {
                Some(p) if *p < n => children[*p].push(i),
                _ => roots.push(i),
            }
        }
        let own: Vec<(Vec3, Vec3)> = (0..n)
            .map(|i| transform_aabb(&models[i], local[i].0, local[i].1))
            .collect();
        let sphere = (0..n)
            .map(|i| {
                let (lo, hi) = local[i];
                let m = &models[i];
                let scale = (m.x_axis.truncate().length())
                    .max(m.y_axis.truncate().length())
                    .max(m.z_axis.truncate().length());
                (
                    m.transform_point3((lo + hi) * 0.5),
                    (hi - lo).length() * 0.5 * scale,
                )
            })
            .collect();
        // Children after parents is not promised: fold bottom-up by depth.
        let mut subtree = own.clone();
        let mut order = Vec::with_capacity(n);
        let mut stack = roots.clone();
        while let Some(i) = stack.pop() {
            order.push(i);
            stack.extend(&children[i]);
        }
        for &i in order.iter().rev() {
            for &c in &children[i] {
                let (a, b) = (subtree[i], subtree[c]);
                subtree[i] = (a.0.min(b.0), a.1.max(b.1));
            }
        }
        CullTree {
            children,
            roots,
            own,
            sphere,
            subtree,
        }
    }

    /// Which objects are (perhaps partly) inside `frustum`; `wanted` says
    /// which to count (the others are walked through but not drawn).
    pub fn visible(&self, frustum: &Frustum, wanted: &[bool]) -> (Vec<bool>, CullStats) {
        let mut seen = vec![false; self.own.len()];
        let mut stats = CullStats::default();
        let mut stack: Vec<(usize, bool)> = self.roots.iter().map(|&r| (r, false)).collect();
        while let Some((i, inside)) = stack.pop() {
            if inside {
                seen[i] = true;
                stack.extend(self.children[i].iter().map(|&c| (c, true)));
                continue;
            }
            stats.tests += 1;
            match frustum.aabb(self.subtree[i].0, self.subtree[i].1) {
                Containment::Outside => continue,
                Containment::Inside => {
                    seen[i] = true;
                    stack.extend(self.children[i].iter().map(|&c| (c, true)));
                    continue;
                }
                Containment::Straddles => {}
            }
            let (c, r) = self.sphere[i];
            stats.tests += 1;
            seen[i] = match frustum.sphere(c, r) {
                Containment::Outside => false,
                Containment::Inside => true,
                Containment::Straddles => {
                    stats.tests += 1;
                    frustum.aabb(self.own[i].0, self.own[i].1) != Containment::Outside
                }
            };
            stack.extend(self.children[i].iter().map(|&c| (c, false)));
        }
        for (i, &shown) in seen.iter().enumerate() {
            if wanted.get(i).copied().unwrap_or(true) {
                stats.objects += 1;
                if shown {
                    stats.drawn += 1;
                } else {
                    stats.culled += 1;
                }
            }
        }
        (seen, stats)
    }
}

/// The camera's walk over `scene`'s opaque objects, from the meshes' boxes
/// (each mesh loaded once): what `gloss plan` prints. Skinned meshes count
/// with their bind pose's box.
pub fn scene_stats(scene: &Scene) -> Result<CullStats> {
    let mut boxes: HashMap<MeshSource, (Vec3, Vec3)> = HashMap::new();
    let mut local = Vec::with_capacity(scene.objects.len());
    for o in &scene.objects {
        let b = match boxes.get(&o.mesh) {
            Some(b) => *b,
            None => {
                let data = crate::scene::meshes::mesh_data(&o.mesh)?;
                let b = mesh_bounds(&data);
                boxes.insert(o.mesh.clone(), b);
                b
            }
        };
        local.push(b);
    }
    let models: Vec<Mat4> = scene.objects.iter().map(|o| o.model).collect();
    let parents: Vec<Option<usize>> = scene.objects.iter().map(|o| o.parent).collect();
    let tree = CullTree::new(&models, &local, &parents);
    let vp = scene.camera.projection(scene.aspect()) * scene.camera.view();
    let wanted: Vec<bool> = (scene.objects.iter())
        .map(|o| !scene.materials[o.material].is_transparent() && o.mirror.is_none())
        .collect();
    Ok(tree.visible(&Frustum::from_view_projection(&vp), &wanted).1)
}

/// The axis-aligned box around the mesh's vertices (a point at the origin
/// for an empty mesh).
pub fn mesh_bounds(data: &MeshData) -> (Vec3, Vec3) {
    let mut lo = Vec3::splat(f32::INFINITY);
    let mut hi = Vec3::splat(f32::NEG_INFINITY);
    for v in &data.vertices {
        let p = Vec3::from(v.position);
        lo = lo.min(p);
        hi = hi.max(p);
    }
    if lo.cmple(hi).all() {
        (lo, hi)
    } else {
        (Vec3::ZERO, Vec3::ZERO)
    }
}
