//! `geometry::load_obj` (tobj inside) on arbitrary bytes, on OBJ-shaped
//! lines with extreme numbers and indices, and on the shipped OBJs mutated:
//! it never panics, returns a mesh whose indices are in range and whose
//! numbers are finite, or an error naming the file; and it holds memory in
//! proportion to the file (`PEAK_PER_BYTE`).

use crate::alloc::peak_bytes;
use crate::{EXTREME_NUMBERS, root, run, scratch};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use std::sync::OnceLock;

/// The most bytes load_obj may hold at once per byte of file, plus
/// `PEAK_BASE`: vertices are split by position/uv/normal and triangulated,
/// every one a 48-byte vertex and its indices.
pub const PEAK_PER_BYTE: usize = 400;
pub const PEAK_BASE: usize = 4 << 20;

/// The small shipped OBJs, whole, and a quad with uvs and normals.
fn seeds() -> &'static [String] {
    static SEEDS: OnceLock<Vec<String>> = OnceLock::new();
    SEEDS.get_or_init(|| {
        let mut v: Vec<String> = std::fs::read_dir(root().join("scenes/assets"))
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|e| e == "obj"))
            .map(|p| std::fs::read_to_string(&p).unwrap())
            .filter(|text| text.len() < 32 << 10)
            .collect();
        v.sort();
        v.push("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 1\nvn 0 0 1\nf 1/1/1 2/2/1 3/1/1 4/2/1\n".into());
        v
    })
}

fn number() -> impl Strategy<Value = String> {
    prop_oneof![
        300 => (-10.0f32..10.0).prop_map(|f| f.to_string()),
        1 => proptest::sample::select(EXTREME_NUMBERS).prop_map(String::from),
        1 => any::<f32>().prop_map(|f| f.to_string()),
        1 => "[0-9./eE+-]{0,6}",
    ]
}

/// A face's corners, all in one of the four forms (`v`, `v/vt`, `v/vt/vn`,
/// `v//vn`), the indices mostly in range.
fn face() -> impl Strategy<Value = String> {
    let i = || {
        prop_oneof![
            40 => (1i64..9).prop_map(|n| n.to_string()),
            4 => (-8i64..0).prop_map(|n| n.to_string()),
            1 => proptest::sample::select(EXTREME_NUMBERS).prop_map(String::from)
        ]
    };
    let corner = (i(), i(), i());
    (0..4u8, proptest::collection::vec(corner, 3..6)).prop_map(|(form, corners)| {
        let c: Vec<String> = corners
            .into_iter()
            .map(|(v, t, n)| match form {
                0 => v,
                1 => format!("{v}/{}", t.replace(|c: char| c.is_ascii_digit(), "1")),
                2 => format!("{v}/1/{n}").replace(&format!("/{n}"), "/1"),
                _ => format!("{v}//1"),
            })
            .collect();
        format!("f {}", c.join(" "))
    })
}

/// One line of an OBJ file, of any kind tobj reads.
fn line() -> impl Strategy<Value = String> {
    prop_oneof![
        40 => proptest::collection::vec(number(), 3..4).prop_map(|n| format!("v {}", n.join(" "))),
        1 => proptest::collection::vec(number(), 0..6).prop_map(|n| format!("v {}", n.join(" "))),
        10 => proptest::collection::vec(number(), 2..3).prop_map(|n| format!("vt {}", n.join(" "))),
        10 => proptest::collection::vec(number(), 3..4).prop_map(|n| format!("vn {}", n.join(" "))),
        30 => face(),
        1 => proptest::collection::vec("-?[0-9/]{1,6}", 0..9).prop_map(|n| format!("f {}", n.join(" "))),
        3 => proptest::sample::select(vec![
            "o a", "g", "g a b", "s off", "s 1", "mtllib none.mtl", "usemtl x", "l 1 2", "p 1", "#", "", "\\",
        ])
        .prop_map(String::from),
    ]
}

/// The property, for one file's bytes.
pub fn check(bytes: &[u8]) -> Result<(), TestCaseError> {
    let path = scratch("case.obj");
    std::fs::write(&path, bytes).expect("write the case");
    let (result, peak) = peak_bytes(|| gloss::geometry::load_obj(&path));
    let allowed = PEAK_BASE + PEAK_PER_BYTE * bytes.len();
    prop_assert!(
        peak <= allowed,
        "load_obj held {peak} bytes for a {}-byte file (at most {allowed})",
        bytes.len()
    );
    match result {
        Ok(mesh) => {
            crate::accepted();
            let n = mesh.vertices.len();
            prop_assert!(mesh.indices.len() % 3 == 0 && mesh.indices.len() >= 3);
            prop_assert!(mesh.indices.iter().all(|&i| (i as usize) < n));
            for v in &mesh.vertices {
                let all = v
                    .position
                    .iter()
                    .chain(&v.normal)
                    .chain(&v.uv)
                    .chain(&v.tangent);
                prop_assert!(all.clone().all(|x| x.is_finite()), "{v:?}");
            }
        }
        Err(e) => {
            let m = format!("{e:#}");
            prop_assert!(m.contains("case.obj"), "the message names no file: {m}");
        }
    }
    Ok(())
}

#[test]
fn load_obj_takes_any_bytes() {
    let bytes = proptest::collection::vec(any::<u8>(), 0..3000);
    run("obj-bytes", bytes, |b| b.clone(), |b| check(&b));
}

#[test]
fn load_obj_takes_any_obj_shaped_text() {
    // Eight vertices first, so that most faces have something to index.
    let head = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\nvt 0 0\nvn 0 0 1\n";
    let text = proptest::collection::vec(line(), 0..30)
        .prop_map(move |l| format!("{head}{}", l.join("\n")));
    run(
        "obj-shaped",
        text,
        |t| t.clone().into_bytes(),
        |t| check(t.as_bytes()),
    );
}

#[test]
fn load_obj_takes_any_mutated_obj() {
    let n = seeds().len();
    let case = (
        0..n,
        proptest::collection::vec((any::<usize>(), 0..7u8, line()), 1..4),
    )
        .prop_map(|(i, edits)| {
            let mut lines: Vec<String> = seeds()[i].lines().map(String::from).collect();
            for (at, what, new) in edits {
                let k = at % (lines.len() + 1);
                match what {
                    0 => lines.insert(k, new),
                    1 if k < lines.len() => lines[k] = new,
                    2 if k < lines.len() => {
                        lines.remove(k);
                    }
                    3 => lines.truncate(k),
                    _ => {}
                }
            }
            lines.join("\n")
        });
    run(
        "obj-mutated",
        case,
        |t| t.clone().into_bytes(),
        |t| check(t.as_bytes()),
    );
}
