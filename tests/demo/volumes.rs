//! src/demo/volume_views.rs: the overdraw view counts, per pixel, the light
//! volumes that cover it: at least one at each point light's own position,
//! never more than there are volumes, and the wireframe and debug views
//! draw without GL errors.

use crate::common;
use gloss::demo::inspector::Inspector;
use gloss::demo::volume_views::{VolumeView, VolumeViews};
use gloss::gl::framebuffer::Framebuffer;
use gloss::gl::program::Sources;
use gloss::renderer::Renderer;
use gloss::scene::{LightKind, RenderPath};

#[test]
fn overdraw_counts_the_volumes_over_each_pixel() {
    let ctx = common::context(common::backend());
    let gl = &ctx.gl;
    let mut scene = common::scene("mixed-lights.toml");
    scene.render.path = RenderPath::Volumes;
    let (w, h) = (192, 108);
    let mut r = Renderer::new(gl, &ctx.debug, &scene, &Sources::Embedded, w, h).unwrap();
    r.render(&scene.camera).unwrap();
    let inspector = Inspector::new(gl, &Sources::Embedded).unwrap();
    let mut views = VolumeViews::new(gl, &Sources::Embedded).unwrap();
    let into = Framebuffer::new(gl, "into", w, h, &[glow::RGBA8], None).unwrap();
    for v in [
        VolumeView::Wireframe,
        VolumeView::Debug,
        VolumeView::Overdraw,
    ] {
        views
            .draw(gl, v, &r, &scene.camera, &inspector, &into)
            .unwrap();
        ctx.debug.check(gl, v.label()).unwrap();
    }
    let count = views.count().unwrap().read_rgba_f32(0);
    let volumes = scene
        .lights
        .iter()
        .filter(|l| l.kind != LightKind::Directional)
        .count() as f32;
    let max = count.chunks(4).map(|p| p[0]).fold(0.0, f32::max);
    assert!(
        max >= 1.0 && max <= volumes,
        "largest count {max}, {volumes} volumes"
    );
    let vp = r
        .frame_uniforms(&scene.camera, &gloss::frame::views::View::camera())
        .view_projection;
    for l in scene.lights.iter().filter(|l| l.kind == LightKind::Point) {
        let ndc = vp.project_point3(l.position);
        let (x, y) = (
            ((ndc.x * 0.5 + 0.5) * w as f32) as usize,
            ((ndc.y * 0.5 + 0.5) * h as f32) as usize,
        );
        let c = count[(y * w as usize + x) * 4];
        assert!(
            c >= 1.0,
            "a point light's own pixel ({x}, {y}) is in its volume: count {c}"
        );
    }
}

/// The stencil light volumes' marks (src/demo/stencil_marks.rs): each
/// surface's stencil is the number of light volumes it lies inside, the
/// CPU's count from the rebuilt world point and each light's radius (and a
/// spot light's cone) on all but the pixels at the volumes' edges (their
/// meshes are polygons around the spheres and cones).
#[test]
fn the_stencil_marks_count_the_volumes_each_surface_lies_inside() {
    let ctx = common::context(common::backend());
    let gl = &ctx.gl;
    let scene = common::scene("stencil-volumes.toml");
    let (w, h) = (192, 108);
    let mut r = Renderer::new(gl, &ctx.debug, &scene, &Sources::Embedded, w, h).unwrap();
    r.render(&scene.camera).unwrap();
    let mut views = VolumeViews::new(gl, &Sources::Embedded).unwrap();
    let u = r.frame_uniforms(&scene.camera, &gloss::frame::views::View::camera());
    let marks = views.marks(gl, &r, u.view_projection).unwrap().unwrap();
    ctx.debug.check(gl, "the stencil marks").unwrap();
    let depth = r.read_depth();
    let (mut drawn, mut agree, mut marked) = (0, 0, 0);
    for y in 0..h as usize {
        for x in 0..w as usize {
            let d = depth[(h as usize - 1 - y) * w as usize + x];
            if d >= 1.0 {
                continue;
            }
            let ndc = glam::Vec3::new(
                2.0 * (x as f32 + 0.5) / w as f32 - 1.0,
                1.0 - 2.0 * (y as f32 + 0.5) / h as f32,
                2.0 * d - 1.0,
            );
            let p = u.inverse_view_projection.project_point3(ndc);
            let inside = (scene.lights.iter().zip(&r.lights().lights))
                .filter(|(l, f)| {
                    let Some(radius) = f.radius else { return false };
                    let v = p - l.position;
                    let cone = l.kind != LightKind::Spot
                        || v.normalize().dot(l.direction.normalize())
                            >= l.outer_angle.to_radians().cos();
                    v.length() <= radius && cone
                })
                .count();
            let m = usize::from(marks[y * w as usize + x]);
            drawn += 1;
            agree += usize::from(m == inside);
            marked += usize::from(m > 0);
        }
    }
    assert!(
        marked > drawn / 10,
        "{marked} of {drawn} surface pixels marked"
    );
    assert!(
        agree as f64 >= 0.9 * drawn as f64,
        "the marks equal the CPU's count on {agree} of {drawn} pixels"
    );
}
