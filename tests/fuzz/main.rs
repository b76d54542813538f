//! The fuzz harness: properties that must hold for *any* input, checked on
//! random and mutated inputs with proptest (no GL context needed).
//!
//! * `scene`: the scene loader, on arbitrary text, on TOML-shaped text made
//!   of the format's own keys, and on the shipped scenes mutated (bytes,
//!   lines, keys deleted, numbers made extreme, values of the wrong type,
//!   `--set` overrides), never panics: it returns a scene (whose warnings
//!   and frame plan are then made) or an error whose message is not empty
//!   and at most `MAX_MESSAGE_CHARS` after the file's name.
//! * `obj`: `geometry::load_obj` on arbitrary bytes and mutated OBJ files.
//! * `mtl`: the MTL reader, through an OBJ's `mtllib`, on arbitrary bytes,
//!   MTL-shaped lines, and a full MTL mutated and cut.
//! * `png`: `gl::texture::load_rgba8` on mutated PNGs (CRCs fixed up or
//!   not, IHDR sizes made extreme).
//! * `cli`: `cli::Cli::try_parse_from` on argument vectors.
//! * `overrides`: `--set` keys of any depth and scene tables nested
//!   hundreds deep, each property for a bounded time.
//!
//! The loaders must not panic and must stay within the memory their own
//! size caps allow: this binary counts every allocation (`alloc`).
//!
//! Cases per property: `GLOSS_FUZZ_CASES` (default `DEFAULT_CASES`); the
//! seed: `GLOSS_FUZZ_SEED` (default: from the clock, printed, so that a
//! failure can be run again). With `-- --nocapture` each property prints
//! how many inputs it tried and how long it took. A failing input is
//! written under target/fuzz-failures/; copied into
//! tests/fuzz/regressions/<property>/ it is replayed on every run
//! (`regressions`).

mod alloc;
mod cli;
mod gltf;
mod gltf_images;
mod mtl;
mod obj;
mod overrides;
mod png;
mod regressions;
mod scene;

use proptest::strategy::Strategy;
use proptest::test_runner::{Config, RngSeed, TestCaseError, TestError, TestRunner};
use std::path::PathBuf;
use std::time::Instant;

/// Inputs per property when `GLOSS_FUZZ_CASES` is not set.
pub const DEFAULT_CASES: u32 = 30_000;

/// Seconds a property tests inputs for when `GLOSS_FUZZ_SECONDS` is not
/// set: past it, the rest of its inputs are drawn but not tried, so the
/// suite's time stays bounded whatever an input costs on this machine.
pub const DEFAULT_SECONDS: u64 = 30;

fn seconds() -> u64 {
    std::env::var("GLOSS_FUZZ_SECONDS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(DEFAULT_SECONDS)
}

pub fn cases() -> u32 {
    std::env::var("GLOSS_FUZZ_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(DEFAULT_CASES)
}

fn seed() -> u64 {
    match std::env::var("GLOSS_FUZZ_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
    {
        Some(s) => s,
        None => std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map(|d| d.as_nanos() as u64)
            .unwrap_or(1),
    }
}

thread_local! {
    /// How many inputs of the running property were accepted (`accepted`).
    static ACCEPTED: std::cell::Cell<u32> = const { std::cell::Cell::new(0) };
}

/// Count an input the code under test accepted (a scene that loaded, a
/// mesh or image that decoded, a command line that parsed), so that the
/// harness can show how deep its inputs get.
pub fn accepted() {
    ACCEPTED.with(|a| a.set(a.get() + 1));
}

pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Check `test` on `cases()` inputs from `strategy`. A failure (a panic
/// or a broken property) is shrunk to a small input, written under
/// target/fuzz-failures/NAME/ as the plain file `bytes` makes of it, and
/// reported with the seed that finds it.
pub fn run<S: Strategy>(
    name: &str,
    strategy: S,
    bytes: fn(&S::Value) -> Vec<u8>,
    test: impl Fn(S::Value) -> Result<(), TestCaseError>,
) {
    let (cases, seed) = (cases(), seed());
    let config = Config {
        cases,
        failure_persistence: None,
        rng_seed: RngSeed::Fixed(seed),
        max_shrink_iters: 2000,
        max_shrink_time: 60_000,
        ..Config::default()
    };
    let mut runner = TestRunner::new(config);
    ACCEPTED.with(|a| a.set(0));
    let start = Instant::now();
    let limit = std::time::Duration::from_secs(seconds());
    let tried = std::cell::Cell::new(0u32);
    let result = runner.run(&strategy, |input| {
        if start.elapsed() > limit {
            return Ok(());
        }
        tried.set(tried.get() + 1);
        test(input)
    });
    let took = start.elapsed().as_secs_f64();
    let tried = tried.get();
    match result {
        Ok(()) => println!(
            "fuzz {name}: {tried} of {cases} inputs tried in {took:.2} s ({:.2} ms each), {} accepted, seed {seed}",
            1e3 * took / f64::from(tried.max(1)),
            ACCEPTED.with(std::cell::Cell::get)
        ),
        Err(TestError::Abort(why)) => panic!("fuzz {name}: aborted: {why}"),
        Err(TestError::Fail(why, input)) => {
            let dir = root().join("target/fuzz-failures").join(name);
            let _ = std::fs::create_dir_all(&dir);
            let file = dir.join(format!("seed-{seed}"));
            let _ = std::fs::write(&file, bytes(&input));
            panic!(
                "fuzz {name}: {why}\nthe input is in {} (GLOSS_FUZZ_SEED={seed} finds it again); copy it into tests/fuzz/regressions/{name}/ to replay it on every run",
                file.display()
            );
        }
    }
}

/// A file for one input, in a folder of this process and thread (the
/// loaders read files).
pub fn scratch(name: &str) -> PathBuf {
    let thread = format!("{:?}", std::thread::current().id())
        .chars()
        .filter(char::is_ascii_alphanumeric)
        .collect::<String>();
    let dir = std::env::temp_dir().join(format!("gloss-fuzz-{}-{thread}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("make the scratch folder");
    dir.join(name)
}

/// Numbers at the edges: zeros, signs, f32 and integer limits, NaN and
/// infinities, TOML that overflows.
pub const EXTREME_NUMBERS: &[&str] = &[
    "0",
    "-0.0",
    "1",
    "-1",
    "0.5",
    "1e-45",
    "1e-39",
    "3.4028235e38",
    "-3.4028235e38",
    "3.5e38",
    "1e308",
    "nan",
    "-nan",
    "inf",
    "-inf",
    "65535",
    "65536",
    "2147483647",
    "-2147483648",
    "4294967295",
    "4294967296",
    "9223372036854775807",
    "-9223372036854775808",
    "99999999999999999999",
    "1e9",
    "100000",
    "100001",
];

#[test]
fn a_broken_property_fails_the_run_and_keeps_its_input() {
    // The harness is worth something only if it can fail: a property that
    // panics on any input holding a 7 is caught, shrunk to just [7], and
    // that input is written out.
    let bytes = proptest::collection::vec(proptest::arbitrary::any::<u8>(), 0..64);
    let failed = std::panic::catch_unwind(|| {
        run(
            "self-test",
            bytes,
            |b| b.clone(),
            |b| {
                assert!(!b.contains(&7), "found a 7");
                Ok(())
            },
        )
    });
    let why = failed.expect_err("the run must fail");
    let why = why.downcast_ref::<String>().cloned().unwrap_or_default();
    assert!(why.contains("target/fuzz-failures/self-test"), "{why}");
    let file = why
        .split("the input is in ")
        .nth(1)
        .and_then(|s| s.split(' ').next())
        .unwrap();
    assert_eq!(std::fs::read(file).unwrap(), vec![7]);
    let _ = std::fs::remove_file(file);
}
