//! Replays every committed fuzz corpus file (`fuzz/corpus/<target>/`) and every regression file
//! (`tests/fuzz_regressions/<target>/`) through the same entry points the fuzz targets call
//! (`fuzz/entry.rs`), on stable Rust: no input may panic (errors are fine) or take longer than
//! [`MAX_PER_INPUT`]. See docs/fuzzing.md.

#![cfg(not(target_arch = "wasm32"))]

#[allow(dead_code)]
#[path = "../fuzz/entry.rs"]
mod entry;

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// Generous for a debug build on a busy machine; the fuzzer itself uses a 1 s timeout (release).
const MAX_PER_INPUT: Duration = Duration::from_secs(3);

fn files(dir: &Path) -> Vec<PathBuf> {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    let mut out: Vec<PathBuf> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.is_file())
        .collect();
    out.sort();
    out
}

#[test]
fn every_corpus_and_regression_file_is_read_without_panic_in_bounded_time() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut failures = Vec::new();
    let mut count = 0;
    for (target, run) in entry::TARGETS {
        let dirs = [
            root.join("fuzz/corpus").join(target),
            root.join("tests/fuzz_regressions").join(target),
        ];
        for path in dirs.iter().flat_map(|d| files(d)) {
            let bytes = std::fs::read(&path).expect("a committed fuzz file is readable");
            let start = Instant::now();
            let outcome = std::panic::catch_unwind(|| run(&bytes));
            let took = start.elapsed();
            count += 1;
            if outcome.is_err() {
                failures.push(format!("{}: panicked", path.display()));
            } else if took > MAX_PER_INPUT {
                failures.push(format!("{}: took {took:?}", path.display()));
            }
        }
    }
    assert!(count > 0, "no corpus files found under fuzz/corpus");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
