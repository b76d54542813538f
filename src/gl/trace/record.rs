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
    /// The `#define`s gloss put after each shader's `#version` line, by
    /// shader, and by program (its shaders'), noted always like the uniforms.
    shader_defines: HashMap<i64, Vec<(String, String)>>,
    program_defines: HashMap<i64, Vec<(String, String)>>,
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

/// The `#define`s program `id` was built with (gloss's, inserted after
/// `#version`: src/gl/program.rs), as the driver was given them; None for
/// a program this thread's recording layer did not see made.
pub fn program_defines(id: i64) -> Option<Vec<(String, String)>> {
    RECORDER.with(|r| r.borrow().program_defines.get(&id).cloned())
}

/// The `#define` lines right after the `#version` line of `text`.
fn inserted_defines(text: &str) -> Vec<(String, String)> {
    let mut lines = text
        .lines()
        .skip_while(|l| !l.trim_start().starts_with("#version"));
    lines.next();
    lines
        .map_while(|l| l.trim_start().strip_prefix("#define "))
        .map(|d| {
            let (k, v) = d.trim().split_once(' ').unwrap_or((d.trim(), ""));
            (k.to_string(), v.trim().to_string())
        })
        .collect()
}

/// The source glShaderSource(shader, count, strings, lengths) was given.
///
/// # Safety
/// Called with that call's arguments, right after it, while they are valid.
unsafe fn shader_text(count: i64, strings: usize, lengths: usize) -> String {
    let mut text = Vec::new();
    if strings == 0 {
        return String::new();
    }
    for i in 0..count.max(0) as usize {
        unsafe {
            let s = *(strings as *const *const u8).add(i);
            if s.is_null() {
                continue;
            }
            let len = if lengths == 0 {
                -1
            } else {
                *(lengths as *const i32).add(i)
            };
            if len < 0 {
                text.extend_from_slice(std::ffi::CStr::from_ptr(s.cast()).to_bytes());
            } else {
                text.extend_from_slice(std::slice::from_raw_parts(s, len as usize));
            }
        }
    }
    String::from_utf8_lossy(&text).into_owned()
}

/// Note the program in use, the uniforms' locations and the programs'
/// `#define`s; show a uniform's location as its name.
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
        ("glCreateProgram", _) => {
            if let Some(p) = result {
                r.program_defines.insert(p.int(), Vec::new());
            }
        }
        ("glShaderSource", Some(shader)) => {
            if let [_, (_, count), (_, Raw::Ptr(strings)), (_, lengths)] = args {
                let lengths = match lengths {
                    Raw::Ptr(l) => *l,
                    _ => 0,
                };
                // SAFETY: the call's own arguments, which the driver just read.
                let text = unsafe { shader_text(count.int(), *strings, lengths) };
                r.shader_defines.insert(shader, inserted_defines(&text));
            }
        }
        ("glAttachShader", Some(p)) => {
            let shader = args.get(1).map(|a| a.1.int());
            if let Some(d) = shader.and_then(|s| r.shader_defines.get(&s)).cloned() {
                r.program_defines.insert(p, d);
            }
        }
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
