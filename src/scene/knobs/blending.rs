//! The knobs of order-independent transparency
//! (docs/blending/order_independent_transparency.md).

use super::{Kind, Knob, Value, index};
use crate::scene::checks::PEEL_LAYERS;
use crate::scene::settings::Transparency;

pub static TRANSPARENCY: Knob = Knob {
    key: "render.transparency",
    label: "transparency",
    help: "sorted per object (notes 01 §6.1), weighted_blended (McGuire and Bavoil 2013: no sort, approximate) or depth_peeling (Everitt 2001: exact, one pass per layer)",
    kind: Kind::Choice(Transparency::WORDS),
    get: |r| Value::Choice(index(Transparency::ALL, r.transparency)),
    set: |r, v| {
        if let Value::Choice(i) = v {
            r.transparency = Transparency::ALL[i];
        }
    },
};

pub static PEEL_LAYERS_KNOB: Knob = Knob {
    key: "render.peel_layers",
    label: "peeled layers",
    help: "depth peeling: how many layers of transparent fragments are peeled (one pass each); fragments deeper than that are dropped",
    kind: Kind::Count {
        min: *PEEL_LAYERS.start(),
        max: *PEEL_LAYERS.end(),
    },
    get: |r| Value::Count(r.peel_layers),
    set: |r, v| {
        if let Value::Count(n) = v {
            r.peel_layers = n;
        }
    },
};
