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
    let what = format!("{name}: images[{index}]");
    // The gltf crate panics on some malformed files (a view image without
    // its MIME type, an index it did not check): every call into it runs
    // under gltf::quietly, and a panic is an error.
    let found = super::gltf::quietly(|| -> Result<(Source, Option<Vec<u8>>)> {
        let doc = gltf::Gltf::from_slice(&bytes)
            .map_err(|e| anyhow!("malformed glTF file {name}: {e}"))?;
        let Some(image) = doc.images().nth(index) else {
            bail!("{what}: the file has {} images", doc.images().len());
        };
        let source = match image.source() {
            gltf::image::Source::Uri { uri, .. } => Source::Uri(uri.to_owned()),
            gltf::image::Source::View { view, .. } => Source::View {
                view: view.index(),
                buffer: view.buffer().index(),
                uri: match view.buffer().source() {
                    gltf::buffer::Source::Bin => None,
                    gltf::buffer::Source::Uri(u) => Some(u.to_owned()),
                },
                start: view.offset(),
                len: view.length(),
            },
        };
        Ok((source, doc.blob.clone()))
    });
    let (source, blob) = match found {
        Ok(r) => r?,
        Err(_) => bail!("malformed glTF file {name}: the gltf crate could not read it"),
    };
    match source {
        Source::Uri(uri) => uri_bytes(&uri, file, &what, "glTF image"),
        Source::View {
            view,
            buffer,
            uri,
            start,
            len,
        } => {
            let data = match uri {
                None => blob.ok_or_else(|| {
                    anyhow!("{what}: its buffer is the binary chunk, which the file lacks")
                })?,
                Some(uri) => {
                    let w = format!("{what}: buffers[{buffer}]");
                    uri_bytes(&uri, file, &w, "glTF buffer")?
                }
            };
            let end = start.saturating_add(len);
            if end > data.len() {
                bail!(
                    "{what}: bufferViews[{view}] ends at byte {end}, past its buffer's {}",
                    data.len()
                );
            }
            Ok(data[start..end].to_vec())
        }
    }
}

/// Where an image's bytes are, as the file says.
enum Source {
    Uri(String),
    View {
        view: usize,
        buffer: usize,
        uri: Option<String>,
        start: usize,
        len: usize,
    },
}
