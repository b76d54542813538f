//! The `[render]` settings that are one word out of a few: written in scene
//! files, given on the command line (`--path volumes`) and, later, picked in
//! the demo. Each is declared once below; the macro derives the parsing,
//! the printing and the list of choices from that one declaration.

/// Declare a setting: an enum whose variants are spelt as the given words
/// in scene files and on the command line.
macro_rules! setting {
    (
        $(#[$meta:meta])*
        pub enum $name:ident {
            $( $(#[$vmeta:meta])* $variant:ident = $word:literal, )+
        }
    ) => {
        $(#[$meta])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, clap::ValueEnum, serde::Serialize)]
        pub enum $name {
            $( $(#[$vmeta])* #[value(name = $word)] #[serde(rename = $word)] $variant, )+
        }

        impl $name {
            /// Every choice, in declaration order.
            pub const ALL: &'static [$name] = &[$($name::$variant),+];
            /// Their words, in the same order.
            pub const WORDS: &'static [&'static str] = &[$($word),+];

            /// The word a scene file uses.
            pub fn name(self) -> &'static str {
                match self {
                    $($name::$variant => $word,)+
                }
            }
        }

        impl std::fmt::Display for $name {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str(self.name())
            }
        }

        impl<'de> serde::Deserialize<'de> for $name {
            fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
                let word = String::deserialize(d)?;
                $name::ALL
                    .iter()
                    .copied()
                    .find(|v| v.name() == word)
                    .ok_or_else(|| {
                        let words: Vec<&str> = $name::ALL.iter().map(|v| v.name()).collect();
                        let (last, rest) = words.split_last().expect("a setting has choices");
                        serde::de::Error::custom(format!(
                            "expected {} or {last}, found \"{word}\"",
                            rest.join(", ")
                        ))
                    })
            }
        }
    };
}
pub(crate) use setting;

setting! {
    /// Which renderer runs the frame.
    pub enum RenderPath {
        /// Every light for every fragment in one pass (notes 04 "forward rendering"): the reference.
        Forward = "forward",
        /// G-buffer, then one full-screen pass per light ("our current deferred shader").
        Deferred = "deferred",
        /// G-buffer, then a volume per light (sphere, cone, full-screen triangle), then composite.
        Volumes = "volumes",
        /// Deferred lighting / light pre-pass (notes 02): diffuse and specular accumulated apart.
        Prepass = "prepass",
        /// G-buffer, lights binned into screen tiles and depth slices on the
        /// CPU, then one full-screen pass shading each pixel with its
        /// cluster's lights (Persson 2015), then composite.
        Tiled = "tiled",
    }
}

setting! {
    /// Notes 01 §8.2 shading modes.
    pub enum Shading {
        /// One colour per triangle (lit at its centroid with its face normal).
        Flat = "flat",
        /// Lighting per vertex, interpolated.
        Gouraud = "gouraud",
        /// Lighting per fragment.
        Phong = "phong",
    }
}

setting! {
    /// The depth test (notes 01 §4.4; notes 05, "Depth Test and Operation":
    /// "Always, Never, <, <=, =, !=, >, >="): a fragment passes when its depth
    /// d compares so with the stored D. Notes 02 says a fragment fails when
    /// d >= D (GL_LESS), notes 01 that it passes when z <= D (GL_LEQUAL).
    /// Every choice is offered, in GL's order.
    pub enum DepthFunc {
        Never = "never",
        Less = "less",
        Equal = "equal",
        Lequal = "lequal",
        Greater = "greater",
        Notequal = "notequal",
        Gequal = "gequal",
        Always = "always",
    }
}

impl DepthFunc {
    /// The glDepthFunc argument.
    pub fn gl(self) -> u32 {
        match self {
            DepthFunc::Never => glow::NEVER,
            DepthFunc::Less => glow::LESS,
            DepthFunc::Equal => glow::EQUAL,
            DepthFunc::Lequal => glow::LEQUAL,
            DepthFunc::Greater => glow::GREATER,
            DepthFunc::Notequal => glow::NOTEQUAL,
            DepthFunc::Gequal => glow::GEQUAL,
            DepthFunc::Always => glow::ALWAYS,
        }
    }

    /// Whether a fragment of depth `d` passes against the stored depth `stored`
    /// (the CPU twin of the test, for the tests).
    pub fn passes(self, d: f64, stored: f64) -> bool {
        match self {
            DepthFunc::Never => false,
            DepthFunc::Less => d < stored,
            DepthFunc::Equal => d == stored,
            DepthFunc::Lequal => d <= stored,
            DepthFunc::Greater => d > stored,
            DepthFunc::Notequal => d != stored,
            DepthFunc::Gequal => d >= stored,
            DepthFunc::Always => true,
        }
    }
}

setting! {
    /// How the post chain's steps pass the image along (notes 01 §9).
    pub enum ChainForm {
        /// "Ping-pong" texturing: one framebuffer and two textures; each
        /// step samples one and renders into the other.
        PingPong = "ping_pong",
        /// "Processing stages may be cascaded": each step its own framebuffer.
        Cascaded = "cascaded",
    }
}

setting! {
    /// The order of a planar mirror's passes (notes 05).
    pub enum MirrorOrder {
        /// "Rendering Normal First": the scene, then each mirror's
        /// stencil, then the reflected world inside it. Handles several
        /// mirrors and recursion.
        NormalFirst = "normal_first",
        /// "Rendering Reflected First": the reflected world, the mirror's
        /// stencil and a clear outside it, then the scene. One mirror.
        ReflectedFirst = "reflected_first",
    }
}

setting! {
    /// The internal format of the light accumulation target.
    pub enum Accumulation {
        /// Half floats: enough for tens of lights per pixel.
        Rgba16f = "rgba16f",
        /// Full floats: no rounding when hundreds of lights add up.
        Rgba32f = "rgba32f",
    }
}

setting! {
    /// Which faces a material's objects cull (notes 01 §3.4, "Face
    /// Culling": "can cull front, back or all faces").
    pub enum Cull {
        /// Faces turned away from the camera (glCullFace(GL_BACK)): the default.
        Back = "back",
        /// Faces turned towards it: a closed mesh shows its inside.
        Front = "front",
        /// Every face (GL_FRONT_AND_BACK): "effectively disables the
        /// rasteriser for triangle based primitives".
        FrontAndBack = "front_and_back",
        /// No culling: both sides drawn (thin, open meshes).
        None = "none",
    }
}

setting! {
    /// Which winding is a front face, for a material's meshes (notes 01
    /// §3.4: "front and back faces are determined by the winding order of
    /// the vertices of triangles").
    pub enum Winding {
        /// Counter-clockwise on screen is the front (glFrontFace(GL_CCW)):
        /// GL's default, and every mesh gloss makes.
        Ccw = "ccw",
        /// Clockwise is the front: a mesh from a tool that winds the other
        /// way (and so do Direct3D's conventions).
        Cw = "cw",
    }
}

impl Cull {
    /// glCullFace's face, or None for glDisable(GL_CULL_FACE).
    pub fn gl(self) -> Option<u32> {
        match self {
            Cull::Back => Some(glow::BACK),
            Cull::Front => Some(glow::FRONT),
            Cull::FrontAndBack => Some(glow::FRONT_AND_BACK),
            Cull::None => None,
        }
    }
}

setting! {
    /// How a point or spot light's attenuation ends.
    pub enum Falloff {
        /// Notes 04's 1 / (Kc + Kl d + Kq d^2), which never reaches 0: the
        /// light-volume paths cut it at the radius and drop the tail.
        Notes = "notes",
        /// A different model: the notes' attenuation times a window that
        /// reaches 0 exactly at the radius, (1 - (d / r)^4)^2 clamped
        /// (Karis 2013). The cutoff then drops nothing.
        Windowed = "windowed",
        /// Notes 01 §8.3's a = 1 - d / Lmax, 0 from Lmax on, with Lmax the
        /// light's `range` (default: its volume radius at the cutoff under
        /// the notes' attenuation). Kc, Kl, Kq are not used. The light
        /// volume's radius is Lmax itself, so the volume paths cut nothing.
        Linear = "linear",
    }
}

setting! {
    /// How a skinned mesh's vertices follow its joints (notes 01 §7.1).
    pub enum SkinMethod {
        /// The notes' formula: the weighted sum of each joint's matrix times
        /// the vertex.
        Linear = "linear",
        /// The joints as unit dual quaternions, blended and normalised
        /// (Kavan et al. 2007): a twisted joint keeps its girth.
        DualQuaternion = "dual_quaternion",
    }
}

setting! {
    /// Where skinned meshes are skinned.
    pub enum SkinningOn {
        /// The skinning pass: a vertex shader with transform feedback.
        Gpu = "gpu",
        /// The CPU reference: each frame's pose skinned on the CPU and
        /// uploaded as a static mesh.
        Cpu = "cpu",
    }
}

setting! {
    /// Where the skinning pass reads the joint matrices from.
    pub enum JointStorage {
        /// A uniform array while the skeleton fits (GL_MAX_VERTEX_UNIFORM_COMPONENTS),
        /// a buffer texture beyond.
        Auto = "auto",
        /// The uniform array (a skeleton that does not fit still reads the
        /// texture, and the pass says so).
        Uniforms = "uniforms",
        /// Always the buffer texture (a texelFetch per column).
        Texture = "texture",
    }
}

setting! {
    /// How the full-screen deferred path loops over the lights.
    pub enum DeferredLights {
        /// One full-screen pass per light, added by blending (notes 04,
        /// "our current deferred shader").
        PerLight = "per_light",
        /// One full-screen pass whose shader loops over every light (notes
        /// 01 §8.6.2: "for every fragment: for every light").
        SinglePass = "single_pass",
    }
}

impl Accumulation {
    /// The texture's internal format.
    pub fn gl(self) -> u32 {
        match self {
            Accumulation::Rgba16f => glow::RGBA16F,
            Accumulation::Rgba32f => glow::RGBA32F,
        }
    }
}

setting! {
    /// The alpha test (notes 05, "Alpha Test"): "if (alpha_fragment op
    /// alpha_reference) pass fragment on". GL 3.3 core has no fixed-function
    /// alpha test: `discard` in glsl/common/alpha_test.glsl does it, and
    /// src/scene/alpha_test.rs is its CPU twin.
    pub enum AlphaTest {
        /// Always let the fragment through (no test: what a material without the key gets).
        Always = "always",
        /// Never let the fragment through.
        Never = "never",
        Less = "less",
        Lequal = "lequal",
        Equal = "equal",
        Notequal = "notequal",
        Greater = "greater",
        /// The notes' default for billboards: pass alpha >= 0.5, discard alpha < 0.5.
        Gequal = "gequal",
    }
}

setting! {
    /// How billboards are drawn (notes 05, "Alpha Test and Billboards").
    pub enum BillboardMode {
        /// The alpha test (discard alpha < 0.5): no blending, no sorting.
        AlphaTest = "alpha_test",
        /// Alpha blending in scene order with depth writes on: the notes' "big problem".
        Blend = "blend",
        /// Alpha blending, sorted back to front by view depth every frame.
        BlendSorted = "blend_sorted",
    }
}

setting! {
    /// Which way a billboard turns to the camera.
    pub enum BillboardKind {
        /// Faces the camera: parallel to the image plane.
        Spherical = "spherical",
        /// Turns only about the world's up axis (y) and stays upright: trees.
        Cylindrical = "cylindrical",
    }
}

setting! {
    /// Parallax mapping of materials with a height_map (docs/lighting/parallax_mapping.md).
    pub enum Parallax {
        /// No offset: the height map is not read (bump mapping alone).
        Off = "off",
        /// One offset along the view, by the height at the fragment (LearnOpenGL, Parallax Mapping).
        Plain = "plain",
        /// Steep parallax: the view ray marched through `render.parallax_layers` layers.
        Steep = "steep",
        /// Parallax occlusion mapping: steep parallax, then the hit interpolated between the last two layers.
        Occlusion = "occlusion",
    }
}

setting! {
    /// How transparent objects are drawn (docs/blending/order_independent_transparency.md).
    pub enum Transparency {
        /// Sorted per object, back to front (notes 01 §6.1): the default.
        Sorted = "sorted",
        /// Weighted blended order-independent transparency (McGuire and Bavoil 2013).
        WeightedBlended = "weighted_blended",
        /// Depth peeling (Everitt 2001), `render.peel_layers` layers: exact per fragment.
        DepthPeeling = "depth_peeling",
    }
}

setting! {
    /// Which reflectance model a material uses.
    pub enum Model {
        /// Notes 01 §8.3: k_d (N . L) + k_s (N . H)^n.
        Phong = "phong",
        /// Notes 03: Cook-Torrance with GGX, dielectric Fresnel and Smith masking.
        Microfacet = "microfacet",
    }
}

setting! {
    /// How the G-buffer stores the microfacet triple (notes 03, Geometry
    /// Pass; src/math/gbuffer_encoding.rs measures each).
    pub enum GBufferEncoding {
        /// The report's: each value above 1 stored as its reciprocal with a
        /// flag in gConvert, gAlpha in 8 bits (UNORM) as the report's [0, 1]
        /// range implies.
        ReportRgba8 = "report_rgba8",
        /// The report's scheme with gAlpha in half floats.
        ReportRgba16f = "report_rgba16f",
        /// The plain values in half floats: no gConvert attachment.
        PlainRgba16f = "plain_rgba16f",
    }
}

setting! {
    /// How the G-buffer holds the normal and shininess (src/frame/gbuffer.rs).
    pub enum GBufferNormals {
        /// Normal xyz and shininess in half floats (RGBA16F, 8 bytes).
        Rgba16f = "rgba16f",
        /// Octahedral normal (Cigolle et al. 2014) in 12 + 12 bits and the
        /// shininess as an index into the scene's table (RGBA8, 4 bytes).
        Octahedral = "octahedral",
    }
}
