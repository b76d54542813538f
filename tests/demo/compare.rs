//! src/demo/compare.rs: "compare with reference" measures the frame against
//! forward rendering: zero for forward itself, the light-volume cutoff's
//! error for volumes, and a difference texture of the frame's size.

use crate::common;
use gloss::demo::compare::compare;
use gloss::gl::program::Sources;
use gloss::image_compare::compare_rgba8;
use gloss::renderer::Renderer;
use gloss::scene::RenderPath;

#[test]
fn compare_with_reference_measures_against_forward() {
    let ctx = common::context(common::backend());
    let gl = &ctx.gl;
    let mut scene = common::scene("mixed-lights.toml");
    let (w, h) = (160, 90);
    for path in [RenderPath::Forward, RenderPath::Volumes] {
        scene.render.path = path;
        let mut r = Renderer::new(gl, &ctx.debug, &scene, &Sources::Embedded, w, h).unwrap();
        r.render(&scene.camera).unwrap();
        let c = compare(gl, &ctx.debug, &Sources::Embedded, &r, &scene.camera).unwrap();
        assert_eq!((c.difference.width, c.difference.height), (w, h));
        let mut forward = scene.clone();
        forward.render.path = RenderPath::Forward;
        let mut f = Renderer::new(gl, &ctx.debug, &forward, &Sources::Embedded, w, h).unwrap();
        f.render(&scene.camera).unwrap();
        let expected = compare_rgba8(&r.read_image(), &f.read_image(), 1.0 / 255.0).unwrap();
        assert_eq!(c.metrics, expected, "{path:?}");
        if path == RenderPath::Forward {
            assert_eq!(c.metrics.max_abs, 0.0);
        } else {
            assert!(
                c.metrics.max_abs > 0.0,
                "volumes cut light off: {}",
                c.metrics
            );
        }
    }
    ctx.debug.check(gl, "comparing").unwrap();
}
