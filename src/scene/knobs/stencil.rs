//! The knobs of the stencil techniques beyond the notes' mirrors: object
//! outlines (LearnOpenGL, 4.advanced_opengl "Stencil testing").

use super::{Kind, Knob, Value};
use crate::scene::outlines::OUTLINE_WIDTHS;

pub static OUTLINES: Knob = Knob {
    key: "render.outlines",
    label: "object outlines",
    help: "draw an outline around the [outlines] objects: the object marks the stencil buffer, then its extruded copy is drawn where the stencil is not marked (LearnOpenGL, Stencil testing)",
    kind: Kind::Bool,
    get: |r| Value::Bool(r.outlines),
    set: |r, v| {
        if let Value::Bool(b) = v {
            r.outlines = b;
        }
    },
};

pub static OUTLINE_WIDTH: Knob = Knob {
    key: "render.outline_width",
    label: "outline width (pixels)",
    help: "how far the outline pass moves each vertex along its normal's direction on screen, in pixels",
    kind: Kind::Count {
        min: *OUTLINE_WIDTHS.start(),
        max: *OUTLINE_WIDTHS.end(),
    },
    get: |r| Value::Count(r.outline_width),
    set: |r, v| {
        if let Value::Count(n) = v {
            r.outline_width = n;
        }
    },
};
