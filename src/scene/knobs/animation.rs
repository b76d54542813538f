//! The knobs of skinned meshes (notes 01 §7.1): where they are skinned, and
//! where the skinning pass reads the joint matrices from.

use super::{Kind, Knob, Value, index};
use crate::scene::settings::{JointStorage, SkinningOn};

pub static SKINNING_ON: Knob = Knob {
    key: "render.skinning_on",
    label: "skinning on",
    help: "gpu: the skinning pass (a vertex shader with transform feedback); cpu: the reference, each pose skinned on the CPU and uploaded",
    kind: Kind::Choice(SkinningOn::WORDS),
    get: |r| Value::Choice(index(SkinningOn::ALL, r.skinning_on)),
    set: |r, v| {
        if let Value::Choice(i) = v {
            r.skinning_on = SkinningOn::ALL[i];
        }
    },
};

pub static JOINT_STORAGE: Knob = Knob {
    key: "render.joint_storage",
    label: "joint matrices in",
    help: "auto: a uniform array while the skeleton fits GL_MAX_VERTEX_UNIFORM_COMPONENTS, a buffer texture beyond; uniforms or texture: always that",
    kind: Kind::Choice(JointStorage::WORDS),
    get: |r| Value::Choice(index(JointStorage::ALL, r.joint_storage)),
    set: |r, v| {
        if let Value::Choice(i) = v {
            r.joint_storage = JointStorage::ALL[i];
        }
    },
};
