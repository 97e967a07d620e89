//! Each landmark's typical estimate error: the mean distance (mm) of the estimate from the true
//! landmark on the development subjects, the prior of the confidence (`confidence.rs`). Measured
//! 2026-11-26 with `cargo run --release --example landmarks_estimate -- --n 10` (10 synthetic
//! subjects of the `tuning` profile, 9 poses, 2 frames, no landmarks given), the segment-wise
//! fit with stretching legs, the arms' swing (raised too), no limb folded past 145°, the knees
//! and elbows placed by the limbs' profiles (the knees by the front of the knee), the elbow of a
//! bent arm, the hands' pose about the wrist (its turn kept when the hand then matches better),
//! the hand of a bent arm laid on the body (its palm across the knuckles' line, its turn about
//! the forearm carried down the forearm), a bent elbow's hinge across the arm's plane, every
//! wrist placed by the forearm's profile and the torso's length from the buttocks; the
//! hands-on-hips subject has its hands laid on the hips (the generator's pose since the
//! afternoon of 2026-11-25); the Acromions' rows measured again 2026-11-27 with the same
//! command once they were found on the scan's shoulder (`acromion.rs`; 23.6 / 22.6 → 16.6 /
//! 17.5 mm, the other rows unchanged); the head's nine rows measured again 2026-12-03 with the
//! same command once the head was held by its nose tip (`segments.rs`; Sellion 13.5 → 3.5,
//! Supramenton 15.3 → 2.2, the Infraorbitales 18.6 / 18.7 → 4.9 / 3.9, the Tragions and Gonions
//! 11.9–13.2 → 4.3–6.1, Nuchale 18.4 → 17.6 mm; Spearman's ρ between confidence and error on
//! those subjects −0.44 → −0.57; on held-out subjects the head's landmarks are 6–7 mm off on
//! average, docs/landmarks-estimate.md). Regenerate it with the same command when the method or
//! the template's landmark vertices change; the held-out figures in docs/landmarks-estimate.md
//! say how well it ranks the errors of subjects it was not measured on. The figures are data, in
//! `typical_error.csv` (CAESAR order, one row a landmark).

use std::sync::OnceLock;

use crate::landmarks::{CAESAR_LANDMARKS, CAESAR_LANDMARK_COUNT};

const TABLE: &str = include_str!("typical_error.csv");

/// Typical error (mm) of CAESAR landmark `k` (CAESAR order).
pub fn typical_error_mm(k: usize) -> f64 {
    static PARSED: OnceLock<[f64; CAESAR_LANDMARK_COUNT]> = OnceLock::new();
    PARSED.get_or_init(|| parse(TABLE).expect("typical_error.csv is checked by its test"))[k]
}

/// The table's values in CAESAR order; an error names the first row out of order or unreadable.
fn parse(table: &str) -> Result<[f64; CAESAR_LANDMARK_COUNT], String> {
    let mut values = [0.0; CAESAR_LANDMARK_COUNT];
    let rows: Vec<&str> = table.lines().skip(1).filter(|l| !l.is_empty()).collect();
    if rows.len() != CAESAR_LANDMARK_COUNT {
        return Err(format!("{} rows, not {CAESAR_LANDMARK_COUNT}", rows.len()));
    }
    for (k, row) in rows.iter().enumerate() {
        let (name, value) = row.rsplit_once(',').ok_or(format!("row {k}: {row}"))?;
        if name != CAESAR_LANDMARKS[k].name {
            return Err(format!("row {k}: {name}, not {}", CAESAR_LANDMARKS[k].name));
        }
        values[k] = value.parse().map_err(|_| format!("row {k}: {value}"))?;
    }
    Ok(values)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_has_every_landmark_in_caesar_order() {
        let values = parse(TABLE).unwrap();
        assert!(values.iter().all(|v| *v > 0.0 && *v < 100.0));
        assert_eq!(typical_error_mm(0), values[0]);
        assert!(parse("landmark,typical_error_mm\nSellion,13.5\n").is_err());
    }
}
