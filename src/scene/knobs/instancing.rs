//! The knob of instancing (LearnOpenGL, 4.advanced_opengl "Instancing").

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
