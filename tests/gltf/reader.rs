//! What a glTF scene becomes: objects whose model matrices are the
//! specification's products of node matrices, keyframes that play the
//! file's animation, skins posed with the nodes above them, triangles from
//! strips and fans, and one warning naming what is left out.

use crate::files::{load, names, object};
use glam::{Mat4, Quat, Vec3};
use gloss::geometry::{GltfBuilder, cube, load_gltf_scene, plane, triangles, write_glb};

/// A node's JSON from its TRS.
pub fn trs(t: Vec3, r: Quat, s: Vec3, rest: &str) -> String {
    format!(
        r#"{{"translation":{:?},"rotation":{:?},"scale":{:?}{rest}}}"#,
        t.to_array(),
        r.to_array(),
        s.to_array()
    )
}

fn close(a: &Mat4, b: &Mat4) -> bool {
    a.abs_diff_eq(*b, 1e-5)
}

/// The nested cube of `images`: node "outer" (TRS) holds node "inner"
/// (a matrix) whose mesh is the unit cube; the entry is moved and scaled.
pub fn nested_cube() -> (GltfBuilder, Mat4, Mat4) {
    let mut b = GltfBuilder::default();
    let mesh = b.mesh(&cube(), None);
    let outer = Mat4::from_scale_rotation_translation(
        Vec3::splat(1.5),
        Quat::from_rotation_z(0.5),
        Vec3::new(0.5, 0.25, 0.0),
    );
    let inner = Mat4::from_scale_rotation_translation(
        Vec3::new(0.5, 0.25, 0.5),
        Quat::from_rotation_y(0.7),
        Vec3::new(0.3, 0.0, 0.0),
    );
    b.nodes.push(trs(
        Vec3::new(0.5, 0.25, 0.0),
        Quat::from_rotation_z(0.5),
        Vec3::splat(1.5),
        r#","name":"outer","children":[1]"#,
    ));
    b.nodes.push(format!(
        r#"{{"name":"inner","mesh":{mesh},"matrix":{:?}}}"#,
        inner.to_cols_array()
    ));
    // The entry: position [-0.5, 0, 0], scale 0.8 (scene_text's extra keys).
    let entry = Mat4::from_scale_rotation_translation(
        Vec3::splat(0.8),
        Quat::IDENTITY,
        Vec3::new(-0.5, 0.0, 0.0),
    );
    (b, entry * outer * inner, entry)
}

pub const NESTED_ENTRY: &str = "position = [-0.5, 0.0, 0.0]\nscale = [0.8, 0.8, 0.8]";

#[test]
fn node_matrices_compose_parent_times_child_under_the_entry() {
    let (b, expected, entry) = nested_cube();
    let s = load("nested", &b, NESTED_ENTRY).unwrap();
    assert_eq!(names(&s), ["model", "model/outer", "model/inner"]);
    let inner = &s.objects[object(&s, "model/inner")];
    assert!(
        close(&inner.model, &expected),
        "{} vs {expected}",
        inner.model
    );
    assert_eq!(inner.parent, Some(object(&s, "model/outer")));
    assert_eq!(s.objects[object(&s, "model/outer")].parent, Some(0));
    assert!(close(&s.objects[0].model, &entry));
    // The file's material is glTF's default (none named): white metal.
    let m = &s.materials[inner.material];
    assert_eq!(m.diffuse, Vec3::ZERO, "metallic 1: no diffuse");
    assert!(s.warnings().is_empty(), "{:?}", s.warnings());
}

/// BoxAnimated's shape: a box that spins about y (LINEAR rotation keys at
/// 0, 1, 2 s) under a node that rises (translation keys at 0 and 2 s).
pub fn spinning_box() -> GltfBuilder {
    let mut b = GltfBuilder::default();
    let mesh = b.mesh(&cube(), None);
    b.nodes.push(r#"{"name":"lift","children":[1]}"#.into());
    b.nodes.push(format!(r#"{{"name":"box","mesh":{mesh}}}"#));
    let times = b.floats(&[0.0, 1.0, 2.0], 1, "SCALAR");
    let keys: Vec<f32> = [0.0f32, 90.0, 180.0]
        .iter()
        .flat_map(|d| Quat::from_rotation_y(d.to_radians()).to_array())
        .collect();
    let rot = b.floats(&keys, 4, "VEC4");
    let t2 = b.floats(&[0.0, 2.0], 1, "SCALAR");
    let lift = b.floats(&[0.0, 0.0, 0.0, 0.0, 2.0, 0.0], 3, "VEC3");
    b.animations.push(format!(
        r#"{{"name":"spin","channels":[{{"sampler":0,"target":{{"node":1,"path":"rotation"}}}},{{"sampler":1,"target":{{"node":0,"path":"translation"}}}}],
        "samplers":[{{"input":{times},"output":{rot},"interpolation":"LINEAR"}},{{"input":{t2},"output":{lift},"interpolation":"LINEAR"}}]}}"#
    ));
    b
}

#[test]
fn the_spinning_box_at_one_second_shows_its_keys() {
    let mut s = load("spin", &spinning_box(), "").unwrap();
    s.set_time(1.0).unwrap();
    let (bx, lift) = (object(&s, "model/box"), object(&s, "model/lift"));
    let q = s.objects[bx].orientation.unwrap();
    assert!(
        q.abs_diff_eq(Quat::from_rotation_y(90f32.to_radians()), 1e-6),
        "{q}"
    );
    assert!((s.objects[lift].position - Vec3::new(0.0, 1.0, 0.0)).length() < 1e-6);
    let expected = Mat4::from_translation(Vec3::Y) * Mat4::from_rotation_y(90f32.to_radians());
    assert!(
        close(&s.objects[bx].model, &expected),
        "{}",
        s.objects[bx].model
    );
    // Halfway between keys 0 and 1: 45 degrees (slerp).
    s.set_time(0.5).unwrap();
    let q = s.objects[bx].orientation.unwrap();
    assert!(
        q.abs_diff_eq(Quat::from_rotation_y(45f32.to_radians()), 1e-5),
        "{q}"
    );
    // "none" keeps the rest pose; a clip the file lacks is named.
    let mut still = load("spin-none", &spinning_box(), "clip = \"none\"").unwrap();
    still.set_time(1.0).unwrap();
    assert_eq!(
        still.objects[object(&still, "model/box")].orientation,
        Some(Quat::IDENTITY)
    );
    let e = load("spin-bad", &spinning_box(), "clip = \"walk\"").unwrap_err();
    let e = format!("{e:#}");
    assert!(
        e.contains("objects[0].clip") && e.contains("\"spin\""),
        "{e}"
    );
}

#[test]
fn a_skin_keeps_the_nodes_above_it_and_stands_upright() {
    // The arm lies along one axis in its file; put the whole file under a
    // root node that turns that axis onto +y, as exporters turn z-up
    // models with a root rotation.
    let (mut arm, _) =
        gloss::geometry::load_gltf(&crate::common::root().join("scenes/assets/arm.glb")).unwrap();
    let (lo, hi) = bounds(
        &arm.mesh
            .vertices
            .iter()
            .map(|v| Vec3::from(v.position))
            .collect::<Vec<_>>(),
    );
    let long = hi - lo;
    let axis = if long.x >= long.y.max(long.z) {
        Vec3::X
    } else if long.z >= long.y {
        Vec3::Z
    } else {
        Vec3::Y
    };
    let turn = Quat::from_rotation_arc(axis, Vec3::Y);
    let root = arm.nodes.len();
    for n in arm.nodes.iter_mut().filter(|n| n.parent.is_none()) {
        n.parent = Some(root);
    }
    arm.nodes.push(gloss::geometry::skin::SkinNode {
        name: "up".into(),
        parent: None,
        translation: Vec3::ZERO,
        rotation: turn,
        scale: Vec3::ONE,
    });
    let d = crate::files::folder("upright");
    std::fs::write(d.join("arm.glb"), write_glb(&arm)).unwrap();
    let scene = load_gltf_scene(&d.join("arm.glb")).unwrap();
    let (skin, _) = scene.skin.as_ref().expect("the file has a skin");
    let posed = skin.skinned(&skin.joint_matrices(None, 0.0), false);
    let p: Vec<Vec3> = posed
        .vertices
        .iter()
        .map(|v| Vec3::from(v.position))
        .collect();
    let (lo, hi) = bounds(&p);
    let size = hi - lo;
    assert!(
        size.y > 2.0 * size.x.max(size.z),
        "the rest pose is upright: box {size}"
    );
    assert!(
        (size.y - long.max_element()).abs() < 1e-4,
        "{size} vs {long}"
    );
}

fn bounds(p: &[Vec3]) -> (Vec3, Vec3) {
    p.iter()
        .fold((Vec3::MAX, Vec3::MIN), |(a, b), &q| (a.min(q), b.max(q)))
}

#[test]
fn strips_and_fans_become_the_specifications_triangles() {
    use gltf::mesh::Mode;
    assert_eq!(
        triangles(Mode::TriangleStrip, &[0, 1, 2, 3, 4]),
        [0, 1, 2, 1, 3, 2, 2, 3, 4]
    );
    assert_eq!(
        triangles(Mode::TriangleFan, &[0, 1, 2, 3]),
        [1, 2, 0, 2, 3, 0]
    );
    assert_eq!(triangles(Mode::Triangles, &[5, 6, 7]), [5, 6, 7]);
    // A quad as a strip is drawn (two triangles), points are named.
    let mut b = GltfBuilder::default();
    let p = b.floats(
        &[
            -1.0, -1.0, 0.0, 1.0, -1.0, 0.0, -1.0, 1.0, 0.0, 1.0, 1.0, 0.0,
        ],
        3,
        "VEC3",
    );
    let mesh = b.primitives(&format!(
        r#"[{{"attributes":{{"POSITION":{p}}},"mode":5}},{{"attributes":{{"POSITION":{p}}},"mode":0}}]"#
    ));
    b.nodes.push(format!(r#"{{"mesh":{mesh}}}"#));
    let s = load("strip", &b, "").unwrap();
    let o = &s.objects[object(&s, "model/node0")];
    let data = gloss::scene::meshes::mesh_data(&o.mesh).unwrap();
    assert_eq!(data.triangle_count(), 2);
    let w = s.warnings();
    assert!(w.len() == 1 && w[0].contains("Points primitives"), "{w:?}");
}

#[test]
fn what_gloss_leaves_out_is_one_warning_per_file() {
    let mut b = GltfBuilder::default();
    let mesh = b.mesh(&plane(2.0, 2.0, 1), Some(0));
    b.materials.push(
        r#"{"name":"glow","emissiveFactor":[1,0,0],"pbrMetallicRoughness":{"baseColorFactor":[1,0.8,0.3,1],"metallicFactor":1}}"#
            .into(),
    );
    b.nodes.push(format!(r#"{{"mesh":{mesh}}}"#));
    b.nodes.push(r#"{"camera":0}"#.into());
    b.extra.push(
        r#""cameras":[{"type":"perspective","perspective":{"yfov":0.8,"znear":0.1}}]"#.into(),
    );
    b.extra
        .push(r#""extensionsUsed":["KHR_lights_punctual"]"#.into());
    let s = load("left-out", &b, "").unwrap();
    let w = s.warnings();
    assert_eq!(w.len(), 1, "{w:?}");
    for what in [
        "1 cameras",
        "KHR_lights_punctual",
        "material 'glow': the metal's tint",
    ] {
        assert!(w[0].contains(what), "{what} in {}", w[0]);
    }
    // Emission is drawn, so it is not in the warning.
    assert!(!w[0].contains("emissive"), "{}", w[0]);
    assert!(w[0].contains("model.gltf"), "{}", w[0]);
}

#[test]
fn the_materials_map_as_docs_gltf_md_says() {
    let mut b = GltfBuilder::default();
    let mesh = b.mesh(&plane(2.0, 2.0, 1), Some(0));
    b.materials.push(r#"{"name":"red","doubleSided":true,"alphaMode":"BLEND","pbrMetallicRoughness":{"baseColorFactor":[0.8,0.2,0.1,0.5],"metallicFactor":0.25,"roughnessFactor":0.6}}"#.into());
    b.nodes.push(format!(r#"{{"mesh":{mesh}}}"#));
    let s = load("material", &b, "").unwrap();
    let m = &s.materials[s.objects[1].material];
    assert!((m.diffuse - Vec3::new(0.8, 0.2, 0.1) * 0.75).length() < 1e-6);
    let mf = m.microfacet.unwrap();
    assert!((mf.alpha - 0.36).abs() < 1e-6);
    assert_eq!(m.cull, gloss::scene::Cull::None);
    assert_eq!(m.opacity, 0.5);
    assert!(m.is_transparent());
    // The entry's material overrides the file's.
    let over = load(
        "material-over",
        &b,
        "material = \"mine\"\n[materials.mine]\ndiffuse = [0.1, 0.2, 0.3]",
    )
    .unwrap();
    assert_eq!(over.materials[over.objects[1].material].name, "mine");
}

#[test]
fn the_shipped_walker_stands_upright_and_walks() {
    // Authored z-up under a turned armature, as exporters write figures.
    let s = load_gltf_scene(&crate::common::root().join("scenes/assets/walker.glb")).unwrap();
    let (skin, _) = s.skin.as_ref().unwrap();
    let clip = skin.clip("walk");
    let size = |t: f32| {
        let posed = skin.skinned(&skin.joint_matrices(clip, t), false);
        let p: Vec<Vec3> = posed
            .vertices
            .iter()
            .map(|v| Vec3::from(v.position))
            .collect();
        let (lo, hi) = bounds(&p);
        (lo, hi - lo)
    };
    for t in [0.0, 0.25, 0.5] {
        let (lo, size) = size(t);
        assert!(
            size.y > 1.8 && size.y > 2.0 * size.x.max(size.z),
            "t = {t}: {size}"
        );
        assert!(
            lo.y.abs() < 0.1,
            "t = {t}: the feet are on the ground ({lo})"
        );
    }
    // Mid-stride the legs spread along z (forward), at a quarter they pass.
    assert!(
        size(0.0).1.z > size(0.25).1.z + 0.2,
        "{} {}",
        size(0.0).1,
        size(0.25).1
    );
}

#[test]
fn samplers_and_texture_transforms_become_the_materials_texturing() {
    use gloss::scene::texturing::{TextureFilter, Wrap};
    let d = crate::files::folder("transform");
    image::RgbaImage::new(2, 2).save(d.join("t.png")).unwrap();
    let mut b = GltfBuilder::default();
    let mesh = b.mesh(&plane(2.0, 2.0, 1), Some(0));
    b.materials.push(r#"{"pbrMetallicRoughness":{"metallicFactor":0,"baseColorTexture":{"index":0,"extensions":{"KHR_texture_transform":{"offset":[0.25,0.5],"scale":[2,3]}}}}}"#.into());
    b.textures.push(r#"{"source":0,"sampler":0}"#.into());
    b.images.push(r#"{"uri":"t.png"}"#.into());
    b.samplers
        .push(r#"{"magFilter":9729,"minFilter":9985,"wrapS":33648,"wrapT":33071}"#.into());
    b.nodes.push(format!(r#"{{"mesh":{mesh}}}"#));
    b.extra.push(r#""extensionsUsed":["KHR_texture_transform"],"extensionsRequired":["KHR_texture_transform"]"#.into());
    std::fs::write(d.join("model.gltf"), b.gltf()).unwrap();
    std::fs::write(d.join("scene.toml"), crate::files::scene_text("")).unwrap();
    let s = gloss::scene::Scene::load(&d.join("scene.toml")).unwrap();
    let m = &s.materials[s.objects[1].material];
    assert_eq!(
        m.diffuse_texture.as_deref(),
        Some(d.join("t.png").as_path())
    );
    let t = m.texturing;
    assert_eq!(t.wrap, [Wrap::Mirror, Wrap::Clamp]);
    assert_eq!(t.filter, TextureFilter::BilinearMip);
    // glTF's v' = v s + o, in gloss's flipped v: v' = v s + (1 - s - o).
    assert_eq!(t.uv_scale, [2.0, 3.0]);
    assert_eq!(t.uv_offset, [0.25, 1.0 - 3.0 - 0.5]);
    // The same uv both ways: a glTF uv (0.1, 0.2) lands where gloss's does.
    let (u, v) = (0.1f32, 0.2f32);
    let gltf_v = v * 3.0 + 0.5;
    let gloss_v = (1.0 - v) * t.uv_scale[1] + t.uv_offset[1];
    assert!((gloss_v - (1.0 - gltf_v)).abs() < 1e-6);
    assert_eq!(u * 2.0 + 0.25, u * t.uv_scale[0] + t.uv_offset[0]);
    assert!(s.warnings().is_empty(), "{:?}", s.warnings());
}
