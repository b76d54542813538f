//! The shadow maps made visible (notes 01 §8.5: "The map is the depth
//! buffer"): one inspector view per casting light. A directional or spot
//! light's 2D map is shown as the light sees it (its x to the right, y up);
//! a point light's cube is unfolded into the usual cross, each face as GL
//! stores it (row t = 0 at the top), so that neighbouring faces share
//! their edges:
//!
//! ```text
//!        +y
//!  -x    +z    +x    -z
//!        -y
//! ```
//!
//! The stored value (window depth; a cube's distance / far) is stretched
//! from the least to the greatest value below 1.0 that the view shows, black
//! to white, so that the shapes stand out however little depth they span;
//! 1.0, where nothing was drawn, is blue, and outside the map the view's
//! background. Two passes of glsl/demo/shadow_views.frag: the layout, as
//! raw depth, into a float target; read back for its least and greatest
//! value; then the stretch into the view.
//!
//! The depth textures compare (GL_TEXTURE_COMPARE_MODE =
//! GL_COMPARE_REF_TO_TEXTURE, for sampler2DShadow): a plain sampler2D on
//! them is undefined. They are read here through a sampler object
//! (glBindSampler, core since 3.3) with GL_TEXTURE_COMPARE_MODE = GL_NONE
//! and GL_NEAREST, whose state overrides the texture's while it is bound:
//! the renderer's textures are never changed, so there is nothing to
//! restore but the unit's sampler binding. Reading a whole map back
//! (`DepthMap::read`) would move up to 6 x 8192² floats a frame (1.5 GB)
//! to show a window's worth of pixels; here only the layout, the view's
//! size, is read back.

use crate::frame::pass::CUBE_FACES;
use crate::frame::shadows::{Caster, ShadowMaps};
use crate::frame::units as unit;
use crate::geometry;
use crate::gl::Gl;
use crate::gl::framebuffer::{Framebuffer, bytemuck_f32};
use crate::gl::mesh::Mesh;
use crate::gl::program::{Program, Sources};
use crate::scene::LightKind;
use anyhow::{Result, anyhow};
use glam::{Mat4, Vec3, Vec4};
use glow::HasContext;

/// Outside the map (and outside the cross).
pub const BACKGROUND: [u8; 3] = [26, 26, 46];
/// Where the map holds 1.0: nothing was drawn there.
pub const NOTHING: [u8; 3] = [90, 140, 230];

/// One casting light's map, as the inspector offers it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShadowView {
    /// The light's index in the scene.
    pub light: usize,
    pub kind: LightKind,
    /// Texels along a side (of each face).
    pub resolution: u32,
    /// One face of a point light's cube (0..6: +X, -X, +Y, -Y, +Z, -Z, as
    /// its shadow pass names it) instead of the whole cross; None otherwise.
    pub face: Option<usize>,
}

impl ShadowView {
    /// The view of each caster, in light order.
    pub fn of<'a>(
        casters: impl IntoIterator<Item = &'a Caster>,
        kind: impl Fn(usize) -> LightKind,
    ) -> Vec<ShadowView> {
        (casters.into_iter())
            .map(|c| ShadowView {
                light: c.light,
                kind: kind(c.light),
                resolution: c.shadow.resolution,
                face: None,
            })
            .collect()
    }

    /// A cube's six faces, each its own view (the output of its face's
    /// pass, "shadow map (light 0, face +X)"); none for a 2D map.
    pub fn faces(&self) -> Vec<ShadowView> {
        match self.cube() && self.face.is_none() {
            true => (0..CUBE_FACES.len())
                .map(|f| ShadowView {
                    face: Some(f),
                    ..*self
                })
                .collect(),
            false => Vec::new(),
        }
    }

    pub fn cube(&self) -> bool {
        self.kind == LightKind::Point
    }

    /// "shadow map: light 0 (2048², directional)" and how it is shown.
    pub fn label(&self) -> String {
        let kind = format!("{:?}", self.kind).to_lowercase();
        let (n, light) = (self.resolution, self.light);
        let (stored, layout) = match (self.cube(), self.face) {
            (true, Some(f)) => ("distance / far", format!("; face {} alone", CUBE_FACES[f])),
            (true, None) => ("distance / far", "; cross +y / -x +z +x -z / -y".into()),
            (false, _) => ("depth", String::new()),
        };
        format!(
            "shadow map: light {light} ({n}², {kind}): {stored}, min..max below 1 as black..white, 1 blue{layout}"
        )
    }
}

/// Where the layout lies in a `w` x `h` view, in pixels (x, y from the
/// bottom left, width, height): centred, with square faces a whole number
/// of pixels wide (one for a 2D map, a 4 x 3 grid of them for a cube).
pub fn layout_rect(cube: bool, w: i32, h: i32) -> [i32; 4] {
    let (cols, rows) = if cube { (4, 3) } else { (1, 1) };
    let face = (w / cols).min(h / rows).max(1);
    let (lw, lh) = (face * cols, face * rows);
    [(w - lw) / 2, (h - lh) / 2, lw, lh]
}

pub struct ShadowViews {
    gl: Gl,
    program: Program,
    fullscreen: Mesh,
    /// GL_TEXTURE_COMPARE_MODE = GL_NONE, GL_NEAREST, clamped.
    sampler: glow::Sampler,
    /// The raw layouts (R32F), one per size drawn lately (the view, the thumbnail).
    layouts: Vec<Framebuffer>,
}

impl ShadowViews {
    pub fn new(gl: &Gl, sources: &Sources) -> Result<ShadowViews> {
        let program = Program::new(
            gl,
            sources,
            &[
                (glow::VERTEX_SHADER, "common/fullscreen.vert"),
                (glow::FRAGMENT_SHADER, "demo/shadow_views.frag"),
            ],
            &[],
        )?;
        let fullscreen = Mesh::upload(gl, &geometry::fullscreen_triangle())?;
        let sampler = unsafe {
            let s = gl
                .create_sampler()
                .map_err(|e| anyhow!("glGenSamplers: {e}"))?;
            gl.sampler_parameter_i32(s, glow::TEXTURE_COMPARE_MODE, glow::NONE as i32);
            for (p, v) in [
                (glow::TEXTURE_MIN_FILTER, glow::NEAREST),
                (glow::TEXTURE_MAG_FILTER, glow::NEAREST),
                (glow::TEXTURE_WRAP_S, glow::CLAMP_TO_EDGE),
                (glow::TEXTURE_WRAP_T, glow::CLAMP_TO_EDGE),
                (glow::TEXTURE_WRAP_R, glow::CLAMP_TO_EDGE),
            ] {
                gl.sampler_parameter_i32(s, p, v as i32);
            }
            s
        };
        Ok(ShadowViews {
            gl: gl.clone(),
            program,
            fullscreen,
            sampler,
            layouts: Vec::new(),
        })
    }

    /// Draw light `view.light`'s map into `into`, full size (only the
    /// background when that light has no map this frame). Returns the least and
    /// greatest value below 1.0 shown, which became black and white.
    pub fn draw(
        &mut self,
        view: &ShadowView,
        maps: &ShadowMaps,
        into: &Framebuffer,
    ) -> Result<Option<(f32, f32)>> {
        let (w, h) = (into.width, into.height);
        let at = self.layout(w, h)?;
        let layout = &self.layouts[at];
        let gl = &self.gl;
        let p = &self.program;
        // A map whose light had nothing to cast onto this frame (view None)
        // holds an old frame's depths that no lookup reads: show none.
        let map = (maps.maps.iter().zip(&maps.views))
            .find(|((c, _), v)| c.light == view.light && v.is_some())
            .map(|(m, _)| m);
        let cube = map.is_some_and(|(c, _)| c.cube);
        // One face of the cube: a square, like a 2D map.
        let face = view.face.filter(|_| cube);
        let rect = layout_rect(cube && face.is_none(), w, h).map(|v| v as f32);
        unsafe {
            // 1. The layout: raw depth, -1 outside it.
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(layout.id));
            gl.viewport(0, 0, w, h);
            gl.disable(glow::DEPTH_TEST);
            gl.clear_color(-1.0, -1.0, -1.0, -1.0);
            gl.clear(glow::COLOR_BUFFER_BIT);
            gl.clear_color(0.0, 0.0, 0.0, 0.0);
            p.use_program();
            p.set_mat4("u_mvp", &Mat4::IDENTITY);
            p.set_i32("u_map", unit::DEMO_VIEW as i32);
            p.set_i32("u_layout", unit::DEMO_VIEW as i32);
            p.set_i32("u_cube_map", unit::DEMO_VIEW_CUBE as i32);
            if let Some((_, m)) = map {
                let unit = if cube {
                    unit::DEMO_VIEW_CUBE
                } else {
                    unit::DEMO_VIEW
                };
                gl.active_texture(glow::TEXTURE0 + unit);
                gl.bind_texture(m.target, Some(m.texture));
                gl.bind_sampler(unit, Some(self.sampler));
                p.set_i32("u_pass", 0);
                p.set_bool("u_cube", cube);
                p.set_i32("u_face", face.map_or(-1, |f| f as i32));
                p.set_vec4("u_rect", Vec4::from(rect));
                self.fullscreen.draw();
                gl.bind_sampler(unit, None);
                gl.bind_texture(m.target, None);
                gl.active_texture(glow::TEXTURE0);
            }
        }
        // 2. Its least and greatest value below 1.0.
        let values = read_red(gl, layout);
        let shown = values.iter().filter(|v| (0.0..1.0).contains(*v));
        let (lo, hi) = shown.fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), &v| {
            (lo.min(v), hi.max(v))
        });
        let stretch = (lo <= hi).then_some((lo, hi));
        let (lo, hi) = stretch.unwrap_or((0.0, 1.0));
        let color = |c: [u8; 3]| Vec3::from(c.map(|v| v as f32 / 255.0));
        unsafe {
            // 3. The stretch into the view.
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(into.id));
            gl.viewport(0, 0, w, h);
            gl.active_texture(glow::TEXTURE0 + unit::DEMO_VIEW);
            gl.bind_texture(glow::TEXTURE_2D, Some(layout.colors[0].id));
            p.set_i32("u_pass", 1);
            p.set_f32("u_min", lo);
            p.set_f32("u_max", hi);
            p.set_vec3("u_background", color(BACKGROUND));
            p.set_vec3("u_nothing", color(NOTHING));
            self.fullscreen.draw();
            gl.bind_texture(glow::TEXTURE_2D, None);
            gl.use_program(None);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
        Ok(stretch)
    }

    /// Which of `layouts` is the R32F layout target of size `w` x `h` (made
    /// when none is; the two last sizes are kept).
    fn layout(&mut self, w: i32, h: i32) -> Result<usize> {
        Ok(
            match self
                .layouts
                .iter()
                .position(|f| (f.width, f.height) == (w, h))
            {
                Some(i) => i,
                None => {
                    if self.layouts.len() >= 2 {
                        self.layouts.remove(0);
                    }
                    let f =
                        Framebuffer::new(&self.gl, "shadow-map layout", w, h, &[glow::R32F], None)?;
                    self.layouts.push(f);
                    self.layouts.len() - 1
                }
            },
        )
    }
}

impl Drop for ShadowViews {
    fn drop(&mut self) {
        unsafe { self.gl.delete_sampler(self.sampler) };
    }
}

/// The red channel of `fb`'s first colour attachment, row 0 at the bottom.
fn read_red(gl: &glow::Context, fb: &Framebuffer) -> Vec<f32> {
    let mut out = vec![0f32; (fb.width * fb.height) as usize];
    unsafe {
        gl.bind_framebuffer(glow::READ_FRAMEBUFFER, Some(fb.id));
        gl.read_buffer(glow::COLOR_ATTACHMENT0);
        gl.pixel_store_i32(glow::PACK_ALIGNMENT, 4);
        gl.read_pixels(
            0,
            0,
            fb.width,
            fb.height,
            glow::RED,
            glow::FLOAT,
            glow::PixelPackData::Slice(Some(bytemuck_f32(&mut out))),
        );
        gl.bind_framebuffer(glow::READ_FRAMEBUFFER, None);
    }
    out
}
