//! JPEG, TGA and BMP textures beside PNG (src/gl/image_file.rs): files the
//! `image` crate's encoders write decode to the texels written (JPEG within
//! its tolerance), flipped for GL like a PNG, and under the same size limit.

use crate::temp_dir;
use gloss::gl::image_file::{MAX_TEXTURE_SIDE, load_rgba8};

/// A smooth, opaque 32 x 16 gradient (JPEG keeps smooth images close).
fn gradient() -> image::RgbImage {
    image::RgbImage::from_fn(32, 16, |x, y| {
        image::Rgb([(x * 8) as u8, (y * 16) as u8, 128])
    })
}

#[test]
fn jpeg_tga_and_bmp_decode_to_the_texels_written() {
    let dir = temp_dir("images");
    let src = gradient();
    for (name, tolerance) in [
        ("g.jpg", 12i32),
        ("g.jpeg", 12),
        ("g.tga", 0),
        ("g.bmp", 0),
        ("g.png", 0),
    ] {
        let path = dir.join(name);
        match name {
            // Quality 95: what a model's textures are usually saved at.
            n if n.ends_with("jpg") || n.ends_with("jpeg") => {
                let f = std::fs::File::create(&path).unwrap();
                let mut e = image::codecs::jpeg::JpegEncoder::new_with_quality(f, 95);
                e.encode_image(&src).unwrap();
            }
            _ => src.save(&path).unwrap(),
        }
        let img = load_rgba8(&path).unwrap_or_else(|e| panic!("{name}: {e:#}"));
        assert_eq!(img.dimensions(), (32, 16), "{name}");
        let mut worst = 0;
        for (x, y, p) in src.enumerate_pixels() {
            // Flipped: row 0 of the texture is the file's bottom row.
            let q = img.get_pixel(x, 15 - y);
            for c in 0..3 {
                worst = worst.max((p.0[c] as i32 - q.0[c] as i32).abs());
            }
            assert_eq!(q.0[3], 255, "{name}: opaque");
        }
        assert!(
            worst <= tolerance,
            "{name}: a texel is {worst} off (at most {tolerance})"
        );
    }
}

#[test]
fn an_oversized_jpeg_is_refused_like_a_png() {
    let dir = temp_dir("images-big");
    let path = dir.join("wide.jpg");
    let img = image::RgbImage::new(MAX_TEXTURE_SIDE + 8, 8);
    let f = std::fs::File::create(&path).unwrap();
    image::codecs::jpeg::JpegEncoder::new_with_quality(f, 50)
        .encode_image(&img)
        .unwrap();
    let e = format!("{:#}", load_rgba8(&path).unwrap_err());
    assert!(e.contains("wide.jpg") && e.contains("pixels a side"), "{e}");
    // Cut short: malformed, named.
    let bytes = std::fs::read(&path).unwrap();
    let cut = dir.join("cut.jpg");
    let small = dir.join("small.jpg");
    let f = std::fs::File::create(&small).unwrap();
    image::codecs::jpeg::JpegEncoder::new_with_quality(f, 90)
        .encode_image(&gradient())
        .unwrap();
    let s = std::fs::read(&small).unwrap();
    std::fs::write(&cut, &s[..s.len() / 3]).unwrap();
    // A JPEG decoder may fill a cut file's missing blocks (zune-jpeg does);
    // what it must never do is panic or give another size.
    match load_rgba8(&cut) {
        Ok(img) => assert_eq!(img.dimensions(), (32, 16)),
        Err(e) => assert!(format!("{e:#}").contains("cut.jpg"), "{e:#}"),
    }
    // Garbage after a JPEG signature: an error naming the file.
    let junk = dir.join("junk.jpg");
    std::fs::write(&junk, [&bytes[..4], &[0x55; 64][..]].concat()).unwrap();
    let e = format!("{:#}", load_rgba8(&junk).unwrap_err());
    assert!(e.contains("junk.jpg"), "{e}");
}
