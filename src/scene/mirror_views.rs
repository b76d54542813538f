//! Which mirrors a reflected view can see, and how many views the mirrors
//! of a scene need (notes 05, "Planar Reflections": "mirrors in mirrors").
//!
//! Normal first draws, for every mirror seen in a view, the world reflected
//! in it, and inside that, every other mirror again, `render.mirror_depth`
//! levels deep. Without a test, n mirrors at depth d need about (n - 1)^d
//! views. A mirror is followed into a view only when its quad can show
//! there: some of it lies
//!
//! - in front of the parent mirror's plane (the view's clip plane),
//! - in front of the near plane and inside the parent mirror's rectangle
//!   on screen (its corners through the view's `VP * R`, clipped, then
//!   bounded), and
//! - facing the eye (a mirror is drawn with back faces culled).
//!
//! The test is conservative (a rectangle, not the polygon, and only the
//! nearest mirror's clip plane): it never drops a mirror the stencil would
//! mark. What is left is bounded by `MAX_MIRROR_VIEWS`, refused with a
//! message when the scene is read (`check`).

use super::{Projection, Scene};
use crate::math::reflection;
use anyhow::{Result, bail};
use glam::{Mat3, Mat4, Vec3, Vec4};

/// The most views a frame's mirrors may add (the camera's view not
/// counted): each is another pass over the world.
pub const MAX_MIRROR_VIEWS: usize = 256;

/// A rectangle in normalised device coordinates: x0, y0, x1, y1.
pub type Rect = [f32; 4];

/// The whole screen.
pub const SCREEN: Rect = [-1.0, -1.0, 1.0, 1.0];

/// What a view of the world is, as far as visibility goes.
#[derive(Clone, Copy, Debug)]
pub struct Seen {
    /// R: the world is drawn at `R * x`.
    pub reflection: Mat4,
    /// The nearest mirror's plane: only what lies in front of it is drawn.
    pub clip_plane: Option<Vec4>,
    /// Where on screen the view can draw (its mirror's rectangle).
    pub rect: Rect,
}

impl Seen {
    /// The camera's own view.
    pub fn camera() -> Seen {
        Seen {
            reflection: Mat4::IDENTITY,
            clip_plane: None,
            rect: SCREEN,
        }
    }
}

/// The rectangle on screen where mirror object `m` can show in view
/// `parent`, or None when it cannot show there at all.
pub fn seen_in(scene: &Scene, parent: &Seen, m: usize) -> Option<Rect> {
    let o = &scene.objects[m];
    let mirror = o.mirror.as_ref()?;
    let camera = &scene.camera;
    // Facing: only with the winding kept right and a model that keeps
    // handedness, so that culling matches the plane's side.
    if scene.render.mirror_winding
        && !mirror.curved
        && Mat3::from_mat4(o.model).determinant() > 0.0
        && let Some(plane) = o.mirror_plane()
    {
        let back = parent.reflection.inverse();
        let facing = match camera.projection {
            Projection::Perspective { .. } => {
                plane.dot(back.transform_point3(camera.eye).extend(1.0))
            }
            Projection::Orthographic { .. } => plane
                .truncate()
                .dot(back.transform_vector3(camera.eye - camera.target)),
        };
        if facing <= 0.0 {
            return None;
        }
    }
    let (lo, hi) = mirror.local_bounds;
    let mut points: Vec<Vec4> = (0..8)
        .map(|i| {
            let c = Vec3::new(
                if i & 1 == 0 { lo.x } else { hi.x },
                if i & 2 == 0 { lo.y } else { hi.y },
                if i & 4 == 0 { lo.z } else { hi.z },
            );
            o.model.transform_point3(c).extend(1.0)
        })
        .collect();
    if let Some(plane) = parent.clip_plane {
        points = clip(&points, |p| plane.dot(*p));
    }
    let vp = camera.projection(scene.aspect()) * camera.view() * parent.reflection;
    let clip_space: Vec<Vec4> = points.iter().map(|p| vp * *p).collect();
    // In front of the near plane (z >= -w), then onto the screen.
    let front = clip(&clip_space, |p| p.z + p.w);
    let mut r = [
        f32::INFINITY,
        f32::INFINITY,
        f32::NEG_INFINITY,
        f32::NEG_INFINITY,
    ];
    for p in front.iter().filter(|p| p.w > 0.0) {
        let (x, y) = (p.x / p.w, p.y / p.w);
        r = [r[0].min(x), r[1].min(y), r[2].max(x), r[3].max(y)];
    }
    let within = parent.rect;
    let r = [
        r[0].max(within[0]),
        r[1].max(within[1]),
        r[2].min(within[2]),
        r[3].min(within[3]),
    ];
    (r[0] <= r[2] && r[1] <= r[3]).then_some(r)
}

/// The part of the convex hull of `points` where `side` >= 0, as points
/// whose hull it is: those inside, and where each pair crosses (every
/// edge of the hull is among the pairs).
fn clip(points: &[Vec4], side: impl Fn(&Vec4) -> f32) -> Vec<Vec4> {
    let d: Vec<f32> = points.iter().map(&side).collect();
    let mut out: Vec<Vec4> = (points.iter().zip(&d))
        .filter(|(_, d)| **d >= 0.0)
        .map(|(p, _)| *p)
        .collect();
    for i in 0..points.len() {
        for j in i + 1..points.len() {
            if (d[i] < 0.0) != (d[j] < 0.0) {
                let t = d[i] / (d[i] - d[j]);
                out.push(points[i].lerp(points[j], t));
            }
        }
    }
    out
}

/// The view `parent` reflected in planar mirror `m`, drawn within `rect`;
/// None for a mirror with no plane (a curved one: nothing is seen in a
/// curved mirror's view again).
pub fn reflected(scene: &Scene, parent: &Seen, m: usize, rect: Rect) -> Option<Seen> {
    let plane = scene.objects[m].mirror_plane()?;
    let n = plane.truncate();
    let r = parent.reflection * reflection::reflection(-plane.w * n, n)?;
    Some(Seen {
        reflection: r,
        clip_plane: Some(plane),
        rect,
    })
}

/// How many views the mirrors of `scene` add, level by level (index 0:
/// mirrors seen by the camera), counting no further once the total
/// passes `limit`.
pub fn count(scene: &Scene, limit: usize) -> Vec<usize> {
    let mirrors = scene.mirrors();
    let mut levels = Vec::new();
    let mut total = 0;
    // (view, the mirror it is seen in)
    let mut frontier: Vec<(Seen, Option<usize>)> = vec![(Seen::camera(), None)];
    for _ in 0..scene.render.mirror_depth {
        let (mut next, mut here) = (Vec::new(), 0);
        for (view, own) in &frontier {
            for &m in mirrors.iter().filter(|&&m| Some(m) != *own) {
                let Some(rect) = seen_in(scene, view, m) else {
                    continue;
                };
                (total, here) = (total + 1, here + 1);
                if total > limit {
                    levels.push(here);
                    return levels;
                }
                // A curved mirror's view is counted, and seen into no further.
                if let Some(seen) = reflected(scene, view, m, rect) {
                    next.push((seen, Some(m)));
                }
            }
        }
        levels.push(here);
        if next.is_empty() {
            break;
        }
        frontier = next;
    }
    levels
}

/// Refuse a scene whose mirrors need more than `MAX_MIRROR_VIEWS` views,
/// saying how deep they would fit.
pub(super) fn check(scene: &Scene) -> Result<()> {
    if scene.mirrors().len() < 2 {
        return Ok(());
    }
    let levels = count(scene, MAX_MIRROR_VIEWS);
    let total: usize = levels.iter().sum();
    if total <= MAX_MIRROR_VIEWS {
        return Ok(());
    }
    let mut sum = 0;
    let fits = levels
        .iter()
        .take_while(|&&n| {
            sum += n;
            sum <= MAX_MIRROR_VIEWS
        })
        .count();
    bail!(
        "render.mirror_depth = {}: the {} mirrors see each other in more than {MAX_MIRROR_VIEWS} reflected views (gloss's limit, MAX_MIRROR_VIEWS; each view draws the world again); they fit at render.mirror_depth = {} or less",
        scene.render.mirror_depth,
        scene.mirrors().len(),
        fits.max(1)
    )
}
