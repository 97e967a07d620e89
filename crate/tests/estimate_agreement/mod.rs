//! The case and the check shared by the native and the WASM half of the landmark estimate's
//! agreement test (`landmarks_estimate_agreement.rs`, `landmarks_estimate_wasm.rs`): the
//! embedded template made wider, taller and bulging by a smooth map, turned into CAESAR's frame
//! (z up, facing −y) and moved, in metres (what the page hands the worker), with Sellion given.
//! Both halves must land in the same narrow band around the native figures.
#![allow(dead_code)]

use bodyspace::landmarks::{Landmark, LandmarkSet};
use bodyspace::mesh::Mesh;
use bodyspace::template::Template;
use nalgebra::{Point3, Vector3};

fn subject(p: &Point3<f64>) -> Point3<f64> {
    let bulge = 0.02 * (-((p.y - 1.0).powi(2)) / 0.02).exp();
    let q = Point3::new(
        p.x * 1.06,
        p.y * 1.03 + 0.01,
        p.z * 1.04 + bulge * p.z.signum().max(0.0),
    );
    // Template frame (y up, facing +z) → z up, facing −y, moved.
    Point3::new(q.x, -q.z, q.y) + Vector3::new(0.4, -1.2, 0.05)
}

/// The scan (metres), all 73 true landmarks, and the given set (Sellion only).
pub fn agreement_case() -> (Mesh, LandmarkSet, LandmarkSet) {
    let template = Template::embedded().unwrap();
    let scan = Mesh::new(
        // Rounded to f32 as the page sends it, so both halves see the same scan.
        template
            .mesh()
            .positions
            .iter()
            .map(|p| subject(p).map(|c| c as f32 as f64))
            .collect(),
        template.mesh().triangles.clone(),
    );
    let truth = LandmarkSet {
        landmarks: template
            .landmark_positions()
            .landmarks
            .iter()
            .map(|l| Landmark {
                name: l.name.clone(),
                position: subject(&l.position),
            })
            .collect(),
        ..LandmarkSet::default()
    };
    let given = LandmarkSet {
        landmarks: truth.landmarks[..1].to_vec(),
        ..LandmarkSet::default()
    };
    (scan, truth, given)
}

/// Native figures of this case: mean and worst landmark error (mm) of the 72 estimated ones.
pub const NATIVE_MEAN_MM: f64 = 1.890;
pub const NATIVE_WORST_MM: f64 = 12.616;
/// How far either half may be from them (mm).
pub const BAND_MM: f64 = 0.5;

/// Checks an estimate (73 positions, metres, NaN for none; given flags) against the truth and
/// the native figures; returns (mean, worst) mm.
pub fn check_agreement(positions: &[f64], given: &[u8], truth: &LandmarkSet) -> (f64, f64) {
    assert_eq!(positions.len(), 73 * 3);
    assert_eq!(given.iter().map(|&g| g as usize).sum::<usize>(), 1);
    assert_eq!(given[0], 1);
    let p0 = truth.landmarks[0].position;
    assert_eq!(
        &positions[..3],
        &[p0.x, p0.y, p0.z],
        "a given landmark moved"
    );
    let errors: Vec<f64> = (1..73)
        .map(|k| {
            let p = Point3::new(positions[3 * k], positions[3 * k + 1], positions[3 * k + 2]);
            (p - truth.landmarks[k].position).norm() * 1000.0
        })
        .collect();
    let mean = errors.iter().sum::<f64>() / errors.len() as f64;
    let worst = errors.iter().cloned().fold(0.0, f64::max);
    assert!(
        (mean - NATIVE_MEAN_MM).abs() <= BAND_MM && (worst - NATIVE_WORST_MM).abs() <= BAND_MM,
        "mean {mean} mm, worst {worst} mm; native {NATIVE_MEAN_MM}, {NATIVE_WORST_MM}"
    );
    (mean, worst)
}
