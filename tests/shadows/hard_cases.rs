//! The hard cases of shadow mapping, each against what must be true:
//!
//! * a point light inside a closed room: every cube face holds geometry,
//!   and with nothing to cast a shadow the shadowed image equals the
//!   unshadowed one everywhere, face edges included (no seam, no acne), to
//!   2/255;
//! * a caster outside the camera's frustum, between the light and the
//!   floor the camera sees, still casts (the fitted box keeps every caster
//!   in depth);
//! * a caster nearer the light than the map's near plane still casts
//!   (GL_DEPTH_CLAMP in the shadow pass).

use crate::common;
use glam::Vec3;
use gloss::frame::views::View;
use gloss::gl::Headless;
use gloss::gl::program::Sources;
use gloss::image_compare::compare_rgba8;
use gloss::lighting::shadow_reference::pixel_world_point;
use gloss::renderer::Renderer;
use gloss::scene::{Scene, ShadowFit};
use image::RgbaImage;

pub fn renderer(ctx: &Headless, scene: &Scene) -> Renderer {
    let (w, h) = scene.render.size;
    let mut r = Renderer::new(
        &ctx.gl,
        &ctx.debug,
        scene,
        &Sources::Embedded,
        w as i32,
        h as i32,
    )
    .unwrap_or_else(|e| panic!("{}: {e:#}", scene.name));
    r.render(&scene.camera.clone())
        .unwrap_or_else(|e| panic!("{}: {e:#}", scene.name));
    r
}

fn image(ctx: &Headless, scene: &Scene) -> RgbaImage {
    renderer(ctx, scene).read_image()
}

fn without_shadows(scene: &Scene) -> Scene {
    let mut s = scene.clone();
    for l in &mut s.lights {
        l.shadow = None;
    }
    s
}

/// The world point each pixel shows (None: background), rows bottom-up.
fn world_points(r: &Renderer, scene: &Scene) -> Vec<Option<Vec3>> {
    let depth = r.read_depth();
    let inverse = r
        .frame_uniforms(&scene.camera, &View::camera())
        .inverse_view_projection;
    let (w, h) = (r.width as usize, r.height as usize);
    (0..w * h)
        .map(|i| {
            let d = depth[i];
            (d < 1.0).then(|| pixel_world_point(i % w, i / w, d, inverse, w, h))
        })
        .collect()
}

#[test]
fn a_point_light_in_a_room_uses_all_six_faces_without_seams() {
    let ctx = common::context(common::backend());
    let mut room = common::scene("shadows-point.toml");
    room.objects
        .retain(|o| o.mesh == gloss::scene::MeshSource::Plane);
    assert_eq!(room.objects.len(), 6, "floor, ceiling and four walls");
    room.render.size = (480, 270);
    for (position, camera_eye) in [
        (Vec3::new(0.3, 2.6, -0.6), None),
        // Off centre, looking at a corner where three faces meet.
        (Vec3::new(-1.7, 1.3, 1.1), Some(Vec3::new(2.5, 2.5, 4.0))),
    ] {
        let mut s = room.clone();
        s.lights[0].position = position;
        if let Some(eye) = camera_eye {
            s.camera.eye = eye;
            s.camera.target = Vec3::new(-5.0, 0.0, -5.0);
        }
        let r = renderer(&ctx, &s);
        let (_, map) = &r.shadows().maps[0];
        for face in 0..6 {
            let depths = map.read(face);
            let covered = depths.iter().filter(|&&d| d < 1.0).count();
            // Where two walls meet, a texel may fall in the crack between
            // two meshes' rasterisations: allow one in a million.
            let missed = depths.len() - covered;
            assert!(
                missed * 1_000_000 <= depths.len(),
                "face {face}: {missed} texels see no wall"
            );
        }
        // Pixels whose direction from the light lies within 2% of a face
        // edge: the test covers the seams.
        let edges = world_points(&r, &s)
            .iter()
            .flatten()
            .filter(|p| {
                let mut a = (**p - position).abs().to_array();
                a.sort_by(f32::total_cmp);
                a[1] > 0.98 * a[2]
            })
            .count();
        assert!(edges > 500, "{edges} pixels near a face edge");
        let shadowed = r.read_image();
        let plain = image(&ctx, &without_shadows(&s));
        let m = compare_rgba8(&shadowed, &plain, 2.0 / 255.0).unwrap();
        assert!(
            m.frac_over == 0.0,
            "light at {position}: with nothing to cast, shadows change {:.3}% of pixels ({m})",
            m.frac_over * 100.0
        );
    }
}

/// A floor, a directional light nearly straight down, and a box high above
/// the floor's centre, out of the camera's view.
fn caster_out_of_view(fit: ShadowFit) -> Scene {
    let text = r#"
        name = "caster-out-of-view"
        [camera]
        eye = [0.0, 3.0, 3.0]
        target = [0.0, 0.0, 0.0]
        fov_y = 40.0
        [render]
        size = [320, 240]
        ambient = [0.05, 0.05, 0.05]
        [[lights]]
        type = "directional"
        direction = [0.0, -1.0, 0.3]
        shadow = true
        [materials.grey]
        diffuse = [0.8, 0.8, 0.8]
        specular = [0.0, 0.0, 0.0]
        [[objects]]
        name = "floor"
        mesh = "plane"
        material = "grey"
        scale = [10.0, 1.0, 10.0]
        [[objects]]
        name = "caster"
        mesh = "cube"
        material = "grey"
        position = [0.0, 6.0, -1.8]
        scale = [0.5, 0.1, 0.5]
    "#;
    let mut s = Scene::parse(text, std::path::Path::new("caster-out-of-view.toml")).unwrap();
    s.lights[0].shadow.as_mut().unwrap().fit = fit;
    s
}

/// A linear value as the 8-bit sRGB output stores it.
fn srgb8(linear: f32) -> u8 {
    (gloss::lighting::srgb_encode(linear) * 255.0).round() as u8
}

/// The centre pixel's red channel.
fn centre(img: &RgbaImage) -> u8 {
    img.get_pixel(img.width() / 2, img.height() / 2)[0]
}

#[test]
fn a_caster_outside_the_camera_frustum_still_casts() {
    let ctx = common::context(common::backend());
    for fit in ShadowFit::ALL {
        let s = caster_out_of_view(fit);
        // The caster lies outside the camera's frustum.
        let vp = s.camera.projection(s.aspect()) * s.camera.view();
        let caster = &s.objects[1];
        for c in gloss::math::shadow::corners(Vec3::splat(-1.0), Vec3::splat(1.0)) {
            let q = vp * caster.model.transform_point3(c).extend(1.0);
            assert!(q.y > q.w, "{fit:?}: the caster is above the view: {q}");
        }
        // Its shadow falls on the floor's centre (0.3 x 6 = 1.8 along z).
        let lit = centre(&image(&ctx, &without_shadows(&s)));
        let shadowed = centre(&image(&ctx, &s));
        let ambient = srgb8(0.05 * 0.8);
        assert!(lit > 150, "{fit:?}: the floor is lit: {lit}");
        assert!(
            shadowed.abs_diff(ambient) <= 2,
            "{fit:?}: the floor's centre is in the caster's shadow: {shadowed} (ambient about {ambient}, lit {lit})"
        );
    }
}

#[test]
fn a_caster_nearer_the_light_than_the_near_plane_still_casts() {
    // A spot light 5 units above the floor; the map's near plane is a
    // thousandth of its far plane (about 7.6 mm here). A 10 cm square 4 mm
    // below the light lies wholly in front of it and covers the cone.
    let text = r#"
        name = "near-plane"
        [camera]
        eye = [0.0, 3.0, 5.0]
        target = [0.0, 0.0, 0.0]
        [render]
        size = [320, 240]
        ambient = [0.05, 0.05, 0.05]
        [[lights]]
        type = "spot"
        position = [0.0, 5.0, 0.0]
        direction = [0.0, -1.0, 0.0]
        intensity = 3.0
        attenuation = [1.0, 0.0, 0.0]
        shadow = true
        [materials.grey]
        diffuse = [0.8, 0.8, 0.8]
        specular = [0.0, 0.0, 0.0]
        [[objects]]
        name = "floor"
        mesh = "plane"
        material = "grey"
        scale = [4.0, 1.0, 4.0]
        [[objects]]
        name = "caster"
        mesh = "plane"
        material = "grey"
        position = [0.0, 4.996, 0.0]
        scale = [0.05, 1.0, 0.05]
    "#;
    let s = Scene::parse(text, std::path::Path::new("near-plane.toml")).unwrap();
    let ctx = common::context(common::backend());
    let r = renderer(&ctx, &s);
    let view = r.shadows().views[0].clone().unwrap();
    assert!(
        view.near > 0.004,
        "the caster is nearer than the near plane {}",
        view.near
    );
    let shadowed = centre(&r.read_image());
    let lit = centre(&image(&ctx, &without_shadows(&s)));
    assert!(lit > 150, "the floor is lit: {lit}");
    let ambient = srgb8(0.05 * 0.8);
    assert!(
        shadowed.abs_diff(ambient) <= 2,
        "the caster in front of the near plane casts: {shadowed} (ambient {ambient}, lit {lit})"
    );
}
