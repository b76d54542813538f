//! Writes the small committed assets next to this file:
//!
//! * `checker.png`: 256x256 sRGB albedo checkerboard (8x8 squares);
//! * `atlas.png`, `atlas-padded.png`, `atlas-cube.obj`,
//!   `atlas-cube-padded.obj`: a texture atlas of four tiles, with and without
//!   gutters, and a cube mapped onto it (`atlas.rs` says how);
//! * `bunny.obj`: the Stanford bunny, 1839 vertices and 3674 triangles,
//!   from the vendored npm package `bunny` (`bunny/`, `bunny.rs`);
//! * `uv-ramp.png`: 64x64, red rising with u and green with v (4 levels a
//!   texel), blue lines every 8 texels: shows what wrap rules do with
//!   coordinates outside [0, 1] (repeat: a sawtooth, mirror: a triangle,
//!   clamp: flat);
//! * `bricks.png`: 256x256 procedural brick albedo (running bond, mortar);
//! * `bricks-normal.png`: its tangent-space normal map (linear data), baked
//!   by `gloss::math::bump::bake_normal_map` from the bricks' height field:
//!   mortar 1.5 texels below the brick faces, with a 3-texel bevel;
//! * `bricks-height.png`: the bricks' height field as a height map (linear
//!   greyscale, white on the brick faces, black in the mortar) for parallax
//!   mapping, and `bricks-parallax-normal.png`, the normal map of that
//!   relief at the depth `scenes/parallax.toml` gives it
//!   (`PARALLAX_DEPTH` texture uv units);
//! * `ripples.png`: 256x256 linear greyscale ripples, 0.55 to 1, that roughen
//!   a mirror's reflection (a lake's surface);
//! * `knot.obj`: a (2, 3) torus knot tube, 3072 triangles, with normals and uvs;
//! * `disc.obj`: a flat unit disc facing +y (a round mirror);
//! * `rgb-triangle.obj`: one triangle in the xz plane facing +y with red,
//!   green and blue corners (`v x y z r g b`: notes 01 §4.1);
//! * `grid.obj`: a 2 x 2 plane in 32 x 32 squares: a floor fine enough for
//!   a curved mirror, which moves vertices, not pixels;
//! * `rock.obj`: a low-poly displaced icosphere, uvs but NO normals, so that
//!   loading it exercises `geometry::compute_normals`;
//! * `rock-20k.obj`: the same rock at 20480 triangles, the ~20k-triangle
//!   mesh of `scenes/logl-like.toml` (nine of them, as LearnOpenGL's
//!   deferred-shading demo draws nine backpacks);
//! * `tree.png`, `grass.png`: 128x128 RGBA billboard sprites with real alpha
//!   (1 on the tree, 0 around it, a one-texel soft edge); the transparent
//!   texels keep the sprite's colour so filtering brings in no dark fringe.
//!
//! * `skybox-px.png` ... `skybox-nz.png`: a cube map's six labelled faces
//!   with a horizon (`skybox.rs` says how);
//!
//! * `arm.glb`: a skinned arm, three joints and two clips, as binary glTF
//!   2.0 (`arm.rs` says how it is built);
//! * `walker.glb`, `showcase.gltf`: the glTF scene's walking figure and its
//!   metallic-roughness spheres, grass card and spinning box
//!   (`gltf_scene.rs`).
//!
//! * `models/`: the model-loading scenes' OBJ + MTL files and textures,
//!   JPEGs among them (`models.rs` says what each holds).
//!
//! Run with `cargo run --release --example gen_assets`. Output is deterministic.

use anyhow::{Context, Result};
use glam::{Vec2, Vec3};
use gloss::geometry::{self, MeshData, Vertex};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

mod arm;
mod atlas;
mod bunny;
mod gltf_scene;
mod model_textures;
mod models;
mod skybox;

fn main() -> Result<()> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenes/assets");
    write_png(&dir.join("checker.png"), checker())?;
    write_png(&dir.join("uv-ramp.png"), uv_ramp())?;
    write_text(&dir.join("rgb-triangle.obj"), RGB_TRIANGLE)?;
    write_png(&dir.join("atlas.png"), atlas::atlas(false))?;
    write_png(&dir.join("atlas-padded.png"), atlas::atlas(true))?;
    write_obj(
        &dir.join("atlas-cube.obj"),
        &atlas::cube(false),
        true,
        "a cube whose faces use the four tiles of atlas.png",
    )?;
    write_obj(
        &dir.join("atlas-cube-padded.obj"),
        &atlas::cube(true),
        true,
        "a cube whose faces use the four padded tiles of atlas-padded.png",
    )?;
    let js =
        std::fs::read_to_string(dir.join("bunny/index.js")).context("reading bunny/index.js")?;
    write_obj(
        &dir.join("bunny.obj"),
        &bunny::bunny(&js)?,
        true,
        "the Stanford bunny, from the npm package bunny (bunny/LICENSE.md)",
    )?;
    write_png(&dir.join("bricks.png"), bricks())?;
    write_png(&dir.join("bricks-normal.png"), bricks_normal())?;
    write_png(&dir.join("bricks-height.png"), bricks_height_map())?;
    write_png(
        &dir.join("bricks-parallax-normal.png"),
        bricks_parallax_normal(),
    )?;
    write_png(&dir.join("ripples.png"), ripples())?;
    write_rgba_png(&dir.join("tree.png"), tree())?;
    write_rgba_png(&dir.join("grass.png"), grass())?;
    for (f, file) in skybox::FILES.iter().enumerate() {
        write_png(&dir.join(file), skybox::face(f))?;
    }
    write_obj(
        &dir.join("knot.obj"),
        &torus_knot(2, 3, 128, 12),
        true,
        "torus knot (2, 3)",
    )?;
    write_obj(
        &dir.join("disc.obj"),
        &disc(48),
        true,
        "a unit disc, 48 sectors",
    )?;
    write_obj(
        &dir.join("grid.obj"),
        &geometry::plane(2.0, 2.0, 32),
        true,
        "a 2 x 2 plane in 32 x 32 squares",
    )?;
    write_obj(
        &dir.join("rock.obj"),
        &rock(2),
        false,
        "displaced icosphere, no normals",
    )?;
    write_obj(
        &dir.join("rock-20k.obj"),
        &rock(5),
        false,
        "displaced icosphere, 20480 triangles, no normals (scenes/logl-like.toml)",
    )?;
    let glb = dir.join("arm.glb");
    std::fs::write(&glb, geometry::write_glb(&arm::arm()))
        .with_context(|| format!("writing {}", glb.display()))?;
    println!("wrote {}", glb.display());
    models::write_all(&dir)?;
    let walker = dir.join("walker.glb");
    std::fs::write(&walker, geometry::write_glb(&gltf_scene::walker()))
        .with_context(|| format!("writing {}", walker.display()))?;
    write_text(&dir.join("showcase.gltf"), &gltf_scene::showcase())?;
    Ok(())
}

/// One triangle, facing +y, counter-clockwise seen from above: red at
/// (-1, 0, 1), green at (1, 0, 1), blue at (0, 0, -1); uvs along x and -z.
const RGB_TRIANGLE: &str = "# gloss scenes/assets: a triangle with red, green and blue corners
# generated by scenes/assets/generate.rs (cargo run --release --example gen_assets)
o rgb-triangle
v -1 0 1 1 0 0
v 1 0 1 0 1 0
v 0 0 -1 0 0 1
vt 0 0
vt 1 0
vt 0.5 1
vn 0 1 0
f 1/1/1 2/2/1 3/3/1
";

fn write_text(path: &Path, text: &str) -> Result<()> {
    std::fs::write(path, text).with_context(|| format!("writing {}", path.display()))?;
    println!("wrote {}", path.display());
    Ok(())
}

fn write_png(path: &Path, img: image::RgbImage) -> Result<()> {
    img.save(path)
        .with_context(|| format!("writing {}", path.display()))?;
    println!("wrote {}", path.display());
    Ok(())
}

fn write_rgba_png(path: &Path, img: image::RgbaImage) -> Result<()> {
    img.save(path)
        .with_context(|| format!("writing {}", path.display()))?;
    println!("wrote {}", path.display());
    Ok(())
}

/// Coverage of a shape at signed distance `d` (pixels, negative inside):
/// a one-pixel soft edge.
fn coverage(d: f32) -> f32 {
    (0.5 - d).clamp(0.0, 1.0)
}

fn rgba(c: [f32; 3], alpha: f32) -> image::Rgba<u8> {
    let b = |x: f32| (x.clamp(0.0, 1.0) * 255.0).round() as u8;
    image::Rgba([b(c[0]), b(c[1]), b(c[2]), b(alpha)])
}

/// A tree: a brown trunk under a crown of four overlapping discs, the
/// leaves' shade varied by noise and lit from the upper left.
fn tree() -> image::RgbaImage {
    let discs = [
        (64.0, 50.0, 34.0),
        (42.0, 68.0, 22.0),
        (86.0, 68.0, 22.0),
        (64.0, 26.0, 22.0),
    ];
    image::RgbaImage::from_fn(128, 128, |x, y| {
        let (px, py) = (x as f32 + 0.5, y as f32 + 0.5);
        let leafy = 2.5 * hash2(x / 3, y / 3);
        let crown = discs
            .iter()
            .map(|&(cx, cy, r)| (px - cx).hypot(py - cy) - r + leafy)
            .fold(f32::MAX, f32::min);
        let trunk = ((px - 64.0).abs() - 6.0).max(80.0 - py).max(py - 126.0);
        let (a_crown, a_trunk) = (coverage(crown), coverage(trunk));
        let shade = 0.75 + 0.25 * hash2(x / 2 + 7, y / 2) - 0.002 * (px + py - 100.0);
        let leaves = [0.16 * shade, 0.42 * shade, 0.14 * shade];
        let bark = [0.36, 0.23, 0.13];
        if a_crown >= a_trunk {
            rgba(leaves, a_crown.max(a_trunk))
        } else {
            rgba(bark, a_trunk)
        }
    })
}

/// A tuft of grass: fourteen blades, each a sliver from the bottom edge to a
/// tip, leaning and tapering; at least 8 texels clear of the side edges, so
/// a neighbour in a sprite sheet never bleeds in.
fn grass() -> image::RgbaImage {
    let blades: Vec<(f32, f32, f32)> = (0..14)
        .map(|i| {
            let base = 24.0 + 80.0 * hash2(i, 1);
            let lean = 30.0 * (hash2(i, 2) - 0.5);
            let tip = 10.0 + 50.0 * hash2(i, 3);
            (base, lean, tip)
        })
        .collect();
    image::RgbaImage::from_fn(128, 128, |x, y| {
        let (px, py) = (x as f32 + 0.5, y as f32 + 0.5);
        let mut best = (0.0f32, 0usize);
        for (i, &(base, lean, tip)) in blades.iter().enumerate() {
            if py < tip {
                continue;
            }
            let t = (py - tip) / (128.0 - tip); // 0 at the tip, 1 at the base
            let centre = base + lean * (1.0 - t);
            let half_width = 0.5 + 3.0 * t;
            let a = coverage((px - centre).abs() - half_width);
            if a > best.0 {
                best = (a, i);
            }
        }
        let shade = 0.8 + 0.4 * hash2(best.1 as u32, 4) - 0.3 * (py / 128.0);
        rgba([0.22 * shade, 0.55 * shade, 0.15 * shade], best.0)
    })
}

/// A small integer hash mapped to 0..1 (deterministic "noise").
fn hash(mut x: u32) -> f32 {
    x ^= x >> 16;
    x = x.wrapping_mul(0x7feb_352d);
    x ^= x >> 15;
    x = x.wrapping_mul(0x846c_a68b);
    x ^= x >> 16;
    (x >> 8) as f32 / (1u32 << 24) as f32
}

fn hash2(a: u32, b: u32) -> f32 {
    hash(a.wrapping_mul(0x9e37_79b9) ^ b.wrapping_add(0x632b_e5ab))
}

fn checker() -> image::RgbImage {
    let cream = [236, 224, 197];
    let teal = [52, 110, 122];
    image::RgbImage::from_fn(256, 256, |x, y| {
        image::Rgb(if (x / 32 + y / 32) % 2 == 0 {
            cream
        } else {
            teal
        })
    })
}

/// The height of the bricks at image position (x, y) in texels (y down, as
/// `bricks` lays them out): 0 in the mortar, rising over a 3-texel bevel to
/// 1.5 texels on a brick's face, plus a little grain.
fn bricks_height(x: f64, y: f64) -> f64 {
    const BRICK_W: f64 = 64.0;
    const BRICK_H: f64 = 32.0;
    const MORTAR: f64 = 3.0;
    let (x, y) = (x.rem_euclid(256.0), y.rem_euclid(256.0));
    let row = (y / BRICK_H).floor();
    let xs = (x + (row % 2.0) * BRICK_W / 2.0).rem_euclid(256.0);
    let (bx, by) = (xs % BRICK_W - MORTAR, y % BRICK_H - MORTAR);
    // Distance to the brick's nearest edge (negative in the mortar).
    let edge = bx
        .min(BRICK_W - MORTAR - bx)
        .min(by)
        .min(BRICK_H - MORTAR - by);
    1.5 * (edge / 3.0).clamp(0.0, 1.0)
}

fn bricks_normal() -> image::RgbImage {
    // Heights in uv units: texels / 256; the image row of v is (1 - v) 256.
    let texels = gloss::math::bump::bake_normal_map(256, 256, |u, v| {
        bricks_height(u * 256.0, (1.0 - v) * 256.0) / 256.0
    });
    image::RgbImage::from_fn(256, 256, |x, y| image::Rgb(texels[(y * 256 + x) as usize]))
}

/// The depth of the bricks' relief in texture uv units: the height_scale
/// of scenes/parallax.toml's brick materials.
const PARALLAX_DEPTH: f64 = 0.04;

/// `bricks_height` as a height map, 0 (mortar) to 1 (a brick's face).
fn bricks_height_map() -> image::RgbImage {
    image::RgbImage::from_fn(256, 256, |x, y| {
        let h = bricks_height(x as f64 + 0.5, y as f64 + 0.5) / 1.5;
        let g = (h.clamp(0.0, 1.0) * 255.0).round() as u8;
        image::Rgb([g, g, g])
    })
}

/// The normals of that relief, `PARALLAX_DEPTH` deep.
fn bricks_parallax_normal() -> image::RgbImage {
    let texels = gloss::math::bump::bake_normal_map(256, 256, |u, v| {
        PARALLAX_DEPTH * bricks_height(u * 256.0, (1.0 - v) * 256.0) / 1.5
    });
    image::RgbImage::from_fn(256, 256, |x, y| image::Rgb(texels[(y * 256 + x) as usize]))
}

fn uv_ramp() -> image::RgbImage {
    // Image row 0 is the top: v = 1 (the loader flips it for GL).
    image::RgbImage::from_fn(64, 64, |x, y| {
        let line = x % 8 == 0 || y % 8 == 7;
        image::Rgb([
            (4 * x + 2) as u8,
            (4 * (63 - y) + 2) as u8,
            if line { 255 } else { 40 },
        ])
    })
}

/// A unit disc in the xz plane facing +y: a fan of `n` triangles.
fn disc(n: u32) -> MeshData {
    let mut m = MeshData::default();
    let vertex = |p: Vec3| Vertex {
        position: p.to_array(),
        normal: [0.0, 1.0, 0.0],
        uv: [0.5 + 0.5 * p.x, 0.5 - 0.5 * p.z],
        tangent: [1.0, 0.0, 0.0, 1.0],
    };
    m.vertices.push(vertex(Vec3::ZERO));
    for i in 0..n {
        let a = std::f32::consts::TAU * i as f32 / n as f32;
        // Counter-clockwise seen from +y: x then -z.
        m.vertices.push(vertex(Vec3::new(a.cos(), 0.0, -a.sin())));
    }
    for i in 0..n {
        m.indices.extend_from_slice(&[0, 1 + i, 1 + (i + 1) % n]);
    }
    m
}

fn ripples() -> image::RgbImage {
    image::RgbImage::from_fn(256, 256, |x, y| {
        // Two families of waves that tile (whole periods across the
        // texture), plus a little grain.
        let (u, v) = (x as f32 / 256.0, y as f32 / 256.0);
        let tau = std::f32::consts::TAU;
        let w = 0.5 * (tau * (6.0 * u + 2.0 * v)).sin() + 0.5 * (tau * (3.0 * v - 4.0 * u)).sin();
        let t = 0.775 + 0.2 * w * 0.5 + 0.025 * (hash2(x, y) - 0.5);
        let g = (t.clamp(0.55, 1.0) * 255.0).round() as u8;
        image::Rgb([g, g, g])
    })
}

fn bricks() -> image::RgbImage {
    const BRICK_W: u32 = 64;
    const BRICK_H: u32 = 32;
    const MORTAR: u32 = 3;
    image::RgbImage::from_fn(256, 256, |x, y| {
        let row = y / BRICK_H;
        // Running bond: every other row shifted by half a brick (wraps, so
        // the texture tiles).
        let xs = (x + (row % 2) * BRICK_W / 2) % 256;
        let col = xs / BRICK_W;
        let (bx, by) = (xs % BRICK_W, y % BRICK_H);
        let grain = hash2(x, y);
        let colour = if bx < MORTAR || by < MORTAR {
            let g = 170.0 + 25.0 * grain;
            [g, g * 0.97, g * 0.9]
        } else {
            // Each brick its own shade of red-brown, darker toward the edges.
            let tone = hash2(col + 17, row + 91);
            let edge =
                (bx.min(BRICK_W - 1 - bx).min(by.min(BRICK_H - 1 - by)) as f32 / 4.0).min(1.0);
            let k = (0.8 + 0.2 * edge) * (0.9 + 0.15 * grain);
            [
                (150.0 + 50.0 * tone) * k,
                (62.0 + 25.0 * tone) * k,
                (45.0 + 15.0 * tone) * k,
            ]
        };
        image::Rgb(colour.map(|c| c.clamp(0.0, 255.0) as u8))
    })
}

/// A tube of radius 0.18 around the (p, q) torus knot on a torus of radii 1
/// and 0.45, `rings` segments along the curve and `sides` around the tube.
/// u runs along the curve (0..8, so textures tile along it), v around the
/// tube; counter-clockwise seen from outside.
fn torus_knot(p: u32, q: u32, rings: u32, sides: u32) -> MeshData {
    let (p, q) = (p as f32, q as f32);
    let curve = |t: f32| {
        let r = 1.0 + 0.45 * (q * t).cos();
        Vec3::new(r * (p * t).cos(), 0.45 * (q * t).sin(), r * (p * t).sin())
    };
    let tube = 0.18;
    let step = std::f32::consts::TAU / rings as f32;
    let mut m = MeshData::default();
    for i in 0..=rings {
        let t = (i % rings) as f32 * step;
        let h = 1e-3;
        let (a, b, c) = (curve(t - h), curve(t), curve(t + h));
        let tangent = (c - a).normalize();
        // Frenet frame: the knot's curvature never vanishes.
        let accel = (c - 2.0 * b + a) / (h * h);
        let normal = (accel - tangent * tangent.dot(accel)).normalize();
        let binormal = tangent.cross(normal);
        for j in 0..=sides {
            let phi = std::f32::consts::TAU * (j % sides) as f32 / sides as f32;
            let n = normal * phi.cos() + binormal * phi.sin();
            m.vertices.push(Vertex {
                position: (b + n * tube).to_array(),
                normal: n.to_array(),
                uv: [8.0 * i as f32 / rings as f32, j as f32 / sides as f32],
                tangent: [0.0; 4],
            });
        }
    }
    let at = |i: u32, j: u32| i * (sides + 1) + j;
    for i in 0..rings {
        for j in 0..sides {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            m.indices.extend_from_slice(&[a, b, c, a, c, d]);
        }
    }
    // Make sure the frame's orientation gives outward-facing CCW triangles.
    let t = &m.indices[0..3];
    let pos = |k: usize| Vec3::from(m.vertices[t[k] as usize].position);
    let face = (pos(1) - pos(0)).cross(pos(2) - pos(0));
    if face.dot(Vec3::from(m.vertices[t[0] as usize].normal)) < 0.0 {
        for tri in m.indices.chunks_exact_mut(3) {
            tri.swap(1, 2);
        }
    }
    m
}

/// An icosphere (`subdivisions` times: 2 gives 320 triangles, 5 gives
/// 20480) pushed in and out along the radius by a deterministic function of
/// position (so vertices split at the uv seam move together), squashed a
/// little in y.
fn rock(subdivisions: u32) -> MeshData {
    let mut m = geometry::icosphere(subdivisions);
    for v in &mut m.vertices {
        let p = Vec3::from(v.position);
        let bump = 0.12 * (3.1 * p.x + 1.3).sin() * (2.7 * p.y - 0.4).cos()
            + 0.07 * (5.3 * p.z + 2.1 * p.x).sin()
            + 0.05 * (7.9 * p.y + 3.3 * p.z).cos();
        let q = p * (1.0 + bump);
        v.position = [q.x, q.y * 0.75, q.z];
    }
    m
}

/// Writes positions once per distinct position (so the rock's seam-split
/// vertices share a `v` and get one welded normal), uvs per vertex, and
/// normals only if asked.
fn write_obj(path: &Path, m: &MeshData, normals: bool, what: &str) -> Result<()> {
    let mut out = String::new();
    writeln!(out, "# gloss scenes/assets: {what}")?;
    writeln!(
        out,
        "# generated by scenes/assets/generate.rs (cargo run --release --example gen_assets)"
    )?;
    writeln!(
        out,
        "o {}",
        path.file_stem().unwrap_or_default().to_string_lossy()
    )?;
    let mut position_index = std::collections::HashMap::new();
    let mut v_of = Vec::with_capacity(m.vertices.len());
    for v in &m.vertices {
        let text = format!(
            "{:.5} {:.5} {:.5}",
            v.position[0], v.position[1], v.position[2]
        );
        let next = position_index.len() + 1;
        let index = *position_index.entry(text.clone()).or_insert_with(|| {
            writeln!(out, "v {text}").ok();
            next
        });
        v_of.push(index);
    }
    for v in &m.vertices {
        let uv = Vec2::from(v.uv);
        writeln!(out, "vt {:.5} {:.5}", uv.x, uv.y)?;
    }
    if normals {
        for v in &m.vertices {
            writeln!(
                out,
                "vn {:.5} {:.5} {:.5}",
                v.normal[0], v.normal[1], v.normal[2]
            )?;
        }
    }
    for t in m.indices.chunks_exact(3) {
        out.push('f');
        for &i in t {
            let (v, k) = (v_of[i as usize], i as usize + 1);
            if normals {
                write!(out, " {v}/{k}/{k}")?;
            } else {
                write!(out, " {v}/{k}")?;
            }
        }
        out.push('\n');
    }
    std::fs::write(path, &out).with_context(|| format!("writing {}", path.display()))?;
    println!(
        "wrote {} ({} triangles, {} bytes)",
        path.display(),
        m.indices.len() / 3,
        out.len()
    );
    Ok(())
}
