//! The MTL reader (`geometry::load_obj_file` through an OBJ whose `mtllib`
//! names the case; tobj parses, src/geometry/mtl.rs maps) on arbitrary
//! bytes, on MTL-shaped lines with extreme numbers and odd texture
//! statements, and on a full MTL mutated and cut: it never panics, returns
//! materials whose every number is finite and in gloss's ranges, or an
//! error naming the MTL file; and it holds memory in proportion to the file.

use crate::alloc::peak_bytes;
use crate::{EXTREME_NUMBERS, run, scratch};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;

/// The most bytes the OBJ + MTL load may hold per byte of MTL, plus `PEAK_BASE`.
pub const PEAK_PER_BYTE: usize = 64;
pub const PEAK_BASE: usize = 4 << 20;

/// A full MTL file: every key gloss reads and some it drops.
const SEED: &str = "# two materials\nnewmtl red\nKa 0 0 0\nKd 0.8 0.1 0.1\nKs 0.5 0.5 0.5\nNs 64\nd 1\nillum 2\nmap_Kd -s 1 1 1 diffuse.png\nmap_Ks spec.jpg\nmap_Bump -bm 0.5 normal.png\n\nnewmtl leaf\nKd 1 1 1\nTr 0.25\nillum 1\nmap_d leaf alpha.png\nnorm tex\\\\n.png\nKe 0.1 0.1 0.1\n";

fn number() -> impl Strategy<Value = String> {
    prop_oneof![
        20 => (-2.0f32..2.0).prop_map(|f| f.to_string()),
        2 => proptest::sample::select(EXTREME_NUMBERS).prop_map(String::from),
        1 => "[0-9./eE+-]{0,6}",
    ]
}

/// One line of an MTL file.
fn line() -> impl Strategy<Value = String> {
    let key = proptest::sample::select(vec![
        "Kd", "Ks", "Ka", "Ke", "Ns", "Ni", "d", "Tr", "illum", "map_Kd", "map_Ks", "map_Bump",
        "map_bump", "bump", "norm", "map_d", "map_Ka", "map_Ns", "MAP_KD", "refl", "newmtl",
    ]);
    let texture = proptest::sample::select(vec![
        "a.png",
        "-bm",
        "-bm 2 n.png",
        "-bm nan n.png",
        "-s 1 2 3 x.png",
        "-o",
        "-clamp on",
        "..\\\\..\\\\x.png",
        "dir/with space.jpg",
        "/dev/zero",
        "\"q.png\"",
        "",
    ]);
    prop_oneof![
        10 => (key.clone(), proptest::collection::vec(number(), 0..5))
            .prop_map(|(k, n)| format!("{k} {}", n.join(" "))),
        5 => (key, texture).prop_map(|(k, t)| format!("{k} {t}")),
        2 => "newmtl [a-z ]{0,8}",
        1 => "[ -~]{0,20}",
    ]
}

/// The property, for one MTL file's bytes.
pub fn check(bytes: &[u8]) -> Result<(), TestCaseError> {
    let mtl = scratch("case.mtl");
    std::fs::write(&mtl, bytes).expect("write the case");
    let obj = scratch("case-mtl.obj");
    let faces = "mtllib case.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nusemtl red\nf 1 2 3\nusemtl leaf\nf 1 3 4\n";
    // Written once per thread: the MTL is the case.
    if std::fs::read(&obj).ok().as_deref() != Some(faces.as_bytes()) {
        std::fs::write(&obj, faces).expect("write the OBJ");
    }
    let (result, peak) = peak_bytes(|| gloss::geometry::load_obj_file(&obj));
    let allowed = PEAK_BASE + PEAK_PER_BYTE * bytes.len();
    prop_assert!(
        peak <= allowed,
        "the MTL read held {peak} bytes for a {}-byte file (at most {allowed})",
        bytes.len()
    );
    match result {
        Ok(file) => {
            crate::accepted();
            prop_assert!(!file.parts.is_empty());
            for m in &file.materials {
                let colours = m.diffuse.iter().chain(&m.specular);
                prop_assert!(colours.clone().all(|x| (0.0..=1.0).contains(x)), "{m:?}");
                prop_assert!((1.0..=4096.0).contains(&m.shininess), "{m:?}");
                prop_assert!((0.0..=1.0).contains(&m.opacity), "{m:?}");
                prop_assert!(m.normal_scale.is_finite(), "{m:?}");
            }
            for p in &file.parts {
                prop_assert!(p.material.is_none_or(|m| m < file.materials.len()));
            }
        }
        Err(e) => {
            let m = format!("{e:#}");
            prop_assert!(m.contains("case.mtl"), "the message names no MTL file: {m}");
        }
    }
    Ok(())
}

#[test]
fn the_mtl_reader_takes_any_bytes() {
    let bytes = proptest::collection::vec(any::<u8>(), 0..2000);
    run("mtl-bytes", bytes, |b| b.clone(), |b| check(&b));
}

#[test]
fn the_mtl_reader_takes_any_mtl_shaped_text() {
    let text = proptest::collection::vec(line(), 0..24)
        .prop_map(|l| format!("newmtl red\n{}", l.join("\n")));
    run(
        "mtl-shaped",
        text,
        |t| t.clone().into_bytes(),
        |t| check(t.as_bytes()),
    );
}

#[test]
fn the_mtl_reader_takes_any_mutated_or_cut_mtl() {
    let case = (
        proptest::collection::vec((any::<usize>(), 0..5u8, line()), 1..4),
        any::<usize>(),
        any::<bool>(),
    )
        .prop_map(|(edits, cut, cutting)| {
            let mut lines: Vec<String> = SEED.lines().map(String::from).collect();
            for (at, what, new) in edits {
                let k = at % (lines.len() + 1);
                match what {
                    0 => lines.insert(k, new),
                    1 if k < lines.len() => lines[k] = new,
                    2 if k < lines.len() => {
                        lines.remove(k);
                    }
                    _ => {}
                }
            }
            let text = lines.join("\n").into_bytes();
            // A file cut anywhere, mid-line and mid-character included.
            if cutting {
                text[..cut % (text.len() + 1)].to_vec()
            } else {
                text
            }
        });
    run("mtl-mutated", case, |b| b.clone(), |b| check(&b));
}
