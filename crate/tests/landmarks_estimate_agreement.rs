//! The native half of the native-vs-WASM agreement check of the landmark estimate: the same
//! case and band as `landmarks_estimate_wasm.rs` (run in a browser by scripts/test-wasm.sh).
#![cfg(not(target_arch = "wasm32"))]

mod estimate_agreement;

use bodyspace::estimate::{estimate_landmarks, EstimateInput, EstimateParams};
use bodyspace::mesh::units::Units;
use bodyspace::template::Template;

#[test]
fn the_estimate_lands_in_the_agreement_band_natively() {
    let (scan, truth, given) = estimate_agreement::agreement_case();
    let template = Template::embedded().unwrap();
    let input = EstimateInput {
        template: &template,
        scan: &scan,
        given: &given,
        units: Some(Units::Metres),
        orientation: None,
    };
    let e = estimate_landmarks(&input, &EstimateParams::default(), &mut ()).unwrap();
    let positions: Vec<f64> = e
        .positions
        .iter()
        .flat_map(|p| p.map_or([f64::NAN; 3], |p| [p.x, p.y, p.z]))
        .collect();
    let given: Vec<u8> = e.given.iter().map(|&g| g as u8).collect();
    let (mean, worst) = estimate_agreement::check_agreement(&positions, &given, &truth);
    eprintln!("native: mean {mean} mm, worst {worst} mm");
}
