//! How far a shadow-mapped frame is from the exact shadows (notes 01 §8.5,
//! §8.5.1): the three error figures `gloss bench` reports for a scene whose
//! lights cast, and the shadow tests assert.
//!
//! The scene is reduced to its first casting light and drawn three times:
//! with shadows, without, and with no light (ambient only). Those give the
//! GL mask (src/image_compare/shadow_mask.rs); the depth of the second gives
//! each pixel's surface point, from which a ray to the light against the
//! scene's triangles gives the exact answer
//! (src/lighting/shadow_reference.rs). The figures
//! (src/image_compare/shadow_metrics.rs):
//!
//! - misclassified: % of judged pixels where the two disagree, outside a
//!   one-pixel band around the true boundary;
//! - acne: % of truly lit pixels the map shadows;
//! - peter-panning: where an object rests on the floor (y = 0) under a
//!   directional light, how much later (world units) the mapped shadow
//!   starts than the true one, along lines from the object's base into its
//!   shadow, averaged.

use super::headless;
use crate::frame::views::View;
use crate::gl::Headless;
use crate::image_compare::shadow_mask::ShadowMask;
use crate::image_compare::shadow_metrics::{ShadowErrors, Visibility, contact_gap, pixel_line};
use crate::lighting::shadow_reference::{SceneTriangles, world_points};
use crate::renderer::Renderer;
use crate::scene::{LightKind, Scene};
use anyhow::{Context as _, Result, anyhow};
use glam::{Mat4, Vec3, Vec4Swizzles};

/// Everything the figures came from (the tests write the masks on failure).
pub struct ShadowEvaluation {
    pub errors: ShadowErrors,
    pub mask: ShadowMask,
    pub reference: Vec<Visibility>,
    /// The three renders: with shadows, without, ambient only.
    pub images: [image::RgbaImage; 3],
    /// The unshadowed render's window depth (bottom row first) and the
    /// camera's inverse view-projection: each pixel's surface point.
    pub depth: Vec<f32>,
    pub inverse_view_projection: Mat4,
}

/// `scene` with only its first casting light.
pub fn single_caster(scene: &Scene) -> Result<Scene> {
    let light = (scene.lights.iter())
        .find(|l| l.shadow.is_some())
        .ok_or_else(|| anyhow!("{}: no light casts a shadow", scene.name))?;
    let mut s = scene.clone();
    s.lights = vec![light.clone()];
    s.light_grid = None;
    s.grid_lights = None;
    Ok(s)
}

fn draw(ctx: &Headless, scene: &Scene) -> Result<Renderer> {
    let (w, h) = scene.render.size;
    let mut r = headless::renderer(ctx, scene, (w, h))?;
    r.render(&scene.camera.clone())?;
    Ok(r)
}

/// Measure `scene`'s first casting light against the exact shadows.
pub fn evaluate(ctx: &Headless, scene: &Scene) -> Result<ShadowEvaluation> {
    let with = single_caster(scene)?;
    let mut without = with.clone();
    without.lights[0].shadow = None;
    let mut dark = with.clone();
    dark.lights.clear();
    let shadowed = draw(ctx, &with).context("the render with shadows")?;
    let plain = draw(ctx, &without)?;
    let ambient = draw(ctx, &dark)?;
    let (w, h) = (plain.width as usize, plain.height as usize);
    let depth = plain.read_depth();
    let inverse = plain
        .frame_uniforms(&with.camera, &View::camera())
        .inverse_view_projection;
    let triangles = SceneTriangles::new(&with)?;
    let reference = triangles.reference_mask(&with, 0, &depth, inverse, w, h);
    let images = [
        shadowed.read_image(),
        plain.read_image(),
        ambient.read_image(),
    ];
    let mask = ShadowMask::from_renders(&images[0], &images[1], &images[2])?;
    let mut errors = ShadowErrors::measure(&mask, &reference);
    let points = world_points(&depth, inverse, w, h);
    let vp = inverse.inverse();
    errors.peter_panning = peter_panning(&with, &mask, &reference, &points, vp, (w, h))?;
    Ok(ShadowEvaluation {
        errors,
        mask,
        reference,
        images,
        depth,
        inverse_view_projection: inverse,
    })
}

/// The mean contact gap over lines from the base of each object resting on
/// y = 0 into its shadow, for a directional light (None: no such object, or
/// no line the two masks both shadow).
fn peter_panning(
    scene: &Scene,
    mask: &ShadowMask,
    reference: &[Visibility],
    points: &[Vec3],
    view_projection: Mat4,
    (w, h): (usize, usize),
) -> Result<Option<f32>> {
    let light = &scene.lights[0];
    if light.kind != LightKind::Directional {
        return Ok(None);
    }
    // The shadow runs away from the light, along the light's direction
    // across the floor; its length is the object's height over tan(elevation).
    let across = Vec3::new(light.direction.x, 0.0, light.direction.z);
    let Some(along) = across.try_normalize() else {
        return Ok(None);
    };
    let side = Vec3::Y.cross(along);
    let pixel = |p: Vec3| {
        let c = view_projection * p.extend(1.0);
        let ndc = c.xyz() / c.w;
        let x = ((ndc.x + 1.0) * 0.5 * w as f32).floor() as i64;
        let y = ((ndc.y + 1.0) * 0.5 * h as f32).floor() as i64;
        (x, y)
    };
    let mut gaps = Vec::new();
    for o in &scene.objects {
        let data = crate::scene::meshes::mesh_data(&o.mesh)?;
        let world: Vec<Vec3> = (data.vertices.iter())
            .map(|v| o.model.transform_point3(Vec3::from(v.position)))
            .collect();
        let (lo, hi) = world
            .iter()
            .fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(a, b), &p| {
                (a.min(p), b.max(p))
            });
        // Resting on the floor: its lowest point at y = 0, and taller than flat.
        if lo.y.abs() > 1e-3 || hi.y - lo.y < 1e-2 {
            continue;
        }
        let base: Vec<Vec3> = world
            .iter()
            .copied()
            .filter(|p| p.y < lo.y + 1e-3)
            .collect();
        let reach = |d: Vec3| base.iter().map(|p| p.dot(d)).fold(f32::MIN, f32::max);
        // The base's point farthest along the shadow, and a line each side
        // of it, a tenth of the base's width apart.
        let Some(corner) = base
            .iter()
            .copied()
            .max_by(|a, b| a.dot(along).total_cmp(&b.dot(along)))
        else {
            continue;
        };
        let width = reach(side) + reach(-side);
        let length = (hi.y - lo.y) * across.length() / (-light.direction.y).max(1e-3);
        for k in [-1.0, 0.0, 1.0] {
            let c = corner + side * (0.1 * width * k);
            let line = pixel_line(w, h, pixel(c), pixel(c + along * length.min(2.0) * 0.8));
            // Only a line whose contact point the camera sees (not hidden
            // behind the object).
            let seen = line.first().is_some_and(|&i| points[i].distance(c) < 0.05);
            if !seen {
                continue;
            }
            if let Some(g) = contact_gap(mask, reference, points, &line, c) {
                gaps.push(g);
            }
        }
    }
    Ok((!gaps.is_empty()).then(|| gaps.iter().sum::<f32>() / gaps.len() as f32))
}
