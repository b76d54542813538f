//! Hostile input, round 3: each class of input that once made gloss hang,
//! run away, crash, damage a file or drop part of a scene in silence. Every
//! case runs the gloss binary under a memory cap (RLIMIT_AS, set in the
//! child before exec) and a time limit, then checks the message and that
//! every file in the folder other than the output is as it was.
//!
//! The time limits are generous bounds against runaway (what once took
//! minutes must end within them), never speed measurements.
//!
//! * `output`: the output written without harming any other file;
//! * `keys`: `--set` keys and scene tables too deep for the stack;
//! * `mirrors`: mirrors in mirrors bounded by what each can see;
//! * `chains`: a long `parent` chain walked in linear time;
//! * `budget`: the frame's textures against GL's limits and the memory budget;
//! * `silent`: nothing dropped without a word; values past the world limits;
//! * `messages`: what a message names.

mod budget;
mod chains;
mod keys;
mod messages;
mod mirrors;
mod output;
mod silent;

use std::collections::BTreeMap;
use std::ffi::OsStr;
use std::io::Read as _;
use std::os::unix::process::CommandExt as _;
use std::path::{Path, PathBuf};
use std::process::{Command, ExitStatus, Stdio};
use std::time::{Duration, Instant};

/// The address space a run may use. A plain render needs less than 1 GB
/// of it (Mesa's llvmpipe included); the runaways this guards against
/// went to 2-16 GB.
pub const MEMORY_CAP: u64 = 1536 << 20;

/// How long a run may take: what used to take minutes.
pub const TIME_LIMIT: Duration = Duration::from_secs(40);

/// A fresh, empty folder for one test.
pub fn temp_dir(test: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("gloss-hostile-{test}"));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("create temp dir");
    d
}

pub fn write(dir: &Path, name: &str, bytes: impl AsRef<[u8]>) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, bytes).expect("write a test file");
    p
}

/// What a run of gloss gave.
pub struct Run {
    pub status: ExitStatus,
    pub stdout: String,
    pub stderr: String,
}

impl Run {
    /// It failed with a message (exit code 1, "error:" first, no panic).
    pub fn failed(&self) -> &str {
        assert_eq!(
            self.status.code(),
            Some(1),
            "gloss should fail cleanly; stderr:\n{}",
            self.stderr
        );
        assert!(
            self.stderr.starts_with("error:") || self.stderr.contains("\nerror:"),
            "no error line:\n{}",
            self.stderr
        );
        for bad in ["panicked", "internal error", "stack overflow"] {
            assert!(!self.stderr.contains(bad), "{bad}:\n{}", self.stderr);
        }
        &self.stderr
    }

    /// It succeeded.
    pub fn succeeded(&self) -> &str {
        assert!(
            self.status.success(),
            "gloss should succeed; status {:?}, stderr:\n{}",
            self.status,
            self.stderr
        );
        &self.stderr
    }
}

/// Run gloss in `dir` with `args`, its address space capped at `MEMORY_CAP`
/// and its time at `TIME_LIMIT` (a run past it is killed and the test fails).
pub fn gloss(dir: &Path, args: &[&str]) -> Run {
    gloss_os(dir, &args.iter().map(OsStr::new).collect::<Vec<_>>())
}

pub fn gloss_os(dir: &Path, args: &[&OsStr]) -> Run {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_gloss"));
    cmd.args(args)
        .current_dir(dir)
        .env("MESA_GL_VERSION_OVERRIDE", "3.3")
        .env("MESA_GLSL_VERSION_OVERRIDE", "330")
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    // SAFETY: setrlimit is async-signal-safe; nothing else runs in the child.
    unsafe {
        cmd.pre_exec(|| {
            let cap = libc::rlimit {
                rlim_cur: MEMORY_CAP,
                rlim_max: MEMORY_CAP,
            };
            if libc::setrlimit(libc::RLIMIT_AS, &cap) != 0 {
                return Err(std::io::Error::last_os_error());
            }
            Ok(())
        });
    }
    let start = Instant::now();
    let mut child = cmd.spawn().expect("run gloss");
    let mut out = child.stdout.take().unwrap();
    let mut err = child.stderr.take().unwrap();
    let out = std::thread::spawn(move || {
        let mut s = Vec::new();
        let _ = out.read_to_end(&mut s);
        s
    });
    let err = std::thread::spawn(move || {
        let mut s = Vec::new();
        let _ = err.read_to_end(&mut s);
        s
    });
    let status = loop {
        if let Some(s) = child.try_wait().expect("wait for gloss") {
            break s;
        }
        if start.elapsed() > TIME_LIMIT {
            let _ = child.kill();
            let _ = child.wait();
            panic!("gloss {args:?} ran past {TIME_LIMIT:?}");
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    let text = |b: Vec<u8>| String::from_utf8_lossy(&b).into_owned();
    Run {
        status,
        stdout: text(out.join().unwrap()),
        stderr: text(err.join().unwrap()),
    }
}

/// One entry of a folder, as far as a test compares it.
#[derive(PartialEq, Eq)]
pub enum Entry {
    File {
        bytes: Vec<u8>,
        mode: u32,
    },
    Link(PathBuf),
    Dir,
    /// A FIFO, device or socket: its type bits, and its device numbers.
    Special {
        mode: u32,
        rdev: u64,
    },
}

impl std::fmt::Debug for Entry {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Entry::File { bytes, mode } => {
                let head = String::from_utf8_lossy(&bytes[..bytes.len().min(24)]);
                write!(f, "file of {} bytes, mode {mode:o}: {head:?}", bytes.len())
            }
            Entry::Link(to) => write!(f, "link to {}", to.display()),
            Entry::Dir => write!(f, "folder"),
            Entry::Special { mode, rdev } => write!(f, "special, mode {mode:o}, rdev {rdev}"),
        }
    }
}

/// Every entry of `dir` (not descending), by name.
pub fn folder(dir: &Path) -> BTreeMap<String, Entry> {
    use std::os::unix::fs::MetadataExt as _;
    let mut out = BTreeMap::new();
    for e in std::fs::read_dir(dir).expect("read the folder") {
        let e = e.unwrap();
        let m = std::fs::symlink_metadata(e.path()).unwrap();
        let entry = if m.file_type().is_symlink() {
            Entry::Link(std::fs::read_link(e.path()).unwrap())
        } else if m.is_dir() {
            Entry::Dir
        } else if m.is_file() {
            Entry::File {
                bytes: std::fs::read(e.path()).unwrap(),
                mode: m.mode(),
            }
        } else {
            Entry::Special {
                mode: m.mode(),
                rdev: m.rdev(),
            }
        };
        out.insert(e.file_name().to_string_lossy().into_owned(), entry);
    }
    out
}

/// Every entry of `after` but those named in `outputs` is as in `before`,
/// and nothing was added but those.
pub fn unchanged_but(
    before: &BTreeMap<String, Entry>,
    after: &BTreeMap<String, Entry>,
    outputs: &[&str],
) {
    for (name, e) in before {
        if outputs.contains(&name.as_str()) {
            continue;
        }
        assert_eq!(after.get(name), Some(e), "{name} was changed or removed");
    }
    for name in after.keys() {
        assert!(
            before.contains_key(name) || outputs.contains(&name.as_str()),
            "{name} was left in the folder"
        );
    }
}

/// Run gloss in `dir` and check that nothing in it but `outputs` changed.
pub fn gloss_in(dir: &Path, args: &[&str], outputs: &[&str]) -> Run {
    let before = folder(dir);
    let run = gloss(dir, args);
    unchanged_but(&before, &folder(dir), outputs);
    run
}

/// A small valid scene: an orthographic camera over a floor, one light.
pub const BASE: &str = r#"name = "base"

[camera]
projection = "orthographic"
eye = [0.0, 10.0, 0.0]
target = [0.0, 0.0, 0.0]
up = [0.0, 0.0, -1.0]
half_height = 5.0
near = 1.0
far = 20.0

[render]
size = [32, 24]

[[lights]]
type = "point"
position = [1.0, 2.0, -0.5]
color = [1.0, 0.9, 0.8]
intensity = 1.5
attenuation = [1.0, 0.09, 0.032]

[materials.floor]
diffuse = [0.7, 0.5, 0.3]

[[objects]]
name = "floor"
mesh = "plane"
material = "floor"
scale = [10.0, 1.0, 10.0]
"#;

pub fn contains_all(msg: &str, words: &[&str]) {
    for w in words {
        assert!(msg.contains(w), "the message should contain {w:?}:\n{msg}");
    }
}
