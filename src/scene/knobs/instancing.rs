//! The knobs of instancing and of the geometry shader's normals (LearnOpenGL,
//! 4.advanced_opengl "Instancing", "Geometry Shader").

use super::{Kind, Knob, Value};

pub static INSTANCING: Knob = Knob {
    key: "render.instancing",
    label: "instanced draw",
    help: "the [instancing] rocks in one glDrawElementsInstanced, each rock's model matrix an instanced vertex attribute (glVertexAttribDivisor), or one glUniformMatrix4fv + glDrawElements per rock: the same image",
    kind: Kind::Bool,
    get: |r| Value::Bool(r.instancing),
    set: |r, v| {
        if let Value::Bool(b) = v {
            r.instancing = b;
        }
    },
};

pub static SHOW_NORMALS: Knob = Knob {
    key: "render.show_normals",
    label: "show normals",
    help: "draw each opaque object's vertex normals as lines: a geometry shader emits one line per vertex of every triangle (LearnOpenGL, Geometry Shader)",
    kind: Kind::Bool,
    get: |r| Value::Bool(r.show_normals),
    set: |r, v| {
        if let Value::Bool(b) = v {
            r.show_normals = b;
        }
    },
};

pub static NORMAL_LENGTH: Knob = Knob {
    key: "render.normal_length",
    label: "normal length",
    help: "how long the drawn normals are, in world units",
    kind: Kind::Number {
        min: 0.01,
        max: 2.0,
        log: true,
    },
    get: |r| Value::Number(r.normal_length),
    set: |r, v| {
        if let Value::Number(x) = v {
            r.normal_length = x;
        }
    },
};
