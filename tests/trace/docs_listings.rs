//! Every GL listing in docs/ is the executed frame's.

use crate::common;
use crate::tracing_context;
use gloss::trace::docs::{block, blocks};

fn pages() -> Vec<std::path::PathBuf> {
    fn walk(dir: &std::path::Path, out: &mut Vec<std::path::PathBuf>) {
        for e in std::fs::read_dir(dir).unwrap().flatten() {
            let p = e.path();
            if p.is_dir() {
                walk(&p, out);
            } else if p.extension().is_some_and(|x| x == "md") {
                out.push(p);
            }
        }
    }
    let mut out = Vec::new();
    walk(&common::root().join("docs"), &mut out);
    out.sort();
    out
}

/// The first line where `a` and `b` differ, shown.
pub fn first_difference(a: &str, b: &str) -> String {
    let (la, lb): (Vec<_>, Vec<_>) = (a.lines().collect(), b.lines().collect());
    for i in 0..la.len().max(lb.len()) {
        let (x, y) = (la.get(i).copied(), lb.get(i).copied());
        if x != y {
            return format!(
                "line {} of the block:\n      page:  {}\n      frame: {}",
                i + 1,
                x.unwrap_or("(nothing)"),
                y.unwrap_or("(nothing)")
            );
        }
    }
    "no difference".into()
}

#[test]
fn every_docs_listing_is_the_executed_frames() {
    let bless = std::env::var("GLOSS_BLESS").as_deref() == Ok("1");
    let mut problems = Vec::new();
    let mut traced = Vec::new();
    for page in pages() {
        let text = std::fs::read_to_string(&page).unwrap();
        let rel = page
            .strip_prefix(common::root())
            .unwrap()
            .display()
            .to_string();
        let found = blocks(&text).unwrap_or_else(|e| panic!("{rel}: {e:#}"));
        let mut fresh = text.clone();
        for (request, start, end) in found.into_iter().rev() {
            // A context of its own, as `gloss trace` makes: the same object names.
            let made =
                block(&tracing_context(), &request).unwrap_or_else(|e| panic!("{rel}: {e:#}"));
            if let Some(t) = &request.filter.technique {
                traced.push((rel.clone(), t.clone()));
            }
            if text[start..end] != made {
                problems.push(format!(
                    "{rel}: the listing of `{}` is not what the frame does; {}",
                    request.command(),
                    first_difference(&text[start..end], &made)
                ));
                fresh.replace_range(start..end, &made);
            }
        }
        if bless && fresh != text {
            std::fs::write(&page, fresh).unwrap();
        }
    }
    // Every technique's page lists its technique's calls (tessellation needs
    // GL 4.0, which the tests' 3.3 context does not have).
    for t in gloss::techniques::ALL
        .iter()
        .filter(|t| t.name != "tessellation")
    {
        if !traced
            .iter()
            .any(|(page, name)| *page == t.docs && name == t.name)
        {
            problems.push(format!(
                "{}: no `<!-- gloss trace SCENE --technique {} -->` block",
                t.docs, t.name
            ));
        }
    }
    assert!(
        problems.is_empty() || bless,
        "{} problems (GLOSS_BLESS=1 cargo test --release --test trace rewrites the listings):\n  {}",
        problems.len(),
        problems.join("\n  ")
    );
}

/// The comparison sees one changed line of a listing.
#[test]
fn an_edited_listing_is_caught() {
    let page = "intro\n<!-- gloss trace mixed-lights --technique light_volumes --size 64x36 -->\nold\n<!-- end of gloss trace -->\n";
    let found = blocks(page).unwrap();
    assert_eq!(found.len(), 1);
    let (request, start, end) = &found[0];
    assert_eq!(&page[*start..*end], "old\n");
    let ctx = tracing_context();
    let made = block(&ctx, request).unwrap();
    assert!(made.contains("glCullFace(GL_FRONT)"), "{made}");
    let edited = made.replace("glCullFace(GL_FRONT)", "glCullFace(GL_BACK)");
    assert_ne!(edited, made);
    assert!(first_difference(&edited, &made).contains("glCullFace(GL_BACK)"));
}
