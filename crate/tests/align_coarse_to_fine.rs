//! Coarse-to-fine alignment of the `fine` template on a cheap scan: the embedded base template
//! deformed by a known smooth map (13K vertices), started from the RBF warp by its landmarks.

use std::ops::ControlFlow;

use bodyspace::align::{
    coarse_to_fine_align, data_weights, AlignObserver, CoarseToFineInput, FineAlignInput,
    FineAlignParams, FineStageParams, Progress, Stage, SurfaceIndex,
};
use bodyspace::mesh::Mesh;
use bodyspace::rbf::{rbf_warp_mesh, RbfParams};
use bodyspace::template::{Resolution, Subdivision, Template};
use nalgebra::{Point3, Vector3};

/// The subject: a wider, slightly taller body with a belly-like bulge, moved (metres).
fn subject(p: &Point3<f64>) -> Point3<f64> {
    let bulge = 0.02 * (-((p.y - 1.0).powi(2)) / 0.02).exp();
    Point3::new(
        p.x * 1.06,
        p.y * 1.03 + 0.01,
        p.z * 1.04 + bulge * p.z.signum().max(0.0),
    ) + Vector3::new(0.05, 0.0, -0.03)
}

struct Case {
    fine: Template,
    base: Template,
    scan: SurfaceIndex,
    /// The base template warped onto the scan by the RBF (paper §3.1): where the fit starts.
    starting: Vec<Point3<f64>>,
}

fn case() -> Case {
    let fine = Template::embedded()
        .unwrap()
        .at_resolution(Resolution::Fine);
    let base = fine.at_resolution(Resolution::Base);
    let scan = Mesh::new(
        base.mesh().positions.iter().map(subject).collect(),
        base.mesh().triangles.clone(),
    );
    let mut landmarks = base.landmark_positions();
    for l in &mut landmarks.landmarks {
        l.position = subject(&l.position);
    }
    let warp = rbf_warp_mesh(
        base.mesh(),
        &base.landmark_positions(),
        &scan,
        &landmarks,
        &RbfParams::default(),
    )
    .unwrap();
    Case {
        scan: SurfaceIndex::new(&scan).unwrap(),
        fine,
        base,
        starting: warp.positions,
    }
}

fn mean_distance(a: &[Point3<f64>], b: &[Point3<f64>]) -> f64 {
    a.iter().zip(b).map(|(p, q)| (p - q).norm()).sum::<f64>() / a.len().min(b.len()) as f64
}

/// The coarse-to-fine input for a start on the base template and the fine template's weights.
fn input<'a>(
    starting: &'a [Point3<f64>],
    base: &'a Template,
    scan: &'a SurfaceIndex,
    refinement: &'a Subdivision,
    weights: &'a [f64],
) -> CoarseToFineInput<'a> {
    CoarseToFineInput {
        base: FineAlignInput {
            positions: starting,
            triangles: &base.mesh().triangles,
            scan,
            weights: &weights[..base.mesh().positions.len()],
            anchors: &[],
        },
        refinement,
        fine_weights: weights,
    }
}

/// Records the stage and number of every iteration, and counts the rounds shown at fine.
struct Recorder {
    fine_vertices: usize,
    seen: Vec<(Stage, usize)>,
    rounds_at_fine: usize,
}

impl AlignObserver for Recorder {
    fn progress(&mut self, p: &Progress) -> ControlFlow<()> {
        self.seen.push((p.stage, p.iteration));
        ControlFlow::Continue(())
    }
    fn round(&mut self, _: Stage, _: usize, positions: &[Point3<f64>]) {
        assert_eq!(positions.len(), self.fine_vertices);
        self.rounds_at_fine += 1;
    }
}

#[test]
fn fine_fit_keeps_the_base_fit_and_comes_back_in_fine_template_order() {
    let Case {
        fine,
        base,
        scan,
        starting,
    } = case();
    let refinement = fine
        .refinement()
        .expect("a fine template keeps its operator");
    let stage = FineStageParams {
        max_iterations: 4,
        ..FineStageParams::default()
    };
    let weights = data_weights(&fine, FineAlignParams::default().sole_weight);
    let mut recorder = Recorder {
        fine_vertices: fine.mesh().positions.len(),
        seen: Vec::new(),
        rounds_at_fine: 0,
    };
    let result = coarse_to_fine_align(
        &input(&starting, &base, &scan, refinement, &weights),
        &FineAlignParams::default(),
        &stage,
        &mut recorder,
    )
    .unwrap();
    let Recorder {
        seen,
        rounds_at_fine,
        ..
    } = recorder;

    assert_eq!(result.positions.len(), 214_050);
    assert_eq!(result.report.template_vertices, 214_050);
    assert_eq!(result.report.per_vertex_distance.len(), 214_050);
    assert_eq!(result.base.template_vertices, base.mesh().positions.len());
    // Iterations count on across the stages, base first, then fine.
    assert!(seen.iter().enumerate().all(|(k, (_, i))| *i == k + 1));
    let switch = seen.iter().position(|(s, _)| *s == Stage::Fine).unwrap();
    assert_eq!(switch, result.base.iterations);
    assert!(seen[switch..].iter().all(|(s, _)| *s == Stage::Fine));
    assert_eq!(result.report.iterations, seen.len());
    // Every round shows its surface, at fine (a round that only finds the surface has stopped
    // moving shows nothing new).
    assert!(rounds_at_fine > result.base.rounds && rounds_at_fine <= result.report.rounds);

    // The fine stage keeps or improves what the base stage reached.
    let (base_rms, fine_rms) = (
        result.base.scan_to_template.rms,
        result.report.scan_to_template.rms,
    );
    eprintln!(
        "scan→template RMS: base stage {:.3} mm, fine {:.3} mm; {} + {} iterations",
        base_rms * 1e3,
        fine_rms * 1e3,
        result.base.iterations,
        result.report.iterations - result.base.iterations
    );
    assert!(fine_rms <= base_rms + 1e-5, "{fine_rms} > {base_rms}");

    // Template order: base vertices first, each fine vertex where the subject puts that vertex
    // of the fine template, as close as the base vertices are to theirs (the fit moves along
    // the normals; the tangential error of the warp stays, up to chord sag and sliding).
    let base_truth: Vec<Point3<f64>> = base.mesh().positions.iter().map(subject).collect();
    let fine_truth: Vec<Point3<f64>> = fine.mesh().positions.iter().map(subject).collect();
    let base_error = mean_distance(&result.positions, &base_truth);
    let fine_error = mean_distance(&result.positions, &fine_truth);
    let start_error = mean_distance(&starting, &base_truth);
    eprintln!(
        "mean error: start {:.2} mm, base vertices {:.2} mm, all fine vertices {:.2} mm",
        start_error * 1e3,
        base_error * 1e3,
        fine_error * 1e3
    );
    assert!(base_error < start_error, "{base_error} vs {start_error}");
    assert!(fine_error < start_error, "{fine_error} vs {start_error}");
    assert!(fine_rms < 5e-4, "scan→template RMS {fine_rms} m");
}

#[test]
fn cancelled_in_the_base_stage_returns_the_last_state_at_fine() {
    let Case {
        fine,
        base,
        scan,
        starting,
    } = case();
    let refinement = fine.refinement().unwrap();
    let weights = data_weights(&fine, FineAlignParams::default().sole_weight);
    let result = coarse_to_fine_align(
        &input(&starting, &base, &scan, refinement, &weights),
        &FineAlignParams::default(),
        &FineStageParams::default(),
        &mut |p: &Progress| {
            assert_eq!(p.stage, Stage::Base);
            if p.iteration >= 3 {
                ControlFlow::Break(())
            } else {
                ControlFlow::Continue(())
            }
        },
    )
    .unwrap();
    assert!(result.report.cancelled && result.base.cancelled);
    assert_eq!(result.report.iterations, 3);
    assert_eq!(result.positions.len(), 214_050);
    assert!(result
        .positions
        .iter()
        .all(|p| p.coords.iter().all(|c| c.is_finite())));
    // It had moved towards the scan.
    let base_truth: Vec<Point3<f64>> = base.mesh().positions.iter().map(subject).collect();
    assert!(mean_distance(&result.positions, &base_truth) < mean_distance(&starting, &base_truth));
}

#[test]
fn an_operator_of_another_template_is_an_error() {
    let Case {
        fine, base, scan, ..
    } = case();
    let refinement = fine.refinement().unwrap();
    let few = &base.mesh().positions[..100];
    let weights = data_weights(&fine, FineAlignParams::default().sole_weight);
    let err = coarse_to_fine_align(
        &input(few, &base, &scan, refinement, &weights),
        &FineAlignParams::default(),
        &FineStageParams::default(),
        &mut (),
    )
    .unwrap_err();
    assert!(err.to_string().contains("subdivision operator"), "{err}");
}
