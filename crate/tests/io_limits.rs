//! Memory stays bounded (see `io::limits`): a gzip bomb is refused after a bounded amount of output,
//! and a header declaring billions of elements is refused before anything is reserved. Memory is
//! measured by a global allocator that tracks the calling thread's live bytes and largest request
//! (time is not asserted; docs/fuzzing.md has the measured figures).

#![cfg(not(target_arch = "wasm32"))]

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::io::Write;

use bodyspace::io::limits::{MAX_INFLATE_RATIO, MAX_SCAN_TRIANGLES, MAX_SCAN_VERTICES};
use bodyspace::io::{read_landmarks, read_scan, IoError};

struct TrackingAllocator;

thread_local! {
    static LIVE: Cell<usize> = const { Cell::new(0) };
    static PEAK: Cell<usize> = const { Cell::new(0) };
    static LARGEST: Cell<usize> = const { Cell::new(0) };
}

fn grew(size: usize, freed: usize) {
    let _ = LIVE.try_with(|live| {
        let now = (live.get() + size).saturating_sub(freed);
        live.set(now);
        let _ = PEAK.try_with(|p| p.set(p.get().max(now)));
    });
    let _ = LARGEST.try_with(|l| l.set(l.get().max(size)));
}

fn shrank(size: usize) {
    let _ = LIVE.try_with(|live| live.set(live.get().saturating_sub(size)));
}

// SAFETY: forwards every call to the system allocator unchanged; only keeps per-thread counts.
unsafe impl GlobalAlloc for TrackingAllocator {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        grew(layout.size(), 0);
        unsafe { System.alloc(layout) }
    }
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        grew(layout.size(), 0);
        unsafe { System.alloc_zeroed(layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        grew(new_size, layout.size());
        unsafe { System.realloc(ptr, layout, new_size) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        shrank(layout.size());
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static TRACKING: TrackingAllocator = TrackingAllocator;

/// Runs `f` and returns its result with the peak live bytes and the largest single request this
/// thread made meanwhile (above what was live before).
fn measured<T>(f: impl FnOnce() -> T) -> (T, usize, usize) {
    let base = LIVE.with(Cell::get);
    PEAK.with(|p| p.set(base));
    LARGEST.with(|l| l.set(0));
    let out = f();
    let peak = PEAK.with(Cell::get) - base;
    (out, peak, LARGEST.with(Cell::get))
}

const MB: usize = 1 << 20;

/// `members` gzip members of `member_bytes` zeros each behind a PLY header: every member is the
/// same few kilobytes, so a multi-gigabyte bomb is built in a fraction of a second (one member
/// is compressed once). The decoder reads members back to back, as `gzip -d` does.
fn zero_bomb(member_bytes: usize, members: usize) -> Vec<u8> {
    let gz = |data: &[u8]| {
        let mut enc = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::best());
        enc.write_all(data).unwrap();
        enc.finish().unwrap()
    };
    let header = b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
    let mut out = gz(header);
    let member = gz(&vec![0u8; member_bytes]);
    for _ in 0..members {
        out.extend_from_slice(&member);
    }
    out
}

#[test]
fn a_gzip_bomb_is_refused_after_a_bounded_amount_of_output() {
    // 80 members of 64 MiB: 5.4 GB of zeros in about 5 MB.
    let bomb = zero_bomb(64 * MB, 80);
    assert!(bomb.len() < 8 * MB, "{} bytes", bomb.len());
    let (result, peak, _) = measured(|| read_scan(&bomb, "bomb.ply.gz"));
    let err = result.unwrap_err();
    let IoError::InflatesTooMuch {
        limit_bytes, ratio, ..
    } = &err
    else {
        panic!("{err}");
    };
    assert_eq!(*ratio, MAX_INFLATE_RATIO);
    assert_eq!(*limit_bytes, bomb.len() as u64 * MAX_INFLATE_RATIO);
    let message = err.to_string();
    assert!(message.starts_with("bomb.ply.gz: "), "{message}");
    assert!(message.contains(&limit_bytes.to_string()), "{message}");
    assert!(message.contains("decompression bomb"), "{message}");
    // Refused once the output passes 40× the input, not after gigabytes; `Vec` doubling may
    // reserve up to twice what was written.
    assert!(
        peak < 2 * *limit_bytes as usize + MB,
        "peak {} MB",
        peak / MB
    );
    assert!(peak < 600 * MB, "peak {} MB", peak / MB);
}

#[test]
fn a_single_member_bomb_and_a_landmark_bomb_are_refused_too() {
    let bomb = zero_bomb(256 * MB, 1);
    let err = read_scan(&bomb, "one.ply.gz").unwrap_err();
    assert!(matches!(err, IoError::InflatesTooMuch { .. }), "{err}");
    let err = read_landmarks(&bomb, "marks.csv.gz").unwrap_err();
    assert!(matches!(err, IoError::InflatesTooMuch { .. }), "{err}");
}

#[test]
fn a_header_declaring_billions_of_vertices_with_a_tiny_body_is_refused_without_allocating() {
    for format in ["ascii", "binary_little_endian", "binary_big_endian"] {
        let file = format!(
            "ply\nformat {format} 1.0\nelement vertex 4000000000\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n"
        );
        let (result, peak, largest) = measured(|| read_scan(file.as_bytes(), "huge.ply"));
        let err = result.unwrap_err();
        assert!(
            matches!(
                err,
                IoError::Truncated {
                    declared: 4_000_000_000,
                    ..
                }
            ),
            "{err}"
        );
        assert!(
            err.to_string().starts_with(
                "huge.ply: header declares 4000000000 vertices but the file ends after "
            ),
            "{err}"
        );
        assert!(
            largest < 64 * 1024,
            "{format}: largest request {largest} bytes"
        );
        assert!(peak < 64 * 1024, "{format}: peak {peak} bytes");
    }
}

#[test]
fn a_file_that_really_holds_more_than_the_largest_scan_is_refused_before_reserving() {
    // One byte per coordinate (`uchar x y z`) and one per empty face list: the smallest bodies
    // that can hold the declared counts (60 MB and 40 MB, zero pages from the allocator).
    let vertices = MAX_SCAN_VERTICES + 1;
    let mut file = format!(
        "ply\nformat binary_little_endian 1.0\nelement vertex {vertices}\nproperty uchar x\nproperty uchar y\nproperty uchar z\nend_header\n"
    )
    .into_bytes();
    file.resize(file.len() + 3 * vertices as usize, 0);
    let (result, peak, _) = measured(|| read_scan(&file, "dense.ply"));
    let err = result.unwrap_err();
    assert_eq!(
        err.to_string(),
        format!("dense.ply: the header declares {vertices} vertices, more than the {MAX_SCAN_VERTICES} vertices of the largest scan accepted; crop or decimate the scan (see Limits in the README)")
    );
    assert!(peak < 64 * 1024, "peak {peak} bytes");
    drop(file);

    let faces = MAX_SCAN_TRIANGLES + 1;
    let mut file = format!(
        "ply\nformat binary_little_endian 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\nelement face {faces}\nproperty list uchar int vertex_indices\nend_header\n"
    )
    .into_bytes();
    file.resize(file.len() + faces as usize, 0);
    let (result, peak, _) = measured(|| read_scan(&file, "dense.ply"));
    let err = result.unwrap_err();
    assert!(
        matches!(err, IoError::TooManyElements { limit, .. } if limit == MAX_SCAN_TRIANGLES),
        "{err}"
    );
    assert!(peak < 64 * 1024, "peak {peak} bytes");
}

#[test]
fn a_count_under_the_limit_reserves_only_what_the_bytes_can_hold() {
    // 19 million declared vertices and faces, a few bytes of body: each reader reserves at most
    // what the remaining bytes could hold, then reports the truncation.
    for format in ["ascii", "binary_little_endian", "binary_big_endian"] {
        let file = format!(
            "ply\nformat {format} 1.0\nelement vertex 19000000\nproperty float x\nproperty float y\nproperty float z\nelement face 19000000\nproperty list uchar int vertex_indices\nend_header\n0 0 0 1 1 1 2 2 2 3 3 3\n"
        );
        let (result, peak, _) = measured(|| read_scan(file.as_bytes(), "liar.ply"));
        let err = result.unwrap_err();
        assert!(matches!(err, IoError::Truncated { .. }), "{format}: {err}");
        assert!(peak < 64 * 1024, "{format}: peak {peak} bytes");
    }
}

#[test]
fn a_binary_stl_declaring_more_triangles_than_it_holds_is_not_reserved() {
    let mut stl = vec![b' '; 80];
    stl.extend_from_slice(&u32::MAX.to_le_bytes());
    stl.extend_from_slice(&[0u8; 50]);
    let (result, peak, _) = measured(|| read_scan(&stl, "liar.stl"));
    let err = result.unwrap_err();
    assert!(matches!(err, IoError::Truncated { .. }), "{err}");
    assert!(peak < 64 * 1024, "peak {peak} bytes");
}

#[test]
fn elements_without_properties_cost_nothing_however_many_are_declared() {
    let file = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement nothing 18446744073709551615\nend_header\n0 0 0\n1 0 0\n0 1 0\n";
    let mesh = read_scan(file.as_bytes(), "empty_records.ply").unwrap();
    assert_eq!(mesh.positions.len(), 3);
}
