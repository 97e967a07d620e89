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
//! average, docs/landmarks-estimate.md); the arms' eighteen rows (elbows, wrists and hands)
//! measured again 2026-12-03 with the same command once every elbow was placed where the arm's
//! axes meet (`bent_arm.rs`; the elbows' 9.7–11.7 → 6.4–9.7 mm, the hands' 6.5–8.8 → 5.1–7.7,
//! the styloids' 2.6–4.3 → 2.4–4.9). Regenerate it with the same command when the method or
//! the template's landmark vertices change; the held-out figures in docs/landmarks-estimate.md
//! say how well it ranks the errors of subjects it was not measured on. The figures are data, in
//! `typical_error.csv` (CAESAR order, one row a landmark).
//!
//! An arm raised beside or above the head (more than `EstimateParams::raised_arm_deg` from
//! hanging down) is not one of those subjects' (their arms hang 10–60° from the body), and its
//! Acromion is placed far worse: its landmarks' typical errors are in `typical_error_raised_arm.csv` (one row a landmark
//! of the arm, either side), measured 2026-12-03 on 16 subjects of the scanner zoo's
//! `arm-raised` class (`bodyspace synth --scanner-class arm-raised --n 8 --step 4`, seeds 2026
//! and 4242, then `bodyspace landmarks` on each scan; the raised arms 83–149° from hanging down):
//! the mean distance of the raised arm's estimated landmarks from the true ones, measured again
//! the same way once every elbow was placed where the arm's axes meet. The raised arm's
//! Acromion lies 74 mm off (the fit's guess: a raised shoulder has no shoulder point,
//! `acromion.rs`), where the table above has 17 mm; its elbow and hand 5–15 mm, a few mm worse
//! than an arm hanging by the body (37–42 mm before; docs/landmarks-estimate.md, "Every elbow
//! where its axes meet; a raised arm").

use std::sync::OnceLock;

use crate::landmarks::{CAESAR_LANDMARKS, CAESAR_LANDMARK_COUNT};

const TABLE: &str = include_str!("typical_error.csv");

/// Typical error (mm) of CAESAR landmark `k` (CAESAR order).
pub fn typical_error_mm(k: usize) -> f64 {
    static PARSED: OnceLock<[f64; CAESAR_LANDMARK_COUNT]> = OnceLock::new();
    PARSED.get_or_init(|| parse(TABLE).expect("typical_error.csv is checked by its test"))[k]
}

const RAISED_ARM: &str = include_str!("typical_error_raised_arm.csv");

/// Typical error (mm) of CAESAR landmark `k` when its arm is raised: `None` for a landmark that
/// is not one of an arm's (the table's names are the landmarks' without `Rt. ` / `Lt. `).
pub fn raised_arm_typical_error_mm(k: usize) -> Option<f64> {
    static PARSED: OnceLock<Vec<(String, f64)>> = OnceLock::new();
    let rows = PARSED.get_or_init(|| {
        parse_raised_arm(RAISED_ARM).expect("typical_error_raised_arm.csv is checked by its test")
    });
    let name = CAESAR_LANDMARKS[k].name;
    let arm_name = name
        .strip_prefix("Rt. ")
        .or_else(|| name.strip_prefix("Lt. "))?;
    rows.iter().find(|(n, _)| n == arm_name).map(|(_, v)| *v)
}

/// The raised arm's rows (name without the side, value); an error names the first row whose
/// name is no CAESAR landmark's on either side, or whose value is unreadable.
fn parse_raised_arm(table: &str) -> Result<Vec<(String, f64)>, String> {
    table
        .lines()
        .skip(1)
        .filter(|l| !l.is_empty())
        .map(|row| {
            let (name, value) = row.rsplit_once(',').ok_or(row.to_string())?;
            let known = ["Rt. ", "Lt. "].iter().all(|side| {
                CAESAR_LANDMARKS
                    .iter()
                    .any(|l| l.name == format!("{side}{name}"))
            });
            if !known {
                return Err(format!("{name} is no landmark of both arms"));
            }
            let value: f64 = value.parse().map_err(|_| format!("{name}: {value}"))?;
            Ok((name.to_string(), value))
        })
        .collect()
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

    #[test]
    fn a_raised_arm_has_its_own_errors_for_both_sides_and_nothing_else() {
        let rows = parse_raised_arm(RAISED_ARM).unwrap();
        assert!(rows.len() >= 10 && rows.iter().all(|(_, v)| *v > 0.0 && *v < 200.0));
        let index = |name: &str| {
            CAESAR_LANDMARKS
                .iter()
                .position(|l| l.name == name)
                .unwrap()
        };
        let (right, left) = (index("Rt. Olecranon"), index("Lt. Olecranon"));
        assert_eq!(
            raised_arm_typical_error_mm(right),
            raised_arm_typical_error_mm(left)
        );
        assert!(raised_arm_typical_error_mm(right).unwrap() > typical_error_mm(right));
        assert_eq!(raised_arm_typical_error_mm(index("Sellion")), None);
        assert_eq!(raised_arm_typical_error_mm(index("Rt. Knee Crease")), None);
        assert!(parse_raised_arm("landmark,typical_error_mm\nSellion,3.5\n").is_err());
    }
}
