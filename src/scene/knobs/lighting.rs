//! The knobs of the lighting paths: the light-volume cutoff, the stencil
//! volumes, the accumulation format, the deferred path's form, and tiled
//! shading's grid and far field; the G-buffer's material encoding; the
//! form of the light data tiled shading and the far field read.

use super::{Kind, Knob, Value, index};
use crate::scene::LightData;
use crate::scene::area_lights::AreaLightReference;
use crate::scene::settings::{
    Accumulation, DeferredLights, Falloff, GBufferEncoding, GBufferNormals,
};

pub static CUTOFF: Knob = Knob {
    key: "render.cutoff",
    label: "light-volume cutoff",
    help: "a light's volume ends where it falls to this fraction of its brightest channel (notes 04: 5/256)",
    kind: Kind::Number {
        min: 1e-5,
        max: 0.5,
        log: true,
    },
    get: |r| Value::Number(r.cutoff),
    set: |r, v| {
        if let Value::Number(x) = v {
            r.cutoff = x;
        }
    },
};

pub static STENCIL_VOLUMES: Knob = Knob {
    key: "render.stencil_volumes",
    label: "stencil volumes",
    help: "mark each light's lit pixels with the two-sided stencil test first (notes 05)",
    kind: Kind::Bool,
    get: |r| Value::Bool(r.stencil_volumes),
    set: |r, v| {
        if let Value::Bool(b) = v {
            r.stencil_volumes = b;
        }
    },
};

pub static ACCUMULATION: Knob = Knob {
    key: "render.accumulation",
    label: "light accumulation",
    help: "the format lights add up in: rgba16f, or rgba32f for hundreds of lights",
    kind: Kind::Choice(Accumulation::WORDS),
    get: |r| Value::Choice(index(Accumulation::ALL, r.accumulation)),
    set: |r, v| {
        if let Value::Choice(i) = v {
            r.accumulation = Accumulation::ALL[i];
        }
    },
};

pub static FALLOFF: Knob = Knob {
    key: "render.falloff",
    label: "falloff",
    help: "notes: 1 / (Kc + Kl d + Kq d^2), cut at the radius by the volume paths; windowed: a different model that reaches 0 at the radius, so no path cuts anything; linear: notes 01's 1 - d / Lmax (a light's range), its volume exactly Lmax",
    kind: Kind::Choice(Falloff::WORDS),
    get: |r| Value::Choice(index(Falloff::ALL, r.falloff)),
    set: |r, v| {
        if let Value::Choice(i) = v {
            r.falloff = Falloff::ALL[i];
        }
    },
};

pub static DEFERRED_LIGHTS: Knob = Knob {
    key: "render.deferred_lights",
    label: "deferred lights",
    help: "the deferred path: a full-screen pass per light (notes 04), or one pass looping over all (notes 01 §8.6.2)",
    kind: Kind::Choice(DeferredLights::WORDS),
    get: |r| Value::Choice(index(DeferredLights::ALL, r.deferred_lights)),
    set: |r, v| {
        if let Value::Choice(i) = v {
            r.deferred_lights = DeferredLights::ALL[i];
        }
    },
};

pub static TILE_SIZE: Knob = Knob {
    key: "render.tile_size",
    label: "tile size",
    help: "tiled shading: the screen tile's edge in pixels (lights are binned per tile on the CPU)",
    kind: Kind::Count {
        min: *crate::scene::checks::TILE_SIZES.start(),
        max: *crate::scene::checks::TILE_SIZES.end(),
    },
    get: |r| Value::Count(r.tile_size),
    set: |r, v| {
        if let Value::Count(n) = v {
            r.tile_size = n;
        }
    },
};

pub static FAR_FIELD: Knob = Knob {
    key: "render.far_field",
    label: "far field",
    help: "tiled shading: 0 stops each light at its cutoff radius; k adds the light beyond half that radius from a far field sampled once per k x k pixels",
    kind: Kind::Count {
        min: 0,
        max: *crate::scene::checks::FAR_FIELD_SCALES.end(),
    },
    get: |r| Value::Count(r.far_field),
    set: |r, v| {
        if let Value::Count(n) = v {
            r.far_field = n;
        }
    },
};

pub static FAR_FIELD_SH: Knob = Knob {
    key: "render.far_field_sh",
    label: "far field as harmonics",
    help: "tiled shading's far field: the diffuse far light as order-2 spherical harmonics per sample, evaluated at each pixel's own normal (curved surfaces too)",
    kind: Kind::Bool,
    get: |r| Value::Bool(r.far_field_sh),
    set: |r, v| {
        if let Value::Bool(b) = v {
            r.far_field_sh = b;
        }
    },
};

pub static NEAR_RADIUS: Knob = Knob {
    key: "render.near_radius",
    label: "near radius",
    help: "tiled shading with a far field: each light's near part (binned per tile) ends at this fraction of its cutoff radius; the far field takes the rest",
    kind: Kind::Number {
        min: 0.05,
        max: 1.0,
        log: false,
    },
    get: |r| Value::Number(r.near_radius),
    set: |r, v| {
        if let Value::Number(x) = v {
            r.near_radius = x;
        }
    },
};

pub static FAR_RADIUS: Knob = Knob {
    key: "render.far_radius",
    label: "far lists' radius",
    help: "tiled shading with a far field: 0, a pixel no sample stands for sums every light's far part; a >= 1, only the lights within 2 a cutoff radii of its cluster, the rest from a sample's harmonics",
    kind: Kind::Count { min: 0, max: 8 },
    get: |r| Value::Count(r.far_radius),
    set: |r, v| {
        if let Value::Count(n) = v {
            r.far_radius = n;
        }
    },
};

pub static DEPTH_SLICES: Knob = Knob {
    key: "render.depth_slices",
    label: "depth slices",
    help: "tiled shading: depth slices between near and far, spaced exponentially (1: tiles only; more: clustered)",
    kind: Kind::Count {
        min: *crate::scene::checks::DEPTH_SLICES.start(),
        max: *crate::scene::checks::DEPTH_SLICES.end(),
    },
    get: |r| Value::Count(r.depth_slices),
    set: |r, v| {
        if let Value::Count(n) = v {
            r.depth_slices = n;
        }
    },
};

pub static GBUFFER_ENCODING: Knob = Knob {
    key: "render.gbuffer_encoding",
    label: "G-buffer material",
    help: "how the G-buffer holds a microfacet material's alpha, eta and k_s (notes 03, Geometry Pass): the report's reciprocal-and-flag scheme (gAlpha + gConvert) in 8 bits or in half floats, or the plain values in half floats (no gConvert)",
    kind: Kind::Choice(GBufferEncoding::WORDS),
    get: |r| Value::Choice(index(GBufferEncoding::ALL, r.gbuffer_encoding)),
    set: |r, v| {
        if let Value::Choice(i) = v {
            r.gbuffer_encoding = GBufferEncoding::ALL[i];
        }
    },
};

pub static AREA_LIGHTS: Knob = Knob {
    key: "render.area_lights",
    label: "area lights (LTC)",
    help: "shade the [[area_lights]] rectangles with linearly transformed cosines and draw them (Heitz et al. 2016; every path, forward with Phong shading)",
    kind: Kind::Bool,
    get: |r| Value::Bool(r.area_lights),
    set: |r, v| {
        if let Value::Bool(b) = v {
            r.area_lights = b;
        }
    },
};

pub static AREA_LIGHT_REFERENCE: Knob = Knob {
    key: "render.area_light_reference",
    label: "area lights' reference",
    help: "off: LTC; exact: the reference LTC is measured against, gloss's own BRDF integrated over each light by quadrature (slow on purpose); table_fresnel: the same with the LTC table's Schlick-average Fresnel",
    kind: Kind::Choice(AreaLightReference::WORDS),
    get: |r| Value::Choice(index(AreaLightReference::ALL, r.area_light_reference)),
    set: |r, v| {
        if let Value::Choice(i) = v {
            r.area_light_reference = AreaLightReference::ALL[i];
        }
    },
};

pub static AREA_LIGHT_POINTS: Knob = Knob {
    key: "render.area_light_points",
    label: "reference points N",
    help: "the area lights' reference: each triangle of a light (clipped to the horizon) cut into N x N, gloss's BRDF taken at each centre",
    kind: Kind::Count { min: 1, max: 256 },
    get: |r| Value::Count(r.area_light_points),
    set: |r, v| {
        if let Value::Count(n) = v {
            r.area_light_points = n;
        }
    },
};

pub static GBUFFER_NORMALS: Knob = Knob {
    key: "render.gbuffer",
    label: "G-buffer normal",
    help: "how the G-buffer holds the normal and shininess: xyz and shininess in half floats (RGBA16F, 8 bytes), or an octahedral normal in 12 + 12 bits with the shininess as an index into the scene's table (RGBA8, 4 bytes; Cigolle et al. 2014)",
    kind: Kind::Choice(GBufferNormals::WORDS),
    get: |r| Value::Choice(index(GBufferNormals::ALL, r.gbuffer)),
    set: |r, v| {
        if let Value::Choice(i) = v {
            r.gbuffer = GBufferNormals::ALL[i];
        }
    },
};

pub static GBUFFER_SLIM: Knob = Knob {
    key: "render.gbuffer_slim",
    label: "slim G-buffer",
    help: "leave the specular attachment out of the G-buffer when every opaque material has one specular colour, no specular map, no microfacet lobe and no reflectivity: the lighting passes read the colour from a uniform (4 bytes a pixel fewer); off: always the full G-buffer",
    kind: Kind::Bool,
    get: |r| Value::Bool(r.gbuffer_slim),
    set: |r, v| {
        if let Value::Bool(b) = v {
            r.gbuffer_slim = b;
        }
    },
};

pub static HARDWARE_SRGB: Knob = Knob {
    key: "render.hardware_srgb",
    label: "sRGB by the hardware",
    help: "the composite writes linear light into an SRGB8_ALPHA8 output with GL_FRAMEBUFFER_SRGB on (no post chain, 8-bit output); off: pow() in the shader",
    kind: Kind::Bool,
    get: |r| Value::Bool(r.hardware_srgb),
    set: |r, v| {
        if let Value::Bool(b) = v {
            r.hardware_srgb = b;
        }
    },
};

pub static LIGHT_DATA: Knob = Knob {
    key: "render.light_data",
    label: "light data",
    help: "with specialised shaders, where tiled shading and the far field read the lights: a buffer texture of floats (4 RGBA32F texels a light), the uniform block (when all fit on every GL: 256), every field as a half float (2 RGBA32UI texels), or the position as floats and the rest halves (3 texels); src/frame/light_halves.rs",
    kind: Kind::Choice(LightData::WORDS),
    get: |r| Value::Choice(index(LightData::ALL, r.light_data)),
    set: |r, v| {
        if let Value::Choice(i) = v {
            r.light_data = LightData::ALL[i];
        }
    },
};
