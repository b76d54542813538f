//! Keyframe tracks (notes 01 §7, "Animation"): a value given at a few
//! times, and in between interpolated by one of three rules.
//!
//! - **Step**: the last key's value until the next key.
//! - **Linear**: straight between keys; for a rotation, `slerp` (the
//!   shortest arc at a constant rate).
//! - **Cubic**: a Catmull-Rom curve through the keys. Each key's tangent is
//!   the slope between its neighbours, (p[i+1] - p[i-1]) / (t[i+1] - t[i-1]),
//!   and one-sided at the ends. So the curve passes through every key, has
//!   no corner at one, and reproduces motion at a constant speed exactly.
//!   For a rotation the four quaternions are first put on one hemisphere
//!   (the shortest arcs), then interpolated as 4-vectors and normalised.
//!
//! Before the first key a track holds its first value, and after the last
//! key its last. Tracks are checked when made, so sampling never fails:
//! at least one key, as many values as times, times finite and strictly
//! increasing, values finite.

use super::slerp::slerp;
use anyhow::{Result, bail};
use glam::{Quat, Vec3, Vec4};

/// How a track fills the time between its keys.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Interpolation {
    Step,
    Linear,
    Cubic,
}

/// What a track can hold: positions and scales (Vec3) or rotations (Quat).
pub trait Keyed: Copy {
    fn is_finite_value(&self) -> bool;
    /// Straight between two keys, `s` of the way.
    fn linear(a: Self, b: Self, s: f32) -> Self;
    /// The Catmull-Rom curve from `p1` to `p2`, `s` of the way, with
    /// neighbours `p0` and `p3`: the tangents times the segment's length in
    /// time are (p2 - p0) w1 and (p3 - p1) w2.
    fn hermite(p0: Self, p1: Self, p2: Self, p3: Self, s: f32, w1: f32, w2: f32) -> Self;
}

/// The Hermite basis at s: (h00, h10, h01, h11).
fn basis(s: f32) -> (f32, f32, f32, f32) {
    let (s2, s3) = (s * s, s * s * s);
    (
        2.0 * s3 - 3.0 * s2 + 1.0,
        s3 - 2.0 * s2 + s,
        -2.0 * s3 + 3.0 * s2,
        s3 - s2,
    )
}

/// Catmull-Rom through p1 and p2 as 4-vectors. `w1`, `w2` turn the
/// neighbour differences into the tangents times the segment's length:
/// m1 = (p2 - p0) w1, m2 = (p3 - p1) w2.
fn hermite4(p0: Vec4, p1: Vec4, p2: Vec4, p3: Vec4, s: f32, w1: f32, w2: f32) -> Vec4 {
    let (h00, h10, h01, h11) = basis(s);
    p1 * h00 + (p2 - p0) * (w1 * h10) + p2 * h01 + (p3 - p1) * (w2 * h11)
}

impl Keyed for Vec3 {
    fn is_finite_value(&self) -> bool {
        self.is_finite()
    }
    fn linear(a: Vec3, b: Vec3, s: f32) -> Vec3 {
        a.lerp(b, s)
    }
    fn hermite(p0: Vec3, p1: Vec3, p2: Vec3, p3: Vec3, s: f32, w1: f32, w2: f32) -> Vec3 {
        hermite4(
            p0.extend(0.0),
            p1.extend(0.0),
            p2.extend(0.0),
            p3.extend(0.0),
            s,
            w1,
            w2,
        )
        .truncate()
    }
}

impl Keyed for Quat {
    fn is_finite_value(&self) -> bool {
        self.is_finite() && self.length() > 1e-6
    }
    fn linear(a: Quat, b: Quat, s: f32) -> Quat {
        slerp(a, b, s)
    }
    fn hermite(p0: Quat, p1: Quat, p2: Quat, p3: Quat, s: f32, w1: f32, w2: f32) -> Quat {
        // Each neighbour on p1's hemisphere, in turn: the shortest arcs.
        let near = |q: Quat, to: Quat| if q.dot(to) < 0.0 { -q } else { q };
        let p1 = p1.normalize();
        let p0 = near(p0.normalize(), p1);
        let p2 = near(p2.normalize(), p1);
        let p3 = near(p3.normalize(), p2);
        let v = hermite4(
            Vec4::from(p0),
            Vec4::from(p1),
            Vec4::from(p2),
            Vec4::from(p3),
            s,
            w1,
            w2,
        );
        Quat::from_vec4(v).normalize()
    }
}

/// Values at times, and the rule between them.
#[derive(Clone, Debug, PartialEq)]
pub struct Track<T> {
    times: Vec<f32>,
    values: Vec<T>,
    pub interpolation: Interpolation,
}

impl<T: Keyed> Track<T> {
    /// A checked track; `what` names it in errors ("objects[2].rotation").
    pub fn new(
        what: &str,
        times: Vec<f32>,
        values: Vec<T>,
        interpolation: Interpolation,
    ) -> Result<Track<T>> {
        if times.is_empty() {
            bail!("{what}: a track needs at least one key");
        }
        if times.len() != values.len() {
            bail!(
                "{what}: {} times but {} values; give one value per time",
                times.len(),
                values.len()
            );
        }
        if let Some(i) = times.iter().position(|t| !t.is_finite()) {
            bail!(
                "{what}: time {} is {}, not a finite number of seconds",
                i,
                times[i]
            );
        }
        if let Some(i) = (1..times.len()).find(|&i| times[i] <= times[i - 1]) {
            bail!(
                "{what}: times must increase, but key {i} is at {} and key {} at {}",
                times[i],
                i - 1,
                times[i - 1]
            );
        }
        if let Some(i) = values.iter().position(|v| !v.is_finite_value()) {
            bail!("{what}: value {i} is not finite (or, for a rotation, is zero)");
        }
        Ok(Track {
            times,
            values,
            interpolation,
        })
    }

    /// The keys' times, increasing.
    pub fn times(&self) -> &[f32] {
        &self.times
    }

    /// The keys' values, one per time.
    pub fn values(&self) -> &[T] {
        &self.values
    }

    /// The first and last key's times.
    pub fn span(&self) -> (f32, f32) {
        (self.times[0], self.times[self.times.len() - 1])
    }

    /// The value at time `t` (NaN: the first key's).
    pub fn sample(&self, t: f32) -> T {
        let n = self.times.len();
        if t.is_nan() || t <= self.times[0] {
            return self.values[0];
        }
        if t >= self.times[n - 1] {
            return self.values[n - 1];
        }
        // The segment [i, i + 1] holding t: times[i] <= t < times[i + 1].
        let i = self.times.partition_point(|&k| k <= t) - 1;
        let (t1, t2) = (self.times[i], self.times[i + 1]);
        let s = (t - t1) / (t2 - t1);
        let v = &self.values;
        match self.interpolation {
            Interpolation::Step => v[i],
            Interpolation::Linear => T::linear(v[i], v[i + 1], s),
            Interpolation::Cubic => {
                // Neighbours, and the tangents' time spans (one-sided at the ends).
                let (i0, i3) = (i.saturating_sub(1), (i + 2).min(n - 1));
                let dt = t2 - t1;
                let w1 = dt / (self.times[i + 1] - self.times[i0]);
                let w2 = dt / (self.times[i3] - self.times[i]);
                T::hermite(v[i0], v[i], v[i + 1], v[i3], s, w1, w2)
            }
        }
    }
}

#[cfg(test)]
mod tests;
