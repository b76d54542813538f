//! The knobs of texture mapping (notes 01 §5): one filter for every
//! material, how texture coordinates are interpolated, and the mip levels
//! shown as colours; and bump mapping (notes 01 §8.4) on or off.

use super::{Kind, Knob, Value, index};
use crate::scene::texturing::{FilterOverride, Interpolation};

pub static TEXTURE_FILTER: Knob = Knob {
    key: "render.texture_filter",
    label: "texture filter",
    help: "material: each material's own filter; otherwise one for all: nearest, bilinear (§5.2), the nearest mip level point-sampled or bilinear (§5.3), trilinear (§5.3.1), anisotropic",
    kind: Kind::Choice(FilterOverride::WORDS),
    get: |r| Value::Choice(index(FilterOverride::ALL, r.texture_filter)),
    set: |r, v| {
        if let Value::Choice(i) = v {
            r.texture_filter = FilterOverride::ALL[i];
        }
    },
};

pub static INTERPOLATION: Knob = Knob {
    key: "render.interpolation",
    label: "interpolation",
    help: "texture coordinates and vertex colours: perspective-correct (divided by w, interpolated, multiplied back: §4.1, §5.1), or affine, linear across the screen (GLSL noperspective), which bends a tilted texture",
    kind: Kind::Choice(Interpolation::WORDS),
    get: |r| Value::Choice(index(Interpolation::ALL, r.interpolation)),
    set: |r, v| {
        if let Value::Choice(i) = v {
            r.interpolation = Interpolation::ALL[i];
        }
    },
};

pub static NORMAL_MAPPING: Knob = Knob {
    key: "render.normal_mapping",
    label: "normal maps",
    help: "materials with a normal_map perturb each fragment's normal with it, through the TBN matrix (notes 01 §8.4); off: the mesh's interpolated normal",
    kind: Kind::Bool,
    get: |r| Value::Bool(r.normal_mapping),
    set: |r, v| {
        if let Value::Bool(b) = v {
            r.normal_mapping = b;
        }
    },
};

pub static LIGHT_MAPS: Knob = Knob {
    key: "render.light_maps",
    label: "light maps",
    help: "objects with a light_map draw the diffuse light baked when the scene loaded, with no light loop (notes 01 §8.2, forward path); off: they are lit per frame like the rest",
    kind: Kind::Bool,
    get: |r| Value::Bool(r.light_maps),
    set: |r, v| {
        if let Value::Bool(b) = v {
            r.light_maps = b;
        }
    },
};

pub static MIP_COLORS: Knob = Knob {
    key: "render.mip_colors",
    label: "mip levels as colours",
    help: "each texture is replaced by a twin of its size whose mip levels are flat colours (level 0 red, 1 green, 2 blue, 3 yellow, 4 magenta, 5 cyan, 6 white, 7 black, then again): the level lambda picks, pixel by pixel (§5.3)",
    kind: Kind::Bool,
    get: |r| Value::Bool(r.mip_colors),
    set: |r, v| {
        if let Value::Bool(b) = v {
            r.mip_colors = b;
        }
    },
};
