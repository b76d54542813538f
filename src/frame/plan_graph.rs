//! The frame plan as a data-flow diagram (`gloss plan SCENE --dot FILE`),
//! like notes 03's "Pipeline Overview": each pass a box in frame order, each
//! target an ellipse, an arrow from a pass to the target it writes and from
//! a target to each pass that reads it. Written in Graphviz's DOT language,
//! plain text that `dot -Tsvg plan.dot > plan.svg` draws (and that a
//! student can read as it is); gloss draws nothing itself.

use crate::frame::plan::FramePlan;
use std::collections::BTreeSet;
use std::fmt::Write as _;

/// The DOT text of `plan`, titled `title`. Alike passes in a row (the four
/// bloom levels) stay separate boxes, numbered as `gloss plan` numbers them.
pub fn dot(plan: &FramePlan, title: &str) -> String {
    let mut out = String::new();
    let quote = |s: &str| format!("\"{}\"", s.replace('\\', "\\\\").replace('"', "\\\""));
    let _ = writeln!(out, "digraph {} {{", quote(title));
    let _ = writeln!(out, "  rankdir = TB;");
    let _ = writeln!(out, "  node [fontname = \"Helvetica\", fontsize = 11];");
    let mut targets = BTreeSet::new();
    for p in &plan.passes {
        targets.insert(p.target);
        targets.extend(p.reads.iter().copied());
    }
    for t in &targets {
        let _ = writeln!(
            out,
            "  {} [shape = ellipse, style = filled, fillcolor = \"#eef3fb\"];",
            quote(&format!("target: {t}"))
        );
    }
    for (i, p) in plan.passes.iter().enumerate() {
        let name = format!("{}. {}", i + 1, p.name);
        let _ = writeln!(out, "  {} [shape = box];", quote(&name));
        for r in &p.reads {
            let _ = writeln!(
                out,
                "  {} -> {};",
                quote(&format!("target: {r}")),
                quote(&name)
            );
        }
        let _ = writeln!(
            out,
            "  {} -> {};",
            quote(&name),
            quote(&format!("target: {}", p.target))
        );
    }
    // The passes in frame order, down the page.
    for i in 0..plan.passes.len().saturating_sub(1) {
        let _ = writeln!(
            out,
            "  {} -> {} [style = invis, weight = 10];",
            quote(&format!("{}. {}", i + 1, plan.passes[i].name)),
            quote(&format!("{}. {}", i + 2, plan.passes[i + 1].name))
        );
    }
    out.push_str("}\n");
    out
}
