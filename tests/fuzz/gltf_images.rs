//! Images inside a glTF file (src/geometry/gltf_images.rs) read through
//! `gl::texture::load_rgba8` as a material names them, `FILE#images[0]`:
//! the vendored Khronos BoxTextured as a .glb (its PNG in a buffer view)
//! with bytes changed, cut or repeated anywhere (JSON chunk, binary chunk,
//! the PNG's IHDR size made extreme), and as a .gltf (its PNG a data: URI)
//! with characters changed or cut. It never panics, returns an image of at
//! most MAX_TEXTURE_SIDE a side or an error naming the file, and holds no
//! more memory than the PNG reader may (`png::peak_allowed`).

use crate::alloc::peak_bytes;
use crate::{root, run, scratch};
use gloss::gl::texture::{MAX_TEXTURE_SIDE, load_rgba8};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use std::sync::OnceLock;

fn sample(file: &str) -> &'static [u8] {
    static GLB: OnceLock<Vec<u8>> = OnceLock::new();
    static GLTF: OnceLock<Vec<u8>> = OnceLock::new();
    let cell = if file.ends_with(".glb") { &GLB } else { &GLTF };
    cell.get_or_init(|| std::fs::read(root().join("scenes/assets/khronos").join(file)).unwrap())
}

/// Where the embedded PNG's IHDR width starts in the .glb (its signature
/// is followed by the IHDR chunk: width at +16).
fn ihdr_width() -> usize {
    let glb = sample("BoxTextured.glb");
    let sig = b"\x89PNG\r\n\x1a\n";
    glb.windows(8).position(|w| w == sig).unwrap() + 16
}

#[derive(Clone, Debug)]
enum Edit {
    Byte(usize, u8),
    Cut(usize),
    Repeat(usize, usize),
    Size(u32, u32),
}

fn any_edit() -> impl Strategy<Value = Edit> {
    prop_oneof![
        4 => (any::<usize>(), any::<u8>()).prop_map(|(i, b)| Edit::Byte(i, b)),
        1 => any::<usize>().prop_map(Edit::Cut),
        1 => (any::<usize>(), 1..200usize).prop_map(|(i, n)| Edit::Repeat(i, n)),
        2 => (0..=u32::MAX, 0..=u32::MAX).prop_map(|(w, h)| Edit::Size(w, h)),
    ]
}

fn mutate(bytes: &[u8], edits: &[Edit], ihdr: Option<usize>) -> Vec<u8> {
    let mut b = bytes.to_vec();
    for e in edits {
        match *e {
            Edit::Byte(i, v) if !b.is_empty() => {
                let i = i % b.len();
                b[i] = v;
            }
            Edit::Cut(i) => b.truncate(i % (b.len() + 1)),
            Edit::Repeat(i, n) if !b.is_empty() => {
                let i = i % b.len();
                let piece = b[i..(i + n).min(b.len())].to_vec();
                b.splice(i..i, piece);
            }
            // The IHDR's width and height, its CRC made right again so the
            // decoder reads the size.
            Edit::Size(w, h) => {
                if let Some(at) = ihdr.filter(|&at| b.len() >= at + 17) {
                    b[at..at + 4].copy_from_slice(&w.to_be_bytes());
                    b[at + 4..at + 8].copy_from_slice(&h.to_be_bytes());
                    let crc = crate::png::crc32(&b[at - 4..at + 13]);
                    b[at + 13..at + 17].copy_from_slice(&crc.to_be_bytes());
                }
            }
            _ => {}
        }
    }
    b
}

/// The property, for one file's bytes written as `case.EXT`.
pub fn check(bytes: &[u8], ext: &str) -> Result<(), TestCaseError> {
    let file = scratch(&format!("case.{ext}"));
    std::fs::write(&file, bytes).expect("write the case");
    let texture = gloss::geometry::gltf_image_path(&file, 0);
    let (result, peak) = peak_bytes(|| load_rgba8(&texture));
    let allowed = crate::png::peak_allowed(bytes.len());
    prop_assert!(
        peak <= allowed,
        "load_rgba8 held {peak} bytes (at most {allowed})"
    );
    match result {
        Ok(img) => {
            crate::accepted();
            let (w, h) = img.dimensions();
            prop_assert!(
                (1..=MAX_TEXTURE_SIDE).contains(&w) && (1..=MAX_TEXTURE_SIDE).contains(&h)
            );
        }
        Err(e) => {
            let m = format!("{e:#}");
            prop_assert!(
                m.contains(&format!("case.{ext}#images[0]")),
                "the message names no file and image: {m}"
            );
        }
    }
    Ok(())
}

#[test]
fn an_image_in_a_mutated_glb_is_read_or_refused_by_name() {
    let case = proptest::collection::vec(any_edit(), 1..5)
        .prop_map(|edits| mutate(sample("BoxTextured.glb"), &edits, Some(ihdr_width())));
    run("gltf-image-glb", case, |b| b.clone(), |b| check(&b, "glb"));
}

#[test]
fn an_image_in_a_mutated_data_uri_is_read_or_refused_by_name() {
    let case = proptest::collection::vec(any_edit(), 1..5)
        .prop_map(|edits| mutate(sample("BoxTextured.gltf"), &edits, None));
    run(
        "gltf-image-data-uri",
        case,
        |b| b.clone(),
        |b| check(&b, "gltf"),
    );
}

#[test]
fn the_unchanged_samples_decode_and_named_faults_are_refused() {
    for ext in ["glb", "gltf"] {
        let file = scratch(&format!("whole.{ext}"));
        std::fs::write(&file, sample(&format!("BoxTextured.{ext}"))).unwrap();
        let img = load_rgba8(&gloss::geometry::gltf_image_path(&file, 0)).unwrap();
        assert_eq!(img.dimensions(), (256, 256));
        // An image the file does not have.
        let e = format!(
            "{:#}",
            load_rgba8(&gloss::geometry::gltf_image_path(&file, 3)).unwrap_err()
        );
        assert!(
            e.contains("images[3]") && e.contains("the file has 1 images"),
            "{e}"
        );
    }
    // A PNG claiming 100000 x 100000 pixels: refused before decoding.
    let big = mutate(
        sample("BoxTextured.glb"),
        &[Edit::Size(100_000, 100_000)],
        Some(ihdr_width()),
    );
    let file = scratch("big.glb");
    std::fs::write(&file, &big).unwrap();
    let (r, peak) = peak_bytes(|| load_rgba8(&gloss::geometry::gltf_image_path(&file, 0)));
    let e = format!("{:#}", r.unwrap_err());
    assert!(
        e.contains("100000x100000") && e.contains("big.glb#images[0]"),
        "{e}"
    );
    assert!(peak < 64 << 20, "{peak} bytes held to refuse it");
    // The binary chunk cut inside the PNG: its view runs past the buffer.
    let cut = &sample("BoxTextured.glb")[..ihdr_width() + 100];
    let file = scratch("cut.glb");
    std::fs::write(&file, cut).unwrap();
    let e = format!(
        "{:#}",
        load_rgba8(&gloss::geometry::gltf_image_path(&file, 0)).unwrap_err()
    );
    assert!(e.contains("cut.glb#images[0]"), "{e}");
}
