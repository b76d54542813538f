//! The knobs of parallax mapping (docs/lighting/parallax_mapping.md).

use super::{Kind, Knob, Value, index};
use crate::scene::checks::PARALLAX_LAYERS as LAYERS;
use crate::scene::settings::Parallax;

pub static PARALLAX: Knob = Knob {
    key: "render.parallax",
    label: "parallax",
    help: "materials with a height_map: off (normal map only), plain (one offset by the height at the fragment), steep (the view ray marched through layers) or occlusion (steep, then the hit interpolated between the last two layers)",
    kind: Kind::Choice(Parallax::WORDS),
    get: |r| Value::Choice(index(Parallax::ALL, r.parallax)),
    set: |r, v| {
        if let Value::Choice(i) = v {
            r.parallax = Parallax::ALL[i];
        }
    },
};

pub static PARALLAX_LAYERS: Knob = Knob {
    key: "render.parallax_layers",
    label: "parallax layers",
    help: "steep and occlusion parallax: how many layers the view ray (and the ray toward each light) is marched through",
    kind: Kind::Count {
        min: *LAYERS.start(),
        max: *LAYERS.end(),
    },
    get: |r| Value::Count(r.parallax_layers),
    set: |r, v| {
        if let Value::Count(n) = v {
            r.parallax_layers = n;
        }
    },
};

pub static PARALLAX_SHADOWS: Knob = Knob {
    key: "render.parallax_shadows",
    label: "relief shadows",
    help: "parallax mapping: a ray from the point the view ray hits toward each light; the light is blocked where the relief rises above it (Tatarchuk 2006)",
    kind: Kind::Bool,
    get: |r| Value::Bool(r.parallax_shadows),
    set: |r, v| {
        if let Value::Bool(b) = v {
            r.parallax_shadows = b;
        }
    },
};

pub static PARALLAX_UV: Knob = Knob {
    key: "render.parallax_uv",
    label: "show parallax uv",
    help: "colour each parallax-mapped pixel by the uv its view ray hits (red u, green v, fractions) and blue 1 where the first light reaches that point, 0 where the relief blocks it",
    kind: Kind::Bool,
    get: |r| Value::Bool(r.parallax_uv),
    set: |r, v| {
        if let Value::Bool(b) = v {
            r.parallax_uv = b;
        }
    },
};
