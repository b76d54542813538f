//! The command line (`cli::Cli`, clap) on argument vectors made of its own
//! words, values at the edges and arbitrary strings: parsing never panics,
//! and an error renders to a message.

use crate::{EXTREME_NUMBERS, run};
use clap::Parser as _;
use gloss::cli::Cli;
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;

const WORDS: &[&str] = &[
    "render",
    "plan",
    "info",
    "scenes",
    "bench",
    "help",
    "--backend",
    "--debug",
    "--set",
    "--no-panel",
    "--no-pass-times",
    "--frames",
    "-o",
    "--output",
    "--size",
    "--path",
    "--shading",
    "--lights",
    "--inspect",
    "--after",
    "--paths",
    "--cutoffs",
    "--stencil",
    "--frames",
    "--warmup",
    "--vary",
    "--reference",
    "--aa",
    "--out",
    "--help",
    "-h",
    "--version",
    "-V",
    "--",
    "-",
    "egl",
    "osmesa",
    "window",
    "forward",
    "deferred",
    "volumes",
    "prepass",
    "flat",
    "gouraud",
    "phong",
    "stencil",
    "64x36",
    "0x0",
    "8192x8192",
    "4294967296x1",
    "x",
    "1x",
    "5/256",
    "1/0",
    "0/0",
    "-1/2",
    "forward,volumes",
    ",,",
    "render.cutoff=0.01",
    "render.cutoff",
    "=",
    "lights[*].shadow.bias=0,1",
    "scenes/default.toml",
    "default",
    "out.png",
    "",
];

fn arg() -> impl Strategy<Value = String> {
    prop_oneof![
        6 => proptest::sample::select(WORDS).prop_map(String::from),
        2 => proptest::sample::select(EXTREME_NUMBERS).prop_map(String::from),
        1 => (proptest::sample::select(WORDS), proptest::sample::select(EXTREME_NUMBERS))
            .prop_map(|(w, n)| format!("{w}={n}")),
        1 => any::<String>(),
    ]
}

/// The property, for one argument vector (without the program name).
pub fn check(args: &[String]) -> Result<(), TestCaseError> {
    let argv = std::iter::once("gloss".to_string()).chain(args.iter().cloned());
    match Cli::try_parse_from(argv) {
        Ok(_) => crate::accepted(),
        Err(e) => {
            let text = e.render().to_string();
            prop_assert!(!text.trim().is_empty(), "an empty clap message");
        }
    }
    Ok(())
}

#[test]
fn the_command_line_parses_any_arguments() {
    let args = proptest::collection::vec(arg(), 0..10);
    run("cli", args, |a| a.join("\n").into_bytes(), |a| check(&a));
}

#[test]
fn the_parser_is_the_binary_s() {
    // The property is about the real command line: a render command parses.
    let args = [
        "gloss", "render", "default", "-o", "x.png", "--size", "64x36",
    ];
    let cli = Cli::try_parse_from(args).expect("parses");
    assert!(matches!(
        cli.command,
        Some(gloss::cli::Command::Render {
            size: Some((64, 36)),
            ..
        })
    ));
    assert!(
        Cli::try_parse_from(["gloss", "render", "default", "-o", "x.png", "--size", "0x1"])
            .is_err()
    );
}
