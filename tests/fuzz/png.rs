//! `gl::texture::load_rgba8` (the `image` crate inside) on mutated PNGs:
//! bytes flipped, cut, repeated; the IHDR's width and height made extreme;
//! every chunk's CRC fixed up afterwards or not (fixed, the decoder reads
//! past its checksums into the image data). It never panics, returns an
//! image of at most MAX_TEXTURE_SIDE a side or an error naming the file,
//! and holds no more memory than a decoded image of the largest size it
//! accepts, a few times over (`peak_allowed`).

use crate::alloc::peak_bytes;
use crate::{root, run, scratch};
use gloss::gl::texture::{MAX_TEXTURE_SIDE, load_rgba8};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use std::sync::OnceLock;

/// The most bytes load_rgba8 may hold at once: the decoded image, its RGBA8
/// copy and the flipped copy (4 bytes a pixel each, at the largest size the
/// header check lets through), and the file.
pub fn peak_allowed(file_bytes: usize) -> usize {
    let side = MAX_TEXTURE_SIDE as usize;
    4 * 4 * side * side + 4 * file_bytes + (8 << 20)
}

/// Small PNGs of every colour type, and the shipped small ones.
fn seeds() -> &'static [Vec<u8>] {
    static SEEDS: OnceLock<Vec<Vec<u8>>> = OnceLock::new();
    SEEDS.get_or_init(|| {
        let encode = |img: image::DynamicImage| {
            let mut bytes = Vec::new();
            img.write_to(
                &mut std::io::Cursor::new(&mut bytes),
                image::ImageFormat::Png,
            )
            .unwrap();
            bytes
        };
        let rgba = image::RgbaImage::from_fn(5, 3, |x, y| {
            image::Rgba([x as u8 * 40, y as u8 * 80, 7, 200])
        });
        let mut v = vec![
            encode(image::DynamicImage::ImageRgba8(rgba.clone())),
            encode(
                image::DynamicImage::ImageRgba8(rgba.clone())
                    .to_luma8()
                    .into(),
            ),
            encode(
                image::DynamicImage::ImageRgba8(rgba.clone())
                    .to_rgb16()
                    .into(),
            ),
            encode(
                image::DynamicImage::ImageRgba8(rgba)
                    .to_luma_alpha8()
                    .into(),
            ),
        ];
        for name in ["checker.png", "grass.png", "tree.png"] {
            v.push(std::fs::read(root().join("scenes/assets").join(name)).unwrap());
        }
        v
    })
}

/// CRC-32 as PNG computes it.
pub fn crc32(data: &[u8]) -> u32 {
    let mut crc = 0xFFFF_FFFFu32;
    for &b in data {
        crc ^= u32::from(b);
        for _ in 0..8 {
            crc = if crc & 1 != 0 {
                (crc >> 1) ^ 0xEDB8_8320
            } else {
                crc >> 1
            };
        }
    }
    !crc
}

/// Recompute the CRC of every whole chunk after the 8-byte signature.
fn fix_crcs(png: &mut [u8]) {
    let mut at = 8;
    while at + 12 <= png.len() {
        let len = u32::from_be_bytes(png[at..at + 4].try_into().unwrap()) as usize;
        let Some(end) = (at + 8).checked_add(len).filter(|e| e + 4 <= png.len()) else {
            return;
        };
        let crc = crc32(&png[at + 4..end]);
        png[end..end + 4].copy_from_slice(&crc.to_be_bytes());
        at = end + 4;
    }
}

const SIDES: [u32; 8] = [0, 1, 2, 8192, 8193, 65535, 0x7fff_ffff, 0xffff_ffff];

/// One change to a file's bytes (shared with gltf_images.rs, whose PNG
/// sits inside a .glb).
#[derive(Clone, Debug)]
pub enum Edit {
    Byte(usize, u8),
    Cut(usize),
    Repeat(usize, usize),
    /// The IHDR's width and height.
    Size(u32, u32),
}

/// Edits, with IHDR sizes drawn from `side`.
pub fn any_edit(side: impl Strategy<Value = u32> + Clone) -> impl Strategy<Value = Edit> {
    prop_oneof![
        4 => (any::<usize>(), any::<u8>()).prop_map(|(i, b)| Edit::Byte(i, b)),
        1 => any::<usize>().prop_map(Edit::Cut),
        1 => (any::<usize>(), 1..200usize).prop_map(|(i, n)| Edit::Repeat(i, n)),
        2 => (side.clone(), side).prop_map(|(w, h)| Edit::Size(w, h)),
    ]
}

/// Apply a byte edit (a byte changed, the file cut, a piece repeated);
/// `Edit::Size` is the caller's, who knows where the IHDR is.
pub fn edit_bytes(b: &mut Vec<u8>, e: &Edit) {
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
        _ => {}
    }
}

/// Write an IHDR's width and height, the width at `at`.
pub fn write_size(b: &mut [u8], at: usize, w: u32, h: u32) {
    b[at..at + 4].copy_from_slice(&w.to_be_bytes());
    b[at + 4..at + 8].copy_from_slice(&h.to_be_bytes());
}

fn mutate(png: &[u8], edits: &[Edit], fix: bool) -> Vec<u8> {
    let mut b = png.to_vec();
    for e in edits {
        match *e {
            // IHDR's width and height: bytes 16..24.
            Edit::Size(w, h) if b.len() >= 24 => write_size(&mut b, 16, w, h),
            _ => edit_bytes(&mut b, e),
        }
    }
    if fix {
        fix_crcs(&mut b);
    }
    b
}

/// The property, for one file's bytes.
pub fn check(bytes: &[u8]) -> Result<(), TestCaseError> {
    let path = scratch("case.png");
    std::fs::write(&path, bytes).expect("write the case");
    check_load(&path, bytes.len(), "case.png")
}

/// The property for an image read from `texture` (a file of `file_len`
/// bytes): an image of at most MAX_TEXTURE_SIDE a side or an error whose
/// message names `named`, within `peak_allowed` bytes held.
pub fn check_load(
    texture: &std::path::Path,
    file_len: usize,
    named: &str,
) -> Result<(), TestCaseError> {
    let (result, peak) = peak_bytes(|| load_rgba8(texture));
    let allowed = peak_allowed(file_len);
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
            prop_assert!(m.contains(named), "the message does not name {named}: {m}");
        }
    }
    Ok(())
}

#[test]
fn load_rgba8_takes_any_mutated_png() {
    let n = seeds().len();
    let case = (
        0..n,
        proptest::collection::vec(any_edit(proptest::sample::select(&SIDES[..])), 1..5),
        any::<bool>(),
    )
        .prop_map(|(i, edits, fix)| mutate(&seeds()[i], &edits, fix));
    run("png-mutated", case, |b| b.clone(), |b| check(&b));
}

#[test]
fn the_crc_fix_up_matches_the_encoder() {
    let png = &seeds()[0];
    let mut copy = png.clone();
    copy[29..33].fill(0);
    fix_crcs(&mut copy);
    assert_eq!(&copy, png);
    let big = mutate(png, &[Edit::Size(8193, 1)], true);
    let msg = format!("{:#}", check_err(&big));
    assert!(msg.contains("8193x1"), "{msg}");
}

fn check_err(bytes: &[u8]) -> anyhow::Error {
    let path = scratch("err.png");
    std::fs::write(&path, bytes).unwrap();
    load_rgba8(&path).unwrap_err()
}
