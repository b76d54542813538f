//! Each pass of the plan, run inside its own KHR_debug group named as
//! `gloss plan` names the pass (so RenderDoc and apitrace show the frame's
//! structure), and labelled for `gloss trace`.

use crate::frame::plan::Pass;
use crate::frame::{Frame, RunPasses};
use crate::gl::trace::{self, PassLabel};
use crate::techniques;
use glow::HasContext;

/// Whether this GL has debug groups (KHR_debug, core in 4.3).
pub fn has_debug_groups(gl: &glow::Context) -> bool {
    gl.supported_extensions().contains("GL_KHR_debug")
        || gl.version().major >= 5
        || (gl.version().major == 4 && gl.version().minor >= 3)
}

/// Run pass number `number` (1-based) of the plan with `technique`;
/// `title` is the pass named by what it draws (`FramePlan::title`). First
/// the technique builds what it builds on first use (`RunPasses::prepare`):
/// a shader that fails there is the frame's error.
pub fn run_pass(
    number: usize,
    pass: &Pass,
    title: &str,
    technique: &dyn RunPasses,
    frame: &Frame,
    groups: bool,
) -> anyhow::Result<()> {
    technique.prepare(pass, frame)?;
    let registered = techniques::ALL[pass.technique];
    let name = format!("{number}. {title} ({})", registered.name);
    if groups {
        unsafe {
            frame
                .gl
                .push_debug_group(glow::DEBUG_SOURCE_APPLICATION, number as u32, &name)
        };
    }
    trace::enter_pass(PassLabel {
        number,
        pass: pass.name.to_string(),
        title: title.to_string(),
        technique: registered.name,
        notes: registered.notes,
        file: registered.file,
    });
    technique.run(pass, frame);
    trace::leave_pass();
    if groups {
        unsafe { frame.gl.pop_debug_group() };
    }
    Ok(())
}
