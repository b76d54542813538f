//! What each light of the frame derives from the scene, computed once here
//! and read by everything that needs it: the light-volume radius (notes 04,
//! "Calculating radius"), the volume that encloses it, and the std140
//! `Lights` block the shaders read (glsl/common/lighting.glsl).
//!
//! The radius is where the attenuated brightest channel falls to the cutoff
//! (src/lighting/attenuation.rs solves it without cancellation). The plan
//! counts the volumes, the light-volume passes draw them, and the shaders
//! read the same radius from the uniform block.

use crate::lighting::attenuation;
use crate::scene::{Falloff, Light, LightKind, RenderPath, Scene};
use glam::{Mat4, Quat, Vec3, Vec4};

/// Bytes per light in the std140 `Lights` block (four vec4).
pub const LIGHT_STRIDE: usize = 64;

/// Added to a light's type code when its attenuation is windowed
/// (`render.falloff = "windowed"`; LIGHT_WINDOWED in glsl/common/lighting.glsl).
pub const WINDOWED: f32 = 4.0;
/// Added to a light's type code for notes 01's linear attenuation
/// (`render.falloff = "linear"`; LIGHT_LINEAR in glsl/common/lighting.glsl).
pub const LINEAR: f32 = 8.0;

/// The most lights gloss's `Lights` block holds on any GL.
pub const MAX_LIGHTS: usize = 1024;

/// The lights that fit on every GL: GL 3.3 promises
/// GL_MAX_UNIFORM_BLOCK_SIZE >= 16384 bytes, 256 lights of 64 bytes.
pub const LIGHTS_ON_EVERY_GL: usize = 16384 / LIGHT_STRIDE;

/// How many lights fit in a uniform block of `max_block_bytes` (at most `MAX_LIGHTS`).
pub fn max_lights(max_block_bytes: i32) -> usize {
    (max_block_bytes.max(16384) as usize / LIGHT_STRIDE).min(MAX_LIGHTS)
}

/// Refuse a scene with more than `max` lights; `why` says where `max`
/// comes from. The renderer checks against its GL, `gloss plan` against
/// `MAX_LIGHTS`: the message is the same up to `why`.
pub fn check_light_count(scene: &Scene, max: usize, why: &str) -> anyhow::Result<()> {
    if scene.lights.len() > max {
        anyhow::bail!(
            "{}: {} lights, but at most {max} fit in the lights uniform block ({why})",
            scene.path.display(),
            scene.lights.len()
        );
    }
    Ok(())
}

/// The lights a buffer texture holds on every GL 3.3
/// (GL_MAX_TEXTURE_BUFFER_SIZE >= 65536 texels, four a light).
pub const BUFFER_LIGHTS_ON_EVERY_GL: usize = 65536 / 4;

/// The most lights the tiled path shades: one pixel's list is one loop of
/// glsl/deferred/tiled_shading.frag, and llvmpipe ends a loop after 65535
/// iterations (silently: the rest of the list goes unshaded).
pub const TILED_LOOP_LIGHTS: usize = 65535;

/// Whether every pass of `scene`'s frame reads the lights from a buffer
/// texture rather than the uniform block: the tiled path, with no
/// transparent object (those are lit forward, from the block).
pub fn lights_in_buffer_texture(scene: &Scene) -> bool {
    scene.render.path == RenderPath::Tiled && scene.opaque_objects() == scene.objects.len()
}

/// `check_light_count`, where a tiled frame may hold more: refuse a scene
/// with more lights than its frame reads. `block_max` lights fit in the
/// uniform block (`block_why` says why), `texels` texels in a buffer
/// texture (four a light). With more lights than the block holds, only the
/// first `block_max` may cast shadows (the `Shadows` block's table).
pub fn check_lights_fit(
    scene: &Scene,
    block_max: usize,
    block_why: &str,
    texels: usize,
) -> anyhow::Result<()> {
    // Packed halves: every value must fit in a half (light_halves.rs).
    let lights = FrameLights::new(scene);
    crate::frame::light_halves::pack_scene(scene, &lights.pack(scene))?;
    if !lights_in_buffer_texture(scene) {
        return check_light_count(scene, block_max, block_why);
    }
    let n = scene.lights.len();
    if n > texels / 4 {
        anyhow::bail!(
            "{}: {n} lights, but at most {} fit in the tiled path's light buffer texture (GL_MAX_TEXTURE_BUFFER_SIZE = {texels} texels, 4 a light)",
            scene.path.display(),
            texels / 4
        );
    }
    if n > TILED_LOOP_LIGHTS {
        anyhow::bail!(
            "{}: {n} lights, but the tiled path shades at most {TILED_LOOP_LIGHTS}: a pixel's list is one shader loop, and llvmpipe runs a loop at most 65535 times",
            scene.path.display()
        );
    }
    if let Some(i) = (scene.lights.iter().enumerate())
        .skip(block_max)
        .find(|(_, l)| l.shadow.is_some())
        .map(|(i, _)| i)
    {
        anyhow::bail!(
            "{}: light {i} casts a shadow, but only the first {block_max} lights can ({block_why}): list the casting lights first",
            scene.path.display()
        );
    }
    Ok(())
}

/// The mesh that bounds a light's reach, with its model matrix.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Volume {
    /// A point light: the unit volume sphere scaled to the radius.
    Sphere(Mat4),
    /// A spot light: the unit cone (half-angle 45°, apex at the origin, axis
    /// -Z, height 1) turned to the light's direction, scaled to its range
    /// and outer angle.
    Cone(Mat4),
    /// A directional light, or one whose attenuation never reaches the
    /// cutoff (Kl = Kq = 0): every pixel, one full-screen triangle.
    FullScreen,
}

/// One light's derived values.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrameLight {
    /// Distance at which the light falls to the cutoff; `None` when there is
    /// no finite one (directional, or Kl = Kq = 0).
    pub radius: Option<f32>,
    pub volume: Volume,
}

/// The derived values of every light of a scene, in the scene's order.
#[derive(Clone, Debug, PartialEq)]
pub struct FrameLights {
    pub lights: Vec<FrameLight>,
}

impl FrameLights {
    /// Compute each light's radius at the scene's cutoff and its volume.
    pub fn new(scene: &Scene) -> FrameLights {
        let lights = scene
            .lights
            .iter()
            .map(|l| {
                let radius = model_radius(l, scene.render.cutoff, scene.render.falloff);
                FrameLight {
                    radius,
                    volume: volume(l, radius),
                }
            })
            .collect();
        FrameLights { lights }
    }

    pub fn len(&self) -> usize {
        self.lights.len()
    }

    pub fn is_empty(&self) -> bool {
        self.lights.is_empty()
    }

    /// How many lights draw a sphere, a cone, a full-screen triangle.
    pub fn count_volumes(&self) -> (usize, usize, usize) {
        let count = |f: fn(&Volume) -> bool| self.lights.iter().filter(|l| f(&l.volume)).count();
        (
            count(|v| matches!(v, Volume::Sphere(_))),
            count(|v| matches!(v, Volume::Cone(_))),
            count(|v| matches!(v, Volume::FullScreen)),
        )
    }

    /// Pack the lights as glsl/common/lighting.glsl's `struct Light` (std140):
    /// position + type, direction + radius (-1: none), colour x intensity +
    /// cos(outer), (Kc, Kl, Kq) + cos(inner). The type is 0 directional, 1
    /// point, 2 spot, plus `WINDOWED` or `LINEAR` when the scene's falloff
    /// is windowed or linear and the light has a radius: the flag travels with the light to every
    /// path, through the uniform block and tiled shading's buffer texture
    /// alike.
    pub fn pack(&self, scene: &Scene) -> Vec<u8> {
        let mut out = Vec::with_capacity(scene.lights.len() * LIGHT_STRIDE);
        for (l, f) in scene.lights.iter().zip(&self.lights) {
            let mut ty = match l.kind {
                LightKind::Directional => 0.0,
                LightKind::Point => 1.0,
                LightKind::Spot => 2.0,
            };
            match scene.render.falloff {
                Falloff::Windowed if f.radius.is_some() => ty += WINDOWED,
                Falloff::Linear if f.radius.is_some() => ty += LINEAR,
                _ => {}
            }
            let c = l.radiance();
            let v = [
                Vec4::new(l.position.x, l.position.y, l.position.z, ty),
                Vec4::new(
                    l.direction.x,
                    l.direction.y,
                    l.direction.z,
                    f.radius.unwrap_or(-1.0),
                ),
                Vec4::new(c.x, c.y, c.z, l.outer_angle.to_radians().cos()),
                Vec4::new(l.kc, l.kl, l.kq, l.inner_angle.to_radians().cos()),
            ];
            for x in v {
                for f in x.to_array() {
                    out.extend_from_slice(&f.to_ne_bytes());
                }
            }
        }
        out
    }
}

/// The light-volume radius at `cutoff` of the brightest channel (notes 04).
pub fn radius(light: &Light, cutoff: f32) -> Option<f32> {
    match light.kind {
        LightKind::Directional => None,
        LightKind::Point | LightKind::Spot => {
            attenuation::light_volume_radius(light.kc, light.kl, light.kq, light.i_max(), cutoff)
        }
    }
}

/// The light's volume radius under the falloff model: for the notes' and the
/// windowed model the radius at `cutoff` (`radius`); for the linear model
/// Lmax, where its attenuation 1 - d / Lmax reaches 0: the light's `range`,
/// or else the radius at the cutoff.
pub fn model_radius(light: &Light, cutoff: f32, falloff: Falloff) -> Option<f32> {
    let r = radius(light, cutoff);
    match (falloff, light.kind) {
        (_, LightKind::Directional) => None,
        (Falloff::Linear, _) => light.range.or(r),
        _ => r,
    }
}

fn volume(light: &Light, radius: Option<f32>) -> Volume {
    match (light.kind, radius) {
        (LightKind::Point, Some(r)) => Volume::Sphere(
            Mat4::from_translation(light.position) * Mat4::from_scale(Vec3::splat(r)),
        ),
        (LightKind::Spot, Some(r)) => {
            // The unit cone has half-angle 45° (radius 1 at height 1): scale
            // its width by tan(outer) and its length by the range, then turn
            // -Z onto the light's direction.
            let w = r * light.outer_angle.to_radians().tan();
            let turn = Quat::from_rotation_arc(Vec3::NEG_Z, light.direction);
            Volume::Cone(Mat4::from_scale_rotation_translation(
                Vec3::new(w, w, r),
                turn,
                light.position,
            ))
        }
        _ => Volume::FullScreen,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spot() -> Light {
        Light {
            range: None,
            kind: LightKind::Spot,
            position: Vec3::new(1.0, 2.0, 3.0),
            direction: Vec3::NEG_Y,
            color: Vec3::ONE,
            intensity: 2.0,
            kc: 1.0,
            kl: 0.09,
            kq: 0.032,
            inner_angle: 20.0,
            outer_angle: 30.0,
            shadow: None,
        }
    }

    #[test]
    fn std140_light_is_64_bytes() {
        let l = spot();
        let f = FrameLight {
            radius: radius(&l, 5.0 / 256.0),
            volume: Volume::FullScreen,
        };
        let mut scene = crate::scene::Scene::parse(
            "[camera]\neye = [0, 0, 5]\ntarget = [0, 0, 0]\n",
            std::path::Path::new("t.toml"),
        )
        .unwrap();
        scene.lights = vec![l.clone(), l];
        let lights = FrameLights { lights: vec![f, f] };
        let b = lights.pack(&scene);
        assert_eq!(b.len(), 128);
        let f = |i: usize| f32::from_ne_bytes(b[i * 4..i * 4 + 4].try_into().unwrap());
        assert_eq!((f(0), f(1), f(2), f(3)), (1.0, 2.0, 3.0, 2.0));
        assert!(f(7) > 0.0, "the radius rides in direction.w");
        assert_eq!(f(8), 2.0); // colour x intensity
        assert!((f(11) - 30f32.to_radians().cos()).abs() < 1e-7);
        assert_eq!(f(13), 0.09);
    }

    #[test]
    fn directional_and_unbounded_lights_are_full_screen() {
        let mut l = spot();
        l.kind = LightKind::Directional;
        assert_eq!(radius(&l, 0.02), None);
        let mut l = spot();
        l.kl = 0.0;
        l.kq = 0.0;
        assert_eq!(radius(&l, 0.02), None);
        assert_eq!(volume(&l, None), Volume::FullScreen);
    }

    #[test]
    fn spot_cone_reaches_the_radius_along_the_axis() {
        let l = spot();
        let r = radius(&l, 5.0 / 256.0).unwrap();
        let Volume::Cone(m) = volume(&l, Some(r)) else {
            panic!("a spot light gets a cone")
        };
        // The cone's base centre (0, 0, -1) lands r along the light's direction.
        let tip = m.transform_point3(Vec3::new(0.0, 0.0, -1.0));
        assert!((tip - (l.position + l.direction * r)).length() < 1e-4 * r);
    }
}
