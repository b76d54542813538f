//! The render settings, described for editing: each knob names its key in
//! the scene file (`render.cutoff`), what kind of value it takes, and how to
//! read and write it. The demo's panel draws a control per knob, `--set
//! KEY=VALUE` on the command line sets the same key as the scene file does
//! (through the same parser and checks: `Scene::parse_with`), and a technique
//! lists the knobs it reads in its registration.

use super::RenderSettings;
use super::settings::{BillboardMode, ChainForm, DepthFunc, RenderPath, Shading};
use glam::Vec3;

mod animation;
mod blending;
mod instancing;
pub mod keys;
mod lighting;
mod parallax;
mod sky;
mod stencil;
mod texturing;
pub use animation::{JOINT_STORAGE, SKINNING_ON};
pub use blending::{PEEL_LAYERS_KNOB as PEEL_LAYERS, TRANSPARENCY};
pub use instancing::{EXPLODE, EXPLODE_MAGNITUDE, INSTANCING, NORMAL_LENGTH, SHOW_NORMALS};
pub use lighting::{
    ACCUMULATION, AREA_LIGHT_POINTS, AREA_LIGHT_REFERENCE, AREA_LIGHTS, CUTOFF, DEFERRED_LIGHTS,
    DEPTH_SLICES, FALLOFF, FAR_FIELD, FAR_FIELD_SH, FAR_RADIUS, GBUFFER_ENCODING, GBUFFER_NORMALS,
    GBUFFER_SLIM, HARDWARE_SRGB, LIGHT_DATA, NEAR_RADIUS, STENCIL_VOLUMES, TILE_SIZE,
};
pub use parallax::{PARALLAX, PARALLAX_LAYERS, PARALLAX_SHADOWS, PARALLAX_UV};
pub use sky::{IBL, SKY_FIRST};
pub use stencil::{
    MIRROR_CLIP, MIRROR_DEPTH, MIRROR_ORDER, MIRROR_WINDING, OUTLINE_WIDTH, OUTLINES,
};
pub use texturing::{INTERPOLATION, LIGHT_MAPS, MIP_COLORS, NORMAL_MAPPING, TEXTURE_FILTER};

/// What a knob holds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Value {
    Bool(bool),
    Number(f32),
    /// A whole number.
    Count(u32),
    /// An index into the knob's `choices`.
    Choice(usize),
    Color(Vec3),
}

/// The kind of control.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Kind {
    Bool,
    /// A number in `min..max` (exclusive ends are enforced by the scene
    /// loader); `log`: a logarithmic slider.
    Number {
        min: f32,
        max: f32,
        log: bool,
    },
    Choice(&'static [&'static str]),
    /// A whole number in `min..=max`.
    Count {
        min: u32,
        max: u32,
    },
    /// A linear RGB colour, each channel >= 0.
    Color,
}

pub struct Knob {
    /// The key in the scene file, `table.key`.
    pub key: &'static str,
    pub label: &'static str,
    /// One line for the panel's tooltip.
    pub help: &'static str,
    pub kind: Kind,
    pub get: fn(&RenderSettings) -> Value,
    pub set: fn(&mut RenderSettings, Value),
}

impl Knob {
    /// The value as TOML (what `--set` and "save as" write).
    pub fn toml(&self, r: &RenderSettings) -> String {
        match ((self.get)(r), self.kind) {
            (Value::Bool(b), _) => b.to_string(),
            (Value::Number(x), _) => format!("{x:?}"),
            (Value::Count(n), _) => n.to_string(),
            // A choice among numbers (render.msaa) is written as the number.
            (Value::Choice(i), Kind::Choice(words)) if words[i].parse::<u32>().is_ok() => {
                words[i].to_string()
            }
            (Value::Choice(i), Kind::Choice(words)) => format!("\"{}\"", words[i]),
            (Value::Color(c), _) => format!("[{:?}, {:?}, {:?}]", c.x, c.y, c.z),
            (Value::Choice(i), _) => i.to_string(),
        }
    }
}

pub static PATH: Knob = Knob {
    key: "render.path",
    label: "lighting path",
    help: "forward, deferred (a full-screen pass per light), volumes (notes 04), prepass (notes 02), tiled (lights binned per screen tile and depth slice)",
    kind: Kind::Choice(RenderPath::WORDS),
    get: |r| Value::Choice(index(RenderPath::ALL, r.path)),
    set: |r, v| {
        if let Value::Choice(i) = v {
            r.path = RenderPath::ALL[i];
        }
    },
};

pub static SHADING: Knob = Knob {
    key: "render.shading",
    label: "shading",
    help: "notes 01 §8.2: flat (per triangle), Gouraud (per vertex), Phong (per fragment)",
    kind: Kind::Choice(Shading::WORDS),
    get: |r| Value::Choice(index(Shading::ALL, r.shading)),
    set: |r, v| {
        if let Value::Choice(i) = v {
            r.shading = Shading::ALL[i];
        }
    },
};

pub static DEPTH_FUNC: Knob = Knob {
    key: "render.depth_func",
    label: "depth test",
    help: "GL_LESS (notes 02: fails when d >= D) or GL_LEQUAL (notes 01: passes when z <= D)",
    kind: Kind::Choice(DepthFunc::WORDS),
    get: |r| Value::Choice(index(DepthFunc::ALL, r.depth_func)),
    set: |r, v| {
        if let Value::Choice(i) = v {
            r.depth_func = DepthFunc::ALL[i];
        }
    },
};

pub static AMBIENT: Knob = Knob {
    key: "render.ambient",
    label: "ambient",
    help: "the ambient light, linear RGB (notes 01 §8.3)",
    kind: Kind::Color,
    get: |r| Value::Color(r.ambient),
    set: |r, v| {
        if let Value::Color(c) = v {
            r.ambient = c;
        }
    },
};

pub static BACKGROUND: Knob = Knob {
    key: "render.background",
    label: "background",
    help: "the clear colour, linear RGB",
    kind: Kind::Color,
    get: |r| Value::Color(r.background),
    set: |r, v| {
        if let Value::Color(c) = v {
            r.background = c;
        }
    },
};

pub static POST_CHAIN: Knob = Knob {
    key: "render.post_chain",
    label: "post chain",
    help: "notes 01 §9: ping-pong (one framebuffer, two textures) or cascaded (a framebuffer per step)",
    kind: Kind::Choice(ChainForm::WORDS),
    get: |r| Value::Choice(index(ChainForm::ALL, r.post_chain)),
    set: |r, v| {
        if let Value::Choice(i) = v {
            r.post_chain = ChainForm::ALL[i];
        }
    },
};

pub static BILLBOARDS: Knob = Knob {
    key: "render.billboards",
    label: "billboards",
    help: "notes 05: alpha_test (discard alpha < 0.5), blend (unsorted: holes), blend_sorted (back to front)",
    kind: Kind::Choice(BillboardMode::WORDS),
    get: |r| Value::Choice(index(BillboardMode::ALL, r.billboards)),
    set: |r, v| {
        if let Value::Choice(i) = v {
            r.billboards = BillboardMode::ALL[i];
        }
    },
};

pub static BILLBOARD_ALPHA_REF: Knob = Knob {
    key: "render.billboard_alpha_ref",
    label: "billboard alpha reference",
    help: "the alpha test passes alpha >= this (notes 05: \"do not let alpha < 0.5 pass through\")",
    kind: Kind::Number {
        min: 0.0,
        max: 1.0,
        log: false,
    },
    get: |r| Value::Number(r.billboard_alpha_ref),
    set: |r, v| {
        if let Value::Number(x) = v {
            r.billboard_alpha_ref = x;
        }
    },
};

pub static SORT_TRANSPARENT: Knob = Knob {
    key: "render.sort_transparent",
    label: "sort transparent",
    help: "draw transparent objects back to front (notes 01 §6.1); off shows the wrong blend order",
    kind: Kind::Bool,
    get: |r| Value::Bool(r.sort_transparent),
    set: |r, v| {
        if let Value::Bool(b) = v {
            r.sort_transparent = b;
        }
    },
};

pub static SORT_OPAQUE: Knob = Knob {
    key: "render.sort_opaque",
    label: "sort opaque",
    help: "draw opaque objects front to back (notes 01 §6.2), so that hidden fragments fail the depth test before they are shaded; off: the scene file's order",
    kind: Kind::Bool,
    get: |r| Value::Bool(r.sort_opaque),
    set: |r, v| {
        if let Value::Bool(b) = v {
            r.sort_opaque = b;
        }
    },
};

pub static SPECIALIZE: Knob = Knob {
    key: "render.specialize",
    label: "specialised shaders",
    help: "compile the lighting passes for what the scene holds (its light types, falloff, shadows, Phong or microfacet: src/frame/variant.rs); off: the general shader, every part for every light",
    kind: Kind::Bool,
    get: |r| Value::Bool(r.specialize),
    set: |r, v| {
        if let Value::Bool(b) = v {
            r.specialize = b;
        }
    },
};

pub static LIGHT_BLOCK: Knob = Knob {
    key: "render.light_block",
    label: "lights from the uniform block",
    help: "the older name of render.light_data = \"block\": with specialised shaders, tiled shading and the far field read the lights from the uniform block when all of them fit on every GL (256); off (the default: on llvmpipe the two measured the same): from the buffer texture (src/frame/variant.rs)",
    kind: Kind::Bool,
    get: |r| Value::Bool(r.light_block),
    set: |r, v| {
        if let Value::Bool(b) = v {
            r.light_block = b;
        }
    },
};

pub static FRUSTUM_CULLING: Knob = Knob {
    key: "render.frustum_culling",
    label: "frustum culling",
    help: "draw only the opaque objects whose bounds reach into the view's frustum (notes 01 §6.3), walking the scene graph: a subtree wholly outside costs one test",
    kind: Kind::Bool,
    get: |r| Value::Bool(r.frustum_culling),
    set: |r, v| {
        if let Value::Bool(b) = v {
            r.frustum_culling = b;
        }
    },
};

pub static WIREFRAME: Knob = Knob {
    key: "render.wireframe",
    label: "triangle edges only",
    help: "the forward and G-buffer passes draw each triangle's edges (glPolygonMode(GL_LINE)): see where the near plane cuts the triangles",
    kind: Kind::Bool,
    get: |r| Value::Bool(r.wireframe),
    set: |r, v| {
        if let Value::Bool(b) = v {
            r.wireframe = b;
        }
    },
};

pub static MSAA: Knob = Knob {
    key: "render.msaa",
    label: "MSAA samples",
    help: "samples per pixel of the world on the forward path, resolved with glBlitFramebuffer (1: no MSAA)",
    kind: Kind::Choice(&["1", "2", "4", "8"]),
    get: |r| Value::Choice(index(&super::checks::MSAA_SAMPLES, r.msaa)),
    set: |r, v| {
        if let Value::Choice(i) = v {
            r.msaa = super::checks::MSAA_SAMPLES[i];
        }
    },
};

/// Every knob, in the order the panel shows the frame-wide ones.
pub static ALL: &[&Knob] = &[
    &PATH,
    &SHADING,
    &DEPTH_FUNC,
    &CUTOFF,
    &FALLOFF,
    &STENCIL_VOLUMES,
    &ACCUMULATION,
    &DEFERRED_LIGHTS,
    &TILE_SIZE,
    &FAR_FIELD,
    &DEPTH_SLICES,
    &GBUFFER_ENCODING,
    &GBUFFER_NORMALS,
    &GBUFFER_SLIM,
    &AMBIENT,
    &BACKGROUND,
    &HARDWARE_SRGB,
    &MIRROR_ORDER,
    &MIRROR_DEPTH,
    &MIRROR_CLIP,
    &MIRROR_WINDING,
    &BILLBOARDS,
    &BILLBOARD_ALPHA_REF,
    &SORT_TRANSPARENT,
    &TRANSPARENCY,
    &PEEL_LAYERS,
    &SORT_OPAQUE,
    &SPECIALIZE,
    &LIGHT_BLOCK,
    &LIGHT_DATA,
    &FRUSTUM_CULLING,
    &WIREFRAME,
    &OUTLINES,
    &OUTLINE_WIDTH,
    &INSTANCING,
    &SHOW_NORMALS,
    &NORMAL_LENGTH,
    &EXPLODE,
    &EXPLODE_MAGNITUDE,
    &TEXTURE_FILTER,
    &INTERPOLATION,
    &MIP_COLORS,
    &NORMAL_MAPPING,
    &PARALLAX,
    &PARALLAX_LAYERS,
    &PARALLAX_SHADOWS,
    &PARALLAX_UV,
    &LIGHT_MAPS,
    &SKY_FIRST,
    &IBL,
    &AREA_LIGHTS,
    &AREA_LIGHT_REFERENCE,
    &AREA_LIGHT_POINTS,
    &POST_CHAIN,
    &MSAA,
    &SKINNING_ON,
    &JOINT_STORAGE,
    &FAR_FIELD_SH,
    &NEAR_RADIUS,
    &FAR_RADIUS,
];

/// Whether a switch applies to a scene (it has what the technique draws).
pub type AppliesTo = fn(&super::Scene) -> bool;

/// Knobs that switch a technique off: when one is off, its technique adds
/// no pass and leaves the panel's list with its knobs, so the panel shows
/// these (for a scene they apply to) among the techniques not in the frame,
/// to switch them on again.
pub static SWITCHES: &[(&Knob, AppliesTo)] = &[
    (&OUTLINES, |s| s.outlines.is_some()),
    (&SHOW_NORMALS, |s| s.opaque_objects() > 0),
    (&AREA_LIGHTS, |s| !s.area_lights.is_empty()),
    (&EXPLODE, |s| s.opaque_objects() > 0),
    (&PARALLAX, |s| {
        s.materials.iter().any(|m| m.height_map.is_some())
    }),
    (&SKINNING_ON, |s| !s.skinned_objects().is_empty()),
];

fn index<T: PartialEq + Copy>(all: &[T], v: T) -> usize {
    all.iter().position(|&x| x == v).unwrap_or(0)
}
