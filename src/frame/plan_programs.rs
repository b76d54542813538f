//! The programs a pass of the plan draws with, named: each one's role and the
//! `#define`s it is built with besides MAX_LIGHTS (which every program
//! gets). `gloss plan` prints them under the pass. A technique names them
//! from the function its passes build them with (the G-buffer's
//! `MaterialVariant`, forward's lighting variant, the shadow pass's caster
//! programs), so the plan says what the frame compiles: tests/trace/plan_programs.rs
//! reads the defines of the programs a frame used back from the trace.
//!
//! The composite's program depends on the target it draws into (with a
//! depth buffer or not, sRGB or not), which the plan knows only once every
//! pass is in: its pass carries `CompositeNeeds` without them, and the plan
//! completes them (`at_output`), as the composite does from its target.

/// One program of a pass: what it is for, and its `#define`s.
#[derive(Clone, Debug, PartialEq)]
pub struct PlanProgram {
    /// "G-buffer", "depth only", "alpha test", "Phong", "composite".
    pub role: &'static str,
    pub defines: Vec<(&'static str, String)>,
}

impl PlanProgram {
    pub fn new(role: &'static str, defines: Vec<(&'static str, String)>) -> PlanProgram {
        PlanProgram { role, defines }
    }

    /// The defines as `gloss plan` prints them: `NO_PBR=1 VARIANT_POINT=0`,
    /// or "no defines".
    pub fn defines_text(&self) -> String {
        if self.defines.is_empty() {
            return "no defines (the general program)".into();
        }
        (self.defines.iter())
            .map(|(k, v)| format!("{k}={v}"))
            .collect::<Vec<_>>()
            .join(" ")
    }
}

/// Which of its programs the composite (src/techniques/deferred/composite.rs)
/// draws with: writing the G-buffer's depth into its target (it has a depth
/// buffer: something after the composite tests depth), tinting each pixel by
/// its cascade, writing linear light for GL to encode (an sRGB target that
/// wants encoded values), and the ambient term's parts the frame has.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CompositeNeeds {
    pub depth: bool,
    pub tints: bool,
    pub hardware: bool,
    pub ibl: bool,
    pub ambient_occlusion: bool,
    pub emission: bool,
}

impl CompositeNeeds {
    /// These needs drawing into a target with a depth buffer or not
    /// (`depth`), of format SRGB8_ALPHA8 or not (`srgb`), for an output
    /// that wants encoded values (`encoded`: every output but the linear one
    /// error measurements read).
    pub fn at_output(self, depth: bool, srgb: bool, encoded: bool) -> CompositeNeeds {
        CompositeNeeds {
            depth,
            hardware: encoded && srgb,
            ..self
        }
    }

    /// Its index among the composite's 64 programs.
    pub fn index(&self) -> usize {
        [
            self.depth,
            self.tints,
            self.hardware,
            self.ibl,
            self.ambient_occlusion,
            self.emission,
        ]
        .iter()
        .fold(0, |i, &on| i * 2 + usize::from(on))
    }

    /// The composite's `#define`s.
    pub fn defines(&self) -> Vec<(&'static str, String)> {
        [
            (self.depth, "WRITE_DEPTH"),
            (self.tints, "CASCADE_TINTS"),
            (self.hardware, "HARDWARE_SRGB"),
            (!self.ibl, "NO_IBL"),
            (!self.ambient_occlusion, "NO_AMBIENT_OCCLUSION"),
            (!self.emission, "NO_EMISSION"),
        ]
        .into_iter()
        .filter(|(on, _)| *on)
        .map(|(_, name)| (name, "1".to_string()))
        .collect()
    }

    /// Its program, as the plan names it.
    pub fn program(&self) -> PlanProgram {
        PlanProgram::new("composite", self.defines())
    }
}

/// A pass's programs as `gloss plan` prints them, under the pass, wrapped:
/// "     program (G-buffer): NO_PBR=1 NO_SPECULAR_MAP=1".
pub fn print(f: &mut std::fmt::Formatter<'_>, programs: &[PlanProgram]) -> std::fmt::Result {
    const WIDTH: usize = 100;
    for p in programs {
        let mut line = format!("     program ({}):", p.role);
        for word in p.defines_text().split(' ') {
            if line.len() + 1 + word.len() > WIDTH && !line.ends_with(':') {
                writeln!(f, "{line}")?;
                line = "       ".to_string();
            }
            line.push(' ');
            line.push_str(word);
        }
        writeln!(f, "{line}")?;
    }
    Ok(())
}
