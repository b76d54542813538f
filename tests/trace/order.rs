//! The calls and the lines they come from.

use crate::common;
use crate::tracing_context;
use gloss::gl::trace::Call;
use gloss::trace::listing::Filter;
use gloss::trace::trace_frame;

/// `glCullFace` -> `cull_face`: the glow method a GL function is called by.
fn glow_method(function: &str) -> String {
    let mut s = String::new();
    for (i, ch) in function.trim_start_matches("gl").chars().enumerate() {
        if ch.is_ascii_uppercase() && i > 0 {
            s.push('_');
        }
        s.push(ch.to_ascii_lowercase());
    }
    s
}

fn source_line(file: &str, line: u32) -> String {
    let text = std::fs::read_to_string(common::root().join(file)).unwrap();
    text.lines()
        .nth(line as usize - 1)
        .unwrap_or("")
        .to_string()
}

/// Whether `line` calls a function of `file` whose last GL call is
/// `method`: made as a tail call, that call leaves no line of the function
/// on the stack, and the trace names the line that called the function.
fn tail_calls(file: &str, line: &str, method: &str) -> bool {
    let text = std::fs::read_to_string(common::root().join(file)).unwrap();
    let called = line.trim().split('(').next().unwrap_or("");
    let Some(at) = text.find(&format!("fn {called}(")) else {
        return false;
    };
    let body = &text[at..];
    let end = body.find("\n}\n").unwrap_or(body.len());
    let last_gl = body[..end].rfind("gl.").map(|i| &body[i..end]);
    last_gl.is_some_and(|tail| tail.starts_with(&format!("gl.{method}(")))
}

#[test]
fn light_volumes_calls_come_in_the_notes_order_from_their_lines() {
    let ctx = tracing_context();
    let mut scene = common::scene("mixed-lights.toml");
    scene.render.size = (320, 180);
    let calls = trace_frame(&ctx, &scene).unwrap();
    let filter = Filter {
        technique: Some("light_volumes".into()),
        pass: None,
    };
    let kept: Vec<&Call> = gloss::trace::listing::by_pass(&calls, &filter)
        .into_iter()
        .flat_map(|(_, c)| c)
        .collect();
    let text: Vec<String> = kept
        .iter()
        .map(|c| gloss::trace::listing::call_text(c))
        .collect();
    // Notes 04: cull the front faces, no depth writes, add the lights up.
    let wanted = [
        "glBlitFramebuffer(0, 0, 320, 180, 0, 0, 320, 180, GL_DEPTH_BUFFER_BIT, GL_NEAREST)",
        "glCullFace(GL_FRONT)",
        "glDepthMask(GL_FALSE)",
        "glBlendFunc(GL_ONE, GL_ONE)",
        "glDepthFunc(GL_GEQUAL)",
        "glDrawElements(GL_TRIANGLES, 960, GL_UNSIGNED_INT, 0)",
        "glDepthMask(GL_TRUE)",
    ];
    let mut at = 0;
    for w in wanted {
        let found = text[at..].iter().position(|t| t == w);
        let Some(i) = found else {
            panic!(
                "{w} is not in the trace after call {at}:\n{}",
                text.join("\n")
            );
        };
        at += i + 1;
    }
    // Each state call's line in the source makes that call.
    let file = "src/techniques/deferred/light_volumes.rs";
    let mut checked = 0;
    for c in kept
        .iter()
        .filter(|c| c.site.file == file && c.site.via.is_none() && c.site.line > 0)
    {
        if ![
            "glCullFace",
            "glDepthMask",
            "glBlendFunc",
            "glDepthFunc",
            "glEnable",
            "glDisable",
            "glFrontFace",
            "glClearColor",
            "glBlitFramebuffer",
        ]
        .contains(&c.function)
        {
            continue;
        }
        let line = source_line(file, c.site.line);
        let method = glow_method(c.function);
        assert!(
            line.contains(&method) || tail_calls(file, &line, &method),
            "{} is said to come from {file}:{}, which reads {line:?}",
            c.function,
            c.site.line
        );
        checked += 1;
    }
    assert!(
        checked >= 12,
        "only {checked} calls checked against their lines"
    );
}

#[test]
fn every_constant_the_source_names_has_its_name() {
    let names: Vec<&str> = gloss::gl::trace::named_constants()
        .map(|(_, n)| n)
        .collect();
    let mut missing = Vec::new();
    let mut files = Vec::new();
    fn walk(dir: &std::path::Path, out: &mut Vec<std::path::PathBuf>) {
        for e in std::fs::read_dir(dir).unwrap().flatten() {
            let p = e.path();
            if p.is_dir() {
                walk(&p, out);
            } else if p.extension().is_some_and(|x| x == "rs") {
                out.push(p);
            }
        }
    }
    walk(&common::root().join("src"), &mut files);
    for f in files {
        let text = std::fs::read_to_string(&f).unwrap();
        for (i, _) in text.match_indices("glow::") {
            let name: String = text[i + 6..]
                .chars()
                .take_while(|c| c.is_ascii_uppercase() || c.is_ascii_digit() || *c == '_')
                .collect();
            let is_constant = name.len() > 1
                && !text[i + 6 + name.len()..].starts_with(|c: char| c.is_ascii_lowercase());
            if is_constant && !names.contains(&format!("GL_{name}").as_str()) {
                missing.push(format!("{}: glow::{name}", f.display()));
            }
        }
    }
    missing.sort();
    missing.dedup();
    assert!(
        missing.is_empty(),
        "constants the trace cannot name (run tools/gen_trace_shims.py):\n{}",
        missing.join("\n")
    );
}

#[test]
fn a_filter_that_keeps_nothing_names_the_passes() {
    let ctx = tracing_context();
    let mut scene = common::scene("mixed-lights.toml");
    scene.render.size = (64, 36);
    let calls = trace_frame(&ctx, &scene).unwrap();
    let filter = Filter {
        technique: Some("bloom".into()),
        pass: None,
    };
    let e = gloss::trace::docs::kept(&calls, &filter)
        .unwrap_err()
        .to_string();
    assert!(e.contains("lighting (light_volumes)"), "{e}");
}
