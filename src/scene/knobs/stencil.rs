//! The knobs of the stencil techniques: the notes 05 mirrors, and beyond
//! them object outlines (LearnOpenGL, 4.advanced_opengl "Stencil testing").

use super::{Kind, Knob, Value, index};
use crate::scene::outlines::OUTLINE_WIDTHS;
use crate::scene::settings::MirrorOrder;

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

pub static MIRROR_ORDER: Knob = Knob {
    key: "render.mirror_order",
    label: "mirror order",
    help: "notes 05: normal first (several mirrors, recursion) or reflected first (one mirror)",
    kind: Kind::Choice(MirrorOrder::WORDS),
    get: |r| Value::Choice(index(MirrorOrder::ALL, r.mirror_order)),
    set: |r, v| {
        if let Value::Choice(i) = v {
            r.mirror_order = MirrorOrder::ALL[i];
        }
    },
};

pub static MIRROR_DEPTH: Knob = Knob {
    key: "render.mirror_depth",
    label: "mirror depth",
    help: "how many mirrors deep a reflection goes (mirrors seen in mirrors)",
    kind: Kind::Count {
        min: 1,
        max: crate::scene::checks::MAX_MIRROR_DEPTH,
    },
    get: |r| Value::Count(r.mirror_depth),
    set: |r, v| {
        if let Value::Count(n) = v {
            r.mirror_depth = n;
        }
    },
};

pub static MIRROR_CLIP: Knob = Knob {
    key: "render.mirror_clip",
    label: "clip behind mirror",
    help: "notes 05: a clip plane (gl_ClipDistance[0]) cuts away what lies behind the mirror; off shows it in the reflection",
    kind: Kind::Bool,
    get: |r| Value::Bool(r.mirror_clip),
    set: |r, v| {
        if let Value::Bool(b) = v {
            r.mirror_clip = b;
        }
    },
};

pub static MIRROR_WINDING: Knob = Knob {
    key: "render.mirror_winding",
    label: "mirror winding fix",
    help: "notes 05 \"Small Problem\": glFrontFace(GL_CW) while drawing a reflection; off culls the wrong faces",
    kind: Kind::Bool,
    get: |r| Value::Bool(r.mirror_winding),
    set: |r, v| {
        if let Value::Bool(b) = v {
            r.mirror_winding = b;
        }
    },
};
