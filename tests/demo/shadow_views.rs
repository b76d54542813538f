//! src/demo/shadow_views.rs: the inspector lists a shadow-map view for
//! exactly the casting lights, and each pixel of the view is the stored
//! depth of the texel under it, stretched from the least to the greatest
//! value below 1.0 to black and white: a 2D map as the light sees it, a
//! cube unfolded into the cross (+y above; -x +z +x -z; -y below) with each
//! face as GL stores it, the background around. Drawing it changes neither
//! the map's comparison mode nor any GL binding.

use crate::common;
use gloss::demo::inspector::views;
use gloss::demo::shadow_views::{BACKGROUND, NOTHING, ShadowView, ShadowViews, layout_rect};
use gloss::gl::framebuffer::Framebuffer;
use gloss::gl::program::Sources;
use gloss::renderer::Renderer;
use gloss::scene::{LightKind, Scene};
use glow::HasContext;

/// The view's size: a cube's faces are 128 pixels, a 2D map 384.
const SIZE: (i32, i32) = (512, 384);
/// The maps' resolution: two or six pixels a texel, so that every pixel
/// centre lies well inside one texel.
const TEXELS: u32 = 64;

struct Inspected {
    scene: Scene,
    renderer: Renderer,
    views: Vec<ShadowView>,
    /// The view, row 0 at the bottom.
    image: image::RgbaImage,
    stretch: (f32, f32),
}

fn inspect(ctx: &gloss::gl::Headless, name: &str) -> Inspected {
    let gl = &ctx.gl;
    let mut scene = common::scene(name);
    for l in &mut scene.lights {
        if let Some(s) = &mut l.shadow {
            s.resolution = TEXELS;
        }
    }
    let mut r = Renderer::new(gl, &ctx.debug, &scene, &Sources::Embedded, 160, 90).unwrap();
    r.render(&scene.camera).unwrap();
    let frame = r.read_image();
    let shadows = ShadowView::of(r.shadows().maps.iter().map(|(c, _)| c), |i| {
        scene.lights[i].kind
    });
    let all = views(&r.plan, false, &shadows);
    // The maps (a cube's cross), each followed by its faces alone.
    let listed: Vec<ShadowView> = (all.iter().filter_map(|v| v.shadow))
        .filter(|s| s.face.is_none())
        .collect();
    let casting: Vec<usize> = (0..scene.lights.len())
        .filter(|&i| scene.lights[i].shadow.is_some())
        .collect();
    assert_eq!(
        listed.iter().map(|v| v.light).collect::<Vec<_>>(),
        casting,
        "{name}: a shadow-map view per casting light"
    );
    for v in &all {
        assert_eq!(v.shadow.is_some(), v.target == "shadow map", "{name}");
    }
    let label = all[0].label();
    assert!(
        label.starts_with(&format!("shadow map: light {} ({TEXELS}²", casting[0])),
        "{label}"
    );

    let mut shadow_views = ShadowViews::new(gl, &Sources::Embedded).unwrap();
    let into = Framebuffer::new(gl, "into", SIZE.0, SIZE.1, &[glow::RGBA8], None).unwrap();
    let before = common::gl_state(gl);
    let stretch = shadow_views
        .draw(&listed[0], r.shadows(), &into)
        .unwrap()
        .expect("some texel below 1.0");
    ctx.debug.check(gl, "drawing a shadow-map view").unwrap();
    assert_eq!(
        common::gl_state(gl),
        before,
        "{name}: GL state left changed"
    );
    let (_, map) = &r.shadows().maps[0];
    unsafe {
        for unit in 0..2 {
            gl.active_texture(glow::TEXTURE0 + unit);
            assert_eq!(gl.get_parameter_i32(glow::SAMPLER_BINDING), 0);
        }
        gl.active_texture(glow::TEXTURE0);
        gl.bind_texture(map.target, Some(map.texture));
        let mode = gl.get_tex_parameter_i32(map.target, glow::TEXTURE_COMPARE_MODE);
        gl.bind_texture(map.target, None);
        assert_eq!(mode as u32, glow::COMPARE_REF_TO_TEXTURE, "{name}");
    }
    r.render(&scene.camera).unwrap();
    assert!(
        r.read_image().as_raw() == frame.as_raw(),
        "{name}: the frame after the inspector differs"
    );
    let image = image::imageops::flip_vertical(&into.read_rgba8_top_down(0));
    Inspected {
        scene,
        renderer: r,
        views: listed,
        image,
        stretch,
    }
}

/// What a stored value looks like in the view.
pub(crate) fn shown(d: f32, (lo, hi): (f32, f32)) -> [u8; 3] {
    if d >= 1.0 {
        return NOTHING;
    }
    let g = ((d - lo) / (hi - lo)).clamp(0.0, 1.0) * 255.0;
    [g.round() as u8; 3]
}

pub(crate) fn close(a: [u8; 3], b: [u8; 3]) -> bool {
    a.iter().zip(b).all(|(x, y)| x.abs_diff(y) <= 1)
}

/// The least and greatest of `values` below 1.0.
pub(crate) fn range<'a>(values: impl Iterator<Item = &'a f32>) -> (f32, f32) {
    let below = values.filter(|&&d| d < 1.0);
    below.fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), &d| {
        (lo.min(d), hi.max(d))
    })
}

#[test]
fn a_2d_map_is_shown_as_the_light_sees_it_stretched_between_its_extremes() {
    let ctx = common::context(common::backend());
    for name in ["shadows-directional.toml", "shadows-spot.toml"] {
        let i = inspect(&ctx, name);
        assert!(!i.views[0].cube());
        let depth = i.renderer.shadows().maps[0].1.read(0);
        assert_eq!(i.stretch, range(depth.iter()), "{name}: the stretch");
        let [x0, y0, side, _] = layout_rect(false, SIZE.0, SIZE.1);
        assert_eq!((x0, y0, side), (64, 0, 384));
        let n = TEXELS as usize;
        let mut greys = std::collections::BTreeSet::new();
        for (x, y, p) in i.image.enumerate_pixels() {
            let (x, y) = (x as i32, y as i32);
            let p = [p[0], p[1], p[2]];
            if x < x0 || x >= x0 + side {
                assert_eq!(p, BACKGROUND, "{name}: ({x}, {y}) beside the map");
                continue;
            }
            let u = (x - x0) as f32 + 0.5;
            let v = (y - y0) as f32 + 0.5;
            let (s, t) = (
                (u / side as f32 * n as f32) as usize,
                (v / side as f32 * n as f32) as usize,
            );
            let want = shown(depth[t * n + s], i.stretch);
            assert!(
                close(p, want),
                "{name}: ({x}, {y}) shows {p:?}, texel ({s}, {t}) gives {want:?}"
            );
            greys.insert(p);
        }
        assert!(
            greys.contains(&[0; 3]) && greys.contains(&[255; 3]) && greys.len() > 20,
            "{name}: {} shades, black and white among them",
            greys.len()
        );
        assert_ne!(i.scene.lights[i.views[0].light].kind, LightKind::Point);
    }
}

#[test]
fn a_cube_map_is_unfolded_into_the_cross_each_face_as_gl_stores_it() {
    let ctx = common::context(common::backend());
    let i = inspect(&ctx, "shadows-point.toml");
    assert!(i.views[0].cube());
    assert_eq!(layout_rect(true, SIZE.0, SIZE.1), [0, 0, 512, 384]);
    let map = &i.renderer.shadows().maps[0].1;
    // GL's face order: +x, -x, +y, -y, +z, -z; their cells (column, row from the bottom).
    let faces: Vec<Vec<f32>> = (0..6).map(|f| map.read(f)).collect();
    let cells = [(2, 1), (0, 1), (1, 2), (1, 0), (1, 1), (3, 1)];
    assert_eq!(i.stretch, range(faces.iter().flatten()), "the stretch");
    let (f, n) = (128, TEXELS as usize);
    for (cx, cy) in [(0, 0), (2, 0), (3, 0), (0, 2), (2, 2), (3, 2)] {
        for y in cy * f..(cy + 1) * f {
            for x in cx * f..(cx + 1) * f {
                let p = i.image.get_pixel(x, y).0;
                assert_eq!(
                    [p[0], p[1], p[2]],
                    BACKGROUND,
                    "({x}, {y}) is outside the cross"
                );
            }
        }
    }
    for (face, &(cx, cy)) in cells.iter().enumerate() {
        let mut greys = std::collections::BTreeSet::new();
        for y in cy * f..(cy + 1) * f {
            for x in cx * f..(cx + 1) * f {
                let p = i.image.get_pixel(x, y).0;
                let p = [p[0], p[1], p[2]];
                // Across the face s to the right, t downwards (t = 0 at the top).
                let u = ((x - cx * f) as f32 + 0.5) / f as f32;
                let v = ((y - cy * f) as f32 + 0.5) / f as f32;
                let (s, t) = ((u * n as f32) as usize, ((1.0 - v) * n as f32) as usize);
                let want = shown(faces[face][t * n + s], i.stretch);
                assert!(
                    close(p, want),
                    "face {face}: ({x}, {y}) shows {p:?}, texel ({s}, {t}) gives {want:?}"
                );
                greys.insert(p[0]);
            }
        }
        let spread = greys.last().unwrap() - greys.first().unwrap();
        assert!(
            spread >= 16,
            "face {face}: the depth varies over it ({spread} grey levels)"
        );
    }
}

/// The inspector keeps showing the same light's map when a caster before it
/// is removed (its place in the list moves), when its resolution changes,
/// and shows the output once its light stops casting. No GL needed.
#[test]
fn the_inspected_shadow_map_follows_its_light_when_the_list_shifts() {
    use gloss::demo::inspector::follow;
    let scene = common::scene("shadows-spot.toml");
    let plan = gloss::techniques::plan(&scene);
    let caster = |light, resolution| ShadowView {
        light,
        kind: LightKind::Spot,
        resolution,
        face: None,
    };
    let before = views(&plan, false, &[caster(0, 512), caster(2, 512)]);
    let mut kept = None;
    // A new choice: light 2's map, second in the list.
    assert_eq!(follow(Some(1), &mut kept, &before), Some(1));
    assert_eq!(
        kept.as_ref().and_then(|v| v.shadow).map(|s| s.light),
        Some(2)
    );
    // Light 0 stops casting: light 2's map is now first.
    let after = views(&plan, false, &[caster(2, 512)]);
    assert_eq!(follow(Some(1), &mut kept, &after), Some(0));
    // Its resolution changes: still the same view.
    let finer = views(&plan, false, &[caster(2, 2048)]);
    assert_eq!(follow(Some(0), &mut kept, &finer), Some(0));
    assert_eq!(
        kept.as_ref().and_then(|v| v.shadow).map(|s| s.resolution),
        Some(2048)
    );
    // Light 2 stops casting too: nothing to show but the output.
    let none = views(&plan, false, &[]);
    assert_eq!(follow(Some(0), &mut kept, &none), None);
    assert!(kept.is_none());
    // Without a shadow map the attachments keep their places.
    let first = none[0].clone();
    assert_eq!(follow(Some(0), &mut kept, &none), Some(0));
    assert!(kept.as_ref().is_some_and(|v| v.same_as(&first)));
}

/// Each face of a cube is a view of its own, the output of its face's pass
/// ("shadow map (light 0, face +X)"), after the cross: the face alone in a
/// square, as GL stores it (s to the right, t = 0 at the top), stretched
/// between its own extremes.
#[test]
fn each_cube_face_is_a_view_of_its_own_after_the_cross() {
    let ctx = common::context(common::backend());
    let i = inspect(&ctx, "shadows-point.toml");
    let all = views(&i.renderer.plan, false, &i.views);
    let faces: Vec<ShadowView> = (all.iter().filter_map(|v| v.shadow)).collect();
    assert_eq!(faces.len(), 7, "the cross and six faces");
    assert_eq!(faces[0].face, None);
    let labels: Vec<String> = all[..7].iter().map(|v| v.label()).collect();
    for (f, name) in ["+X", "-X", "+Y", "-Y", "+Z", "-Z"].iter().enumerate() {
        assert_eq!(faces[f + 1].face, Some(f));
        assert!(
            labels[f + 1].contains(&format!("face {name} alone")),
            "{labels:?}"
        );
        assert!(!all[0].same_as(&all[f + 1]));
    }
    let gl = &ctx.gl;
    let map = &i.renderer.shadows().maps[0].1;
    let n = TEXELS as usize;
    let side = 2 * TEXELS as i32;
    let into = Framebuffer::new(gl, "face", side, side, &[glow::RGBA8], None).unwrap();
    let mut shadow_views = ShadowViews::new(gl, &Sources::Embedded).unwrap();
    for face in 0..6 {
        let texels = map.read(face as u32);
        let view = faces[face + 1];
        let stretch = shadow_views
            .draw(&view, i.renderer.shadows(), &into)
            .unwrap();
        ctx.debug.check(gl, "drawing a cube face's view").unwrap();
        assert_eq!(
            stretch,
            Some(range(texels.iter())),
            "face {face}: its own stretch"
        );
        let image = into.read_rgba8_top_down(0);
        for y in 0..side as u32 {
            for x in 0..side as u32 {
                let p = image.get_pixel(x, y).0;
                let (s, t) = ((x / 2) as usize, (y / 2) as usize);
                let want = shown(texels[t * n + s], stretch.unwrap());
                assert!(
                    close([p[0], p[1], p[2]], want),
                    "face {face}: ({x}, {y}) shows {p:?}, texel ({s}, {t}) gives {want:?}"
                );
            }
        }
    }
}
