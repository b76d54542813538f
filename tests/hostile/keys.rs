//! `--set` keys and scene tables nested too deep for the stack are refused
//! before any recursion, with the reason kept in the message.

use crate::{BASE, contains_all, gloss_in, temp_dir, write};

#[test]
fn a_set_key_of_tens_of_thousands_of_parts_is_refused() {
    let dir = temp_dir("deep_set_key");
    write(&dir, "scene.toml", BASE);
    for parts in [17usize, 40_000, 60_000] {
        let key = format!("render{}", ".x".repeat(parts - 1));
        let set = format!("{key}=1");
        for command in ["plan", "render"] {
            let mut args = vec![command, "scene.toml", "--set", &set];
            if command == "render" {
                args.extend(["-o", "out.png"]);
            }
            let run = gloss_in(&dir, &args, &[]);
            let msg = run.failed();
            contains_all(
                msg,
                &[
                    "--set render.x.x",
                    &format!("the key has {parts} dotted parts"),
                    "at most 16",
                ],
            );
            assert!(msg.len() < 3000, "a short message: {} bytes", msg.len());
        }
    }
    // Sixteen parts are read as usual (and name no key of the scene).
    let sixteen = format!("render{}=1", ".x".repeat(15));
    let run = gloss_in(&dir, &["plan", "scene.toml", "--set", &sixteen], &[]);
    assert!(!run.failed().contains("dotted parts"));
}

#[test]
fn tables_nested_too_deep_keep_the_parsers_reason() {
    let dir = temp_dir("deep_tables");
    let deep = 40_000;
    let cases = [
        ("dotted.toml", format!("x{} = 1\n", ".x".repeat(deep))),
        ("header.toml", format!("[x{}]\n", ".x".repeat(deep))),
        (
            "arrays.toml",
            format!("x = {}{}\n", "[".repeat(deep), "]".repeat(deep)),
        ),
        (
            "inline.toml",
            format!("x = {}1{}\n", "{a = ".repeat(deep), "}".repeat(deep)),
        ),
    ];
    for (name, text) in &cases {
        write(&dir, name, format!("{BASE}\n{text}"));
    }
    for (name, _) in &cases {
        let run = gloss_in(&dir, &["plan", name], &[]);
        let msg = run.failed();
        contains_all(msg, &[name]);
        assert!(
            msg.contains("recursion limit") || msg.contains("cannot recurse further"),
            "{name}: the parser's reason is kept:\n{}",
            &msg[msg.len().saturating_sub(400)..]
        );
        assert!(msg.len() < 3000, "{name}: {} bytes", msg.len());
    }
    // A deep value given on the command line is no table: it is refused
    // as a value of the wrong type, not by the stack.
    write(&dir, "scene.toml", BASE);
    let set = format!("render.size={}{}", "[".repeat(deep), "]".repeat(deep));
    let run = gloss_in(&dir, &["plan", "scene.toml", "--set", &set], &[]);
    contains_all(run.failed(), &["render.size", "more characters"]);
}
