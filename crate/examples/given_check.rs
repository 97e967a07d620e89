//! False alarms, detection and cost of the check of a given landmark file
//! (`estimate/check.rs`, [`check_given`]) on the correct landmark files of
//! `bodyspace synth` populations.
//!
//! `cargo run --release --example given_check -- DIR... [--metres] [--residuals] [--params JSON]`
//!
//! Each `DIR` is a `bodyspace synth` output (`landmarks_ID.csv`, `subjects.json`; millimetres,
//! CAESAR's frame). Per pose (arms raised, arms down, hands on hips, from `subjects.json`): the
//! correct files' flags per file; then, on every file, each Lt./Rt. pair swapped in turn (found:
//! both flagged) and each landmark given a 30 mm typo in one coordinate in turn, x, y and z
//! (found: it is flagged; axis: flagged as `coordinate` on that axis), with the other landmarks
//! flagged meanwhile; and the check's time per file. `--metres` checks the files in metres
//! (`to_mm` 1000) instead. `--residuals` prints each landmark's largest residual over its
//! tolerance on the correct files; `--params` sets any of
//! `CheckParams` (the rest default).

use std::collections::BTreeMap;
use std::path::Path;
use std::time::Instant;

use bodyspace::estimate::caesar_points::{given_landmarks, landmark_rest};
use bodyspace::estimate::check::{
    judge_given, predict_given, rigid_groups, tolerance_mm, CheckParams,
};
use bodyspace::estimate::suspicious::partner_of;
use bodyspace::estimate::SuspicionKind;
use bodyspace::io::read_landmarks;
use bodyspace::landmarks::{LandmarkSet, CAESAR_LANDMARKS};
use bodyspace::template::Template;

/// Per pose: files, flags on the correct files, pairs tried / found, typos tried / found /
/// found on the right axis, flags of other landmarks meanwhile.
#[derive(Default)]
struct Tally {
    files: usize,
    false_flags: usize,
    files_flagged: usize,
    pairs: usize,
    pairs_found: usize,
    typos: usize,
    typos_found: usize,
    typos_axis: usize,
    bystanders: usize,
}

/// The arms' pose of subject `s` of `subjects.json`: hands on hips (elbows bent), arms down
/// (under 17° from the body; the model's A-pose hangs 39.6° from it) or raised.
fn pose_of(s: &serde_json::Value) -> &'static str {
    let pose = &s["params"]["pose"];
    let f = |k: &str| pose[k].as_f64().unwrap_or(0.0);
    if f("left_elbow_flexion") > 0.0 || f("right_elbow_flexion") > 0.0 {
        "hands on hips"
    } else if (f("left_shoulder_abduction") + f("right_shoulder_abduction")) / 2.0 + 39.6 < 17.0 {
        "arms down"
    } else {
        "arms raised"
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let metres = args.iter().any(|a| a == "--metres");
    let residuals = args.iter().any(|a| a == "--residuals");
    let to_mm = if metres { 1000.0 } else { 1.0 };
    let params: CheckParams = args
        .iter()
        .position(|a| a == "--params")
        .map(|k| serde_json::from_str(&args[k + 1]).expect("--params takes CheckParams as JSON"))
        .unwrap_or_default();
    let template = Template::embedded().expect("the embedded template");
    let rest = landmark_rest(&template);
    let check_given = |set: &LandmarkSet| judge_given(&rest, &given_landmarks(set), to_mm, &params);

    let groups = rigid_groups();
    let mut tallies: BTreeMap<&str, Tally> = BTreeMap::new();
    let mut flagged_names: BTreeMap<String, usize> = BTreeMap::new();
    let mut worst = vec![(0.0f64, String::new()); CAESAR_LANDMARKS.len()];
    let (mut checks, mut seconds) = (0usize, 0.0f64);
    let dirs = args
        .iter()
        .enumerate()
        .filter(|(k, a)| !a.starts_with("--") && (*k == 0 || args[k - 1] != "--params"))
        .map(|(_, a)| a);
    for dir in dirs {
        let dir = Path::new(dir);
        let subjects: serde_json::Value = serde_json::from_slice(
            &std::fs::read(dir.join("subjects.json")).expect("subjects.json"),
        )
        .expect("subjects.json is JSON");
        for s in subjects["subjects"].as_array().expect("a subjects list") {
            let id = s["id"].as_str().expect("an id");
            let file = dir.join(format!("landmarks_{id}.csv"));
            let set = read_landmarks(&std::fs::read(&file).expect("the landmarks"), "l.csv")
                .expect("a landmark file")
                .scaled(1.0 / to_mm);
            let tally = tallies.entry(pose_of(s)).or_default();
            let start = Instant::now();
            let check = check_given(&set);
            seconds += start.elapsed().as_secs_f64();
            checks += 1;
            tally.files += 1;
            tally.false_flags += check.flagged.len();
            tally.files_flagged += usize::from(!check.flagged.is_empty());
            for f in &check.flagged {
                *flagged_names.entry(f.name.clone()).or_default() += 1;
                println!(
                    "{} {id} ({}): {} {:.1} mm — {}",
                    dir.display(),
                    pose_of(s),
                    f.name,
                    f.distance_mm,
                    f.suggestion
                );
            }
            let given = given_landmarks(&set);
            if residuals {
                for (i, p) in predict_given(&rest, &groups, &given, &given, &params)
                    .iter()
                    .enumerate()
                {
                    let (Some(p), Some((_, q))) = (p, given.iter().find(|(j, _)| *j == i)) else {
                        continue;
                    };
                    let name = CAESAR_LANDMARKS[i].name;
                    let ratio = (q - p.position).norm() * to_mm
                        / tolerance_mm(name, p.misfit * to_mm, &params);
                    if ratio > worst[i].0 {
                        worst[i] = (ratio, format!("{id} {}", pose_of(s)));
                    }
                }
            }
            let names = |set: &LandmarkSet| -> Vec<String> {
                check_given(set)
                    .flagged
                    .into_iter()
                    .map(|f| f.name)
                    .collect()
            };
            let correct: Vec<String> = check.flagged.iter().map(|f| f.name.clone()).collect();
            let at = |name: &str| set.landmarks.iter().position(|l| l.name == name);
            for (i, l) in CAESAR_LANDMARKS.iter().enumerate() {
                let Some(a) = at(l.name) else { continue };
                if let Some(b) = partner_of(i)
                    .filter(|&j| j > i)
                    .and_then(|j| at(CAESAR_LANDMARKS[j].name))
                {
                    let mut swapped = set.clone();
                    swapped.landmarks[a].position = set.landmarks[b].position;
                    swapped.landmarks[b].position = set.landmarks[a].position;
                    let flagged = names(&swapped);
                    tally.pairs += 1;
                    let pair = [&set.landmarks[a].name, &set.landmarks[b].name];
                    tally.pairs_found += usize::from(pair.iter().all(|n| flagged.contains(n)));
                    tally.bystanders += flagged
                        .iter()
                        .filter(|n| !pair.contains(n) && !correct.contains(n))
                        .count();
                }
                for axis in 0..3 {
                    let mut typo = set.clone();
                    typo.landmarks[a].position[axis] += 30.0 / to_mm;
                    let result = check_given(&typo);
                    tally.typos += 1;
                    let own = result.flagged.iter().find(|f| f.name == l.name);
                    tally.typos_found += usize::from(own.is_some());
                    let axis_name = format!("check the {} coordinate", ['x', 'y', 'z'][axis]);
                    tally.typos_axis += usize::from(own.is_some_and(|f| {
                        f.kind == SuspicionKind::Coordinate && f.suggestion.contains(&axis_name)
                    }));
                    tally.bystanders += result
                        .flagged
                        .iter()
                        .filter(|f| f.name != l.name && !correct.contains(&f.name))
                        .count();
                }
            }
        }
    }
    if residuals {
        for (i, (ratio, at)) in worst.iter().enumerate() {
            println!(
                "{:<28} worst residual / tolerance {ratio:.2} ({at})",
                CAESAR_LANDMARKS[i].name
            );
        }
    }
    println!("\nflagged on correct files: {flagged_names:?}");
    println!(
        "\n| pose | files | flags per correct file | files with a flag | swapped pairs found | 30 mm typos found | on the right axis | other landmarks flagged per case |"
    );
    println!("| --- | --- | --- | --- | --- | --- | --- | --- |");
    let mut all = Tally::default();
    for (pose, t) in &tallies {
        row(pose, t);
        all.files += t.files;
        all.false_flags += t.false_flags;
        all.files_flagged += t.files_flagged;
        all.pairs += t.pairs;
        all.pairs_found += t.pairs_found;
        all.typos += t.typos;
        all.typos_found += t.typos_found;
        all.typos_axis += t.typos_axis;
        all.bystanders += t.bystanders;
    }
    row("all", &all);
    println!(
        "\ncheck_given: {checks} files, {:.3} ms per file",
        seconds * 1000.0 / checks.max(1) as f64
    );
}

fn row(pose: &str, t: &Tally) {
    let share = |a: usize, b: usize| 100.0 * a as f64 / b.max(1) as f64;
    println!(
        "| {pose} | {} | {:.2} | {} | {:.1} % ({}/{}) | {:.1} % ({}/{}) | {:.1} % | {:.3} |",
        t.files,
        t.false_flags as f64 / t.files.max(1) as f64,
        t.files_flagged,
        share(t.pairs_found, t.pairs),
        t.pairs_found,
        t.pairs,
        share(t.typos_found, t.typos),
        t.typos_found,
        t.typos,
        share(t.typos_axis, t.typos),
        t.bystanders as f64 / (t.pairs + t.typos).max(1) as f64,
    );
}
