//! The check of a given landmark file (`estimate/check.rs`, `check_given`) end to end on
//! the correct landmark files of synthetic `held-out` subjects (placement noise included, CAESAR
//! frame, millimetres and metres): few flags on correct files; a swapped Lt./Rt. pair and a
//! 60 mm typo in one coordinate found (a 30 mm one is found about one time in three on these
//! bodies, docs/landmarks-estimate.md; the unit tests find it on the template's own shape); a
//! hand laid on the hip (the wrist turned about the forearm) raises no flag on its styloids, and
//! a swapped pair there is still found; a raised arm's Acromion (risen with the shoulder girdle)
//! raises none either, and a swapped Acromion pair is still found. Native only (MakeHuman data
//! from node_modules).
#![cfg(not(target_arch = "wasm32"))]

#[path = "synth_support/mod.rs"]
mod synth_support;

use bodyspace::estimate::check::{judge_given, CheckParams};
use bodyspace::estimate::{check_given, given_landmarks, landmark_rest, SuspicionKind};
use bodyspace::landmarks::LandmarkSet;
use bodyspace::synth::{
    population_subject, zoo_subject, LandmarkParams, PopulationProfile, ScannerClass,
    ScannerParams, SubjectId, Units, ZooParams,
};
use synth_support::base_template_and_data;

/// Subjects 1..=N of a `held-out` seed the check was not tuned on (tuned on 101 and 202).
const SEED: u64 = 3131;
const N: u64 = 8;

/// The `held-out` profile's scanner, coarse: only the landmarks are used.
fn coarse_scanner() -> ScannerParams {
    ScannerParams {
        vertical_step: 0.02,
        horizontal_step: 0.02,
        ..PopulationProfile::HeldOut.scanner()
    }
}

/// Subject `index` of [`SEED`]: whether its hands are on its hips, its correct landmark file
/// (metres for an even index, else millimetres) and the file's units in mm.
fn subject(
    template: &bodyspace::template::Template,
    data: &bodyspace::synth::MakeHumanData,
    index: u64,
) -> (bool, LandmarkSet, f64) {
    let scanner = coarse_scanner();
    let id = SubjectId {
        profile: PopulationProfile::HeldOut,
        seed: SEED,
        index,
    };
    let units = if index % 2 == 0 {
        Units::Metres
    } else {
        Units::Millimetres
    };
    let to_mm = if units == Units::Metres { 1000.0 } else { 1.0 };
    let (subject, set) = population_subject(
        data,
        template,
        id,
        &scanner,
        &LandmarkParams::default(),
        units,
    )
    .unwrap();
    (subject.params.pose.left_elbow_flexion > 0.0, set, to_mm)
}

fn swap(set: &LandmarkSet, a: &str, b: &str) -> LandmarkSet {
    let at = |name: &str| set.landmarks.iter().position(|l| l.name == name).unwrap();
    let (a, b) = (at(a), at(b));
    let mut swapped = set.clone();
    swapped.landmarks[a].position = set.landmarks[b].position;
    swapped.landmarks[b].position = set.landmarks[a].position;
    swapped
}

#[test]
fn correct_files_raise_few_flags_and_a_swap_and_a_typo_are_found() {
    let (template, data) = base_template_and_data();
    let mut flags = 0;
    let mut hands_on_hips = 0;
    for index in 1..=N {
        let (on_hips, set, to_mm) = subject(&template, &data, index);
        hands_on_hips += usize::from(on_hips);
        let check = check_given(&template, &set, to_mm);
        assert!(check.unjudged.is_empty(), "{:?}", check.unjudged);
        flags += check.flagged.len();
        eprintln!("subject {index}: {:?}", check.flagged);

        let at = |set: &LandmarkSet, name: &str| {
            set.landmarks.iter().position(|l| l.name == name).unwrap()
        };
        let found = |set: &LandmarkSet| -> Vec<(String, SuspicionKind, String)> {
            check_given(&template, set, to_mm)
                .flagged
                .into_iter()
                .map(|f| (f.name, f.kind, f.suggestion))
                .collect()
        };
        let flagged = found(&swap(&set, "Rt. ASIS", "Lt. ASIS"));
        for name in ["Rt. ASIS", "Lt. ASIS"] {
            assert!(
                flagged
                    .iter()
                    .any(|(n, k, _)| n == name && *k == SuspicionKind::Swapped),
                "subject {index}: {flagged:?}"
            );
        }

        let mut typo = set.clone();
        let sellion = at(&set, "Sellion");
        typo.landmarks[sellion].position.z += 60.0 / to_mm;
        let flagged = found(&typo);
        let sellion = flagged.iter().find(|(n, _, _)| n == "Sellion");
        assert!(
            sellion.is_some_and(
                |(_, k, s)| *k == SuspicionKind::Coordinate && s.contains("z coordinate")
            ),
            "subject {index}: {flagged:?}"
        );
    }
    assert!(hands_on_hips > 0, "no subject with the hands on the hips");
    let per_file = flags as f64 / N as f64;
    assert!(per_file <= 1.0, "{per_file} flags per correct file");
}

/// Issue 31: a hand laid on the hip turns the wrist about the forearm, and the rigid forearm's
/// prediction put the ulnar styloids of such files 28–46 mm off (23 of 30 false alarms on hands
/// on hips). With the forearm's twist (`estimate/forearm_twist.rs`, turned on here) they raise no flag, and the
/// styloids swapped between the sides are still found (both flagged).
#[test]
fn a_laid_hand_raises_no_flag_on_its_styloids_and_a_swap_there_is_found() {
    let (template, data) = base_template_and_data();
    let rest = landmark_rest(&template);
    // The forearm's twist on, as measured (off by default: `CheckParams`).
    let twist = CheckParams {
        tolerance_mm: 21.0,
        twist_min_bend_deg: 60.0,
        ..CheckParams::default()
    };
    let mut laid = 0;
    for index in 1..=N {
        let (on_hips, set, to_mm) = subject(&template, &data, index);
        if !on_hips {
            continue;
        }
        laid += 1;
        let flagged = |set: &LandmarkSet| -> Vec<(String, SuspicionKind)> {
            judge_given(&rest, &given_landmarks(set), to_mm, &twist)
                .flagged
                .into_iter()
                .map(|f| (f.name, f.kind))
                .collect()
        };
        let correct = flagged(&set);
        assert!(
            !correct.iter().any(|(n, _)| n.contains("Styloid")),
            "subject {index}: {correct:?}"
        );
        for styloid in ["Ulnar Styloid", "Radial Styloid"] {
            let (lt, rt) = (format!("Lt. {styloid}"), format!("Rt. {styloid}"));
            let swapped = flagged(&swap(&set, &lt, &rt));
            // Found: both flagged (the example's measure). Laid on the hips the two wrists lie
            // apart mostly across the body, and their rigid forearms' predictions 30–50 mm off:
            // the words may name that coordinate or the other side's landmark, not the swap.
            for name in [&lt, &rt] {
                assert!(
                    swapped.iter().any(|(n, _)| n == name),
                    "subject {index}, {name}: {swapped:?}"
                );
            }
        }
    }
    assert!(laid > 0, "no subject with the hands on the hips");
}

/// Issue 31: the zoo's raised arm (one arm 83–149° from hanging, the clavicle raised with it)
/// has its Acromion 44–101 mm from where the thorax and the upper arm put it, and the check
/// called it suspicious on 12 of 16 correct files of seed 3917 as `bodyspace synth` writes them
/// (0.81 flags per file on 7193; here, with a coarse scanner's noise, on 8 of 16). A raised
/// arm's Acromion now has its tolerance widened by `raised_acromion_mm` (`estimate/check.rs`):
/// no Acromion is flagged on these files. The Acromions swapped between the sides lie 300 mm and
/// more apart and are still found (both flagged). Without the widening (`raised_acromion_mm` 0)
/// the same files flag the raised Acromion, so the test sees the difference.
#[test]
fn a_raised_arms_acromion_raises_no_flag_and_a_swapped_pair_is_still_found() {
    let (template, data) = base_template_and_data();
    let rest = landmark_rest(&template);
    let scanner = coarse_scanner();
    let names = |set: &LandmarkSet, params: &CheckParams| -> Vec<String> {
        judge_given(&rest, &given_landmarks(set), 1.0, params)
            .flagged
            .into_iter()
            .map(|f| f.name)
            .collect()
    };
    let mut before = 0;
    for index in 1..=16 {
        let id = SubjectId {
            profile: PopulationProfile::HeldOut,
            seed: 3917,
            index,
        };
        let (_, set) = zoo_subject(
            &data,
            &template,
            id,
            ScannerClass::ArmRaised,
            &scanner,
            &ZooParams::default(),
            &LandmarkParams::default(),
            Units::Millimetres,
        )
        .unwrap();
        let correct = names(&set, &CheckParams::default());
        assert!(
            !correct.iter().any(|n| n.contains("Acromion")),
            "subject {index}: {correct:?}"
        );
        let unwidened = CheckParams {
            raised_acromion_mm: 0.0,
            ..CheckParams::default()
        };
        before += names(&set, &unwidened)
            .iter()
            .filter(|n| n.contains("Acromion"))
            .count();
        let swapped = names(
            &swap(&set, "Lt. Acromion", "Rt. Acromion"),
            &CheckParams::default(),
        );
        for name in ["Lt. Acromion", "Rt. Acromion"] {
            assert!(
                swapped.iter().any(|n| n == name),
                "subject {index}, {name}: {swapped:?}"
            );
        }
    }
    assert!(
        before > 0,
        "no raised Acromion was flagged without the widening"
    );
}
