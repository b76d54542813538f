//! Mirrors in scene files (src/scene/mirrors.rs): a mirror must be flat and
//! have a plane; the reflected-first order draws one mirror; the recursion
//! depth fits the stencil buffer. Each is a clear error naming the key.

use crate::scene::scene_fails;
use crate::{BASE, temp_dir, write};

fn with_mirror(mesh: &str, extra: &str) -> String {
    format!(
        "{BASE}\n[[objects]]\nname = \"glass\"\nmesh = \"{mesh}\"\n{extra}mirror = {{ tint = [1.0, 1.0, 1.0] }}\n"
    )
}

#[test]
fn a_mirror_must_be_flat() {
    scene_fails(
        "mirror_sphere",
        &with_mirror("sphere", ""),
        &["objects[1].mirror", "must be flat", "Sphere"],
    );
    // An OBJ whose faces are not coplanar.
    let dir = temp_dir("mirror_bent_obj");
    write(
        &dir,
        "bent.obj",
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0.5\nf 1 2 3\nf 1 3 4\n",
    );
    let text = with_mirror("bent.obj", "");
    let path = write(&dir, "scene.toml", &text);
    let e = format!("{:#}", gloss::scene::Scene::load(&path).unwrap_err());
    assert!(
        e.contains("objects[1].mirror") && e.contains("not flat"),
        "{e}"
    );
    // A flat OBJ is a mirror.
    write(
        &dir,
        "flat.obj",
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n",
    );
    let path = write(&dir, "scene.toml", with_mirror("flat.obj", ""));
    let s = gloss::scene::Scene::load(&path).unwrap();
    let plane = s.objects[1].mirror_plane().unwrap();
    assert!(
        (plane.truncate() - glam::Vec3::Z).length() < 1e-6,
        "{plane}"
    );
}

#[test]
fn a_mirror_flattened_to_no_plane_is_refused() {
    scene_fails(
        "mirror_zero_scale",
        &with_mirror("plane", "scale = [0.0, 1.0, 1.0]\n"),
        &["objects[1]", "flattens the mirror's normal"],
    );
}

#[test]
fn bad_mirror_values_are_refused() {
    scene_fails(
        "mirror_reflectance",
        &format!("{BASE}\n[[objects]]\nmesh = \"plane\"\nmirror = {{ reflectance = 2.0 }}\n"),
        &["objects[1].mirror.reflectance", "[0, 1]"],
    );
    scene_fails(
        "mirror_unknown_key",
        &format!("{BASE}\n[[objects]]\nmesh = \"plane\"\nmirror = {{ shiny = true }}\n"),
        &["shiny"],
    );
    scene_fails(
        "mirror_missing_texture",
        &format!("{BASE}\n[[objects]]\nmesh = \"plane\"\nmirror = {{ roughness = \"no.png\" }}\n"),
        &["objects[1].mirror.roughness", "no.png"],
    );
}

#[test]
fn reflected_first_draws_one_mirror_without_recursion() {
    let two = format!(
        "{}[[objects]]\nname = \"b\"\nmesh = \"plane\"\nposition = [0.0, 1.0, 0.0]\nmirror = {{}}\n",
        with_mirror("plane", "")
    );
    let two = two.replace(
        "[render]\n",
        "[render]\nmirror_order = \"reflected_first\"\n",
    );
    scene_fails(
        "mirror_rf_two",
        &two,
        &["render.mirror_order", "normal_first"],
    );
    let deep = with_mirror("plane", "").replace(
        "[render]\n",
        "[render]\nmirror_order = \"reflected_first\"\nmirror_depth = 2\n",
    );
    scene_fails(
        "mirror_rf_deep",
        &deep,
        &["render.mirror_order", "mirror_depth = 2"],
    );
}

#[test]
fn the_recursion_depth_is_bounded() {
    for d in [0, 9] {
        let text = with_mirror("plane", "")
            .replace("[render]\n", &format!("[render]\nmirror_depth = {d}\n"));
        scene_fails(
            &format!("mirror_depth_{d}"),
            &text,
            &["render.mirror_depth", "1..=8"],
        );
    }
}
