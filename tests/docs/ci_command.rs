//! README.md's test command is the command `.ci/run` runs.

use crate::{lines, root};
use std::path::Path;

#[test]
fn readme_test_command_is_what_ci_runs() {
    let ci = std::fs::read_to_string(root().join(".ci/run")).expect(".ci/run");
    let ci_command = ci
        .lines()
        .map(str::trim)
        .rfind(|l| !l.is_empty())
        .expect(".ci/run has a last line");
    let readme = lines()
        .into_iter()
        .filter(|l| l.file == Path::new("README.md"))
        .collect::<Vec<_>>();
    let test_line = readme
        .iter()
        .find(|l| l.fenced && l.text.contains("cargo test"))
        .expect("README.md shows the test command in a code block");
    let command = test_line.text.split(" #").next().unwrap_or("").trim();
    assert_eq!(
        command,
        ci_command,
        "{}: README.md's test command differs from the last line of .ci/run",
        test_line.at()
    );
}
