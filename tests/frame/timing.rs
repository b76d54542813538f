//! src/frame/timing.rs: with timing on, one CPU time per planned pass; with
//! GPU timers (forced on here, where llvmpipe's under-report: only the code
//! path is checked, not the values), one GL_TIMESTAMP interval per pass too,
//! and the query objects are freed.

use crate::common;
use gloss::gl::live;
use gloss::gl::program::Sources;
use gloss::renderer::Renderer;
use gloss::scene::RenderPath;

#[test]
fn pass_times_on_the_cpu_and_gpu_clocks() {
    let ctx = common::context(common::backend());
    let mut scene = common::scene("mixed-lights.toml");
    scene.render.path = RenderPath::Prepass;
    let mut r = Renderer::new(&ctx.gl, &ctx.debug, &scene, &Sources::Embedded, 64, 36).unwrap();
    assert!(
        !r.gpu_timers,
        "llvmpipe's timer queries are not trusted by default"
    );
    r.timing = true;
    r.render(&scene.camera).unwrap();
    assert_eq!(r.last_times.passes.len(), r.plan.passes.len());
    assert!(r.last_times.gpu.is_empty());
    let before = live::counts();
    r.gpu_timers = true;
    r.render(&scene.camera).unwrap();
    let gpu = &r.last_times.gpu;
    assert_eq!(gpu.len(), r.plan.passes.len());
    assert!(gpu.iter().all(|ms| ms.is_finite() && *ms >= 0.0), "{gpu:?}");
    assert_eq!(
        live::counts(),
        before,
        "the frame's timestamp queries are freed"
    );
    ctx.debug.check(&ctx.gl, "timing").unwrap();
}
