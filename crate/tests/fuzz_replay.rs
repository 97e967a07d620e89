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

#[test]
fn the_bsm_target_gets_past_the_checksum_of_a_mutated_data_section() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut bytes = std::fs::read(root.join("fuzz/corpus/bsm/tube_f32.bsm")).unwrap();
    assert!(bodyspace::model_file::file::read_model(&bytes).is_ok());
    let last = bytes.len() - 2;
    bytes[last] ^= 0x01;
    let err = bodyspace::model_file::file::read_model(&bytes).unwrap_err();
    assert!(err.to_string().contains("CRC-32"), "{err}");
    let fixed = entry::with_valid_crc(&bytes).expect("the header is found");
    assert!(bodyspace::model_file::file::read_model(&fixed).is_ok());
    assert!(entry::with_valid_crc(&fixed).is_none());
}
