//! Image files decoded for textures, through the `image` crate: PNG (grey,
//! grey + alpha, RGB, RGBA; 8 or 16 bits a channel), JPEG (baseline and
//! progressive), TGA and BMP, to RGBA8, flipped so that v = 0 is the bottom
//! row, with absurd sizes refused before decoding and the same
//! `image::Limits` for every format. The format is read from the file's
//! first bytes; TGA, which has no signature, from its extension.

use crate::assets;
use anyhow::{Context as _, Result, bail};
use std::path::Path;

/// Largest texture side gloss will load from a file (an absurd PNG is refused
/// before it is decoded into memory).
pub const MAX_TEXTURE_SIDE: u32 = 8192;

/// Decode an image file to RGBA8 with v flipped for GL, refusing absurd sizes
/// before decoding.
pub fn load_rgba8(path: &Path) -> Result<image::RgbaImage> {
    // What is there, from its metadata alone: a FIFO is never opened.
    if let Some(why) = assets::not_a_file(path) {
        bail!("texture {} {why}", path.display());
    }
    let open = || reader(path);
    let (w, h) = open()?
        .into_dimensions()
        .with_context(|| format!("texture {} is not a readable image", path.display()))?;
    if w == 0 || h == 0 || w > MAX_TEXTURE_SIDE || h > MAX_TEXTURE_SIDE {
        bail!(
            "texture {} is {w}x{h}; gloss accepts 1..={MAX_TEXTURE_SIDE} pixels a side",
            path.display()
        );
    }
    let mut limits = image::Limits::default();
    limits.max_image_width = Some(MAX_TEXTURE_SIDE);
    limits.max_image_height = Some(MAX_TEXTURE_SIDE);
    let mut reader = open()?;
    reader.limits(limits);
    let img = reader
        .decode()
        .with_context(|| format!("texture {} is malformed", path.display()))?;
    Ok(image::imageops::flip_vertical(&img.to_rgba8()))
}

/// Whether the image file has an alpha channel, from its header alone (an
/// OBJ's map_Kd with alpha is alpha-tested: src/scene/obj_materials.rs).
pub fn has_alpha(path: &Path) -> Result<bool> {
    if let Some(why) = assets::not_a_file(path) {
        bail!("texture {} {why}", path.display());
    }
    let decoder = reader(path)?
        .into_decoder()
        .with_context(|| format!("texture {} is not a readable image", path.display()))?;
    Ok(image::ImageDecoder::color_type(&decoder).has_alpha())
}

/// `load_rgba8` with the alpha taken from the first channel (red, or grey)
/// of the image at `alpha` (an MTL's map_d), scaled to the colour image's
/// size (nearest texel); without `colour`, white with that alpha.
pub fn load_rgba8_with_alpha(colour: Option<&Path>, alpha: &Path) -> Result<image::RgbaImage> {
    let a = load_rgba8(alpha)?;
    let mut img = match colour {
        Some(c) => load_rgba8(c)?,
        None => image::RgbaImage::from_pixel(a.width(), a.height(), image::Rgba([255; 4])),
    };
    let (w, h) = img.dimensions();
    for (x, y, p) in img.enumerate_pixels_mut() {
        let ax = (u64::from(x) * u64::from(a.width()) / u64::from(w)) as u32;
        let ay = (u64::from(y) * u64::from(a.height()) / u64::from(h)) as u32;
        p.0[3] = a.get_pixel(ax, ay).0[0];
    }
    Ok(img)
}

/// The width and height of an image file, from its header alone (the frame
/// plan reports a texture's memory without decoding it).
pub fn dimensions(path: &Path) -> Result<(u32, u32)> {
    if let Some(why) = assets::not_a_file(path) {
        bail!("texture {} {why}", path.display());
    }
    reader(path)?
        .into_dimensions()
        .with_context(|| format!("texture {} is not a readable image", path.display()))
}

/// A reader of the image at `path`: a shipped scene's texture is embedded in
/// the binary (src/assets.rs), an image inside a glTF file is read from it,
/// any other is opened.
fn reader(path: &Path) -> Result<image::ImageReader<Box<dyn BufReadSeek>>> {
    let reader: Box<dyn BufReadSeek> = match (assets::embedded(path), assets::gltf_image(path)) {
        (Some(f), _) => Box::new(std::io::Cursor::new(f.contents())),
        // An image inside a glTF file (src/geometry/gltf_images.rs).
        (None, Some((file, i))) => Box::new(std::io::Cursor::new(
            crate::geometry::gltf_image_bytes(&file, i)
                .with_context(|| format!("cannot read texture {}", path.display()))?,
        )),
        (None, None) => Box::new(std::io::BufReader::new(
            std::fs::File::open(path)
                .with_context(|| format!("cannot open texture {}", path.display()))?,
        )),
    };
    let mut r = image::ImageReader::new(reader)
        .with_guessed_format()
        .with_context(|| format!("cannot read texture {}", path.display()))?;
    if r.format().is_none()
        && let Ok(f) = image::ImageFormat::from_path(path)
    {
        r.set_format(f);
    }
    Ok(r)
}

/// What `image` reads from: a file or embedded bytes.
trait BufReadSeek: std::io::BufRead + std::io::Seek {}
impl<T: std::io::BufRead + std::io::Seek> BufReadSeek for T {}
