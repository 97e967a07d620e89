//! What a partial file of correct landmarks does to the fit (issue 31: never worse than no file):
//! held-out synthetic subjects fitted by the one subject path (`subject::fit_subject`, 40 fine
//! iterations as `tests/subject_paths.rs`) with no landmark file and with each of a few partial
//! files of their true landmarks (2 mm placement noise), the mean correspondence error against
//! the truth.
//!
//! `cargo run --release --example partial_files -- [--seed S] [--indices 0,1,2] [--step MM]
//!  [--split] [--params JSON] [--first-only]`
//!
//! The partial files: the estimate test's ten (`PARTIAL`) and those of
//! `tests/synth_support/partial.rs` (`PARTIAL_FILES`); `--first-only` tries the first alone.
//! `--params JSON` also fits with the estimate run with those `EstimateParams` (the rest
//! default).
//!
//! `--split` also separates the two ways the given landmarks act: *estimate only* (the estimate
//! runs with them, the warp uses the estimate's own fitted landmark vertices in their place) and
//! *warp only* (the estimate runs without them, the warp uses them in place of the estimate's).

#[cfg(not(target_arch = "wasm32"))]
#[path = "../tests/synth_support/mod.rs"]
mod synth_support;

#[cfg(not(target_arch = "wasm32"))]
mod native {
    use super::synth_support::partial::{correspondence_mm, only, PARTIAL, PARTIAL_FILES};
    use super::synth_support::{base_template_and_data, subject_in_metres};
    use bodyspace::estimate::{estimate_landmarks, EstimateInput, EstimateParams};
    use bodyspace::landmarks::{Landmark, LandmarkSet};
    use bodyspace::mesh::Mesh;
    use bodyspace::subject::{PriorEstimate, SubjectInput, SubjectOptions};
    use bodyspace::synth::{PopulationProfile, ScannerParams, SubjectId};
    use bodyspace::template::{Resolution, Template};
    use nalgebra::Point3;

    fn fit(
        template: &Template,
        scan: &Mesh,
        truth: &[Point3<f64>],
        given: Option<LandmarkSet>,
        prior: Option<PriorEstimate>,
    ) -> f64 {
        let mut options = SubjectOptions::default();
        options.params.fine.max_iterations = 40;
        correspondence_mm(template, scan, truth, given, prior, &options).0
    }

    pub fn main() {
        let args: Vec<String> = std::env::args().skip(1).collect();
        let value = |flag: &str| {
            args.iter()
                .position(|a| a == flag)
                .map(|k| args[k + 1].clone())
        };
        let seed: u64 = value("--seed").map_or(5151, |s| s.parse().unwrap());
        let step: f64 = value("--step").map_or(12.0, |s| s.parse().unwrap());
        let indices: Vec<u64> = value("--indices")
            .unwrap_or("0".into())
            .split(',')
            .map(|s| s.parse().unwrap())
            .collect();
        let split = args.iter().any(|a| a == "--split");
        let first = args.iter().any(|a| a == "--first-only");
        let params: Option<EstimateParams> =
            value("--params").map(|j| serde_json::from_str(&j).expect("--params: EstimateParams"));
        let (template, data) = base_template_and_data();
        let base = template.at_resolution(Resolution::Base);
        let vertices = base.landmark_vertices();
        for index in indices {
            let id = SubjectId {
                profile: PopulationProfile::HeldOut,
                seed,
                index,
            };
            let scanner = ScannerParams {
                vertical_step: step / 1000.0,
                horizontal_step: step / 1000.0,
                ..id.profile.scanner()
            };
            let (scan, landmarks, truth) = subject_in_metres(&data, &template, id, &scanner);
            let none = fit(&template, &scan, &truth, None, None);
            println!("seed {seed} subject {index}: no file {none:.2} mm");
            let partials = [("estimate-test-10", &PARTIAL[..])]
                .into_iter()
                .chain(PARTIAL_FILES);
            for (name, names) in partials.take(if first { 1 } else { PARTIAL_FILES.len() + 1 }) {
                let given = only(&landmarks, names);
                let with = fit(&template, &scan, &truth, Some(given.clone()), None);
                let mut line = format!(
                    "  {name} ({}): {with:.2} mm ({:+.2})",
                    names.len(),
                    with - none
                );
                if let Some(params) = &params {
                    let input = EstimateInput {
                        template: &template,
                        scan: &scan,
                        given: &given,
                        units: None,
                        orientation: None,
                    };
                    let e = estimate_landmarks(&input, params, &mut ()).unwrap();
                    let prior = PriorEstimate {
                        set: e.to_set(),
                        report: serde_json::Value::Null,
                    };
                    let tried = fit(&template, &scan, &truth, Some(given.clone()), Some(prior));
                    line += &format!("; with --params {tried:.2} ({:+.2})", tried - none);
                }
                if split {
                    let estimate = |given: &LandmarkSet| {
                        SubjectInput {
                            name: "partial".into(),
                            scan: scan.clone(),
                            units: None,
                            given: None,
                        }
                        .estimate_landmarks(&template, given, None, &mut ())
                        .unwrap()
                    };
                    // Estimate only: the estimate with the given ones, its own vertices warped.
                    let e = estimate(&given);
                    let set = LandmarkSet {
                        landmarks: vertices
                            .iter()
                            .map(|(n, v)| Landmark {
                                name: n.to_string(),
                                position: e.fitted[*v as usize] / e.scale_to_metres,
                            })
                            .collect(),
                        ..LandmarkSet::default()
                    };
                    let prior = PriorEstimate {
                        set,
                        report: serde_json::Value::Null,
                    };
                    let estimate_only = fit(&template, &scan, &truth, None, Some(prior));
                    // Warp only: the estimate without them, the given ones in the warp.
                    let e = estimate(&LandmarkSet::default());
                    let prior = PriorEstimate {
                        set: e.to_set(),
                        report: serde_json::Value::Null,
                    };
                    let warp_only = fit(&template, &scan, &truth, Some(given), Some(prior));
                    line += &format!(
                        "; estimate only {estimate_only:.2} ({:+.2}), warp only {warp_only:.2} ({:+.2})",
                        estimate_only - none,
                        warp_only - none
                    );
                }
                println!("{line}");
            }
        }
    }
}

fn main() {
    #[cfg(not(target_arch = "wasm32"))]
    native::main();
}
