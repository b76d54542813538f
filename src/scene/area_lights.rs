//! `[[area_lights]]`: rectangles of uniform radiance, shaded with linearly
//! transformed cosines on the forward path
//! (src/techniques/lighting/ltc_area_lights.rs):
//!
//! ```toml
//! [[area_lights]]
//! center = [0.0, 2.0, 0.0]
//! size = [1.0, 0.5]           # width, height (along `up`)
//! normal = [0.0, -1.0, 0.0]   # the side it shines toward
//! up = [0.0, 0.0, 1.0]        # default [0, 1, 0], or [0, 0, 1] for a light facing up or down
//! color = [1.0, 0.9, 0.8]     # linear RGB
//! intensity = 4.0             # radiance = color x intensity
//! two_sided = false           # true: both faces shine
//! ```
//!
//! A separate list from `[[lights]]`: those are points and directions that
//! every path, shadow map and light volume reads; a rectangle has none of
//! their keys (attenuation, range, cone) and needs its own shading.

use super::checks::{finite, non_negative};
use anyhow::{Result, bail};
use glam::Vec3;
use serde::Deserialize;

/// The most area lights a scene may have (the shader's uniform arrays).
pub const MAX_AREA_LIGHTS: usize = 8;

/// `render.area_light_points`: N, each triangle of a light cut into N x N
/// (glsl/lighting/area_light_reference.glsl); 256 is 131 072 points a light.
pub const REFERENCE_POINTS: std::ops::RangeInclusive<u32> = 1..=256;

/// `render.area_light_points`, checked against `REFERENCE_POINTS`.
pub(super) fn reference_points(n: u32) -> Result<u32> {
    let range = REFERENCE_POINTS;
    if !range.contains(&n) {
        bail!(
            "render.area_light_points: expected {}..={} (N x N points per triangle of a light), found {n}",
            range.start(),
            range.end()
        );
    }
    Ok(n)
}

super::settings::setting! {
    /// `render.area_light_reference`: how the forward pass shades the area
    /// lights. LTC, or the reference LTC is measured against: gloss's own
    /// BRDF integrated over each light by quadrature
    /// (glsl/lighting/area_light_reference.glsl), slow on purpose.
    pub enum AreaLightReference {
        /// Linearly transformed cosines (glsl/lighting/ltc_area_lights.glsl).
        Off = "off",
        /// The quadrature with gloss's exact dielectric Fresnel per point.
        Exact = "exact",
        /// The quadrature with F = 1 per point, times the LTC table's one
        /// Schlick-average Fresnel: what LTC would give with a perfect fit.
        TableFresnel = "table_fresnel",
    }
}

#[derive(Deserialize, Debug, Clone, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct AreaLightFile {
    pub center: [f32; 3],
    pub size: [f32; 2],
    pub normal: [f32; 3],
    pub up: Option<[f32; 3]>,
    #[serde(default = "white")]
    pub color: [f32; 3],
    #[serde(default = "one")]
    pub intensity: f32,
    #[serde(default)]
    pub two_sided: bool,
}

fn white() -> [f32; 3] {
    [1.0, 1.0, 1.0]
}
fn one() -> f32 {
    1.0
}

/// An area light as checked: unit `normal` and `up` at right angles.
#[derive(Debug, Clone, PartialEq)]
pub struct AreaLight {
    pub center: Vec3,
    pub size: [f32; 2],
    pub normal: Vec3,
    pub up: Vec3,
    pub color: Vec3,
    pub intensity: f32,
    pub two_sided: bool,
}

impl AreaLight {
    /// What the light emits toward every direction it faces (linear RGB).
    pub fn radiance(&self) -> Vec3 {
        self.color * self.intensity
    }

    /// The four corners, as the shader receives them: C - T - B, C + T - B,
    /// C + T + B, C - T + B with B = up height / 2, T = (up x normal)
    /// width / 2, so that (c1 - c0) x (c3 - c0) points along `normal`
    /// (`QuadLight::rectangle` in src/lighting/area_light.rs, in f64).
    pub fn corners(&self) -> [Vec3; 4] {
        let (c, b) = (self.center, self.up * (0.5 * self.size[1]));
        let t = self.up.cross(self.normal) * (0.5 * self.size[0]);
        [c - t - b, c + t - b, c + t + b, c - t + b]
    }
}

pub(super) fn resolve(files: &[AreaLightFile]) -> Result<Vec<AreaLight>> {
    if files.len() > MAX_AREA_LIGHTS {
        bail!(
            "area_lights: expected at most {MAX_AREA_LIGHTS} area lights, found {}",
            files.len()
        );
    }
    let mut lights = Vec::new();
    for (i, f) in files.iter().enumerate() {
        let key = |k: &str| format!("area_lights[{i}].{k}");
        finite(&key("center"), &f.center)?;
        if !f
            .size
            .iter()
            .all(|s| s.is_finite() && *s > 0.0 && *s <= 1e4)
        {
            bail!(
                "{}: expected a width and height in (0, 1e4], found {:?}",
                key("size"),
                f.size
            );
        }
        finite(&key("normal"), &f.normal)?;
        let normal = Vec3::from(f.normal);
        if normal.length() < 1e-6 {
            bail!("{}: must not be zero", key("normal"));
        }
        let normal = normal.normalize();
        let up = match f.up {
            Some(u) => {
                finite(&key("up"), &u)?;
                Vec3::from(u)
            }
            None if normal.y.abs() > 0.99 => Vec3::Z,
            None => Vec3::Y,
        };
        // Up at right angles to the normal (its part along the normal dropped).
        let square = up - normal * up.dot(normal);
        if square.length() < 1e-3 * up.length().max(1e-30) {
            bail!(
                "{}: expected a direction not parallel to normal {:?}, found {:?}",
                key("up"),
                f.normal,
                up.to_array()
            );
        }
        non_negative(&key("color"), &f.color)?;
        non_negative(&key("intensity"), &[f.intensity])?;
        lights.push(AreaLight {
            center: Vec3::from(f.center),
            size: f.size,
            normal,
            up: square.normalize(),
            color: Vec3::from(f.color),
            intensity: f.intensity,
            two_sided: f.two_sided,
        });
    }
    Ok(lights)
}

/// What the scene's area lights do not reach, one line each (printed with
/// the scene's warnings): forward's other shading modes, the objects the
/// parallax and transparency passes draw. Nothing is left out in silence.
pub(super) fn warnings(scene: &super::Scene) -> Vec<String> {
    use super::{Parallax, RenderPath, Shading};
    let (n, r) = (scene.area_lights.len(), &scene.render);
    if n == 0 || !r.area_lights {
        return vec![];
    }
    let lights = format!("area_lights: the {n} area lights are");
    // The G-buffer paths light every pixel, whatever render.shading says.
    if r.path == RenderPath::Forward && r.shading != Shading::Phong {
        return vec![format!(
            "{lights} shaded per fragment only (render.shading = \"phong\"); {} shading leaves them out",
            r.shading
        )];
    }
    let mut w = Vec::new();
    if r.path != RenderPath::Forward && r.area_light_reference != AreaLightReference::Off {
        w.push(format!(
            "area_lights: render.area_light_reference = \"{}\" is drawn on the forward path only; the {} path shades the area lights by LTC",
            r.area_light_reference, r.path
        ));
    }
    let drawn = |o: &&super::Object| o.mirror.is_none();
    let material = |o: &super::Object| &scene.materials[o.material];
    let relief = (scene.objects.iter().filter(drawn))
        .filter(|o| material(o).height_map.is_some() && !material(o).is_transparent())
        .count();
    // Only forward has the parallax pass; elsewhere they are in the G-buffer.
    if relief > 0 && r.parallax != Parallax::Off && r.path == RenderPath::Forward {
        w.push(format!(
            "{lights} not lit on the {relief} objects the parallax pass draws (materials with a height_map)"
        ));
    }
    let glass = (scene.objects.iter().filter(drawn))
        .filter(|o| material(o).is_transparent())
        .count();
    if glass > 0 {
        w.push(format!(
            "{lights} not lit on the {glass} transparent objects (the transparency passes)"
        ));
    }
    w
}
