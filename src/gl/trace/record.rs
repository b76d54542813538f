//! The recording: on the thread whose context is current, between `start`
//! and `stop`, each shim's call is kept with its arguments shown, the source
//! line that made it, and the pass it belongs to.

use super::values::{Kind, Raw};
use std::cell::{Cell, RefCell};
use std::collections::HashMap;
use std::path::Path;
use std::rc::Rc;

/// The pass a call belongs to, as the renderer names it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PassLabel {
    /// Its place in the frame, 1-based, as `gloss plan` numbers passes.
    pub number: usize,
    pub pass: String,
    /// The pass named by what it draws, as `gloss plan` shows it
    /// ("shadow map (light 1, face +X)").
    pub title: String,
    pub technique: &'static str,
    pub notes: &'static str,
    /// The technique's file.
    pub file: &'static str,
}

/// The GL error and feedback-loop checks, whose calls are left out.
const DEBUG_CHECKS: &str = "src/gl/debug.rs";

/// The renderer's file that calls each technique's `run`.
const RUNS_PASSES: &str = "src/renderer/passes.rs";

/// Where in gloss's source a call was made: `file` (relative to the crate,
/// `src/...`) and `line`; `via` is the owner in src/gl/ that made the call
/// itself, when the code that asked for it is elsewhere.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Site {
    pub file: String,
    pub line: u32,
    pub via: Option<(String, u32)>,
}

/// One GL call.
#[derive(Clone, Debug)]
pub struct Call {
    pub function: &'static str,
    pub args: Vec<String>,
    pub result: Option<String>,
    pub site: Site,
    pub pass: Option<Rc<PassLabel>>,
}

#[derive(Default)]
struct Recorder {
    calls: Vec<Call>,
    pass: Option<Rc<PassLabel>>,
    /// The program in use, and every uniform location looked up, by program.
    program: i64,
    uniforms: HashMap<(i64, i64), String>,
}

thread_local! {
    static RECORDING: Cell<bool> = const { Cell::new(false) };
    static RECORDER: RefCell<Recorder> = RefCell::new(Recorder::default());
}

/// Begin recording this thread's GL calls.
pub fn start() {
    RECORDER.with(|r| r.borrow_mut().calls.clear());
    RECORDING.with(|r| r.set(true));
}

/// End recording; the calls made since `start`, in order.
pub fn stop() -> Vec<Call> {
    RECORDING.with(|r| r.set(false));
    RECORDER.with(|r| std::mem::take(&mut r.borrow_mut().calls))
}

/// Calls from now on belong to `label`.
pub fn enter_pass(label: PassLabel) {
    RECORDER.with(|r| r.borrow_mut().pass = Some(Rc::new(label)));
}

/// Calls from now on belong to no pass.
pub fn leave_pass() {
    RECORDER.with(|r| r.borrow_mut().pass = None);
}

/// Every call, after the driver returned: the uniforms' names are noted
/// always (programs look them up at load), the call kept while recording.
pub(super) fn record(function: &'static str, args: &[(Kind, Raw)], result: Option<Raw>) {
    if !RECORDING.with(|r| r.get()) {
        RECORDER.with(|r| {
            let mut shown: Vec<String> = args.iter().map(|(k, v)| v.show(*k)).collect();
            name_uniforms(&mut r.borrow_mut(), function, args, &mut shown, result);
        });
        return;
    }
    // A call made while a call is recorded (the debug callback's) is not nested.
    RECORDING.with(|r| r.set(false));
    let site = RECORDER.with(|r| site(r.borrow().pass.as_deref()));
    // The debug checks' own queries (tests, --debug) are not the frame's.
    let checker = |f: &str| f == DEBUG_CHECKS;
    if checker(&site.file) || site.via.as_ref().is_some_and(|v| checker(&v.0)) {
        RECORDING.with(|r| r.set(true));
        return;
    }
    RECORDER.with(|r| {
        let mut r = r.borrow_mut();
        let mut shown: Vec<String> = args.iter().map(|(k, v)| v.show(*k)).collect();
        name_uniforms(&mut r, function, args, &mut shown, result);
        let result = result.map(|v| match v {
            Raw::Ptr(_) => v.show(Kind::Ptr),
            _ => v.show(Kind::Num),
        });
        let pass = r.pass.clone();
        r.calls.push(Call {
            function,
            args: shown,
            result,
            site,
            pass,
        });
    });
    RECORDING.with(|r| r.set(true));
}

/// Note the program in use and the uniforms' locations; show a uniform's
/// location as its name.
fn name_uniforms(
    r: &mut Recorder,
    function: &str,
    args: &[(Kind, Raw)],
    shown: &mut [String],
    result: Option<Raw>,
) {
    let first = args.first().map(|a| a.1.int());
    match (function, first) {
        ("glUseProgram", Some(p)) => r.program = p,
        ("glGetUniformLocation", Some(p)) => {
            if let (Some(name), Some(loc)) = (shown.get(1), result) {
                let name = name.trim_matches('"').to_string();
                r.uniforms.insert((p, loc.int()), name);
            }
        }
        (f, Some(loc)) if f.starts_with("glUniform") && !f.starts_with("glUniformBlock") => {
            if let Some(name) = r.uniforms.get(&(r.program, loc)) {
                shown[0] = name.clone();
            }
        }
        _ => {}
    }
}

/// The innermost line of gloss's own source on the stack outside src/gl/,
/// with the src/gl/ owner in between (if any) as `via`. A technique's last
/// call is a tail call, whose line the stack no longer holds: it is put in
/// the pass's technique file, line 0 ("tail call").
fn site(pass: Option<&PassLabel>) -> Site {
    let mut via = None;
    let mut found = None;
    backtrace::trace(|frame| {
        backtrace::resolve_frame(frame, |symbol| {
            if found.is_some() {
                return;
            }
            let (Some(file), Some(line)) = (symbol.filename(), symbol.lineno()) else {
                return;
            };
            let Some(file) = crate_relative(file) else {
                return;
            };
            if file.starts_with("src/gl/trace") {
                return;
            }
            if file.starts_with("src/gl/") {
                via.get_or_insert((file, line));
            } else {
                found = Some((file, line));
            }
        });
        found.is_none()
    });
    let (mut file, mut line) = found.unwrap_or_default();
    if let Some(p) = pass.filter(|_| file == RUNS_PASSES) {
        (file, line) = (p.file.to_string(), 0);
    }
    Site { file, line, via }
}

/// `src/...` for a file of this crate (as the debug info names it:
/// relative to the crate, or absolute).
fn crate_relative(file: &Path) -> Option<String> {
    let crate_dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let rel = file.strip_prefix(crate_dir).unwrap_or(file);
    let rel = rel.to_string_lossy().replace('\\', "/");
    rel.starts_with("src/").then_some(rel)
}
