//! The knobs of instancing and of the geometry shader's normals and
//! exploding objects (LearnOpenGL, 4.advanced_opengl "Instancing",
//! "Geometry Shader").

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

pub static EXPLODE: Knob = Knob {
    key: "render.explode",
    label: "explode",
    help: "draw the opaque objects exploded: a geometry shader moves each triangle along its face normal by magnitude x (sin(t) + 1) / 2, t the scene's time (LearnOpenGL, Geometry Shader; forward path, Phong shading)",
    kind: Kind::Bool,
    get: |r| Value::Bool(r.explode),
    set: |r, v| {
        if let Value::Bool(b) = v {
            r.explode = b;
        }
    },
};

pub static EXPLODE_MAGNITUDE: Knob = Knob {
    key: "render.explode_magnitude",
    label: "explode magnitude",
    help: "how far the exploded triangles move at most, in world units",
    kind: Kind::Number {
        min: 0.0,
        max: 4.0,
        log: false,
    },
    get: |r| Value::Number(r.explode_magnitude),
    set: |r, v| {
        if let Value::Number(x) = v {
            r.explode_magnitude = x;
        }
    },
};
