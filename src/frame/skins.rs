//! The skinned objects of a draw list (notes 01 §7.1): each one's
//! bind-pose vertices with their joints and weights (`gl::skin_vertices`),
//! and its joint matrices at the scene's time. The skinning pass
//! (src/techniques/animation/skinned_meshes.rs) skins them into the
//! object's mesh on the GPU; with `render.skinning_on = "cpu"` the CPU
//! reference does it here instead and uploads the result.

use crate::geometry::skin::posed_bounds;
use crate::gl::Gl;
use crate::gl::mesh::Mesh;
use crate::gl::skin_vertices::SkinVertices;
use crate::math::skinning::DualQuat;
use crate::scene::skins::ObjectSkin;
use crate::scene::{SkinMethod, SkinningOn};
use anyhow::Result;
use glam::{Mat4, Vec3, Vec4};

pub struct SkinDraw {
    /// The draw item it poses (its mesh is this object's own).
    pub item: usize,
    pub vertices: SkinVertices,
    pub skin: ObjectSkin,
    /// This frame's joint matrices t_j (bind pose to posed, mesh space).
    pub joints: Vec<Mat4>,
    /// Per joint, the box of the bind-pose vertices it moves.
    boxes: Vec<Option<(Vec3, Vec3)>>,
}

impl SkinDraw {
    pub fn new(gl: &Gl, item: usize, skin: &ObjectSkin) -> Result<SkinDraw> {
        Ok(SkinDraw {
            item,
            vertices: SkinVertices::upload(gl, &skin.mesh)?,
            skin: skin.clone(),
            joints: vec![Mat4::IDENTITY; skin.mesh.joint_nodes.len()],
            boxes: skin.mesh.joint_boxes(),
        })
    }

    /// Take the pose at `time`. On the CPU (`on`), skin the vertices here and
    /// write them into `mesh`; on the GPU the skinning pass will. Returns
    /// the box that holds the posed skin.
    pub fn pose(&mut self, time: f32, on: SkinningOn, mesh: &Mesh) -> (Vec3, Vec3) {
        self.joints = self.skin.joint_matrices(time);
        let dual = self.skin.method == SkinMethod::DualQuaternion;
        if on == SkinningOn::Cpu {
            mesh.write_vertices(&self.skin.mesh.skinned(&self.joints, dual));
        }
        let grow = if dual { 1.0 } else { 0.0 };
        posed_bounds(&self.boxes, &self.joints, grow).unwrap_or((Vec3::ZERO, Vec3::ZERO))
    }

    /// The joints as the skinning shader reads them, four vec4 each: a
    /// linear blend's matrix columns; for dual quaternions (real, dual, 0, 0)
    /// with real and dual as (x, y, z, w).
    pub fn joint_columns(&self) -> Vec<Mat4> {
        match self.skin.method {
            SkinMethod::Linear => self.joints.clone(),
            SkinMethod::DualQuaternion => (self.joints.iter())
                .map(|m| {
                    let d = DualQuat::from_mat4(m);
                    Mat4::from_cols(
                        Vec4::from(d.real),
                        Vec4::from(d.dual),
                        Vec4::ZERO,
                        Vec4::ZERO,
                    )
                })
                .collect(),
        }
    }
}
