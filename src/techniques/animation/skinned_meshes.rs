//! Skinned meshes on the GPU (notes 01 §7.1, "Skinned meshes"): "skinning
//! can be performed on the GPU; skeletal transformation data can be sent
//! as a large uniform array or sampled from a texture".
//!
//! Once a frame, before the shadow maps and the views, this pass skins
//! every skinned object: each bind-pose vertex goes in as a point
//! (glDrawArrays(GL_POINTS)), the vertex shader
//! (glsl/animation/skinned_meshes.vert) applies the notes' formula,
//! position = sum of (t . v) . w, or blends dual quaternions, and transform
//! feedback writes the skinned position, normal and uv into the object's own
//! mesh. The rasterizer is off (GL_RASTERIZER_DISCARD): nothing is drawn.
//! Every later pass (shadow maps, forward, the G-buffer, mirrors) then
//! draws that mesh like any other, so skinning costs one pass however many
//! times the frame draws the object, and no other shader changes.
//!
//! The joint matrices go in a uniform array of MAX_JOINTS mat4s, MAX_JOINTS
//! computed from GL_MAX_VERTEX_UNIFORM_COMPONENTS (16 components a matrix,
//! 64 kept back for the rest); a skeleton with more joints reads them from a
//! buffer texture instead, four RGBA32F texels a joint (`render.joint_storage`
//! chooses; "auto" does as just said).
//!
//! GL state: glEnable(GL_RASTERIZER_DISCARD), the mesh's VBO bound to
//! GL_TRANSFORM_FEEDBACK_BUFFER index 0, glBeginTransformFeedback(GL_POINTS)
//! ... glEndTransformFeedback(), with the output's framebuffer bound (a draw
//! needs a complete one, rasterizer or not); restores: the bindings to 0,
//! the rasterizer on, texture unit 0 unbound, no program.

use crate::frame::lights::FrameLights;
use crate::frame::plan::Pass;
use crate::frame::skins::SkinDraw;
use crate::frame::targets::{OUTPUT, TargetDesc};
use crate::frame::uniforms::unit;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::program::Program;
use crate::gl::texture_buffer::TextureBuffer;
use crate::math::skinning::uniform_joint_limit;
use crate::scene::knobs::{JOINT_STORAGE, SKINNING_ON};
use crate::scene::{JointStorage, Scene, SkinMethod, SkinningOn};
use anyhow::Result;
use glow::HasContext;
use std::cell::Cell;

pub const SKINNED_MESHES: Technique = Technique {
    name: "skinned_meshes",
    notes: "notes 01 §7.1, Skinned meshes",
    file: file!(),
    shaders: &["animation/skinned_meshes.vert"],
    scene: "scenes/skinned-arm.toml",
    docs: "docs/animation/skinned_meshes.md",
    knobs: &[&SKINNING_ON, &JOINT_STORAGE],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::BeforeViews,
};

fn passes(scene: &Scene, _: &FrameLights) -> Vec<Pass> {
    let skinned = scene.skinned_objects();
    if skinned.is_empty() || scene.render.skinning_on == SkinningOn::Cpu {
        return vec![];
    }
    let (mut vertices, mut joints) = (0, 0);
    let mut dual = 0;
    for &i in &skinned {
        let s = scene.objects[i].skin.as_ref().unwrap();
        vertices += s.mesh.mesh.vertices.len();
        joints = joints.max(s.mesh.joint_nodes.len());
        dual += usize::from(s.method == SkinMethod::DualQuaternion);
    }
    let storage = match scene.render.joint_storage {
        JointStorage::Auto => "joints in a uniform array while they fit, else a buffer texture",
        JointStorage::Uniforms => "joints in a uniform array",
        JointStorage::Texture => "joints in a buffer texture",
    };
    let draws = format!(
        "{} skinned meshes ({dual} dual quaternion), {vertices} vertices as points into transform feedback, up to {joints} joints, {storage}",
        skinned.len()
    );
    vec![Pass::new("skinning", "skinned vertices", draws, file!())]
}

fn targets(_: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    vec![]
}

struct SkinnedMeshes {
    /// [linear, dual quaternion] x [uniform array, buffer texture].
    programs: [[Program; 2]; 2],
    /// The joints of the mesh being skinned, when they go in the texture.
    joint_texture: TextureBuffer,
    max_uniform_joints: usize,
    reported: Cell<bool>,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    let components = unsafe { p.gl.get_parameter_i32(glow::MAX_VERTEX_UNIFORM_COMPONENTS) };
    let max_uniform_joints = uniform_joint_limit(components);
    let build = |dual: bool, texture: bool| {
        let mut defines = vec![("MAX_JOINTS", max_uniform_joints.to_string())];
        if dual {
            defines.push(("DUAL_QUATERNION", "1".into()));
        }
        if texture {
            defines.push(("JOINTS_IN_TEXTURE", "1".into()));
        }
        p.build_feedback(
            &[(glow::VERTEX_SHADER, "animation/skinned_meshes.vert")],
            &defines,
            &["v_position", "v_normal", "v_uv"],
        )
    };
    Ok(Box::new(SkinnedMeshes {
        programs: [
            [build(false, false)?, build(false, true)?],
            [build(true, false)?, build(true, true)?],
        ],
        joint_texture: TextureBuffer::new(p.gl, glow::RGBA32F)?,
        max_uniform_joints,
        reported: Cell::new(false),
    }))
}

impl SkinnedMeshes {
    /// Whether `s`'s joints go in the buffer texture.
    fn in_texture(&self, storage: JointStorage, s: &SkinDraw) -> bool {
        let fits = s.joints.len() <= self.max_uniform_joints;
        match storage {
            JointStorage::Auto | JointStorage::Uniforms => !fits,
            JointStorage::Texture => true,
        }
    }
}

impl RunPasses for SkinnedMeshes {
    fn run(&self, _: &Pass, f: &Frame) {
        let gl = f.gl;
        let storage = f.scene.render.joint_storage;
        if !self.reported.replace(true) {
            let most = f
                .draws
                .skins
                .iter()
                .map(|s| s.joints.len())
                .max()
                .unwrap_or(0);
            let textured = (f.draws.skins.iter())
                .filter(|s| self.in_texture(storage, s))
                .count();
            eprintln!(
                "skinning: up to {most} joints a mesh; this GL holds {} joint matrices in a uniform array (GL_MAX_VERTEX_UNIFORM_COMPONENTS), more go in a buffer texture: {textured} of {} meshes read the texture",
                self.max_uniform_joints,
                f.draws.skins.len()
            );
            if storage == JointStorage::Uniforms && most > self.max_uniform_joints {
                eprintln!(
                    "skinning: render.joint_storage = \"uniforms\", but {most} joints do not fit: those meshes read a buffer texture"
                );
            }
        }
        unsafe {
            // A draw needs a complete framebuffer even with the rasterizer
            // off (a headless context has no default one): the output's.
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(f.targets.get(OUTPUT).id));
            gl.enable(glow::RASTERIZER_DISCARD);
            for s in &f.draws.skins {
                let dual = usize::from(s.skin.method == SkinMethod::DualQuaternion);
                let texture = self.in_texture(storage, s);
                let program = &self.programs[dual][usize::from(texture)];
                program.use_program();
                let joints = s.joint_columns();
                if texture {
                    let bytes: Vec<u8> = (joints.iter())
                        .flat_map(|m| m.to_cols_array())
                        .flat_map(f32::to_le_bytes)
                        .collect();
                    self.joint_texture.write(&bytes);
                    gl.active_texture(glow::TEXTURE0 + unit::JOINT_TEXTURE);
                    gl.bind_texture(glow::TEXTURE_BUFFER, Some(self.joint_texture.texture));
                    program.set_i32("u_joint_texture", unit::JOINT_TEXTURE as i32);
                } else {
                    program.set_mat4_array("u_joints", &joints);
                }
                let mesh = &f.draws.meshes[f.draws.items[s.item].mesh];
                gl.bind_buffer_base(
                    glow::TRANSFORM_FEEDBACK_BUFFER,
                    0,
                    Some(mesh.vertex_buffer()),
                );
                gl.begin_transform_feedback(glow::POINTS);
                gl.bind_vertex_array(Some(s.vertices.vao));
                gl.draw_arrays(glow::POINTS, 0, s.vertices.count);
                gl.end_transform_feedback();
                gl.bind_buffer_base(glow::TRANSFORM_FEEDBACK_BUFFER, 0, None);
            }
            gl.bind_vertex_array(None);
            gl.bind_texture(glow::TEXTURE_BUFFER, None);
            gl.disable(glow::RASTERIZER_DISCARD);
            gl.use_program(None);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }
}
