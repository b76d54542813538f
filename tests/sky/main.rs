//! Notes 03's sky: the sun-sky pass (src/techniques/sky/sun_sky.rs).

#[path = "../common/mod.rs"]
mod common;

mod assignment;
mod bunny;
mod environment_reflection;
mod image_based_lighting;
mod skybox;
mod sun_sky;
