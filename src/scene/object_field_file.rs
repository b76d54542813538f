//! One `[[object_fields]]` table as the scene file holds it, with its
//! defaults (src/scene/object_fields.rs says what each key does and makes
//! the objects). Apart from object_fields.rs so that the file's tables
//! (file.rs) can hold it without importing the file that reads them.

use serde::Deserialize;

#[derive(Deserialize, Debug, Clone, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct ObjectFieldFile {
    #[serde(default = "field_name")]
    pub name: String,
    pub count: usize,
    #[serde(default)]
    pub children: usize,
    #[serde(default = "one")]
    pub seed: u64,
    pub area: [f32; 4],
    #[serde(default = "cube")]
    pub mesh: String,
    pub material: Option<String>,
    #[serde(default = "plate")]
    pub size: [f32; 2],
    #[serde(default = "cube")]
    pub child_mesh: String,
    pub child_material: Option<String>,
    #[serde(default = "house")]
    pub child_size: [f32; 2],
}

fn field_name() -> String {
    "field".into()
}
fn one() -> u64 {
    1
}
fn cube() -> String {
    "cube".into()
}
fn plate() -> [f32; 2] {
    [8.0, 0.2]
}
fn house() -> [f32; 2] {
    [1.2, 4.0]
}
