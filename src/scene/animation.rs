//! Keyframe animation of objects (notes 01 §7, "Animation": "key frames",
//! values given at some times and interpolated between). A scene's
//! `[animation]` table gives the instant to show and tracks that move
//! objects:
//!
//! ```toml
//! [animation]
//! time = 0.75                  # seconds; `gloss render --time 1.25` sets it
//!
//! [[animation.tracks]]
//! object = "box"               # an object's name
//! interpolation = "linear"     # "step", "linear" (the default) or "cubic"
//! times = [0.0, 1.0, 2.0]      # seconds, increasing
//! position = [[0, 0, 0], [2, 0, 0], [2, 1, 0]]            # optional
//! rotation = [[0, 0, 0, 1], [0, 0.7071, 0, 0.7071], ...]  # optional, quaternions (x, y, z, w)
//! scale = [[1, 1, 1], ...]                                # optional
//! ```
//!
//! At a time, each track gives its object a local position, rotation and
//! scale from `math::keyframes` (rotations by `math::slerp`). Children
//! follow through the model-matrix chain (`update_models`). The time is an
//! input, never the clock, so a test or a bench renders any instant exactly.
//!
//! Notes 01 §7: "combine/blend several animations that affect different
//! parts of a model tree". A track may name a `clip`; `[animation.weights]`
//! gives each clip a weight (default 1). Clips on different objects each
//! move their own part of the tree. Clips on the same object are blended by
//! weight (a cross-fade). What the weights leave below 1 goes to the
//! object's pose in the file, so a clip at weight 0.3 moves its object 30%
//! of the way from rest.

use super::{Object, Scene};
use crate::math::keyframes::{Interpolation, Track};
use anyhow::{Result, anyhow, bail};
use glam::{Quat, Vec3};
use serde::Deserialize;

#[derive(Deserialize, Debug, Default, Clone)]
#[serde(deny_unknown_fields)]
pub(super) struct AnimationFile {
    #[serde(default)]
    pub(super) time: f32,
    #[serde(default)]
    pub(super) tracks: Vec<TrackFile>,
    /// Each clip's weight (default 1).
    #[serde(default)]
    pub(super) weights: std::collections::BTreeMap<String, f32>,
}

#[derive(Deserialize, Debug, Clone)]
#[serde(deny_unknown_fields)]
pub(super) struct TrackFile {
    object: String,
    clip: Option<String>,
    interpolation: Option<String>,
    times: Vec<f32>,
    position: Option<Vec<[f32; 3]>>,
    rotation: Option<Vec<[f32; 4]>>,
    scale: Option<Vec<[f32; 3]>>,
}

/// One object's tracks in one clip.
#[derive(Clone, Debug, PartialEq)]
pub struct ObjectTracks {
    /// Index into the scene's objects.
    pub object: usize,
    /// The clip it belongs to ("main" unless the file names one).
    pub clip: String,
    /// The clip's weight.
    pub weight: f32,
    pub position: Option<Track<Vec3>>,
    pub rotation: Option<Track<Quat>>,
    pub scale: Option<Track<Vec3>>,
}

/// An object's pose as the file writes it: what an animation whose
/// weights add up to less than 1 blends with.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pose {
    pub position: Vec3,
    pub rotation: Quat,
    pub scale: Vec3,
}

/// The instant shown, the tracks, and the file's pose of every animated
/// object.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Animation {
    pub time: f32,
    pub tracks: Vec<ObjectTracks>,
    /// (object, its pose in the file), one per animated object.
    pub rest: Vec<(usize, Pose)>,
}

impl Animation {
    /// The first and last key over every track (None: no tracks).
    pub fn span(&self) -> Option<(f32, f32)> {
        let spans = (self.tracks.iter()).flat_map(|t| {
            [
                t.position.as_ref().map(Track::span),
                t.rotation.as_ref().map(Track::span),
                t.scale.as_ref().map(Track::span),
            ]
        });
        spans.flatten().reduce(|a, b| (a.0.min(b.0), a.1.max(b.1)))
    }
}

fn interpolation(key: &str, word: Option<&str>) -> Result<Interpolation> {
    match word.unwrap_or("linear") {
        "step" => Ok(Interpolation::Step),
        "linear" => Ok(Interpolation::Linear),
        "cubic" => Ok(Interpolation::Cubic),
        w => {
            bail!("{key}.interpolation: expected \"step\", \"linear\" or \"cubic\", found \"{w}\"")
        }
    }
}

/// Check the `[animation]` table against the scene's objects.
pub(super) fn resolve(f: &AnimationFile, objects: &[Object]) -> Result<Animation> {
    if !f.time.is_finite() {
        bail!(
            "animation.time: expected a finite number of seconds, found {}",
            f.time
        );
    }
    for (clip, &w) in &f.weights {
        if !(w.is_finite() && w >= 0.0) {
            bail!("animation.weights.{clip}: expected a weight >= 0, found {w}");
        }
        if !f
            .tracks
            .iter()
            .any(|t| t.clip.as_deref().unwrap_or(MAIN) == clip)
        {
            bail!("animation.weights.{clip}: no track belongs to a clip named \"{clip}\"");
        }
    }
    let mut tracks: Vec<ObjectTracks> = Vec::new();
    for (i, t) in f.tracks.iter().enumerate() {
        let key = format!("animation.tracks[{i}]");
        let object = (objects.iter().position(|o| o.name == t.object))
            .ok_or_else(|| anyhow!("{key}.object: no object named \"{}\"", t.object))?;
        let clip = t.clip.clone().unwrap_or_else(|| MAIN.to_string());
        if let Some(j) = (tracks.iter()).position(|o| o.object == object && o.clip == clip) {
            bail!(
                "{key}.object: \"{}\" is already moved by animation.tracks[{j}] in clip \"{clip}\"; give one track per object and clip",
                t.object
            );
        }
        if t.position.is_none() && t.rotation.is_none() && t.scale.is_none() {
            bail!("{key}: give position, rotation or scale keys (or more than one)");
        }
        let how = interpolation(&key, t.interpolation.as_deref())?;
        let vec3 = |name: &str, v: &Option<Vec<[f32; 3]>>| -> Result<Option<Track<Vec3>>> {
            v.as_ref()
                .map(|v| {
                    for (k, a) in v.iter().enumerate() {
                        let at = format!("{key}.{name}[{k}]");
                        super::camera_limits::within_world(&at, a)?;
                    }
                    let values = v.iter().map(|&a| Vec3::from(a)).collect();
                    Track::new(&format!("{key}.{name}"), t.times.clone(), values, how)
                })
                .transpose()
        };
        let rotation = (t.rotation.as_ref())
            .map(|v| {
                let values = v
                    .iter()
                    .map(|&[x, y, z, w]| Quat::from_xyzw(x, y, z, w))
                    .collect();
                Track::new(&format!("{key}.rotation"), t.times.clone(), values, how)
            })
            .transpose()?;
        let weight = f.weights.get(&clip).copied().unwrap_or(1.0);
        tracks.push(ObjectTracks {
            object,
            clip,
            weight,
            position: vec3("position", &t.position)?,
            rotation,
            scale: vec3("scale", &t.scale)?,
        });
    }
    let mut rest: Vec<(usize, Pose)> = Vec::new();
    for t in &tracks {
        if !rest.iter().any(|(o, _)| *o == t.object) {
            let o = &objects[t.object];
            let pose = Pose {
                position: o.position,
                rotation: o
                    .orientation
                    .unwrap_or_else(|| Quat::from_mat4(&o.local()))
                    .normalize(),
                scale: o.scale,
            };
            rest.push((t.object, pose));
        }
    }
    Ok(Animation {
        time: f.time,
        tracks,
        rest,
    })
}

/// The clip of tracks that name none.
pub const MAIN: &str = "main";

/// One clip's values for an object at an instant, and the clip's weight.
struct Sample {
    weight: f32,
    position: Option<Vec3>,
    rotation: Option<Quat>,
    scale: Option<Vec3>,
}

/// Weighted sum of the samples that have a value, and `rest` with what the
/// weights leave below 1 (the sum normalised when they reach 1).
fn blend_vec3(samples: &[Sample], pick: impl Fn(&Sample) -> Option<Vec3>, rest: Vec3) -> Vec3 {
    let (mut sum, mut w) = (Vec3::ZERO, 0.0);
    for s in samples {
        if let Some(v) = pick(s) {
            sum += v * s.weight;
            w += s.weight;
        }
    }
    if w >= 1.0 {
        sum / w
    } else {
        sum + rest * (1.0 - w)
    }
}

/// Blend poses: each clip's value with its weight, and the file's pose with
/// what the weights leave below 1. Positions and scales are weighted sums;
/// rotations a weighted sum of quaternions turned onto one hemisphere,
/// normalised (for two, the normalised lerp: between the two, but not at a
/// constant rate as slerp would be).
fn blend(rest: Pose, samples: &[Sample]) -> Pose {
    let position = blend_vec3(samples, |s| s.position, rest.position);
    let scale = blend_vec3(samples, |s| s.scale, rest.scale);
    let (mut q, mut w) = (Quat::from_xyzw(0.0, 0.0, 0.0, 0.0), 0.0);
    let mut anchor: Option<Quat> = None;
    let mut add = |r: Quat, weight: f32| {
        let a = *anchor.get_or_insert(r);
        let r = if r.dot(a) < 0.0 { -r } else { r };
        q += r * weight;
    };
    for s in samples {
        if let Some(r) = s.rotation {
            add(r, s.weight);
            w += s.weight;
        }
    }
    if w < 1.0 {
        add(rest.rotation, 1.0 - w);
    }
    let rotation = if q.length() > 1e-12 {
        q.normalize()
    } else {
        rest.rotation
    };
    Pose {
        position,
        rotation,
        scale,
    }
}

impl Scene {
    /// The span of time worth playing: the keys' and the skinned meshes'
    /// clips' span, or for a scene with
    /// particles and no keys, four lifetimes of its fountain (the demo
    /// loops over it). None: nothing in the scene moves with time.
    pub fn playable_span(&self) -> Option<(f32, f32)> {
        let keys = match (self.animation.span(), self.skin_span()) {
            (Some(a), Some(b)) => Some((a.0.min(b.0), a.1.max(b.1))),
            (a, b) => a.or(b),
        };
        keys.or_else(|| self.particles.as_ref().map(|p| (0.0, 4.0 * p.lifetime)))
            // Exploding objects swing with sin(t): one period.
            .or_else(|| self.render.explode.then_some((0.0, std::f32::consts::TAU)))
    }

    /// Show the instant `time` (seconds): each animated object's local
    /// transform from its tracks, then every model matrix again. A time
    /// that is not finite is refused and changes nothing.
    pub fn set_time(&mut self, time: f32) -> Result<()> {
        if !time.is_finite() {
            bail!("animation time: expected a finite number of seconds, found {time}");
        }
        self.animation.time = time;
        // Each object's tracks, gathered once: linear in the tracks (a
        // glTF file can animate a great many nodes).
        let mut by_object: std::collections::HashMap<usize, Vec<&ObjectTracks>> =
            Default::default();
        for t in &self.animation.tracks {
            by_object.entry(t.object).or_default().push(t);
        }
        for &(object, rest) in &self.animation.rest {
            let samples: Vec<Sample> = (by_object.get(&object).into_iter().flatten())
                .map(|t| Sample {
                    weight: t.weight,
                    position: t.position.as_ref().map(|p| p.sample(time)),
                    rotation: t.rotation.as_ref().map(|r| r.sample(time)),
                    scale: t.scale.as_ref().map(|s| s.sample(time)),
                })
                .collect();
            let pose = blend(rest, &samples);
            let o = &mut self.objects[object];
            o.position = pose.position;
            o.orientation = Some(pose.rotation);
            o.scale = pose.scale;
        }
        super::update_models(&mut self.objects);
        Ok(())
    }
}
