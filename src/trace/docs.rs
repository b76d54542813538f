//! The GL listings in docs/, generated from executed frames. A page holds
//!
//! ```text
//! <!-- gloss trace mixed-lights --technique light_volumes --size 640x360 -->
//! ... generated ...
//! <!-- end of gloss trace -->
//! ```
//!
//! and `block` makes what goes between the two markers: the listing of the
//! frame the marker's command traces, the source lines to read in the order
//! the calls came from them, the shaders, and how to try it (the commands,
//! the demo's switches and views: src/trace/try_it.rs). The
//! docs test regenerates every block and fails where a page differs.

use super::listing::{self, Filter};
use super::{trace_first_frame, trace_frame};
use crate::assets;
use crate::gl::Headless;
use crate::gl::trace::Call;
use crate::scene::Scene;
use crate::techniques;
use anyhow::{Context as _, Result, anyhow, bail};
use std::fmt::Write as _;
use std::path::Path;

/// A block's opening marker starts with this; its arguments follow.
pub const OPEN: &str = "<!-- gloss trace ";
/// A block's closing marker.
pub const CLOSE: &str = "<!-- end of gloss trace -->";

/// What a marker asks for: `SCENE [--technique T] [--pass P] [--size WxH] [--set K=V]..`.
#[derive(Clone, Debug, Default)]
pub struct Request {
    pub scene: String,
    pub filter: Filter,
    pub size: Option<(u32, u32)>,
    pub set: Vec<String>,
    /// The first frame rather than the second.
    pub first: bool,
}

impl Request {
    pub fn parse(args: &str) -> Result<Request> {
        let mut words = args.split_whitespace();
        let mut r = Request {
            scene: words.next().ok_or_else(|| anyhow!("no scene"))?.to_string(),
            ..Request::default()
        };
        while let Some(w) = words.next() {
            let mut value = || words.next().ok_or_else(|| anyhow!("{w} wants a value"));
            match w {
                "--technique" => r.filter.technique = Some(value()?.to_string()),
                "--pass" => r.filter.pass = Some(value()?.to_string()),
                "--size" => {
                    let v = value()?;
                    let size = v
                        .split_once('x')
                        .and_then(|(w, h)| Some((w.parse().ok()?, h.parse().ok()?)));
                    r.size =
                        Some(size.ok_or_else(|| anyhow!("--size {v}: expected WIDTHxHEIGHT"))?);
                }
                "--set" => r.set.push(value()?.to_string()),
                "--first-frame" => r.first = true,
                _ => bail!(
                    "unknown argument {w:?} (--technique, --pass, --size, --set, --first-frame)"
                ),
            }
        }
        Ok(r)
    }

    /// The command line that makes the same listing.
    pub fn command(&self) -> String {
        let mut s = format!("gloss trace {}", self.scene);
        if let Some(t) = &self.filter.technique {
            let _ = write!(s, " --technique {t}");
        }
        if let Some(p) = &self.filter.pass {
            let _ = write!(s, " --pass {p}");
        }
        if let Some((w, h)) = self.size {
            let _ = write!(s, " --size {w}x{h}");
        }
        for kv in &self.set {
            let _ = write!(s, " --set {kv}");
        }
        if self.first {
            s += " --first-frame";
        }
        s
    }

    /// The scene, loaded as the command line loads it.
    pub fn load(&self) -> Result<Scene> {
        let mut scene = Scene::load_with(&assets::scene_path(Path::new(&self.scene)), &self.set)?;
        if let Some(size) = self.size {
            scene.render.size = size;
        }
        Ok(scene)
    }
}

/// The kept calls, or an error naming what the frame does run.
pub fn kept<'a>(
    calls: &'a [Call],
    filter: &Filter,
) -> Result<Vec<(Option<&'a crate::gl::trace::PassLabel>, Vec<&'a Call>)>> {
    let groups = listing::by_pass(calls, filter);
    if groups.is_empty() {
        let mut ran: Vec<String> = calls
            .iter()
            .filter_map(|c| c.pass.as_ref())
            .map(|l| format!("{} ({})", l.title, l.technique))
            .collect();
        ran.dedup();
        bail!(
            "no call of this frame is kept by {filter:?}; its passes are: {}",
            ran.join(", ")
        );
    }
    Ok(groups)
}

/// What goes between a marker and the closing marker.
pub fn block(ctx: &Headless, request: &Request) -> Result<String> {
    let scene = request.load()?;
    let calls = if request.first {
        trace_first_frame(ctx, &scene)
    } else {
        trace_frame(ctx, &scene)
    };
    let calls = calls.with_context(|| request.command())?;
    let groups = kept(&calls, &request.filter).with_context(|| request.command())?;
    let (w, h) = scene.render.size;
    let which = if request.first {
        "the first frame"
    } else {
        "one frame"
    };
    let mut s = format!(
        "The GL calls of {which} of `{}` at {w}x{h}, as `{}` lists them from the \
         executed frame (a test fails when this page and the frame differ):\n\n",
        request.scene,
        request.command()
    );
    s += &listing::render(&calls, &request.filter, true);
    s += "Read in this order:\n\n";
    let mut n = 0;
    for (file, lines) in files_in_call_order(&groups) {
        n += 1;
        let _ = writeln!(s, "{n}. `{file}`: {}", line_ranges(&lines));
    }
    let mut techniques_seen: Vec<&str> = Vec::new();
    for (label, _) in &groups {
        if let Some(l) = label.filter(|l| !techniques_seen.contains(&l.technique)) {
            techniques_seen.push(l.technique);
        }
    }
    for t in techniques::ALL
        .iter()
        .filter(|t| techniques_seen.contains(&t.name))
    {
        for shader in t.shaders {
            n += 1;
            let _ = writeln!(s, "{n}. `glsl/{shader}` ({})", t.name);
        }
    }
    s += &super::try_it::text(
        &request.scene,
        &request.set,
        &scene,
        &techniques_seen,
        &request.command(),
    );
    Ok(s)
}

/// Each source file the kept calls came from, in the order of its first
/// call, with its lines (the owner in src/gl/ after the line that used it).
fn files_in_call_order(
    groups: &[(Option<&crate::gl::trace::PassLabel>, Vec<&Call>)],
) -> Vec<(String, Vec<u32>)> {
    let mut files: Vec<(String, Vec<u32>)> = Vec::new();
    let mut add = |file: &str, line: u32| match files.iter_mut().find(|(f, _)| f == file) {
        Some((_, lines)) if !lines.contains(&line) => lines.push(line),
        Some(_) => {}
        None => files.push((file.to_string(), vec![line])),
    };
    for c in groups.iter().flat_map(|(_, calls)| calls) {
        if c.site.line > 0 {
            add(&c.site.file, c.site.line);
        }
        if let Some((file, line)) = &c.site.via {
            add(file, *line);
        }
    }
    files
}

/// `12, 15-18, 30`: the lines, ascending, runs joined.
fn line_ranges(lines: &[u32]) -> String {
    let mut sorted = lines.to_vec();
    sorted.sort_unstable();
    let mut parts: Vec<String> = Vec::new();
    let mut i = 0;
    while i < sorted.len() {
        let mut j = i;
        while j + 1 < sorted.len() && sorted[j + 1] <= sorted[j] + 2 {
            j += 1;
        }
        parts.push(if i == j {
            format!("line {}", sorted[i])
        } else {
            format!("lines {}-{}", sorted[i], sorted[j])
        });
        i = j + 1;
    }
    parts.join(", ")
}

/// The blocks of a page: `(request, start, end)` with the byte range of the
/// generated text between the markers.
pub fn blocks(page: &str) -> Result<Vec<(Request, usize, usize)>> {
    let mut out = Vec::new();
    let mut at = 0;
    while let Some(open) = page[at..].find(OPEN).map(|i| i + at) {
        let args_end = page[open..]
            .find("-->")
            .map(|i| i + open)
            .ok_or_else(|| anyhow!("a trace marker is not closed with -->"))?;
        let request = Request::parse(&page[open + OPEN.len()..args_end])?;
        let start = args_end + "-->".len() + 1;
        let end = page[start..]
            .find(CLOSE)
            .map(|i| i + start)
            .ok_or_else(|| anyhow!("no {CLOSE} after the marker {}", request.command()))?;
        out.push((request, start, end));
        at = end + CLOSE.len();
    }
    Ok(out)
}
