//! The sky's knob (notes 03, Implementation).

use super::{Kind, Knob, Value};

pub static IBL: Knob = Knob {
    key: "render.ibl",
    label: "image-based lighting",
    help: "the ambient term from the environment (the [sky]'s cube map or the [skybox]): an irradiance cube map for k_d, a prefiltered cube map and the split-sum table for the microfacet specular (Karis 2013, \"Real Shading in Unreal Engine 4\"), instead of the constant ambient",
    kind: Kind::Bool,
    get: |r| Value::Bool(r.ibl),
    set: |r, v| {
        if let Value::Bool(b) = v {
            r.ibl = b;
        }
    },
};

pub static SKY_FIRST: Knob = Knob {
    key: "render.sky_first",
    label: "sky first",
    help: "draw the skybox before the opaque world with the depth test off, over every pixel, instead of last at z = w with GL_LEQUAL, where only the background is drawn (notes 03, Implementation; forward path)",
    kind: Kind::Bool,
    get: |r| Value::Bool(r.sky_first),
    set: |r, v| {
        if let Value::Bool(b) = v {
            r.sky_first = b;
        }
    },
};
