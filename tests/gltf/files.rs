//! Writing a built glTF file and a scene that names it into a fresh folder.

use gloss::geometry::GltfBuilder;
use gloss::scene::Scene;
use std::path::PathBuf;

/// A fresh folder under target/ for one test.
pub fn folder(name: &str) -> PathBuf {
    let d = dir(name);
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Folder `name` as `folder` made it, kept.
pub fn dir(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("target/test-output/gltf")
        .join(name)
}

/// The scene text around one glTF entry: a camera looking down -z from
/// z = 5 at the origin (orthographic, half height 2, 200 x 200 pixels), one
/// white directional light from the camera, and `entry` as the object's
/// extra keys.
pub fn scene_text(entry: &str) -> String {
    format!(
        r#"
[camera]
eye = [0.0, 0.0, 5.0]
target = [0.0, 0.0, 0.0]
projection = "orthographic"
half_height = 2.0
near = 0.1
far = 20.0

[render]
size = [200, 200]
ambient = [0.0, 0.0, 0.0]
background = [0.0, 0.0, 0.0]

[[lights]]
type = "directional"
direction = [0.0, 0.0, -1.0]
color = [1.0, 1.0, 1.0]
intensity = 1.0

[[objects]]
name = "model"
mesh = "model.gltf"
{entry}
"#
    )
}

/// Write `b` as model.gltf and the scene beside it into folder `name`;
/// load the scene.
pub fn load(name: &str, b: &GltfBuilder, entry: &str) -> anyhow::Result<Scene> {
    let d = folder(name);
    std::fs::write(d.join("model.gltf"), b.gltf()).unwrap();
    std::fs::write(d.join("scene.toml"), scene_text(entry)).unwrap();
    Scene::load(&d.join("scene.toml"))
}

/// The object named `name`, by index.
pub fn object(s: &Scene, name: &str) -> usize {
    (s.objects.iter().position(|o| o.name == name))
        .unwrap_or_else(|| panic!("no object {name}: {:?}", names(s)))
}

pub fn names(s: &Scene) -> Vec<&str> {
    s.objects.iter().map(|o| o.name.as_str()).collect()
}
