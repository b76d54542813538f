//! The sections of the five files of the course notes, in the notes' order,
//! for the map in docs/README.md that src/trace/coverage.rs generates.
//!
//! A section is built by the registered techniques whose `notes` cite it
//! (found by `coverage::cited`, never listed here), and otherwise by what
//! `otherwise` says: the files that do it without a technique of their own
//! (each path checked to exist by tests/trace/registry.rs), or why it is not
//! built. A technique registered later that cites a section shows up there
//! by itself; one that cites none is listed as beyond the notes.

/// One section of the notes.
pub struct Section {
    /// "01" .. "05": the notes file.
    pub notes: &'static str,
    /// What a technique's `notes` cites for it: `§8.5` in notes 01 (a
    /// citation's § numbers, exactly), a heading's title in notes 02 to 05
    /// (found inside the citation, any case). None: no technique can build
    /// it (a gap named by itself).
    pub cites: &'static [&'static str],
    /// The section as the map prints it.
    pub title: &'static str,
    /// When no registered technique cites it.
    pub otherwise: Otherwise,
}

pub enum Otherwise {
    /// Built without a technique of its own, in these files.
    In(&'static [&'static str]),
    /// Not built, and why.
    NotBuilt(&'static str),
}

use Otherwise::{In, NotBuilt};

const fn s(
    notes: &'static str,
    cites: &'static [&'static str],
    title: &'static str,
    otherwise: Otherwise,
) -> Section {
    Section {
        notes,
        cites,
        title,
        otherwise,
    }
}

#[rustfmt::skip]
pub static SECTIONS: &[Section] = &[
    s("01", &["§1.3"], "§1.3 OpenGL: buffers in graphics memory, uniforms", In(&["src/gl/buffer.rs", "src/frame/lights.rs"])),
    s("01", &["§2.2", "§2.3", "§2.4"], "§2.2–2.4 scale, translation, rotation", In(&["src/math/mod.rs"])),
    s("01", &["§2.5", "§2.5.1", "§2.5.2", "§2.5.3"], "§2.5 orthographic, perspective, perspective divide", In(&["src/math/mod.rs"])),
    s("01", &["§2.6", "§2.7"], "§2.6–2.7 object definition, the MVP matrix", In(&["src/scene/resolve.rs", "src/frame/uniforms.rs"])),
    s("01", &["§3.1"], "§3.1 Amplification (Tessellation Shader)", In(&[])),
    s("01", &["§3.2"], "§3.2 Generation (Geometry Shader)", In(&["glsl/lighting/forward_flat.geom"])),
    s("01", &["§3.3"], "§3.3 Clipping (user clip planes)", In(&["src/scene/clip_planes.rs", "glsl/common/view.glsl"])),
    s("01", &["§3.4"], "§3.4 Face Culling", In(&[ "src/techniques/lighting/forward.rs", "src/frame/draw_list.rs"])),
    s("01", &["§4.1"], "§4.1 Interpolation", In(&["src/math/interpolation.rs", "glsl/common/surface.glsl"])),
    s("01", &["§4.2"], "§4.2 Scissor testing", In(&[])),
    s("01", &["§4.3"], "§4.3 Stencil testing", In(&[ "src/techniques/deferred/stencil_light_volumes.rs", "src/techniques/stencil/mirror.rs"])),
    s("01", &["§4.4"], "§4.4 Depth Buffer / Depth Test, z-fighting", In(&["src/scene/settings.rs", "src/math/depth.rs"])),
    s("01", &["§4.5"], "§4.5 Blending", In(&[])),
    s("01", &["§5", "§5.1", "§5.2", "§5.3", "§5.3.1"], "§5 Texture Mapping: wrap rules, §5.1 affine, §5.2 bilinear, §5.3 mip maps, §5.3.1 trilinear", In(&[ "src/scene/texturing.rs", "src/gl/sampler.rs", "src/math/texture_mapping.rs"])),
    s("01", &["§6.1"], "§6.1 Handling Transparent Objects", In(&[])),
    s("01", &["§6.2"], "§6.2 Early Z test (opaque objects front to back)", In(&["src/frame/draw_list.rs"])),
    s("01", &["§6.3"], "§6.3 Frustum Culling", In(&["src/frame/culling.rs"])),
    s("01", &["§6.4"], "§6.4 Scene Graphs", In(&["src/scene/hierarchy.rs", "src/math/scene_graph.rs"])),
    s("01", &["§7"], "§7 Animation: keyframes, slerp", In(&[ "src/math/keyframes.rs", "src/math/slerp.rs", "src/scene/animation.rs"])),
    s("01", &["§7.1"], "§7.1 Skinned meshes", In(&[])),
    s("01", &["§8.1", "§8.1.1"], "§8.1 Normals, §8.1.1 the normal matrix", In(&["src/math/mod.rs", "src/geometry/normals.rs"])),
    s("01", &["§8.2"], "§8.2 Lighting Models: static, flat, Gouraud, Phong shading", In(&[])),
    s("01", &["§8.3"], "§8.3 Phong Reflection Model", In(&["glsl/common/lighting.glsl", "src/lighting/mod.rs"])),
    s("01", &["§8.4"], "§8.4 Bump mapping", In(&[ "glsl/common/bump_mapping.glsl", "src/geometry/tangents.rs", "src/math/bump.rs"])),
    s("01", &["§8.5"], "§8.5 Shadow mapping", In(&[])),
    s("01", &["§8.5.1"], "§8.5.1 Issues: surface acne, aliasing", In(&["glsl/common/shadow.glsl", "src/scene/shadows.rs"])),
    s("01", &["§8.6"], "§8.6 Deferred Rendering", In(&[])),
    s("01", &[], "§8.6 a G-buffer flag for post-processing", NotBuilt("no pass reads one: every post stage runs on the whole image")),
    s("01", &[], "§8.6 MSAA on the deferred paths", NotBuilt("the G-buffer is single-sampled (per-sample lighting is not built); FXAA anti-aliases those paths")),
    s("01", &["§8.6.1"], "§8.6.1 Light volumes", In(&[])),
    s("01", &["§8.6.2"], "§8.6.2 Workflow: fill the G-buffer, lighting, generate the final image", In(&[])),
    s("01", &["§9"], "§9 Post processing", In(&["src/frame/post.rs"])),
    s("02", &["Deferred shading"], "Multipass Rendering: deferred shading", In(&[])),
    s("02", &["Deferred lighting"], "Multipass Rendering: deferred lighting", In(&[])),
    s("02", &["Framebuffer Objects"], "OpenGL Framebuffer Objects", In(&["src/gl/framebuffer.rs", "src/frame/targets.rs"])),
    s("02", &["Depth Culling"], "Depth Culling (d >= D fails)", In(&["src/scene/settings.rs"])),
    s("02", &["G-Buffers"], "G-Buffers", In(&[])),
    s("02", &["Rendering Cast Shadows"], "Rendering Cast Shadows", In(&[])),
    s("03", &["Geometry Pass"], "Geometry Pass (with the material triple)", In(&[ "src/techniques/deferred/gbuffer.rs", "glsl/common/gbuffer_material.glsl"])),
    s("03", &["Shadow Pass"], "Shadow Pass", In(&["src/techniques/shadows/shadow_map.rs"])),
    s("03", &["Point light"], "Lighting Pass: Point light (the microfacet material)", In(&["glsl/common/microfacet.glsl", "src/lighting/microfacet.rs"])),
    s("03", &["Ambient Light"], "Lighting Pass: Ambient Light", In(&[])),
    s("03", &["Sun Sky"], "Lighting Pass: Sun Sky", In(&[])),
    s("03", &["Blur Pass"], "Blur Pass and Merge Pass", In(&[])),
    s("03", &["Gamma Correction Pass"], "Gamma Correction Pass", In(&[])),
    s("03", &["Implementation"], "Implementation: the skybox, its mirror reflection", In(&[])),
    s("04", &["Forward rendering"], "Forward rendering", In(&[])),
    s("04", &["our current deferred shader"], "Our current deferred shader", In(&[])),
    s("04", &["Light Volumes"], "Light volumes: the radius, the sphere, blending, a directional and a spot light", In(&[])),
    s("04", &["debug views"], "the debug views: the volumes and the G-buffer on screen", In(&["src/demo/volume_views.rs", "src/demo/inspect_views.rs"])),
    s("05", &["Buffers"], "Buffers: the accumulation buffer", NotBuilt("core GL 3.3 has none; a float framebuffer would stand in")),
    s("05", &["Alpha Test"], "Alpha Test", In(&[])),
    s("05", &["Billboards"], "Billboards", In(&[])),
    s("05", &["Alpha Test and Billboards"], "Alpha Test and Billboards", In(&[])),
    s("05", &["Stencil Tests"], "Stencil Tests", In(&[])),
    s("05", &["Stencil Operations"], "Stencil Operations", In(&[])),
    s("05", &["Depth Test and Operation"], "Depth Test and Operation (eight functions, per material)", In(&[ "src/scene/settings.rs", "src/techniques/lighting/forward.rs"])),
    s("05", &["Planar Reflections"], "Planar Reflections (Flat Mirrors)", In(&[])),
    s("05", &["Reflecting Objects"], "Reflecting Objects", In(&["src/math/reflection.rs"])),
    s("05", &["Small Problem"], "Small Problem (glFrontFace)", In(&[])),
    s("05", &["Rendering Reflected First"], "Rendering Reflected First", In(&[])),
    s("05", &["Reflected Scene First"], "Reflected Scene First (issues)", In(&[])),
    s("05", &["Rendering Normal First"], "Rendering Normal First", In(&[])),
    s("05", &["Normal First Addendum"], "Normal First Addendum: several and recursive mirrors", In(&[])),
];
