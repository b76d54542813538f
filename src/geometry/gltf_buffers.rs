//! The bytes behind a glTF 2.0 file, and every count checked before any
//! array is read: the first steps of both glTF readers (`gltf` for the
//! skin, `gltf_scene` for the whole scene).
//!
//! * The file itself: glTF 1.0 (a .glb of version 1, or `"version": "1.x"`)
//!   is refused by name; so is an extension in `extensionsRequired` that
//!   gloss does not read.
//! * Buffers: the .glb's binary chunk, a `data:` URI (base64), or a file
//!   beside the glTF that passes the regular-file check meshes and textures
//!   pass (`assets::not_a_file`: a FIFO, a device or a directory is named,
//!   never opened), each at most [`MAX_GLTF_BYTES`].
//! * Accessors: every accessor, before anything is read, lies inside its
//!   buffer view, every view inside its buffer, a sparse accessor's index and
//!   value views likewise, and all accessors together describe at most
//!   [`MAX_ACCESSOR_BYTES`]. An accessor without a buffer view (zeros, or a
//!   sparse accessor's base) is backed by no bytes at all, so those
//!   together may describe at most [`UNBACKED_PER_BYTE`] times the bytes
//!   of the file's buffers, plus [`UNBACKED_SLACK`]: a 2 KB file cannot ask
//!   for gigabytes.

use crate::assets;
use anyhow::{Result, anyhow, bail};
use std::path::Path;

/// Largest glTF file (and each of its buffers) gloss reads.
pub const MAX_GLTF_BYTES: u64 = 64 * 1024 * 1024;
/// The most bytes all the accessors of one file may describe together.
pub const MAX_ACCESSOR_BYTES: u64 = 512 * 1024 * 1024;
/// Accessors without a buffer view may describe this many bytes per byte
/// of the file's buffers (a morph target's zeros match real positions)...
pub const UNBACKED_PER_BYTE: u64 = 4;
/// ... plus this many.
pub const UNBACKED_SLACK: u64 = 1 << 16;
/// The extensions gloss reads; any other in `extensionsRequired` is refused.
pub const SUPPORTED_EXTENSIONS: &[&str] = &["KHR_texture_transform"];

/// A parsed file and its buffers' bytes, every accessor checked.
pub struct Parsed {
    pub doc: gltf::Gltf,
    pub buffers: Vec<Vec<u8>>,
}

impl Parsed {
    /// The reader's view of the buffers.
    pub fn get<'s>(&'s self) -> impl Fn(gltf::Buffer) -> Option<&'s [u8]> + Clone + 's {
        move |b: gltf::Buffer| self.buffers.get(b.index()).map(Vec::as_slice)
    }
}

/// Parse `bytes` (the file at `path`, named `name`), load its buffers and
/// check its accessors.
pub fn parse(bytes: &[u8], path: &Path, name: &str) -> Result<Parsed> {
    if bytes.len() >= 8 && &bytes[..4] == b"glTF" && bytes[4..8] == 1u32.to_le_bytes() {
        bail!("{name}: glTF 1.0 is not supported (gloss reads glTF 2.0)");
    }
    let doc = match gltf::Gltf::from_slice(bytes) {
        Ok(d) => d,
        Err(e) if says_version_1(bytes) => {
            bail!("{name}: glTF 1.0 is not supported (gloss reads glTF 2.0; the parser said: {e})")
        }
        Err(e) => bail!("malformed glTF file {name}: {e}"),
    };
    if let Some(v) = Some(doc.as_json().asset.version.as_str()).filter(|v| !v.starts_with("2.")) {
        bail!("{name}: asset.version is \"{v}\"; gloss reads glTF 2.0 only");
    }
    for ext in doc.extensions_required() {
        if !SUPPORTED_EXTENSIONS.contains(&ext) {
            bail!(
                "{name}: extensionsRequired names \"{ext}\", which gloss does not read (it reads {})",
                SUPPORTED_EXTENSIONS.join(", ")
            );
        }
    }
    let mut buffers: Vec<Vec<u8>> = Vec::new();
    for b in doc.buffers() {
        let what = format!("{name}: buffers[{}]", b.index());
        let data = match b.source() {
            gltf::buffer::Source::Bin => doc
                .blob
                .clone()
                .ok_or_else(|| anyhow!("{what} is the binary chunk, which the file lacks"))?,
            gltf::buffer::Source::Uri(uri) => uri_bytes(uri, path, &what, "glTF buffer")?,
        };
        if data.len() < b.length() {
            bail!(
                "{what} holds {} bytes but its byteLength says {}",
                data.len(),
                b.length()
            );
        }
        buffers.push(data);
    }
    check_accessors(&doc, &buffers, name)?;
    Ok(Parsed { doc, buffers })
}

/// Does the JSON say `"version": "1...`? (Only to word the error of a file
/// that did not parse.)
fn says_version_1(bytes: &[u8]) -> bool {
    let text = String::from_utf8_lossy(&bytes[..bytes.len().min(1 << 16)]);
    let Some(at) = text.find("\"version\"") else {
        return false;
    };
    let rest = text[at + 9..]
        .trim_start()
        .trim_start_matches(':')
        .trim_start();
    rest.starts_with("\"1")
}

/// The bytes a `uri` names: a `data:` URI decoded, or a file relative to
/// the glTF file at `path`, checked to be a regular file first.
pub fn uri_bytes(uri: &str, path: &Path, what: &str, kind: &str) -> Result<Vec<u8>> {
    if let Some(data) = uri.strip_prefix("data:") {
        let Some((_, b64)) = data.split_once(";base64,") else {
            bail!("{what}: a data: URI that is not base64 (expected data:...;base64,...)");
        };
        // 4 characters carry 3 bytes: refuse before decoding.
        if b64.len() as u64 / 4 * 3 > MAX_GLTF_BYTES {
            bail!("{what}: its data: URI holds more than {MAX_GLTF_BYTES} bytes, the limit");
        }
        use base64::Engine as _;
        return base64::engine::general_purpose::STANDARD
            .decode(b64.trim_end())
            .map_err(|e| anyhow!("{what}: its data: URI is not valid base64: {e}"));
    }
    let at = file_beside(uri, path, what)?;
    if let Some(why) = assets::not_a_file(&at) {
        bail!("{what}: uri \"{uri}\": file {} {why}", at.display());
    }
    assets::read(&at, MAX_GLTF_BYTES, kind)
        .map(|c| c.into_owned())
        .map_err(|e| anyhow!("{what}: {e}"))
}

/// The file a relative `uri` names beside the glTF file at `path`
/// (percent escapes such as %20 decoded); other schemes are refused.
pub fn file_beside(uri: &str, path: &Path, what: &str) -> Result<std::path::PathBuf> {
    if uri.contains("://") {
        bail!("{what}: uri \"{uri}\" is not a file beside the glTF file (gloss reads no URLs)");
    }
    let mut bytes = Vec::with_capacity(uri.len());
    let raw = uri.as_bytes();
    let mut i = 0;
    while i < raw.len() {
        let hex = |c: u8| (c as char).to_digit(16);
        if raw[i] == b'%'
            && i + 2 < raw.len()
            && let (Some(a), Some(b)) = (hex(raw[i + 1]), hex(raw[i + 2]))
        {
            bytes.push((a * 16 + b) as u8);
            i += 3;
        } else {
            bytes.push(raw[i]);
            i += 1;
        }
    }
    let decoded = String::from_utf8(bytes)
        .map_err(|_| anyhow!("{what}: uri \"{uri}\" is not UTF-8 once decoded"))?;
    Ok(path.parent().unwrap_or(Path::new("")).join(decoded))
}

/// Every accessor inside its view, every view inside its buffer, and all of
/// them together within [`MAX_ACCESSOR_BYTES`], before anything is read.
fn check_accessors(doc: &gltf::Gltf, buffers: &[Vec<u8>], name: &str) -> Result<()> {
    let view_ok = |v: &gltf::buffer::View, what: &str| -> Result<()> {
        let len = buffers.get(v.buffer().index()).map_or(0, Vec::len) as u64;
        let end = v.offset() as u64 + v.length() as u64;
        if end > len {
            bail!(
                "{name}: {what}: bufferViews[{}] ends at byte {end}, past its buffer's {len}",
                v.index()
            );
        }
        Ok(())
    };
    // Bytes `count` items of `size` take from `offset` in `view`, strided.
    let inside = |v: &gltf::buffer::View, offset: usize, count: u64, size: u64, what: &str| {
        view_ok(v, what)?;
        if count == 0 {
            return Ok(());
        }
        let stride = v.stride().map_or(size, |s| s as u64);
        let end = offset as u64 + stride.saturating_mul(count - 1).saturating_add(size);
        if end > v.length() as u64 {
            bail!(
                "{name}: {what}: {count} items of {size} bytes need {end} bytes of bufferViews[{}], which has {}",
                v.index(),
                v.length()
            );
        }
        Ok(())
    };
    let mut total: u64 = 0;
    let backing: u64 = buffers.iter().map(|b| b.len() as u64).sum();
    let unbacked_limit = backing.saturating_mul(UNBACKED_PER_BYTE) + UNBACKED_SLACK;
    let mut unbacked: u64 = 0;
    for a in doc.accessors() {
        let what = format!("accessors[{}]", a.index());
        let (count, size) = (a.count() as u64, a.size() as u64);
        let bytes = count.saturating_mul(size);
        total = total.saturating_add(bytes);
        if bytes > MAX_ACCESSOR_BYTES || total > MAX_ACCESSOR_BYTES {
            bail!(
                "{name}: {what}: count {count} of {size}-byte items takes the file's accessors past {MAX_ACCESSOR_BYTES} bytes, the limit"
            );
        }
        match a.view() {
            Some(v) => inside(&v, a.offset(), count, size, &what)?,
            None => {
                unbacked = unbacked.saturating_add(bytes);
                if unbacked > unbacked_limit {
                    bail!(
                        "{name}: {what}: count {count} of {size}-byte items without a bufferView: accessors without one may describe {unbacked_limit} bytes in this file ({UNBACKED_PER_BYTE} per byte of its buffers + {UNBACKED_SLACK}), the limit"
                    );
                }
            }
        }
        if let Some(s) = a.sparse() {
            let n = s.count() as u64;
            if n > count {
                bail!("{name}: {what}: sparse.count {n} is more than the accessor's count {count}");
            }
            let index_size = s.indices().index_type().size() as u64;
            inside(
                &s.indices().view(),
                s.indices().offset(),
                n,
                index_size,
                &format!("{what}.sparse.indices"),
            )?;
            inside(
                &s.values().view(),
                s.values().offset(),
                n,
                size,
                &format!("{what}.sparse.values"),
            )?;
            total = total.saturating_add(n.saturating_mul(size + index_size));
        }
    }
    Ok(())
}
