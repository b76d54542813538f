//! Images inside a glTF file (src/geometry/gltf_images.rs) read through
//! `gl::texture::load_rgba8` as a material names them, `FILE#images[0]`:
//! the vendored Khronos BoxTextured as a .glb (its PNG in a buffer view)
//! with bytes changed, cut or repeated anywhere (JSON chunk, binary chunk,
//! the PNG's IHDR size made extreme), and as a .gltf (its PNG a data: URI)
//! with characters changed or cut. It never panics, returns an image of at
//! most MAX_TEXTURE_SIDE a side or an error naming the file, and holds no
//! more memory than the PNG reader may (`png::peak_allowed`).

use crate::alloc::peak_bytes;
use crate::png::{self, Edit};
use crate::{root, run, scratch};
use gloss::gl::texture::load_rgba8;
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

fn any_edit() -> impl Strategy<Value = Edit> {
    png::any_edit(0..=u32::MAX)
}

fn mutate(bytes: &[u8], edits: &[Edit], ihdr: Option<usize>) -> Vec<u8> {
    let mut b = bytes.to_vec();
    for e in edits {
        match *e {
            // The IHDR's width and height, its CRC made right again so the
            // decoder reads the size.
            Edit::Size(w, h) => {
                if let Some(at) = ihdr.filter(|&at| b.len() >= at + 17) {
                    png::write_size(&mut b, at, w, h);
                    let crc = png::crc32(&b[at - 4..at + 13]);
                    b[at + 13..at + 17].copy_from_slice(&crc.to_be_bytes());
                }
            }
            _ => png::edit_bytes(&mut b, e),
        }
    }
    b
}

/// The property, for one file's bytes written as `case.EXT`.
pub fn check(bytes: &[u8], ext: &str) -> Result<(), TestCaseError> {
    let file = scratch(&format!("case.{ext}"));
    std::fs::write(&file, bytes).expect("write the case");
    let texture = gloss::geometry::gltf_image_path(&file, 0);
    png::check_load(&texture, bytes.len(), &format!("case.{ext}#images[0]"))
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
