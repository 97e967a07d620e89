//! CAESAR `.lnd` landmark files: reader and writer.
//!
//! Layout: `KEY = value` header lines (`SUBJECT_ID`, `STD_LAND`, `AUX_LAND`, ...), the section
//! markers `STANDARD =` and `AUX =`, then one line per landmark until `END =`:
//! `index  int  int  float  x  y  z  name` with x y z in millimetres and a name that may contain
//! spaces, commas, periods and slashes. −999 in an integer field marks a missing landmark. Lines
//! may end in CRLF.

use std::fmt::Write as _;

use super::landmark_raw::{finite, RawLandmark};
use super::IoError;
use crate::landmarks::{LandmarkSet, CAESAR_LANDMARKS};

/// The marker value CAESAR uses for a landmark that could not be located.
pub const LND_MISSING: i64 = -999;

/// Whether `text` has the `.lnd` section markers.
pub fn looks_like_lnd(text: &str) -> bool {
    text.lines().any(|l| {
        let l = l.trim();
        l.starts_with("AUX =") || l.starts_with("STANDARD =") || l.starts_with("END =")
    })
}

/// A `KEY = value` line's key, if the line is one (keys are upper-case words).
fn header_key(line: &str) -> Option<&str> {
    let (key, _) = line.split_once('=')?;
    let key = key.trim();
    let is_key = !key.is_empty()
        && key
            .chars()
            .all(|c| c.is_ascii_uppercase() || c.is_ascii_digit() || c == '_');
    is_key.then_some(key)
}

/// The landmark entries of a `.lnd` file, in file order.
pub fn parse_lnd(text: &str, file: &str) -> Result<Vec<RawLandmark>, IoError> {
    let mut in_section = false;
    let mut saw_marker = false;
    let mut out = Vec::new();
    for (k, line) in text.lines().enumerate() {
        let line_no = k + 1;
        let line = line.trim_end_matches('\r');
        if line.trim().is_empty() {
            continue;
        }
        if let Some(key) = header_key(line) {
            match key {
                "AUX" | "STANDARD" => {
                    in_section = true;
                    saw_marker = true;
                }
                "END" => break,
                _ => {}
            }
            continue;
        }
        if !in_section {
            return Err(IoError::at_line(
                file,
                line_no,
                "expected a `KEY = value` header line or the `AUX =` marker before landmark lines",
            ));
        }
        out.push(parse_landmark_line(line, line_no, file)?);
    }
    if !saw_marker {
        return Err(IoError::malformed(
            file,
            "header",
            "no `AUX =` (or `STANDARD =`) marker; not a CAESAR .lnd file",
        ));
    }
    Ok(out)
}

fn parse_landmark_line(line: &str, line_no: usize, file: &str) -> Result<RawLandmark, IoError> {
    let mut rest = line;
    let mut fields = [""; 7];
    for field in &mut fields {
        rest = rest.trim_start();
        let end = rest.find(char::is_whitespace).unwrap_or(rest.len());
        *field = &rest[..end];
        rest = &rest[end..];
    }
    let name = rest.trim();
    if name.is_empty() {
        return Err(IoError::at_line(
            file,
            line_no,
            "a landmark line needs index, two integers, a number, x y z and a name",
        ));
    }
    let number = |s: &str| -> Result<f64, IoError> {
        s.parse::<f64>().map_err(|_| {
            IoError::at_line(
                file,
                line_no,
                format!("cannot read {s:?} as a number in the line for {name:?}"),
            )
        })
    };
    let mut values = [0.0f64; 7];
    for (v, f) in values.iter_mut().zip(fields) {
        *v = number(f)?;
    }
    let missing = values[1] == LND_MISSING as f64 || values[2] == LND_MISSING as f64;
    let position = if missing {
        None
    } else {
        Some(finite([values[4], values[5], values[6]], name, file)?)
    };
    Ok(RawLandmark {
        name: name.to_string(),
        position,
    })
}

/// A CAESAR `.lnd` file holding all 73 landmarks in CAESAR order (−999 for those `set` lacks),
/// followed by the set's non-CAESAR landmarks as auxiliary landmarks. Positions are written as
/// given; `.lnd` readers expect millimetres.
pub fn write_lnd(set: &LandmarkSet, subject_id: &str) -> Vec<u8> {
    let extras: Vec<_> = set
        .landmarks
        .iter()
        .filter(|l| !CAESAR_LANDMARKS.iter().any(|c| c.name == l.name))
        .collect();
    let mut out = String::new();
    let _ = writeln!(out, "SUBJECT_ID = {subject_id}");
    let _ = writeln!(out, "STD_LAND = {}", CAESAR_LANDMARKS.len());
    let _ = writeln!(out, "AUX_LAND = {}", extras.len());
    out.push_str("STANDARD =\nAUX =\n");
    let mut index = 0;
    let mut line = |out: &mut String, name: &str, p: Option<[f64; 3]>| {
        index += 1;
        match p {
            Some([x, y, z]) => {
                let _ = writeln!(
                    out,
                    "{index:4} {:4} {:4} {:8.3} {x:10.3} {y:10.3} {z:10.3} {name}",
                    0, 1, 0.0
                );
            }
            None => {
                let m = LND_MISSING;
                let _ = writeln!(
                    out,
                    "{index:4} {m:4} {m:4} {:8.3} {:10.3} {:10.3} {:10.3} {name}",
                    m as f64, m as f64, m as f64, m as f64
                );
            }
        }
    };
    for c in &CAESAR_LANDMARKS {
        let p = set.get(c.name).map(|p| [p.x, p.y, p.z]);
        line(&mut out, c.name, p);
    }
    for l in extras {
        line(
            &mut out,
            &l.name,
            Some([l.position.x, l.position.y, l.position.z]),
        );
    }
    out.push_str("END =\n");
    out.into_bytes()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_keep_inner_spaces_commas_and_slashes() {
        let text = "AUX =\r\n  13   0   1   0.0  1 2 3  Rt. Thelion/Bustpoint \r\n  28 0 1 0.0 4 5 6 Waist,  Preferred, Post.\r\nEND =\r\n";
        let raw = parse_lnd(text, "a.lnd").unwrap();
        assert_eq!(raw[0].name, "Rt. Thelion/Bustpoint");
        assert_eq!(raw[1].name, "Waist,  Preferred, Post.");
        assert!(looks_like_lnd(text));
        assert!(!looks_like_lnd("name,x,y,z\n"));
    }

    #[test]
    fn minus_999_in_either_integer_field_is_missing() {
        let text = "AUX =\n1 -999 0 0.0 1 2 3 Sellion\n2 0 -999 0.0 1 2 3 Crotch\n3 0 1 0.0 1 2 3 Cervicale\n";
        let raw = parse_lnd(text, "a.lnd").unwrap();
        let present: Vec<bool> = raw.iter().map(|r| r.position.is_some()).collect();
        assert_eq!(present, [false, false, true]);
    }
}
