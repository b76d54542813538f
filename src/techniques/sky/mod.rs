//! Notes 03's sky: the sun-sky pass (Preetham, Shirley and Smits 1999), the
//! skybox cube map (the sky rendered into one, or six images), the skybox
//! pass drawn last at z = w (or first, for comparison) and the skybox mirror
//! reflection of the deferred paths; and, beyond the notes, image-based
//! lighting from that cube map (Karis 2013, image_based_lighting.rs).

pub mod image_based_lighting;
pub mod sky_cube_map;
pub mod sky_first;
pub mod skybox;
pub mod skybox_reflection;
pub mod sun_sky;
