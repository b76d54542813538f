//! Notes 01 §7.1, skinned meshes (src/techniques/animation/skinned_meshes.rs):
//! the GPU's skinned vertices are the CPU reference's, for linear blending
//! and dual quaternions; the image is the CPU reference's on the forward
//! and deferred paths, shadows included; the uniform array and the buffer
//! texture give the same image; the plan skins only when it must; and a
//! scene's skinning keys are checked.

use crate::common;
use gloss::image_compare::{Tolerance, compare_rgba8};
use gloss::math::skinning::uniform_joint_limit;
use gloss::renderer::{Output, render_scene};
use gloss::scene::{JointStorage, RenderPath, Scene, SkinMethod, SkinningOn};
use std::path::Path;

fn scene(f: impl FnOnce(&mut Scene)) -> Scene {
    let mut s = common::scene("skinned-arm.toml");
    s.render.size = (320, 180);
    f(&mut s);
    s
}

#[test]
fn the_gpu_skins_every_vertex_as_the_cpu_reference_does() {
    let ctx = common::context(common::backend());
    let s = scene(|_| {});
    let r = render_scene(&ctx, &s, Output::Srgb8).expect("renders");
    let draws = r.draws();
    assert_eq!(draws.skins.len(), 3);
    let mut methods = Vec::new();
    for sd in &draws.skins {
        let gpu: Vec<f32> = draws.meshes[draws.items[sd.item].mesh]
            .read_vertices()
            .concat();
        let dual = sd.skin.method == SkinMethod::DualQuaternion;
        let cpu = sd.skin.mesh.skinned(&sd.joints, dual);
        let (mut dp, mut dn) = (0f32, 0f32);
        for (i, v) in cpu.vertices.iter().enumerate() {
            let g = &gpu[8 * i..8 * i + 8];
            for k in 0..3 {
                dp = dp.max((g[k] - v.position[k]).abs());
                dn = dn.max((g[3 + k] - v.normal[k]).abs());
            }
            assert_eq!([g[6], g[7]], v.uv, "vertex {i}: the uv passes through");
        }
        // f32 sums in a different order: a few ulps of positions about 3 long.
        assert!(
            dp < 2e-5 && dn < 2e-5,
            "{:?}: position {dp}, normal {dn}",
            sd.skin.method
        );
        methods.push(sd.skin.method);
        // The pose is not the rest pose: skinning moved something.
        let moved = (cpu.vertices.iter().zip(&sd.skin.mesh.mesh.vertices)).any(|(a, b)| {
            (glam::Vec3::from(a.position) - glam::Vec3::from(b.position)).length() > 0.1
        });
        assert!(moved, "the clip moves the skin");
    }
    assert!(methods.contains(&SkinMethod::Linear) && methods.contains(&SkinMethod::DualQuaternion));
    ctx.debug
        .check(&ctx.gl, "reading the skinned vertices back")
        .unwrap();
}

/// At most a pixel in 500 one 8-bit step apart (positions differ in their
/// last bits, so an edge may cover a pixel centre on one side only), and
/// no channel more than 2 steps apart anywhere but there.
const SAME: Tolerance = Tolerance {
    threshold: 1.0 / 255.0,
    max_frac_over: 0.002,
    max_abs: None,
};

#[test]
fn gpu_skinning_draws_the_cpu_references_image_forward_deferred_and_in_shadow() {
    for path in [RenderPath::Forward, RenderPath::Deferred] {
        let gpu = common::render(&scene(|s| s.render.path = path), Output::Srgb8).image;
        let cpu = common::render(
            &scene(|s| {
                s.render.path = path;
                s.render.skinning_on = SkinningOn::Cpu;
            }),
            Output::Srgb8,
        )
        .image;
        let m = common::assert_close(&format!("skinning-gpu-vs-cpu-{path:?}"), &gpu, &cpu, &SAME);
        eprintln!("{path:?}: GPU vs CPU skinning: {m}");
    }
    // The pose shows, shadows included: the rest pose's image differs.
    let posed = common::render(&scene(|_| {}), Output::Srgb8).image;
    let rest = common::render(&scene(|s| s.set_time(0.0).unwrap()), Output::Srgb8).image;
    let d = compare_rgba8(&posed, &rest, 8.0 / 255.0).unwrap();
    assert!(d.frac_over > 0.01, "posed vs rest: {d}");
}

#[test]
fn the_uniform_array_and_the_buffer_texture_give_the_same_image() {
    let uniforms = common::render(
        &scene(|s| s.render.joint_storage = JointStorage::Uniforms),
        Output::Srgb8,
    )
    .image;
    let texture = common::render(
        &scene(|s| s.render.joint_storage = JointStorage::Texture),
        Output::Srgb8,
    )
    .image;
    assert!(uniforms == texture, "the same matrices, read two ways");
    // GL 3.3's minimum of 1024 vertex uniform components holds 60 joints.
    assert_eq!(uniform_joint_limit(1024), 60);
    assert_eq!(uniform_joint_limit(16384), 1020);
}

#[test]
fn linear_blending_collapses_the_twisted_elbow_and_dual_quaternions_keep_it() {
    let s = scene(|_| {});
    let arm = |method: SkinMethod| {
        let o = (s.objects.iter())
            .find(|o| o.skin.as_ref().is_some_and(|k| k.method == method))
            .unwrap();
        o.skin.clone().unwrap()
    };
    // The ring nearest the elbow (x = 0.975 in the bind pose; the elbow is
    // at x = 1), its weights w0 on the upper arm and w1 on the forearm.
    let skin = arm(SkinMethod::Linear);
    let ring: Vec<usize> = (0..skin.mesh.mesh.vertices.len())
        .filter(|&i| (skin.mesh.mesh.vertices[i].position[0] - 0.975).abs() < 1e-4)
        .collect();
    assert_eq!(ring.len(), 21);
    let w = skin.mesh.weights[ring[0]];
    let girth = |method: SkinMethod| {
        let skin = arm(method);
        let dual = method == SkinMethod::DualQuaternion;
        let posed = skin.mesh.skinned(&skin.joint_matrices(2.0), dual);
        (ring.iter())
            .map(|&i| {
                glam::Vec2::new(posed.vertices[i].position[1], posed.vertices[i].position[2])
                    .length()
            })
            .fold(0f32, f32::max)
    };
    // 180° of twist about the bone: the linear blend takes each point to
    // w0 p + w1 (-p) (the twist negates y and z), radius 0.18 |w0 - w1|,
    // almost nothing; dual quaternions turn the ring part way round and it
    // keeps its radius, 0.18.
    let lbs = girth(SkinMethod::Linear);
    assert!(
        (lbs - 0.18 * (w[0] - w[1]).abs()).abs() < 1e-5,
        "{lbs} {w:?}"
    );
    assert!(lbs < 0.03, "{lbs}");
    let dq = girth(SkinMethod::DualQuaternion);
    assert!((dq - 0.18).abs() < 1e-4, "{dq}");
}

#[test]
fn the_plan_skins_on_the_gpu_only_when_a_scene_has_a_skin() {
    let plan = gloss::techniques::plan(&scene(|_| {}));
    let names: Vec<&str> = plan.passes.iter().map(|p| p.name).collect();
    assert_eq!(names[..2], ["skinning", "shadow map"], "{names:?}");
    let cpu = gloss::techniques::plan(&scene(|s| s.render.skinning_on = SkinningOn::Cpu));
    assert!(cpu.passes.iter().all(|p| p.name != "skinning"));
    let none = gloss::techniques::plan(&common::scene("default.toml"));
    assert!(none.passes.iter().all(|p| p.name != "skinning"));
    // The clips' span is the scene's playable span: "wave" lasts 4 s.
    assert_eq!(scene(|_| {}).playable_span(), Some((0.0, 4.0)));
}

fn load(objects: &str) -> String {
    let text = format!(
        "name = \"t\"\n[camera]\neye = [0.0, 1.0, 5.0]\ntarget = [0.0, 0.0, 0.0]\n{objects}"
    );
    let path = common::root().join("scenes/t.toml");
    match Scene::parse(&text, Path::new(&path)) {
        Ok(_) => panic!("accepted: {objects}"),
        Err(e) => format!("{e:#}"),
    }
}

#[test]
fn the_skinning_keys_are_checked() {
    let e = load("[[objects]]\nmesh = \"cube\"\nskinning = \"linear\"\n");
    assert!(
        e.contains("objects[0]: `skinning` and `clip` are for a skinned mesh"),
        "{e}"
    );
    let e = load("[[objects]]\nmesh = \"assets/arm.glb\"\nclip = \"dance\"\n");
    assert!(
        e.contains("no animation named \"dance\"; it has \"wave\", \"twist\""),
        "{e}"
    );
    let e = load("[[objects]]\nmesh = \"assets/arm.glb\"\nskinning = \"quadratic\"\n");
    assert!(
        e.contains("quadratic") && e.contains("dual_quaternion"),
        "{e}"
    );
    let e = load("[[objects]]\nmesh = \"assets/missing.glb\"\n");
    assert!(e.contains("missing.glb"), "{e}");
    let e = load("[[objects]]\nmesh = \"assets/checker.png\"\n");
    assert!(e.contains(".obj, .glb or .gltf"), "{e}");
}

#[test]
fn a_files_weight_warnings_reach_the_scene_and_its_errors_name_the_file() {
    let dir = std::env::temp_dir().join(format!("gloss-skin-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let arm = common::root().join("scenes/assets/arm.glb");
    let (mut skin, _) = gloss::geometry::load_gltf(&arm).unwrap();
    skin.weights[5] = [0.3, 0.3, 0.0, 0.0];
    std::fs::write(dir.join("loose.glb"), gloss::geometry::write_glb(&skin)).unwrap();
    skin.weights[6] = [0.0; 4];
    std::fs::write(dir.join("zero.glb"), gloss::geometry::write_glb(&skin)).unwrap();
    let text = |mesh: &str| {
        format!(
            "name = \"t\"\n[camera]\neye = [0.0, 1.0, 5.0]\ntarget = [0.0, 0.0, 0.0]\n[[objects]]\nmesh = \"{mesh}\"\n[[objects]]\nmesh = \"{mesh}\"\n"
        )
    };
    let path = dir.join("t.toml");
    let s = Scene::parse(&text("loose.glb"), &path).unwrap();
    let w: Vec<String> = s
        .warnings()
        .into_iter()
        .filter(|w| w.contains("loose.glb"))
        .collect();
    assert_eq!(w.len(), 1, "once for the file, not per object: {w:?}");
    assert!(
        w[0].contains("vertex 5: 0.6") && w[0].contains("scaled so that they do"),
        "{w:?}"
    );
    let e = format!("{:#}", Scene::parse(&text("zero.glb"), &path).unwrap_err());
    assert!(
        e.contains("zero.glb") && e.contains("vertex 6") && e.contains("every weight is 0"),
        "{e}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn bench_measures_skinning_on_the_gpu_against_the_cpu() {
    let stdout = common::gloss(&[
        "bench",
        "--skinning",
        "900",
        "--frames",
        "1",
        "--warmup",
        "0",
        "--size",
        "96x54",
    ]);
    // One arm of 903 vertices, each way: the GPU gets 3 joint matrices (192
    // bytes), the CPU sends 32 bytes a vertex.
    let rows: Vec<&str> = (stdout.lines())
        .filter(|l| l.trim_start().starts_with("903 ") && !l.contains("vertices,"))
        .collect();
    assert_eq!(rows.len(), 4, "{stdout}");
    assert!(
        rows[0].contains(" gpu ") && rows[0].contains(" 192 "),
        "{stdout}"
    );
    assert!(
        rows[1].contains(" cpu ") && rows[1].contains(" 28896 "),
        "{stdout}"
    );
    // The GPU's vertices are the CPU reference's.
    for r in &rows {
        let error: f32 = r.split_whitespace().last().unwrap().parse().unwrap();
        assert!(error < 1e-5, "{r}");
    }
}

#[test]
fn a_skeleton_past_the_uniform_limit_reads_the_buffer_texture() {
    // The arm with 1100 joints more than it uses (each the wrist again,
    // weight 0 everywhere): past llvmpipe's 1020 uniform matrices, and
    // past GL 3.3's minimum of 60.
    let dir = std::env::temp_dir().join(format!("gloss-joints-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (mut skin, _) =
        gloss::geometry::load_gltf(&common::root().join("scenes/assets/arm.glb")).unwrap();
    for _ in 0..1100 {
        skin.joint_nodes.push(3);
        skin.inverse_bind.push(skin.inverse_bind[2]);
    }
    std::fs::write(dir.join("big.glb"), gloss::geometry::write_glb(&skin)).unwrap();
    std::fs::copy(
        common::root().join("scenes/assets/arm.glb"),
        dir.join("arm.glb"),
    )
    .unwrap();
    let scene = |mesh: &str| {
        format!(
            "name = \"t\"\n[camera]\neye = [1.5, 1.0, 5.0]\ntarget = [1.5, 0.0, 0.0]\n[render]\nsize = [96, 54]\n\
             [[lights]]\ntype = \"directional\"\ndirection = [0.0, -1.0, -1.0]\n\
             [[objects]]\nmesh = \"{mesh}\"\nclip = \"twist\"\n[animation]\ntime = 1.5\n"
        )
    };
    let run = |name: &str, mesh: &str| {
        std::fs::write(dir.join(format!("{name}.toml")), scene(mesh)).unwrap();
        let out = dir.join(format!("{name}.png"));
        let o = std::process::Command::new(env!("CARGO_BIN_EXE_gloss"))
            .args(["render", "--debug"])
            .arg(dir.join(format!("{name}.toml")))
            .arg("-o")
            .arg(&out)
            .env("MESA_GL_VERSION_OVERRIDE", "3.3")
            .env("MESA_GLSL_VERSION_OVERRIDE", "330")
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&o.stderr).into_owned();
        assert!(o.status.success(), "{stderr}");
        (image::open(&out).unwrap().to_rgba8(), stderr)
    };
    let (small, said_small) = run("small", "arm.glb");
    let (big, said_big) = run("big", "big.glb");
    assert!(
        said_small.contains("0 of 1 meshes read the texture"),
        "{said_small}"
    );
    assert!(
        said_big.contains("up to 1103 joints")
            && said_big.contains("1 of 1 meshes read the texture"),
        "{said_big}"
    );
    assert!(small == big, "the same pose, read from the texture");
    std::fs::remove_dir_all(&dir).unwrap();
}
