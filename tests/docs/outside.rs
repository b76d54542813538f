//! The text points at nothing outside the repository: no `../shared`, no
//! issue numbers, no "closing note".

use crate::{lines, report};

/// Where `word` occurs in `text` (ASCII case-insensitive), at word starts.
fn word_starts(text: &str, word: &str) -> Vec<usize> {
    let lower = text.to_ascii_lowercase();
    lower
        .match_indices(word)
        .map(|(i, _)| i)
        .filter(|&i| {
            i == 0
                || !lower[..i]
                    .chars()
                    .next_back()
                    .is_some_and(|c| c.is_ascii_alphanumeric())
        })
        .collect()
}

/// "issue 3", "issues 3 and 4", "issue #12", "Issue no. 7".
pub fn names_an_issue_number(text: &str) -> bool {
    word_starts(text, "issue").into_iter().any(|i| {
        let rest = &text[i + "issue".len()..];
        let rest = rest.strip_prefix(['s', 'S']).unwrap_or(rest);
        let rest = rest.trim_start();
        let rest = rest
            .strip_prefix("no.")
            .or_else(|| rest.strip_prefix("No."))
            .unwrap_or(rest)
            .trim_start();
        let rest = rest.strip_prefix('#').unwrap_or(rest);
        rest.starts_with(|c: char| c.is_ascii_digit())
    })
}

#[test]
fn docs_point_at_nothing_outside_the_repository() {
    let mut problems = Vec::new();
    for line in lines() {
        let t = &line.text;
        if t.contains("../shared") {
            problems.push(format!(
                "{}: `../shared` is outside the repository: cite the notes by file name and section",
                line.at()
            ));
        }
        if names_an_issue_number(t) {
            problems.push(format!(
                "{}: an issue number means nothing to a reader of the repository: say what it holds",
                line.at()
            ));
        }
        if !word_starts(t, "closing note").is_empty() {
            problems.push(format!(
                "{}: \"closing note\" points outside the repository: link the file that holds it",
                line.at()
            ));
        }
    }
    report("references outside the repository", problems);
}
