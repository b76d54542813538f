//! The renderer: uploads a scene's meshes, textures and lights, builds the
//! targets the frame plan names, and runs the plan's passes each frame.
//! The passes themselves live in the technique files (forward.rs, ...).

use crate::forward::Forward;
use crate::geometry::{self, MeshData};
use crate::gl::debug::DebugLog;
use crate::gl::framebuffer::Framebuffer;
use crate::gl::mesh::Mesh;
use crate::gl::program::{Program, Sources};
use crate::gl::texture::{Sampling, Texture};
use crate::gl::{Gl, buffer::Buffer};
use crate::lighting;
use crate::math;
use crate::plan::FramePlan;
use crate::scene::{Camera, MeshSource, RenderPath, Scene};
use anyhow::{Result, bail};
use glam::{Mat3, Mat4, Vec3};
use glow::HasContext;
use std::collections::HashMap;
use std::path::PathBuf;
use std::time::Instant;

/// Per-frame values every pass needs.
pub struct FrameUniforms {
    pub view: Mat4,
    pub projection: Mat4,
    pub view_projection: Mat4,
    pub inverse_view_projection: Mat4,
    pub eye: Vec3,
    pub light_count: i32,
    pub lights_ubo: glow::Buffer,
    pub output_srgb: bool,
    /// The background as written to the output (sRGB-encoded when the output is).
    pub clear_color: Vec3,
}

/// One object ready to draw.
pub struct DrawItem {
    pub mesh: usize,
    pub model: Mat4,
    pub normal_matrix: Mat3,
    pub mirrored: bool,
    pub diffuse: Vec3,
    pub specular: Vec3,
    pub shininess: f32,
    pub texture: Option<usize>,
}

/// Every object of the scene, with the meshes and textures they share.
pub struct DrawList {
    pub items: Vec<DrawItem>,
    pub meshes: Vec<Mesh>,
    pub textures: Vec<Texture>,
}

impl DrawList {
    /// Draw every object with program `p` (in use): per object, glFrontFace
    /// (a mirroring model matrix turns counter-clockwise triangles clockwise),
    /// its uniforms and texture, glDrawElements. Leaves glFrontFace(GL_CCW).
    pub fn draw_objects(&self, gl: &glow::Context, p: &Program) {
        for d in &self.items {
            unsafe { gl.front_face(if d.mirrored { glow::CW } else { glow::CCW }) };
            self.set_object_uniforms(gl, p, d);
            self.meshes[d.mesh].draw();
        }
        unsafe { gl.front_face(glow::CCW) };
    }

    /// glUniform* for one object's transform and material; binds its texture on unit 0.
    pub fn set_object_uniforms(&self, gl: &glow::Context, p: &Program, d: &DrawItem) {
        p.set_mat4("u_model", &d.model);
        p.set_mat3("u_normal_matrix", &d.normal_matrix);
        p.set_f32("u_mirror", if d.mirrored { -1.0 } else { 1.0 });
        p.set_vec3("u_diffuse", d.diffuse);
        p.set_vec3("u_specular", d.specular);
        p.set_f32("u_shininess", d.shininess);
        p.set_bool("u_has_diffuse_texture", d.texture.is_some());
        unsafe {
            gl.active_texture(glow::TEXTURE0);
            gl.bind_texture(glow::TEXTURE_2D, d.texture.map(|t| self.textures[t].id));
        }
    }
}

/// The normal matrix (notes 01 §8.1.1): transpose(inverse(mat3(model))).
/// For a singular model matrix (a zero scale flattens the object) the
/// inverse does not exist; the cofactor matrix, det x inverse-transpose, is
/// still defined and gives the flattened surface's normal, so use that.
pub fn normal_matrix(model: &Mat4) -> Mat3 {
    match math::normal_matrix(model) {
        Some(n) => n,
        None => {
            let m = Mat3::from_mat4(*model);
            let (c0, c1, c2) = (m.x_axis, m.y_axis, m.z_axis);
            // cofactor(M) has columns c1 x c2, c2 x c0, c0 x c1.
            Mat3::from_cols(c1.cross(c2), c2.cross(c0), c0.cross(c1))
        }
    }
}

fn mesh_data(source: &MeshSource) -> Result<MeshData> {
    Ok(match source {
        MeshSource::Sphere => geometry::uv_sphere(32, 64),
        MeshSource::Icosphere => geometry::icosphere(3),
        MeshSource::Cube => geometry::cube(),
        MeshSource::Plane => geometry::plane(2.0, 2.0, 1),
        MeshSource::Cylinder => geometry::cylinder(48),
        MeshSource::Cone => geometry::cone(48),
        MeshSource::Torus => geometry::torus(1.0, 0.35, 64, 24),
        MeshSource::Obj(path) => geometry::load_obj(path)?,
    })
}

impl DrawList {
    pub fn new(gl: &Gl, scene: &Scene) -> Result<DrawList> {
        let mut meshes = Vec::new();
        let mut mesh_index: HashMap<MeshSource, usize> = HashMap::new();
        let mut textures = Vec::new();
        let mut texture_index: HashMap<PathBuf, usize> = HashMap::new();
        let mut items = Vec::new();
        for o in &scene.objects {
            let mesh = match mesh_index.get(&o.mesh) {
                Some(&i) => i,
                None => {
                    let data = mesh_data(&o.mesh)?;
                    meshes.push(Mesh::upload(gl, &data)?);
                    mesh_index.insert(o.mesh.clone(), meshes.len() - 1);
                    meshes.len() - 1
                }
            };
            let m = &scene.materials[o.material];
            let texture = match &m.diffuse_texture {
                None => None,
                Some(p) => Some(match texture_index.get(p) {
                    Some(&i) => i,
                    None => {
                        textures.push(Texture::load(gl, p, true, Sampling::TRILINEAR_REPEAT)?);
                        texture_index.insert(p.clone(), textures.len() - 1);
                        textures.len() - 1
                    }
                }),
            };
            items.push(DrawItem {
                mesh,
                model: o.model,
                normal_matrix: normal_matrix(&o.model),
                mirrored: Mat3::from_mat4(o.model).determinant() < 0.0,
                diffuse: m.diffuse,
                specular: m.specular,
                shininess: m.shininess,
                texture,
            });
        }
        Ok(DrawList {
            items,
            meshes,
            textures,
        })
    }
}

/// How the final image is stored.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Output {
    /// RGBA8 holding sRGB-encoded colour: what PNGs and the window show.
    Srgb8,
    /// RGBA32F holding linear colour: for error measurements.
    Linear32F,
}

/// Wall-clock time of each pass, measured around glFinish (see stack-facts:
/// timer queries under-report on llvmpipe). Only when `Renderer::timing` is on.
#[derive(Clone, Debug, Default)]
pub struct PassTimes {
    pub passes: Vec<(&'static str, f64)>,
    pub frame_ms: f64,
}

pub struct Renderer {
    gl: Gl,
    debug: DebugLog,
    pub scene: Scene,
    pub plan: FramePlan,
    pub width: i32,
    pub height: i32,
    pub output_kind: Output,
    output: Framebuffer,
    draws: DrawList,
    lights_ubo: Buffer,
    forward: Option<Forward>,
    deferred: Option<crate::deferred::Deferred>,
    /// Measure each pass with glFinish + the CPU clock.
    pub timing: bool,
    pub last_times: PassTimes,
}

impl Renderer {
    pub fn new(
        gl: &Gl,
        debug: &DebugLog,
        scene: &Scene,
        sources: &Sources,
        width: i32,
        height: i32,
    ) -> Result<Renderer> {
        Self::with_output(gl, debug, scene, sources, width, height, Output::Srgb8)
    }

    pub fn with_output(
        gl: &Gl,
        debug: &DebugLog,
        scene: &Scene,
        sources: &Sources,
        width: i32,
        height: i32,
        output_kind: Output,
    ) -> Result<Renderer> {
        let max_block = unsafe { gl.get_parameter_i32(glow::MAX_UNIFORM_BLOCK_SIZE) };
        let max_lights = lighting::max_lights(max_block);
        if scene.lights.len() > max_lights {
            bail!(
                "{}: {} lights, but this GL's uniform blocks hold at most {max_lights} (GL_MAX_UNIFORM_BLOCK_SIZE = {max_block})",
                scene.path.display(),
                scene.lights.len()
            );
        }
        let defines = [("MAX_LIGHTS", max_lights.to_string())];
        let plan = FramePlan::new(scene);
        let output = make_output(gl, width, height, output_kind)?;
        let draws = DrawList::new(gl, scene)?;
        let lights_ubo = Buffer::new(
            gl,
            glow::UNIFORM_BUFFER,
            max_lights * lighting::LIGHT_STRIDE,
            glow::DYNAMIC_DRAW,
        )?;
        let mut r = Renderer {
            gl: gl.clone(),
            debug: debug.clone(),
            scene: scene.clone(),
            plan,
            width,
            height,
            output_kind,
            output,
            draws,
            lights_ubo,
            forward: None,
            deferred: None,
            timing: false,
            last_times: PassTimes::default(),
        };
        r.upload_lights();
        match scene.render.path {
            RenderPath::Forward => r.forward = Some(Forward::new(gl, sources, &defines)?),
            _ => {
                r.deferred = Some(crate::deferred::Deferred::new(
                    gl, sources, &defines, scene, width, height,
                )?)
            }
        }
        debug.check(gl, "renderer set-up")?;
        Ok(r)
    }

    /// Write the scene's lights into the uniform buffer (after editing them).
    pub fn upload_lights(&mut self) {
        let bytes = lighting::pack_lights(&self.scene.lights, self.scene.render.cutoff);
        if !bytes.is_empty() {
            self.lights_ubo.write(&bytes);
        }
    }

    pub fn resize(&mut self, width: i32, height: i32) -> Result<()> {
        if width < 1 || height < 1 || (width, height) == (self.width, self.height) {
            return Ok(());
        }
        self.output = make_output(&self.gl, width, height, self.output_kind)?;
        if let Some(d) = &mut self.deferred {
            d.resize(&self.gl, width, height)?;
        }
        self.width = width;
        self.height = height;
        Ok(())
    }

    /// The finished frame (colour attachment 0).
    pub fn output(&self) -> &Framebuffer {
        &self.output
    }

    pub fn frame_uniforms(&self, camera: &Camera) -> FrameUniforms {
        let view = camera.view();
        let projection = camera.projection(self.width as f32 / self.height as f32);
        let vp = projection * view;
        let srgb = self.output_kind == Output::Srgb8;
        let bg = self.scene.render.background;
        FrameUniforms {
            view,
            projection,
            view_projection: vp,
            inverse_view_projection: vp.inverse(),
            eye: camera.eye,
            light_count: self.scene.lights.len() as i32,
            lights_ubo: self.lights_ubo.id,
            output_srgb: srgb,
            clear_color: if srgb {
                bg.map(lighting::srgb_encode)
            } else {
                bg
            },
        }
    }

    /// Run the frame plan with the given camera into `output()`.
    pub fn render(&mut self, camera: &Camera) -> Result<()> {
        let frame = self.frame_uniforms(camera);
        let mut timer = PassTimer::new(&self.gl, self.timing);
        match self.scene.render.path {
            RenderPath::Forward => {
                let f = self
                    .forward
                    .as_ref()
                    .expect("forward programs exist for the forward path");
                f.draw(
                    &self.gl,
                    &self.scene.render,
                    &frame,
                    &self.draws,
                    &self.output,
                );
                timer.mark("forward");
            }
            _ => {
                let d = self.deferred.as_ref().expect("deferred resources exist");
                d.render(
                    &self.gl,
                    &self.scene,
                    &frame,
                    &self.draws,
                    &self.output,
                    &mut timer,
                );
            }
        }
        self.last_times = timer.finish();
        self.debug.check(&self.gl, "the frame")?;
        Ok(())
    }

    /// The output as an sRGB PNG-ready image (top row first).
    pub fn read_image(&self) -> image::RgbaImage {
        match self.output_kind {
            Output::Srgb8 => self.output.read_rgba8_top_down(0),
            Output::Linear32F => {
                let f = self.output.read_rgba_f32(0);
                let (w, h) = (self.width as u32, self.height as u32);
                let mut img = image::RgbaImage::new(w, h);
                for y in 0..h {
                    for x in 0..w {
                        let i = (((h - 1 - y) * w + x) * 4) as usize;
                        let px = |c: f32| (lighting::srgb_encode(c) * 255.0).round() as u8;
                        img.put_pixel(
                            x,
                            y,
                            image::Rgba([px(f[i]), px(f[i + 1]), px(f[i + 2]), 255]),
                        );
                    }
                }
                img
            }
        }
    }

    /// The output as linear RGBA floats, bottom row first (Linear32F output only
    /// gives the unquantised values).
    pub fn read_linear(&self) -> Vec<f32> {
        match self.output_kind {
            Output::Linear32F => self.output.read_rgba_f32(0),
            Output::Srgb8 => self
                .output
                .read_rgba_f32(0)
                .chunks(4)
                .flat_map(|p| {
                    [
                        lighting::srgb_decode(p[0]),
                        lighting::srgb_decode(p[1]),
                        lighting::srgb_decode(p[2]),
                        p[3],
                    ]
                })
                .collect(),
        }
    }
}

fn make_output(gl: &Gl, width: i32, height: i32, kind: Output) -> Result<Framebuffer> {
    let color = match kind {
        Output::Srgb8 => glow::RGBA8,
        Output::Linear32F => glow::RGBA32F,
    };
    Framebuffer::new(
        gl,
        "output",
        width,
        height,
        &[color],
        Some(glow::DEPTH24_STENCIL8),
    )
}

/// Splits a frame into passes for timing: glFinish, then the CPU clock.
pub struct PassTimer<'a> {
    gl: &'a glow::Context,
    on: bool,
    start: Instant,
    last: Instant,
    times: PassTimes,
}

impl<'a> PassTimer<'a> {
    pub fn new(gl: &'a glow::Context, on: bool) -> PassTimer<'a> {
        if on {
            unsafe { gl.finish() };
        }
        let now = Instant::now();
        PassTimer {
            gl,
            on,
            start: now,
            last: now,
            times: PassTimes::default(),
        }
    }

    /// The pass `name` has been issued: wait for it and note its time.
    pub fn mark(&mut self, name: &'static str) {
        if !self.on {
            return;
        }
        unsafe { self.gl.finish() };
        let now = Instant::now();
        self.times
            .passes
            .push((name, (now - self.last).as_secs_f64() * 1000.0));
        self.last = now;
    }

    pub fn finish(mut self) -> PassTimes {
        if self.on {
            unsafe { self.gl.finish() };
            self.times.frame_ms = self.start.elapsed().as_secs_f64() * 1000.0;
        }
        self.times
    }
}
