//! One pass of the frame plan (src/frame/plan.rs): what it draws, where it
//! writes, which technique's file runs it, and what it reads. Techniques
//! make their passes (`Technique::passes`), the plan orders them, the
//! renderer runs them.

use crate::frame::plan_programs::{CompositeNeeds, PlanProgram};

#[derive(Clone, Debug, PartialEq)]
pub struct Pass {
    pub name: &'static str,
    /// Which of its technique's passes this is (a technique with one pass: 0).
    pub step: u32,
    /// Where the pass writes.
    pub target: &'static str,
    /// What the pass draws, in words (e.g. "12 objects", "256 spheres").
    pub draws: String,
    /// Source file that implements it (`file!()`).
    pub code: &'static str,
    /// Index of its technique in the registry the plan was made from.
    pub technique: usize,
    /// Index of the view it draws for in `FramePlan::views` (0: the camera).
    pub view: usize,
    /// What one of several alike passes is about (a mirror's object index).
    pub item: usize,
    /// A number the pass needs (the stencil value a mirror pass writes).
    pub value: u32,
    /// The mip level of its target it draws into (0: the full-size image;
    /// bloom's blurs draw into levels 1-4).
    pub level: u32,
    /// Whether it needs its target's depth-stencil buffer. Every pass that
    /// draws geometry does; the deferred composite, one triangle over every
    /// pixel, does not (it copies the G-buffer's depth only for the passes
    /// that come after it). A world image no pass needs depth from has none.
    pub needs_depth: bool,
    /// The targets it reads (the data-flow diagram's edges into it,
    /// src/frame/plan_graph.rs): declared by the passes of notes 03's
    /// pipeline; empty where a pass does not say.
    pub reads: Vec<&'static str>,
    /// The lighting variant its shader is compiled for, in words
    /// (src/frame/variant.rs); None for a pass without one.
    pub variant: Option<String>,
    /// The cube face it draws (0..6: +X, -X, +Y, -Y, +Z, -Z, GL's order),
    /// for a point light's shadow drawn one face per pass; `ALL_FACES`
    /// for a pass that reaches all six at once (gl_Layer); None otherwise.
    pub face: Option<usize>,
    /// The programs it draws with, each with its `#define`s
    /// (src/frame/plan_programs.rs); empty where a pass does not say.
    pub programs: Vec<PlanProgram>,
    /// The composite's needs, but its target's: the plan completes them
    /// and names the program once the target is known.
    pub composite: Option<CompositeNeeds>,
}

/// The cube faces as GL orders them (GL_TEXTURE_CUBE_MAP_POSITIVE_X + i).
pub const CUBE_FACES: [&str; 6] = ["+X", "-X", "+Y", "-Y", "+Z", "-Z"];

/// `Pass::face` of a pass that draws all six faces of a cube in one go.
pub const ALL_FACES: usize = 6;

impl Pass {
    /// A pass of the technique in file `code` (step 0).
    pub fn new(
        name: &'static str,
        target: &'static str,
        draws: String,
        code: &'static str,
    ) -> Pass {
        Pass {
            name,
            step: 0,
            target,
            draws,
            code,
            technique: 0,
            view: 0,
            item: 0,
            value: 0,
            level: 0,
            needs_depth: true,
            reads: Vec::new(),
            variant: None,
            face: None,
            programs: Vec::new(),
            composite: None,
        }
    }

    /// The same pass, drawing with `programs`.
    pub fn with_programs(self, programs: Vec<PlanProgram>) -> Pass {
        Pass { programs, ..self }
    }

    /// The same pass, the composite with `needs` (its target's to come).
    pub fn with_composite(self, needs: CompositeNeeds) -> Pass {
        Pass {
            composite: Some(needs),
            ..self
        }
    }

    /// The same pass, reading `targets`.
    pub fn reading(mut self, targets: &[&'static str]) -> Pass {
        self.reads.extend_from_slice(targets);
        self
    }

    /// The same pass, its shader compiled as lighting variant `variant`.
    pub fn with_variant(self, variant: String) -> Pass {
        Pass {
            variant: Some(variant),
            ..self
        }
    }

    /// The same pass, needing no depth-stencil buffer in its target.
    pub fn without_depth(self) -> Pass {
        Pass {
            needs_depth: false,
            ..self
        }
    }

    /// The same pass, as step `step` of its technique.
    pub fn step(self, step: u32) -> Pass {
        Pass { step, ..self }
    }

    /// The same pass, about `item`, with `value`.
    pub fn about(self, item: usize, value: u32) -> Pass {
        Pass {
            item,
            value,
            ..self
        }
    }

    /// The same pass, drawing into mip level `level` of its target.
    pub fn level(self, level: u32) -> Pass {
        Pass { level, ..self }
    }

    /// The same pass, drawing cube face `face` (an index of `CUBE_FACES`,
    /// or `ALL_FACES`).
    pub fn face(self, face: usize) -> Pass {
        Pass {
            face: Some(face),
            ..self
        }
    }

    /// The same pass, drawing for view `view`.
    pub fn for_view(self, view: usize) -> Pass {
        Pass { view, ..self }
    }
}
