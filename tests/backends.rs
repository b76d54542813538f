//! The same scene through EGL and through OSMesa gives the same image
//! (tolerance: at most 0.1% of pixels differ by more than 2/255; in practice
//! they are identical, since both are Mesa's llvmpipe).

mod common;

use gloss::gl::Backend;
use gloss::image_compare::Tolerance;
use gloss::renderer::Output;

#[test]
fn egl_and_osmesa_render_the_same_images() {
    let tol = Tolerance {
        threshold: 2.0 / 255.0,
        max_frac_over: 0.001,
        max_abs: None,
    };
    let egl = common::context(Backend::Egl);
    let osmesa = common::context(Backend::Osmesa);
    assert_eq!(egl.info.backend, Backend::Egl);
    assert_eq!(osmesa.info.backend, Backend::Osmesa);
    assert_eq!(
        (egl.info.major, egl.info.minor),
        (osmesa.info.major, osmesa.info.minor)
    );
    for name in ["default.toml", "mixed-lights.toml"] {
        let mut scene = common::scene(name);
        scene.render.size = (480, 270);
        let a = common::render_with(&egl, &scene, Output::Srgb8);
        let b = common::render_with(&osmesa, &scene, Output::Srgb8);
        let m = common::assert_close(
            &format!("osmesa-vs-egl-{}", scene.name),
            &b.image,
            &a.image,
            &tol,
        );
        eprintln!("{name}: OSMesa vs EGL: {m}");
    }
}

#[test]
fn info_prints_version_renderer_and_backend() {
    for backend in ["egl", "osmesa"] {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_gloss"))
            .args(["info", "--backend", backend])
            .output()
            .unwrap();
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        for key in [
            "GL_VERSION",
            "GL_RENDERER",
            "GLSL",
            "core",
            &format!("backend        {backend}"),
        ] {
            assert!(
                text.contains(key),
                "gloss info --backend {backend} lacks {key}:\n{text}"
            );
        }
    }
}

#[test]
fn no_arguments_without_a_display_renders_the_default_scene() {
    let dir = std::env::temp_dir().join("gloss-no-args");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_gloss"))
        .current_dir(&dir)
        .env_remove("DISPLAY")
        .env_remove("WAYLAND_DISPLAY")
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let png = dir.join("gloss-default.png");
    assert!(
        stdout.contains(&png.display().to_string()),
        "says where: {stdout}"
    );
    let img = image::open(&png).unwrap();
    assert_eq!((img.width(), img.height()), (1280, 720));
}

#[test]
fn shipped_scenes_run_from_any_directory() {
    // The binary carries the scenes and their meshes and textures: from an
    // empty directory, `gloss scenes` lists them all and any of them renders
    // by name, read from the embedded copy.
    let dir = std::env::temp_dir().join("gloss-any-directory");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let gloss = |args: &[&str]| {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_gloss"))
            .args(args)
            .current_dir(&dir)
            .env_remove("DISPLAY")
            .env_remove("WAYLAND_DISPLAY")
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "gloss {args:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        String::from_utf8_lossy(&out.stdout).into_owned()
    };
    let listed = gloss(&["scenes"]);
    let mut shipped: Vec<String> = std::fs::read_dir(common::root().join("scenes"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".toml"))
        .map(|n| format!("scenes/{n}"))
        .collect();
    shipped.sort();
    assert_eq!(listed.lines().collect::<Vec<_>>(), shipped);
    // default.toml uses an OBJ mesh and a PNG texture from scenes/assets/.
    let out = gloss(&["render", "default", "-o", "default.png", "--size", "64x36"]);
    assert!(out.contains("wrote default.png"), "{out}");
    let img = image::open(dir.join("default.png")).unwrap();
    assert_eq!((img.width(), img.height()), (64, 36));
    let plan = gloss(&["plan", "scenes/many-lights.toml"]);
    assert!(plan.contains("256 spheres"), "{plan}");
    let out = gloss(&[]);
    assert!(out.contains("embedded:scenes/default.toml"), "{out}");
}
