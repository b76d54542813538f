//! Wavefront OBJ loading through tobj, with size limits and errors that name
//! the file and say what is wrong with it.

use super::normals::compute_normals;
use super::tangents::compute_tangents;
use super::{MeshData, Vertex};
use crate::assets;
use anyhow::{Context, Result, anyhow, bail};
use glam::Vec3;
use std::io::Read;
use std::path::Path;

/// Largest OBJ file `load_obj` reads.
pub const MAX_OBJ_BYTES: u64 = 256 * 1024 * 1024;
/// Most vertices `load_obj` accepts (after splitting by position/uv/normal).
pub const MAX_OBJ_VERTICES: usize = 16_000_000;

/// Loads a Wavefront OBJ through tobj (polygons triangulated, one index per
/// vertex), merging all its objects and groups into one mesh. Materials are
/// ignored. Objects without normals in the file get smooth normals
/// ([`compute_normals`]); tangents are always computed. A file without uvs
/// loads with uv (0, 0) everywhere (and arbitrary tangents).
///
/// Refuses, with an error naming the file: a missing or unreadable file, one
/// over 256 MiB (checked before reading) or with more than 16 million
/// vertices, malformed content, no triangles, NaN or infinite numbers, and
/// face indices out of range.
pub fn load_obj(path: &Path) -> Result<MeshData> {
    load_obj_limited(path, MAX_OBJ_BYTES, MAX_OBJ_VERTICES)
}

fn load_obj_limited(path: &Path, max_bytes: u64, max_vertices: usize) -> Result<MeshData> {
    let name = path.display();
    let bytes: Vec<u8> = match assets::embedded(path) {
        Some(f) => f.contents().to_vec(),
        None => {
            // What is there, from its metadata alone: a FIFO is never opened.
            if let Some(why) = assets::not_a_file(path) {
                bail!("OBJ file {name} {why}");
            }
            let meta =
                std::fs::metadata(path).with_context(|| format!("cannot open OBJ file {name}"))?;
            if meta.len() > max_bytes {
                bail!(
                    "OBJ file {name} is too large: {} bytes, the limit is {max_bytes} bytes",
                    meta.len()
                );
            }
            let mut bytes = Vec::with_capacity(meta.len() as usize);
            std::fs::File::open(path)
                .and_then(|f| f.take(max_bytes + 1).read_to_end(&mut bytes))
                .with_context(|| format!("cannot read OBJ file {name}"))?;
            if bytes.len() as u64 > max_bytes {
                bail!(
                    "OBJ file {name} is too large: it grew past {max_bytes} bytes while being read"
                );
            }
            bytes
        }
    };
    // Cheap count before tobj allocates anything per vertex.
    let positions = bytes
        .split(|&b| b == b'\n')
        .filter(|l| {
            l.trim_ascii_start().starts_with(b"v ") || l.trim_ascii_start().starts_with(b"v\t")
        })
        .count();
    if positions > max_vertices {
        bail!(
            "OBJ file {name} is too large: {positions} vertex positions, the limit is {max_vertices}"
        );
    }

    let options = tobj::LoadOptions {
        triangulate: true,
        single_index: true,
        ignore_points: true,
        ignore_lines: true,
    };
    let (models, _materials) = tobj::load_obj_buf(&mut bytes.as_slice(), &options, |_| {
        Ok((Vec::new(), Default::default()))
    })
    .map_err(|e| anyhow!("malformed OBJ file {name}: {}", describe_tobj_error(&e)))?;

    let mut mesh = MeshData::default();
    for model in &models {
        let m = &model.mesh;
        let object = &model.name;
        if m.positions.len() % 3 != 0 {
            bail!("malformed OBJ file {name}: object '{object}' has a partial position");
        }
        let n = m.positions.len() / 3;
        if mesh.vertices.len() + n > max_vertices {
            bail!(
                "OBJ file {name} is too large: more than {max_vertices} vertices after splitting by uv and normal"
            );
        }
        let finite = |values: &[f32], what: &str| -> Result<()> {
            match values.iter().position(|x| !x.is_finite()) {
                Some(_) => bail!("OBJ file {name}: object '{object}' has a NaN or infinite {what}"),
                None => Ok(()),
            }
        };
        finite(&m.positions, "vertex position")?;
        finite(&m.normals, "normal")?;
        finite(&m.texcoords, "texture coordinate")?;
        if m.indices.len() % 3 != 0 {
            bail!("malformed OBJ file {name}: object '{object}' has a partial triangle");
        }
        if let Some(&bad) = m.indices.iter().find(|&&i| i as usize >= n) {
            bail!(
                "OBJ file {name}: object '{object}' has face index {bad} out of range ({n} vertices)"
            );
        }
        finite(&m.vertex_color, "vertex colour")?;
        let has_normals = m.normals.len() == m.positions.len();
        let has_colors = m.vertex_color.len() == m.positions.len();
        let has_uvs = m.texcoords.len() == 2 * n;
        let mut part = MeshData {
            vertices: (0..n)
                .map(|i| Vertex {
                    position: [
                        m.positions[3 * i],
                        m.positions[3 * i + 1],
                        m.positions[3 * i + 2],
                    ],
                    normal: if has_normals {
                        [m.normals[3 * i], m.normals[3 * i + 1], m.normals[3 * i + 2]]
                    } else {
                        [0.0; 3]
                    },
                    uv: if has_uvs {
                        [m.texcoords[2 * i], m.texcoords[2 * i + 1]]
                    } else {
                        [0.0; 2]
                    },
                    tangent: [1.0, 0.0, 0.0, 1.0],
                })
                .collect(),
            indices: m.indices.clone(),
            colors: if has_colors {
                m.vertex_color
                    .chunks_exact(3)
                    .map(|c| [c[0], c[1], c[2]])
                    .collect()
            } else {
                Vec::new()
            },
        };
        if !has_normals {
            compute_normals(&mut part);
        }
        // Colours for every vertex once any object has them (white for the others).
        if !part.colors.is_empty() || !mesh.colors.is_empty() {
            mesh.colors.resize(mesh.vertices.len(), [1.0; 3]);
            let mut c = std::mem::take(&mut part.colors);
            c.resize(part.vertices.len(), [1.0; 3]);
            mesh.colors.extend(c);
        }
        let offset = mesh.vertices.len() as u32;
        for mut v in part.vertices {
            // File normals of zero length fall back to +y rather than NaN.
            v.normal = Vec3::from(v.normal)
                .try_normalize()
                .unwrap_or(Vec3::Y)
                .to_array();
            mesh.vertices.push(v);
        }
        mesh.indices.extend(part.indices.iter().map(|i| i + offset));
    }
    if mesh.indices.len() < 3 {
        bail!("OBJ file {name} contains no triangles");
    }
    compute_tangents(&mut mesh);
    Ok(mesh)
}

fn describe_tobj_error(e: &tobj::LoadError) -> String {
    use tobj::LoadError as E;
    match e {
        E::FaceVertexOutOfBounds | E::FaceTexCoordOutOfBounds | E::FaceNormalOutOfBounds => {
            format!("{e} (face index out of range)")
        }
        E::ReadError => "read error (not UTF-8 text?)".to_string(),
        _ => e.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::tests::check_mesh;
    use std::path::PathBuf;

    fn temp_obj(name: &str, contents: &[u8]) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("gloss-geometry-tests-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join(name);
        std::fs::write(&path, contents).unwrap();
        path
    }

    fn load_err(name: &str, contents: &str) -> String {
        let path = temp_obj(name, contents.as_bytes());
        let err = load_obj(&path).expect_err("should fail");
        let msg = format!("{err:#}");
        assert!(msg.contains(name), "error does not name the file: {msg}");
        msg
    }

    const QUAD: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n";

    #[test]
    fn load_obj_quad_without_normals() {
        let path = temp_obj(
            "quad.obj",
            format!("{QUAD}o a\nf 1/1 2/2 3/3 4/4\n").as_bytes(),
        );
        let m = load_obj(&path).unwrap();
        assert_eq!((m.vertices.len(), m.indices.len()), (4, 6));
        check_mesh("quad.obj", &m);
        for v in &m.vertices {
            assert_eq!(v.normal, [0.0, 0.0, 1.0]);
            assert_eq!(v.tangent, [1.0, 0.0, 0.0, 1.0]);
        }
    }

    #[test]
    fn load_obj_merges_models_and_keeps_file_normals() {
        let text = format!("{QUAD}vn 0 0 2\no a\nf 1/1/1 2/2/1 3/3/1\no b\nf 1/1 3/3 4/4\n");
        let m = load_obj(&temp_obj("two.obj", text.as_bytes())).unwrap();
        assert_eq!(m.triangle_count(), 2);
        check_mesh("two.obj", &m);
        // The first object's file normal (normalised); no uvs -> still finite.
        assert_eq!(m.vertices[0].normal, [0.0, 0.0, 1.0]);
        let m = load_obj(&temp_obj(
            "nouv.obj",
            b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
        ))
        .unwrap();
        check_mesh("nouv.obj", &m);
    }

    #[test]
    fn load_obj_missing_file() {
        let path = std::env::temp_dir().join("gloss-no-such-dir/missing.obj");
        let msg = format!("{:#}", load_obj(&path).unwrap_err());
        assert!(
            msg.contains("OBJ file") && msg.contains("missing.obj does not exist"),
            "{msg}"
        );
    }

    #[test]
    fn load_obj_malformed() {
        let msg = load_err("malformed.obj", "v 1.0 abc 2.0\nf 1 1 1\n");
        assert!(
            msg.contains("malformed OBJ file") && msg.contains("position parse error"),
            "{msg}"
        );
        let msg = load_err("badface.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 two 3\n");
        assert!(
            msg.contains("malformed OBJ file") && msg.contains("face parse error"),
            "{msg}"
        );
        let path = temp_obj("binary.obj", &[0xff, 0xfe, 0x00, 0x76, 0x20, 0x31, 0x0a]);
        let msg = format!("{:#}", load_obj(&path).unwrap_err());
        assert!(
            msg.contains("malformed OBJ file") && msg.contains("binary.obj"),
            "{msg}"
        );
    }

    #[test]
    fn load_obj_no_triangles() {
        let msg = load_err("empty.obj", "");
        assert!(msg.contains("contains no triangles"), "{msg}");
        let msg = load_err("lines.obj", "v 0 0 0\nv 1 0 0\nl 1 2\np 1\n");
        assert!(msg.contains("contains no triangles"), "{msg}");
    }

    #[test]
    fn load_obj_non_finite() {
        let msg = load_err("nan.obj", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        assert!(msg.contains("NaN or infinite vertex position"), "{msg}");
        let msg = load_err("inf.obj", "v 0 0 0\nv 1 0 0\nv 0 inf 0\nf 1 2 3\n");
        assert!(msg.contains("NaN or infinite vertex position"), "{msg}");
        let msg = load_err(
            "nanvt.obj",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt NaN 0\nf 1/1 2/1 3/1\n",
        );
        assert!(msg.contains("NaN or infinite texture coordinate"), "{msg}");
    }

    #[test]
    fn load_obj_index_out_of_range() {
        let msg = load_err("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n");
        assert!(msg.contains("face index out of range"), "{msg}");
        let msg = load_err(
            "rangevt.obj",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/5 3/1\n",
        );
        assert!(msg.contains("face index out of range"), "{msg}");
    }

    #[test]
    fn load_obj_too_large() {
        // The real limits are 256 MiB and 16M vertices; the same checks run
        // here with small limits so the test files stay small.
        let path = temp_obj("big.obj", format!("{QUAD}f 1 2 3 4\n").as_bytes());
        let msg = format!(
            "{:#}",
            load_obj_limited(&path, 16, MAX_OBJ_VERTICES).unwrap_err()
        );
        assert!(
            msg.contains("big.obj") && msg.contains("too large") && msg.contains("bytes"),
            "{msg}"
        );
        let msg = format!(
            "{:#}",
            load_obj_limited(&path, MAX_OBJ_BYTES, 3).unwrap_err()
        );
        assert!(
            msg.contains("big.obj")
                && msg.contains("too large")
                && msg.contains("vertex positions"),
            "{msg}"
        );
        // 3 positions but 6 vertices once split by uv.
        let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 1\nf 1/1 2/1 3/1\nf 1/2 3/2 2/2\n";
        let path = temp_obj("split.obj", text.as_bytes());
        let msg = format!(
            "{:#}",
            load_obj_limited(&path, MAX_OBJ_BYTES, 5).unwrap_err()
        );
        assert!(
            msg.contains("split.obj") && msg.contains("after splitting"),
            "{msg}"
        );
        assert!(load_obj_limited(&path, MAX_OBJ_BYTES, 6).is_ok());
    }

    #[test]
    fn committed_assets_load() {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/assets");
        for name in ["knot.obj", "rock.obj"] {
            let path = dir.join(name);
            if !path.exists() {
                continue; // generated by `cargo run --release --example gen_assets`
            }
            let m = load_obj(&path).unwrap();
            check_mesh(name, &m);
            assert!(m.triangle_count() > 50);
        }
    }
}
