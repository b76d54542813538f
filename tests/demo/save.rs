//! "Save as" (src/scene/save.rs): a scene with the panel's edits, saved and
//! loaded again, is the same scene and renders the same image, also when
//! saved away from its assets and when it is a shipped (embedded) scene.

use crate::common;
use gloss::renderer::{Output, render_scene};
use gloss::scene::knobs::{self, Value};
use gloss::scene::{Accumulation, Scene};

/// A saved scene reloads to the same image: no channel off by more than one step.
pub const EXACT: gloss::image_compare::Tolerance = gloss::image_compare::Tolerance {
    threshold: 1.0 / 255.0,
    max_frac_over: 0.0,
    max_abs: Some(1.0 / 255.0),
};

#[test]
fn a_saved_scene_loads_to_the_same_image() {
    let ctx = common::context(common::backend());
    let dir = std::env::temp_dir().join("gloss-save-as");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let root = common::root();
    for (i, path) in [
        root.join("scenes/default.toml"),
        root.join("scenes/many-lights.toml"),
        "embedded:scenes/default.toml".into(),
    ]
    .iter()
    .enumerate()
    {
        let mut scene = Scene::load(path).unwrap();
        // Edits as the panel makes them.
        let r = &mut scene.render;
        (knobs::PATH.set)(r, Value::Choice(2));
        (knobs::CUTOFF.set)(r, Value::Number(0.0123));
        (knobs::AMBIENT.set)(r, Value::Color(glam::Vec3::new(0.1, 0.05, 0.02)));
        r.accumulation = Accumulation::Rgba32f;
        if scene.grid_lights.is_some() {
            scene.set_light_count(17).unwrap();
        }
        // Edited lights and materials, as the panel makes them (the panel
        // edits the lights the file lists, not a grid's).
        let fixed = scene.lights.len() - scene.grid_lights.unwrap_or(0);
        if fixed > 0 {
            let l = &mut scene.lights[0];
            l.color = glam::Vec3::new(0.3, 0.9, 0.4);
            l.intensity *= 1.7;
            l.kq = 0.0;
        }
        // A moved, turned, scaled object.
        let o = &mut scene.objects[0];
        o.position.y += 0.25;
        o.rotation.z += 10.0;
        o.scale *= 1.5;
        gloss::scene::update_models(&mut scene.objects);
        // The demo saves the view it shows: another eye, another lens.
        scene.camera.eye += glam::Vec3::new(0.5, 0.25, -0.125);
        scene.camera.near *= 2.0;
        if let gloss::scene::Projection::Perspective { fov_y_degrees } =
            &mut scene.camera.projection
        {
            *fov_y_degrees += 7.5;
        }
        if let Some(m) = scene.materials.get_mut(1) {
            m.diffuse = glam::Vec3::new(0.9, 0.2, 0.1);
            m.shininess = 77.0;
        }
        let file = dir.join(format!("saved-{i}.toml"));
        scene.save_as(&file).unwrap();
        let mut again = Scene::load(&file).unwrap();
        assert_eq!(again.render, scene.render, "{}", path.display());
        assert_eq!(again.lights.len(), scene.lights.len());
        assert_eq!(again.grid_lights, scene.grid_lights);
        assert_eq!(again.lights, scene.lights, "{}", path.display());
        assert_eq!(again.materials, scene.materials, "{}", path.display());
        assert_eq!(again.camera, scene.camera, "{}", path.display());
        assert_eq!(again.objects, scene.objects, "{}", path.display());
        for s in [&mut scene, &mut again] {
            s.render.size = (96, 54);
        }
        let a = render_scene(&ctx, &scene, Output::Srgb8)
            .unwrap()
            .read_image();
        let b = render_scene(&ctx, &again, Output::Srgb8)
            .unwrap()
            .read_image();
        assert!(
            a.as_raw() == b.as_raw(),
            "{}: the saved scene renders differently",
            path.display()
        );
    }
}

#[test]
fn save_as_keeps_opacity_depth_functions_and_the_sort_knob() {
    let dir = std::env::temp_dir().join("gloss-save-as-glass");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let mut scene = Scene::load(&common::root().join("scenes/transparency.toml")).unwrap();
    (knobs::SORT_TRANSPARENT.set)(&mut scene.render, Value::Bool(false));
    scene.render.depth_func = gloss::scene::DepthFunc::Lequal;
    let glass = scene
        .materials
        .iter()
        .position(|m| m.opacity < 1.0)
        .unwrap();
    scene.materials[glass].opacity = 0.3;
    scene.materials[glass].depth_func = Some(gloss::scene::DepthFunc::Always);
    scene.materials[1].opacity = 0.75;
    let file = dir.join("glass.toml");
    scene.save_as(&file).unwrap();
    let again = Scene::load(&file).unwrap();
    assert_eq!(again.render, scene.render);
    assert_eq!(again.materials, scene.materials);
    // And a material's depth test taken away again is gone from the file.
    let mut back = again.clone();
    back.materials[glass].depth_func = None;
    back.save_as(&file).unwrap();
    assert_eq!(Scene::load(&file).unwrap().materials, back.materials);
}

#[test]
fn meshes_materials_parents_textures_light_types_and_the_light_grid_survive_save_as() {
    // The panel's structural edits: what a fresh renderer draws from the
    // edited scene, the saved and reloaded file draws too.
    let ctx = common::context(common::backend());
    let dir = std::env::temp_dir().join("gloss-save-structure");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let root = common::root();
    let mut scene = Scene::load(&root.join("scenes/default.toml")).unwrap();
    let index = |name: &str| scene.objects.iter().position(|o| o.name == name).unwrap();
    let (ball, box_, ring) = (index("ball"), index("box"), index("ring"));
    let jade = scene
        .materials
        .iter()
        .position(|m| m.name == "jade")
        .unwrap();
    let bricks = scene.materials[scene.objects[box_].material]
        .diffuse_texture
        .clone();
    scene.objects[ball].mesh = gloss::scene::MeshSource::Torus;
    scene.objects[ball].material = jade;
    scene.objects[ring].parent = Some(box_);
    scene.objects[ring].material = 0; // gloss's default material
    gloss::scene::update_models(&mut scene.objects);
    let floor = scene
        .materials
        .iter()
        .position(|m| m.name == "floor")
        .unwrap();
    scene.materials[floor].diffuse_texture = bricks;
    scene.lights[0].kind = gloss::scene::LightKind::Spot;
    scene.lights[0].direction = glam::Vec3::new(-0.5, -1.0, -0.3).normalize();
    scene.render.size = (320, 180);
    let edited = render_scene(&ctx, &scene, Output::Srgb8)
        .unwrap()
        .read_image();
    let path = dir.join("structure.toml");
    scene.save_as(&path).unwrap();
    let mut again = Scene::load(&path).unwrap();
    again.render.size = scene.render.size;
    assert_eq!(again.objects[ball].mesh, gloss::scene::MeshSource::Torus);
    assert_eq!(again.objects[ring].parent, Some(box_));
    assert_eq!(again.objects[ring].material, 0);
    let saved = render_scene(&ctx, &again, Output::Srgb8)
        .unwrap()
        .read_image();
    common::assert_close("save-structure", &saved, &edited, &EXACT);

    // The light grid's parameters, not only its count.
    let mut many = Scene::load(&root.join("scenes/many-lights.toml")).unwrap();
    let mut grid = many.light_grid.clone().unwrap();
    grid.seed = 7;
    grid.count = 40;
    grid.intensity *= 2.0;
    grid.height = [0.5, 1.5];
    many.set_light_grid(grid.clone()).unwrap();
    let path = dir.join("grid.toml");
    many.save_as(&path).unwrap();
    let again = Scene::load(&path).unwrap();
    assert_eq!(again.light_grid, Some(grid));
    assert_eq!(again.lights, many.lights);
    // A bad grid is refused with the key named, and the scene is unchanged.
    let mut bad = again.light_grid.clone().unwrap();
    bad.attenuation = [0.0, 0.0, 0.0];
    let before = many.lights.clone();
    let e = many.set_light_grid(bad).unwrap_err().to_string();
    assert!(e.contains("light_grid.attenuation"), "{e}");
    assert_eq!(many.lights, before);
}

#[test]
fn mirror_view_and_fragment_test_edits_survive_save_as() {
    let ctx = common::context(common::backend());
    let dir = std::env::temp_dir().join("gloss-save-mirror-views");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let root = common::root();
    // A mirror's tint, reflectance and the infinite flag; a material's depth
    // and alpha tests.
    let mut scene = Scene::load(&root.join("scenes/mirror-normal-first.toml")).unwrap();
    let m = scene
        .objects
        .iter()
        .position(|o| o.mirror.is_some())
        .unwrap();
    let mirror = scene.objects[m].mirror.as_mut().unwrap();
    mirror.tint = glam::Vec3::new(0.5, 0.8, 1.0);
    mirror.reflectance = 0.6;
    mirror.covered = true;
    let mat = &mut scene.materials[1];
    mat.depth_func = Some(gloss::scene::DepthFunc::Lequal);
    mat.alpha_test = gloss::scene::AlphaTest::Gequal;
    mat.alpha_ref = 0.25;
    // Split views' rectangles.
    let mut views = Scene::load(&root.join("scenes/viewports.toml")).unwrap();
    views.views[0].viewport = [0.05, 0.55, 0.4, 0.4];
    for (name, s) in [("mirror", &scene), ("views", &views)] {
        let path = dir.join(format!("{name}.toml"));
        s.save_as(&path).unwrap();
        let mut again = Scene::load(&path).unwrap();
        again.render.size = s.render.size;
        assert_eq!(
            again.objects.iter().map(|o| &o.mirror).collect::<Vec<_>>(),
            s.objects.iter().map(|o| &o.mirror).collect::<Vec<_>>()
        );
        assert_eq!(again.materials, s.materials);
        assert_eq!(again.views, s.views);
        let a = render_scene(&ctx, s, Output::Srgb8).unwrap().read_image();
        let b = render_scene(&ctx, &again, Output::Srgb8)
            .unwrap()
            .read_image();
        common::assert_close(&format!("save-{name}"), &b, &a, &EXACT);
    }
}

#[test]
fn billboard_edits_survive_save_as() {
    let ctx = common::context(common::backend());
    let dir = std::env::temp_dir().join("gloss-save-billboards");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let mut scene = Scene::load(&common::root().join("scenes/billboards-forest.toml")).unwrap();
    let before = scene.billboards.len();
    let (mut list, mut fields) = (scene.billboard_list.clone(), scene.billboard_fields.clone());
    assert!(!fields.is_empty());
    fields[0].count += 25;
    fields[0].seed = 99;
    fields[0].height = [0.8, 1.6];
    if let Some(b) = list.first_mut() {
        b.center[0] += 0.5;
        b.kind = gloss::scene::BillboardKind::Spherical;
    }
    scene.set_billboards(list, fields).unwrap();
    assert_eq!(scene.billboards.len(), before + 25);
    // A field that breaks a rule is refused, and the scene keeps its billboards.
    let mut bad = scene.billboard_fields.clone();
    bad[0].height = [2.0, 1.0];
    let e = scene
        .set_billboards(scene.billboard_list.clone(), bad)
        .unwrap_err()
        .to_string();
    assert!(e.contains("billboard_fields[0].height"), "{e}");
    assert_eq!(scene.billboards.len(), before + 25);
    let path = dir.join("forest.toml");
    scene.save_as(&path).unwrap();
    let mut again = Scene::load(&path).unwrap();
    again.render.size = scene.render.size;
    assert_eq!(again.billboards, scene.billboards);
    let a = render_scene(&ctx, &scene, Output::Srgb8)
        .unwrap()
        .read_image();
    let b = render_scene(&ctx, &again, Output::Srgb8)
        .unwrap()
        .read_image();
    common::assert_close("save-billboards", &b, &a, &EXACT);
}

#[test]
fn shadow_knobs_survive_save_as() {
    // The panel's shadow knobs: every one off its default on a directional,
    // a point and a spot light; "casts shadows" turned on where no light
    // cast, and off where one did.
    use gloss::scene::{CubeRender, Pcf, Shadow, ShadowFit};
    let ctx = common::context(common::backend());
    let dir = std::env::temp_dir().join("gloss-save-shadows");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let knobs = |resolution, pcf, fit, cube| Shadow {
        resolution,
        bias: 0.013,
        slope_bias: 2.75,
        normal_offset: 0.4,
        cull_front: true,
        pcf,
        fit,
        cube,
        ..Shadow::default()
    };
    let mut directional = common::scene("shadows-directional.toml");
    directional.lights[0].shadow = Some(knobs(
        512,
        Pcf::Poisson,
        ShadowFit::Scene,
        CubeRender::SixPasses,
    ));
    let mut point = common::scene("shadows-point.toml");
    point.lights[0].shadow = Some(knobs(
        256,
        Pcf::Box3,
        ShadowFit::Visible,
        CubeRender::GeometryShader,
    ));
    let mut spot = common::scene("shadows-spot.toml");
    spot.lights[0].shadow = Some(knobs(
        1024,
        Pcf::None,
        ShadowFit::Scene,
        CubeRender::SixPasses,
    ));
    let mut on = common::scene("default.toml");
    assert!(on.lights.iter().all(|l| l.shadow.is_none()));
    on.lights[3].shadow = Some(knobs(
        128,
        Pcf::Box5,
        ShadowFit::Visible,
        CubeRender::SixPasses,
    ));
    let mut off = common::scene("shadows-point.toml");
    off.lights[0].shadow = None;
    for (name, scene) in [
        ("directional", &mut directional),
        ("point", &mut point),
        ("spot", &mut spot),
        ("on", &mut on),
        ("off", &mut off),
    ] {
        scene.render.size = (160, 90);
        let path = dir.join(format!("{name}.toml"));
        scene.save_as(&path).unwrap();
        let mut again = Scene::load(&path).unwrap();
        again.render.size = scene.render.size;
        assert_eq!(again.lights, scene.lights, "{name}");
        let a = render_scene(&ctx, scene, Output::Srgb8)
            .unwrap()
            .read_image();
        let b = render_scene(&ctx, &again, Output::Srgb8)
            .unwrap()
            .read_image();
        common::assert_close(&format!("save-shadows-{name}"), &b, &a, &EXACT);
    }
}

#[test]
fn texture_sampling_and_the_texture_knobs_survive_save_as() {
    use gloss::scene::texturing::{FilterOverride, Interpolation, TextureFilter, Wrap};
    let dir = std::env::temp_dir().join("gloss-save-as-sampling");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let mut scene = Scene::load(&common::root().join("scenes/texture-wrap.toml")).unwrap();
    let m = scene
        .materials
        .iter()
        .position(|m| m.name == "clamp")
        .unwrap();
    scene.materials[m].texturing.wrap = [Wrap::Mirror, Wrap::Clamp];
    scene.materials[m].texturing.filter = TextureFilter::Trilinear;
    scene.render.texture_filter = FilterOverride::Anisotropic;
    scene.render.interpolation = Interpolation::Affine;
    scene.render.mip_colors = true;
    let file = dir.join("sampling.toml");
    scene.save_as(&file).unwrap();
    let again = Scene::load(&file).unwrap();
    assert_eq!(again.materials, scene.materials);
    assert_eq!(again.render, scene.render);
    // The defaults are not written.
    let text = std::fs::read_to_string(&file).unwrap();
    assert!(!text.contains("filter = \"trilinear\""), "{text}");
}
