//! What each fuzz target does with its input, shared by the targets in `fuzz_targets/` and by the
//! stable replay test `crate/tests/fuzz_replay.rs` (both include this file by path), so a corpus
//! or regression file replays through exactly what the fuzzer ran. Every function feeds the bytes
//! to a public reader and ignores the result: errors are fine, panics, hangs and runaway memory are
//! not.

use bodyspace::io::{read_landmarks, read_scan};
use bodyspace::model_file::file::read_model;

/// What a target does with one input.
pub type Target = fn(&[u8]);

/// Every target by name (the folder name under `corpus/` and `tests/fuzz_regressions/`).
pub const TARGETS: [(&str, Target); 10] = [
    ("ply_ascii", ply_ascii),
    ("ply_binary", ply_binary),
    ("obj", obj),
    ("stl_ascii", stl_ascii),
    ("stl_binary", stl_binary),
    ("gzip", gzip),
    ("lnd", lnd),
    ("landmarks_csv", landmarks_csv),
    ("landmarks_json", landmarks_json),
    ("bsm", bsm),
];

/// PLY with ASCII seeds (the content, not the name, picks the reader).
pub fn ply_ascii(data: &[u8]) {
    let _ = read_scan(data, "fuzz.ply");
}

/// PLY with binary (little- and big-endian) seeds.
pub fn ply_binary(data: &[u8]) {
    let _ = read_scan(data, "fuzz.ply");
}

pub fn obj(data: &[u8]) {
    let _ = read_scan(data, "fuzz.obj");
}

pub fn stl_ascii(data: &[u8]) {
    let _ = read_scan(data, "fuzz.stl");
}

/// Binary STL as given, then with its triangle count made consistent with its length, because a
/// binary STL is recognised only when `84 + 50·count` is exactly its size and most mutations of
/// the body would otherwise never reach the triangle reader.
pub fn stl_binary(data: &[u8]) {
    let _ = read_scan(data, "fuzz.stl");
    if data.len() >= 84 {
        let count = (data.len() - 84) / 50;
        let mut fixed = data[..84 + 50 * count].to_vec();
        fixed[80..84].copy_from_slice(&(count as u32).to_le_bytes());
        let _ = read_scan(&fixed, "fuzz.stl");
    }
}

/// The gzip wrapper and whatever reader the inflated content selects.
pub fn gzip(data: &[u8]) {
    let _ = read_scan(data, "fuzz.ply.gz");
}

pub fn lnd(data: &[u8]) {
    let _ = read_landmarks(data, "fuzz.lnd");
}

pub fn landmarks_csv(data: &[u8]) {
    let _ = read_landmarks(data, "fuzz.csv");
}

pub fn landmarks_json(data: &[u8]) {
    let _ = read_landmarks(data, "fuzz.json");
}

/// The `.bsm` model file as given, then with its data checksum corrected: a random mutation of the
/// data section almost never keeps the CRC-32 right, and the arrays behind it would go unfuzzed.
pub fn bsm(data: &[u8]) {
    let _ = read_model(data);
    if let Some(fixed) = with_valid_crc(data) {
        let _ = read_model(&fixed);
    }
}

/// `data` with the header's `data_crc32` set to the checksum of its data section, or `None` when
/// the header cannot be found or the checksum is already right.
pub fn with_valid_crc(data: &[u8]) -> Option<Vec<u8>> {
    let header_len = u32::from_le_bytes(data.get(12..16)?.try_into().ok()?) as usize;
    let header_end = header_len.checked_add(16)?;
    let mut header: serde_json::Value = serde_json::from_slice(data.get(16..header_end)?).ok()?;
    let data_start = header_end.checked_add(3)? / 4 * 4;
    let data_bytes = usize::try_from(header.get("data_bytes")?.as_u64()?).ok()?;
    let data_end = data_start.checked_add(data_bytes)?;
    let section = data.get(data_start..data_end)?;
    let mut crc = flate2::Crc::new();
    crc.update(section);
    let crc = crc.sum();
    if header.get("data_crc32")?.as_u64() == Some(crc as u64) {
        return None;
    }
    *header.get_mut("data_crc32")? = crc.into();
    let json = serde_json::to_vec(&header).ok()?;
    let mut out = data[..12].to_vec();
    out.extend_from_slice(&(json.len() as u32).to_le_bytes());
    out.extend_from_slice(&json);
    while out.len() % 4 != 0 {
        out.push(b' ');
    }
    out.extend_from_slice(section);
    out.extend_from_slice(&data[data_end..]);
    Some(out)
}
