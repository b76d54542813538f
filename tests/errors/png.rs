//! PNG textures: random bytes, truncated, absurdly large (refused from the
//! header, without decoding); and the CRC-32 the large-PNG test patches with.

use crate::{base_with, contains_all, png_bytes, render_fails, temp_dir, write};
use gloss::gl::texture::{MAX_TEXTURE_SIDE, load_rgba8};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// BASE with the floor textured by `name` (in `dir`); returns the scene path.
fn textured_scene(dir: &Path, name: &str) -> PathBuf {
    write(
        dir,
        "scene.toml",
        base_with(
            "shininess = 24.0",
            &format!("shininess = 24.0\ndiffuse_texture = \"{name}\""),
        ),
    )
}

/// CRC-32 (ISO 3309, as PNG uses), bit by bit.
fn crc32(data: &[u8]) -> u32 {
    let mut crc = 0xFFFF_FFFFu32;
    for &b in data {
        crc ^= b as u32;
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

#[test]
fn crc32_matches_a_real_png() {
    // The IHDR CRC the image crate wrote must be what our crc32 computes.
    let png = png_bytes(1, 1);
    assert_eq!(&png[12..16], b"IHDR");
    let stored = u32::from_be_bytes(png[29..33].try_into().unwrap());
    assert_eq!(crc32(&png[12..29]), stored);
}

#[test]
fn png_random_bytes() {
    let dir = temp_dir("png_random_bytes");
    // Deterministic noise that starts like nothing in particular.
    let mut x = 0x1234_5678u32;
    let noise: Vec<u8> = (0..4096)
        .map(|_| {
            x ^= x << 13;
            x ^= x >> 17;
            x ^= x << 5;
            x as u8
        })
        .collect();
    let png = write(&dir, "noise.png", &noise);
    let msg = format!("{:#}", load_rgba8(&png).unwrap_err());
    contains_all(&msg, &["texture", "noise.png", "is not a readable image"]);
    let stderr = render_fails(&textured_scene(&dir, "noise.png"), &dir.join("out.png"));
    contains_all(
        &stderr,
        &["texture", "noise.png", "is not a readable image"],
    );
}

#[test]
fn png_truncated() {
    let dir = temp_dir("png_truncated");
    let real = std::fs::read(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenes/assets/checker.png"
    ))
    .expect("read scenes/assets/checker.png");
    assert!(real.len() > 100);
    let png = write(&dir, "truncated.png", &real[..100]);
    let msg = format!("{:#}", load_rgba8(&png).unwrap_err());
    contains_all(&msg, &["texture", "truncated.png", "is malformed"]);
    let stderr = render_fails(&textured_scene(&dir, "truncated.png"), &dir.join("out.png"));
    contains_all(&stderr, &["texture", "truncated.png", "is malformed"]);
}

#[test]
fn png_absurdly_large() {
    let dir = temp_dir("png_absurdly_large");
    // A real 1x1 PNG whose header claims 100000x100000 (40 GB of RGBA8), with
    // a correct IHDR CRC so only the size is wrong.
    let mut png = png_bytes(1, 1);
    assert_eq!(&png[12..16], b"IHDR");
    png[16..20].copy_from_slice(&100_000u32.to_be_bytes());
    png[20..24].copy_from_slice(&100_000u32.to_be_bytes());
    let crc = crc32(&png[12..29]);
    png[29..33].copy_from_slice(&crc.to_be_bytes());
    let path = write(&dir, "huge.png", &png);

    let start = Instant::now();
    let msg = format!("{:#}", load_rgba8(&path).unwrap_err());
    let took = start.elapsed();
    contains_all(
        &msg,
        &[
            "texture",
            "huge.png",
            "100000x100000",
            &format!("1..={MAX_TEXTURE_SIDE}"),
        ],
    );
    assert_eq!(MAX_TEXTURE_SIDE, 8192);
    assert!(
        took < Duration::from_secs(1),
        "refusing a huge PNG should not decode it: took {took:?}"
    );

    let stderr = render_fails(&textured_scene(&dir, "huge.png"), &dir.join("out.png"));
    contains_all(&stderr, &["huge.png", "100000x100000", "1..=8192"]);
}
