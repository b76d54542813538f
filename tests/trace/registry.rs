//! docs/README.md's map of the notes against the registry is generated
//! (src/trace/coverage.rs): the page's block equals what the registry and
//! the notes' sections give, every file the map names exists, and the
//! registry's citations are read as the techniques write them.

use crate::common;
use crate::docs_listings::first_difference;
use gloss::techniques::ALL;
use gloss::trace::coverage::{beyond_the_notes, block, citations, cited, numbers, problems, range};
use gloss::trace::notes_sections::SECTIONS;

#[test]
fn the_readme_map_of_the_notes_is_the_registrys() {
    let bless = std::env::var("GLOSS_BLESS").as_deref() == Ok("1");
    let path = common::root().join("docs/README.md");
    let text = std::fs::read_to_string(&path).unwrap();
    let (start, end) =
        range(&text).expect("docs/README.md has no <!-- gloss registry --> ... block");
    let wrong = problems(ALL, &common::root());
    assert!(
        wrong.is_empty(),
        "src/trace/notes_sections.rs:\n  {}",
        wrong.join("\n  ")
    );
    let made = block(ALL);
    if text[start..end] != made {
        if bless {
            let mut fresh = text.clone();
            fresh.replace_range(start..end, &made);
            std::fs::write(&path, fresh).unwrap();
        } else {
            panic!(
                "docs/README.md's map of the notes is not the registry's \
                 (GLOSS_BLESS=1 cargo test --release --test trace rewrites it); {}",
                first_difference(&text[start..end], &made)
            );
        }
    }
}

#[test]
fn citations_are_read_as_the_techniques_write_them() {
    let pair = |a: &str, b: &str| (a.to_string(), b.to_string());
    assert_eq!(
        citations("notes 01 §4.5, Blending; §6.1, Handling Transparent Objects"),
        [
            pair("01", "§4.5, Blending"),
            pair("01", "§6.1, Handling Transparent Objects")
        ]
    );
    assert_eq!(numbers("§8.2-8.3"), ["§8.2", "§8.3"]);
    assert_eq!(numbers("§8.6.2 step 1"), ["§8.6.2"]);
    assert_eq!(numbers("§9, Post processing"), ["§9"]);
    let titles = |name: &str| -> Vec<String> {
        let t = ALL.iter().find(|t| t.name == name).unwrap();
        cited(t)
            .into_iter()
            .map(|i| format!("{} {}", SECTIONS[i].notes, SECTIONS[i].title))
            .collect()
    };
    // Two files' sections, one by number and one by title.
    let lv = titles("light_volumes");
    assert!(lv.iter().any(|s| s.starts_with("01 §8.6.1")), "{lv:?}");
    assert!(
        lv.iter().any(|s| s.starts_with("04 Light volumes")),
        "{lv:?}"
    );
    assert!(!lv.iter().any(|s| s.starts_with("01 §8.6 ")), "{lv:?}");
    // A range of numbers, and a range of headings ("A to B").
    let fw = titles("forward");
    assert!(fw.iter().any(|s| s.starts_with("01 §8.2")), "{fw:?}");
    assert!(fw.iter().any(|s| s.starts_with("01 §8.3")), "{fw:?}");
    let mirror = titles("mirror");
    let fives = SECTIONS.iter().filter(|s| s.notes == "05").count();
    assert_eq!(mirror.len(), 7, "{mirror:?} of {fives}");
    assert!(mirror[0].starts_with("05 Planar Reflections"), "{mirror:?}");
    assert!(
        mirror[6].starts_with("05 Normal First Addendum"),
        "{mirror:?}"
    );
    // A clause without "notes NN" stays in the notes of the one before it.
    let tr = titles("transparency");
    assert!(
        tr.iter().any(|s| s.starts_with("01 §6.1 Handling")),
        "{tr:?}"
    );
    // Beyond the notes cites nothing, whatever notes it names.
    let far = ALL.iter().find(|t| t.name == "far_field").unwrap();
    assert!(beyond_the_notes(far) && cited(far).is_empty());
}

/// The map lists every registered technique: a technique cites a section,
/// or it is listed as beyond the notes.
#[test]
fn every_registered_technique_is_in_the_map() {
    let made = block(ALL);
    for t in ALL {
        assert!(
            made.contains(&format!("[`{}`](", t.name)),
            "{} is not in the generated map",
            t.name
        );
    }
}
