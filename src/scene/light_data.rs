//! `render.light_data`: the form in which tiled shading and the far field
//! read the lights (src/frame/light_halves.rs).

use super::settings::setting;

setting! {
    /// Where tiled shading and the far field read the lights
    /// (src/frame/light_halves.rs, docs/many-lights.md "Light data").
    pub enum LightData {
        /// Four RGBA32F texels a light in a buffer texture.
        Texture = "texture",
        /// The std140 `Lights` uniform block (when every light fits on every GL).
        Block = "block",
        /// Every field as a half float, two to a uint: two RGBA32UI texels a light.
        Halves = "halves",
        /// The position as three floats, the rest halves: three RGBA32UI texels a light.
        HalvesFloatPosition = "halves_float_position",
    }
}
