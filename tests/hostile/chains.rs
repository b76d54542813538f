//! A `parent` chain in `[[objects]]` is walked once, parents first
//! (src/scene/hierarchy.rs): a chain of 40000 takes as long as 40000
//! objects side by side, and a cycle of any length is found.

use crate::{BASE, contains_all, gloss_in, temp_dir, write};

/// BASE and `n` small cubes, each the child of the one before it when
/// `chained`, each moved a little along x from its parent.
fn objects(n: usize, chained: bool) -> String {
    let mut s = String::from(BASE);
    for i in 0..n {
        s += &format!("[[objects]]\nname = \"c{i}\"\nmesh = \"cube\"\n");
        if chained && i > 0 {
            s += &format!("parent = \"c{}\"\nposition = [0.0001, 0.0, 0.0]\n", i - 1);
        } else {
            s += "scale = [0.01, 0.01, 0.01]\n";
        }
    }
    s
}

#[test]
fn a_parent_chain_of_40000_is_walked_in_linear_time() {
    let dir = temp_dir("parent_chain");
    write(&dir, "chain.toml", objects(40_000, true));
    assert!(std::fs::metadata(dir.join("chain.toml")).unwrap().len() < 4 << 20);
    for args in [
        &["plan", "chain.toml"][..],
        &["render", "chain.toml", "-o", "out.png"][..],
    ] {
        gloss_in(&dir, args, &["out.png"]).succeeded();
    }
    // The last cube is 39999 steps of 0.0001 along x from the first: the
    // plan's frustum test sees them all where the chain puts them.
    let run = gloss_in(&dir, &["plan", "chain.toml"], &[]);
    contains_all(&run.stdout, &["of 40001 opaque objects"]);
}

#[test]
fn a_long_cycle_is_found() {
    let dir = temp_dir("parent_cycle");
    let mut text = objects(30_000, true);
    // The first cube's parent: the last, closing a cycle of 30000.
    text = text.replacen(
        "name = \"c0\"\nmesh = \"cube\"\n",
        "name = \"c0\"\nmesh = \"cube\"\nparent = \"c29999\"\n",
        1,
    );
    write(&dir, "cycle.toml", text);
    let run = gloss_in(&dir, &["plan", "cycle.toml"], &[]);
    contains_all(
        run.failed(),
        &["cycle.toml", ".parent: the parent chain is a cycle"],
    );
}
