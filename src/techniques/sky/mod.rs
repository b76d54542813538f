//! Notes 03's sky: the sun-sky pass (Preetham, Shirley and Smits 1999).

pub mod sun_sky;
