//! Images inside a glTF 2.0 file: a .glb's `bufferView` images and
//! `data:` URI images. A material names one by a path of its own,
//! `FILE#images[N]` (`scenes/assets/box.glb#images[0]`), which every
//! texture reader takes as it takes an image file (src/gl/image_file.rs:
//! the same size check before decoding and the same `image::Limits`); the
//! bytes are read here, from the file again, when the texture loads.
//!
//! Each step is checked before it is taken: the file is at most
//! [`MAX_GLTF_BYTES`], the image index exists, its buffer view lies
//! inside its buffer, a data: URI is base64 and at most the same size.

use super::gltf_buffers::{MAX_GLTF_BYTES, uri_bytes};
use crate::assets;
use anyhow::{Result, anyhow, bail};
use std::path::{Path, PathBuf};

/// The path a material gives image `index` of the glTF file at `file`.
pub fn gltf_image_path(file: &Path, index: usize) -> PathBuf {
    let mut s = file.as_os_str().to_owned();
    s.push(format!("#images[{index}]"));
    PathBuf::from(s)
}

/// The encoded bytes (PNG, JPEG, ...) of image `index` of the glTF file at
/// `file`: a buffer view's bytes or a data: URI decoded.
pub fn gltf_image_bytes(file: &Path, index: usize) -> Result<Vec<u8>> {
    let name = file.display();
    let bytes = assets::read(file, MAX_GLTF_BYTES, "glTF file")?;
    let doc =
        gltf::Gltf::from_slice(&bytes).map_err(|e| anyhow!("malformed glTF file {name}: {e}"))?;
    let what = format!("{name}: images[{index}]");
    let Some(image) = doc.images().nth(index) else {
        bail!("{what}: the file has {} images", doc.images().len());
    };
    match image.source() {
        gltf::image::Source::Uri { uri, .. } => uri_bytes(uri, file, &what, "glTF image"),
        gltf::image::Source::View { view, .. } => {
            let b = view.buffer();
            let owned;
            let data: &[u8] = match b.source() {
                gltf::buffer::Source::Bin => doc.blob.as_deref().ok_or_else(|| {
                    anyhow!("{what}: its buffer is the binary chunk, which the file lacks")
                })?,
                gltf::buffer::Source::Uri(uri) => {
                    let w = format!("{what}: buffers[{}]", b.index());
                    owned = uri_bytes(uri, file, &w, "glTF buffer")?;
                    &owned
                }
            };
            let (start, len) = (view.offset(), view.length());
            let end = start.checked_add(len).unwrap_or(usize::MAX);
            if end > data.len() {
                bail!(
                    "{what}: bufferViews[{}] ends at byte {end}, past its buffer's {}",
                    view.index(),
                    data.len()
                );
            }
            Ok(data[start..end].to_vec())
        }
    }
}
