//! The parsing and matching helpers the other checks rely on, on known inputs.

use crate::links::{is_external, link_targets, normalize};
use crate::outside::names_an_issue_number;
use crate::paths::{clean_path, glob, wildcard};
use crate::root;
use std::path::{Path, PathBuf};

#[test]
fn the_checks_themselves() {
    assert!(names_an_issue_number("see issue 3"));
    assert!(names_an_issue_number("Issues #12 and 13"));
    assert!(!names_an_issue_number("a known issue with 3 lights"));
    assert!(!names_an_issue_number("tissue 3"));
    assert_eq!(
        link_targets("[a](docs/x.md) and ![b](<y z.png>) `[c](no.md)`"),
        ["docs/x.md", "y z.png"]
    );
    assert_eq!(
        link_targets("[ref]: ../tests/golden/plane.png"),
        ["../tests/golden/plane.png"]
    );
    assert_eq!(
        clean_path("`src/math/mod.rs::normal_matrix`".trim_matches('`')),
        "src/math/mod.rs"
    );
    assert_eq!(clean_path("tests/golden/<scene>.png"), "tests/golden/*.png");
    assert_eq!(clean_path("src/gl/mesh.rs:159"), "src/gl/mesh.rs");
    assert!(wildcard("forward_flat.*", "forward_flat.geom"));
    assert!(!wildcard("forward_flat.*", "forward.frag"));
    assert_eq!(normalize(Path::new("docs"), "../../x"), None);
    assert_eq!(
        normalize(Path::new("docs/deferred"), "../../tests/golden/plane.png"),
        Some(PathBuf::from("tests/golden/plane.png"))
    );
    assert!(is_external("https://www.khronos.org/opengl/wiki"));
    assert!(!is_external("lighting/forward.md"));
    assert!(glob(&root(), "tests/golden/*.png"));
    assert!(glob(&root(), "scenes/*.toml"));
}
