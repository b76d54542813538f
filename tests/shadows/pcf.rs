//! Percentage-closer filtering (notes 01 §8.5, glsl/common/shadow.glsl):
//! each kernel averages depth comparisons, each 0 or 1, so its result is a
//! fraction of the light, never more. A shadow only takes light away: with
//! every kernel, on the directional, spot and point shadow scenes, no pixel
//! is brighter than the same scene with the light casting no shadow, the
//! pixels the shadow does not reach are unchanged, and some are darker.

use crate::common;
use gloss::renderer::Output;
use gloss::scene::shadows::Pcf;

#[test]
fn every_kernel_only_takes_light_away() {
    let ctx = common::context(common::backend());
    for name in [
        "shadows-directional.toml",
        "shadows-spot.toml",
        "shadows-point.toml",
    ] {
        let mut base = common::scene(name);
        base.render.size = (160, 90);
        let caster = (base.lights.iter())
            .position(|l| l.shadow.is_some())
            .unwrap();
        let mut bare = base.clone();
        bare.lights[caster].shadow = None;
        let open = common::render_with(&ctx, &bare, Output::Linear32F).linear;
        for pcf in [Pcf::None, Pcf::Hardware, Pcf::Box3, Pcf::Box5, Pcf::Poisson] {
            let mut s = base.clone();
            s.lights[caster].shadow.as_mut().unwrap().pcf = pcf;
            let shadowed = common::render_with(&ctx, &s, Output::Linear32F).linear;
            let (mut brighter, mut darker, mut same, mut worst) = (0, 0, 0, 0.0f32);
            for (a, b) in shadowed.chunks(4).zip(open.chunks(4)) {
                let d = (0..3).map(|c| a[c] - b[c]).fold(f32::MIN, f32::max);
                let least = (0..3).map(|c| a[c] - b[c]).fold(f32::MAX, f32::min);
                worst = worst.max(d);
                if d > 1e-4 {
                    brighter += 1;
                } else if least < -1e-3 {
                    darker += 1;
                } else {
                    same += 1;
                }
            }
            let n = open.len() / 4;
            assert_eq!(
                brighter, 0,
                "{name} {pcf:?}: {brighter} of {n} pixels brighter than without the shadow (by up to {worst})"
            );
            assert!(
                darker >= 50,
                "{name} {pcf:?}: only {darker} of {n} pixels in shadow"
            );
            assert!(
                same * 5 > n,
                "{name} {pcf:?}: only {same} of {n} pixels untouched"
            );
        }
    }
}
