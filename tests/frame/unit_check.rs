//! The fixed units' shared pieces: a scene key that reads a unit the GL
//! does not have is an error that names the key, the unit and what to set
//! instead, counted against GL_MAX_TEXTURE_IMAGE_UNITS (units 0 to max - 1;
//! src/frame/unit_check.rs); and a list bound, then unbound, leaves the
//! units as they were with unit 0 active (src/gl/texture_units.rs).

use crate::common;
use gloss::frame::unit_check::{self, UnitsNeeded};
use gloss::gl::texture_units::{self, OnUnit};
use glow::HasContext;
use std::path::Path;

const IBL: UnitsNeeded = UnitsNeeded {
    key: "render.ibl",
    reads: "its maps",
    units: &[21, 22, 23],
    instead: "set render.ibl = false",
};

#[test]
fn a_unit_the_gl_lacks_is_an_error_naming_the_key() {
    // 24 units are 0..=23: the last one fits; with 23, unit 23 is missing.
    unit_check::units_fit(24, &IBL).unwrap();
    unit_check::units_fit(32, &IBL).unwrap();
    let e = unit_check::units_fit(23, &IBL).unwrap_err().to_string();
    assert_eq!(
        e,
        "render.ibl reads its maps from texture units 21, 22 and 23, but this GL has 23 \
         fragment texture units (0 to 22): set render.ibl = false"
    );
    let one = UnitsNeeded {
        key: "shadow.cascades > 1",
        reads: "a directional light's cascades",
        units: &[24],
        instead: "set shadow.cascades = 1",
    };
    let e = unit_check::units_fit(16, &one).unwrap_err().to_string();
    assert!(
        e.starts_with(
            "shadow.cascades > 1 reads a directional light's cascades from texture unit 24,"
        ),
        "{e}"
    );
    assert!(e.contains("this GL has 16 fragment texture units"), "{e}");
}

#[test]
fn the_gl_check_counts_this_gls_units() {
    let ctx = common::context(common::backend());
    let gl = &ctx.gl;
    let have = unsafe { gl.get_parameter_i32(glow::MAX_TEXTURE_IMAGE_UNITS) };
    assert!(have >= 16, "GL 3.3 promises 16, this GL has {have}");
    assert_eq!(unit_check::fragment_units(gl), have);
    let file = Path::new("scenes/some.toml");
    let last = UnitsNeeded {
        units: &[have as u32 - 1],
        ..IBL
    };
    unit_check::check_units(gl, file, &last).unwrap();
    let past = UnitsNeeded {
        key: "[[area_lights]]",
        units: &[have as u32],
        ..IBL
    };
    let e = unit_check::check_units(gl, file, &past)
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("scenes/some.toml: [[area_lights]] reads"),
        "{e}"
    );
    assert!(e.contains(&format!("texture unit {have},")), "{e}");
}

#[test]
fn a_list_bound_then_unbound_leaves_unit_0_active_and_the_units_empty() {
    let ctx = common::context(common::backend());
    let gl = &ctx.gl;
    unsafe {
        let a = gl.create_texture().unwrap();
        let b = gl.create_texture().unwrap();
        let list = [
            OnUnit {
                unit: 21,
                target: glow::TEXTURE_CUBE_MAP,
                texture: a,
            },
            OnUnit {
                unit: 23,
                target: glow::TEXTURE_2D,
                texture: b,
            },
        ];
        let bound = |u: u32, binding: u32| {
            gl.active_texture(glow::TEXTURE0 + u);
            let id = gl.get_parameter_i32(binding);
            gl.active_texture(glow::TEXTURE0);
            id
        };
        texture_units::bind(gl, &list);
        assert_eq!(
            gl.get_parameter_i32(glow::ACTIVE_TEXTURE) as u32,
            glow::TEXTURE0
        );
        assert_eq!(bound(21, glow::TEXTURE_BINDING_CUBE_MAP) as u32, a.0.get());
        assert_eq!(bound(23, glow::TEXTURE_BINDING_2D) as u32, b.0.get());
        assert_eq!(bound(22, glow::TEXTURE_BINDING_2D), 0);
        texture_units::unbind(gl, &list);
        assert_eq!(
            gl.get_parameter_i32(glow::ACTIVE_TEXTURE) as u32,
            glow::TEXTURE0
        );
        assert_eq!(bound(21, glow::TEXTURE_BINDING_CUBE_MAP), 0);
        assert_eq!(bound(23, glow::TEXTURE_BINDING_2D), 0);
        gl.delete_texture(a);
        gl.delete_texture(b);
    }
    ctx.debug.check(gl, "binding on units").unwrap();
}
