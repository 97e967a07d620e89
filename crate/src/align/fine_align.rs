//! The outer loop of fine alignment (paper §3.2): find closest points, minimise
//! E = a·E_d + b·E_s with L-BFGS for a few iterations, find closest points again, until E stops
//! falling.
//!
//! Schedule: round r finds correspondences from the current surface (positions T_i ṽ_i and their
//! vertex normals), switches off the data term of vertices without a compatible match, on a hole
//! rim or too far (paper §3.2.1), then runs `iterations_per_round` L-BFGS iterations warm-started
//! from the current transforms, with E_s weighted by b·max(1, initial_stiffness·decay^r). It stops
//! after a round that lowered E by less than `relative_tolerance`·E or moved the vertices by less
//! than `displacement_tolerance` RMS (once annealing is over), after
//! `max_iterations` iterations in total, or when the observer returns `Break`.

use super::energy::{
    identity_transforms, transformed, AlignEnergy, BlockPreconditioner, EnergyTerms, TangentialTerm,
};
use super::error::AlignError;
use super::fine_input::FineAlignInput;
use super::follow::follow_neighbours;
use super::lbfgs::{Lbfgs, Objective, Step};
use super::observer::{AlignObserver, Progress, Stage};
use super::params::FineAlignParams;
use super::report::{
    scan_to_template_distances, template_to_scan_distances, AlignReport, CurvePoint, DistanceStats,
};
use super::scan_term::ScanTerm;
use super::surface_index::{validate_mesh, MatchQuery};
use crate::mesh::normals::vertex_normals_into;
use crate::mesh::topology::unique_edges;
use crate::utils::now_ms;
use crate::utils::parallel::for_each_pair_mut;
use nalgebra::{Point3, Vector3};

/// The aligned template and its report.
#[derive(Debug, Clone, PartialEq)]
pub struct FineAlignResult {
    /// Fitted template positions: same vertices, same order as the input (metres).
    pub positions: Vec<Point3<f64>>,
    /// Statistics, curve and per-vertex distances.
    pub report: AlignReport,
}

/// The energy of one round plus its preconditioner, remembering the terms of the last evaluation.
struct RoundObjective<'a> {
    energy: AlignEnergy<'a>,
    preconditioner: &'a BlockPreconditioner,
    last: EnergyTerms,
}

impl Objective for RoundObjective<'_> {
    fn value_and_gradient(&mut self, x: &[f64], grad: &mut [f64]) -> f64 {
        self.last = self.energy.evaluate(x, grad);
        self.last.total
    }
    fn curvature(&self, d: &[f64]) -> Option<f64> {
        Some(self.energy.curvature(d))
    }
    fn precondition(&self, q: &mut [f64]) -> bool {
        self.preconditioner.apply(q);
        true
    }
}

/// Fits the (RBF-warped) template to the scan by per-vertex affine transforms T_i minimising
/// E = a·κ·Σ w_i dist²(T_i v_i, Γ) + b·Σ_edges ‖T_i − T_j‖²_F (+ the scan-to-template term E_r
/// when `params.scan_term_weight` > 0) (paper eq. 6–8; the energy is in `energy.rs`),
/// κ = (h̄/h_ref)².
///
/// `observer` hears every iteration (stage [`Stage::Base`]) and every round's surface; a `Break`
/// cancels, and the result is then the last accepted iterate with `report.cancelled = true`.
///
/// Returns the fitted positions (input order) and the report. Vertices are centred on the
/// template centroid before building ṽ_i, so E_s does not depend on where the scan's origin is.
pub fn fine_align(
    input: &FineAlignInput<'_>,
    params: &FineAlignParams,
    observer: &mut dyn AlignObserver,
) -> Result<FineAlignResult, AlignError> {
    let FineAlignInput {
        positions: template_positions,
        triangles,
        scan,
        weights,
        anchors,
    } = *input;
    let start = now_ms();
    params.validate()?;
    let n = template_positions.len();
    if n == 0 || triangles.is_empty() {
        return Err(AlignError::EmptyTemplate {
            vertices: n,
            triangles: triangles.len(),
        });
    }
    validate_mesh("template", template_positions, triangles)?;
    if weights.len() != n {
        return Err(AlignError::WeightCount {
            got: weights.len(),
            expected: n,
        });
    }
    if let Some(vertex) = weights.iter().position(|w| !(w.is_finite() && *w >= 0.0)) {
        return Err(AlignError::BadWeight {
            vertex,
            value: weights[vertex],
        });
    }

    for (anchor, (vertex, target)) in anchors.iter().enumerate() {
        if *vertex as usize >= n || !target.coords.iter().all(|c| c.is_finite()) {
            return Err(AlignError::BadAnchor {
                anchor,
                vertex: *vertex,
                target: [target.x, target.y, target.z],
                vertices: n,
            });
        }
    }

    let centroid = template_positions
        .iter()
        .fold(Vector3::zeros(), |acc, p| acc + p.coords)
        / n as f64;
    let vertices: Vec<[f64; 4]> = template_positions
        .iter()
        .map(|p| {
            let c = p.coords - centroid;
            [c.x, c.y, c.z, 1.0]
        })
        .collect();
    let edges = unique_edges(triangles);
    let mut degrees = vec![0u32; n];
    let mut edge_length_sum = 0.0;
    for &[i, j] in &edges {
        degrees[i as usize] += 1;
        degrees[j as usize] += 1;
        edge_length_sum += (template_positions[i as usize] - template_positions[j as usize]).norm();
    }
    let mean_edge = edge_length_sum / edges.len().max(1) as f64;
    let kappa = (mean_edge / params.reference_edge_length).powi(2);
    let data_scale = params.a * kappa;

    let query = MatchQuery {
        mode: params.correspondence,
        min_cos: params
            .normal_compatibility
            .then(|| params.max_normal_angle_deg.to_radians().cos()),
        candidates: params.candidates,
    };

    let mut optimizer = Lbfgs::new(identity_transforms(n), params.lbfgs_memory);
    let mut positions = template_positions.to_vec();
    let mut normals = vec![Vector3::zeros(); n];
    let mut targets = vec![Point3::origin(); n];
    let mut coefficients = vec![0.0; n];
    let mut preconditioner = BlockPreconditioner::default();
    // Reserved so that recording the curve never allocates inside the iteration loop.
    let mut curve = Vec::with_capacity(params.max_iterations.min(1 << 16) + 1);
    let (mut iteration, mut rounds) = (0usize, 0usize);
    let (mut cancelled, mut converged) = (false, false);
    let mut last_stiffness = f64::NAN;
    let mut matched_vertices = 0usize;
    let mut scan_term = ScanTerm::new(scan, params, data_scale, weights);
    // The tangential term holds vertices along the start surface (the RBF-warped template).
    let (rest, rest_normals) = if params.tangential_weight > 0.0 {
        let mut normals = vec![Vector3::zeros(); n];
        vertex_normals_into(template_positions, triangles, &mut normals);
        let rest: Vec<Point3<f64>> = template_positions
            .iter()
            .map(|p| Point3::from(p.coords - centroid))
            .collect();
        (rest, normals)
    } else {
        (Vec::new(), Vec::new())
    };
    let tangential = TangentialTerm {
        rest: &rest,
        normals: &rest_normals,
        coefficient: data_scale * params.tangential_weight,
    };

    'rounds: while iteration < params.max_iterations {
        let round = rounds;
        rounds += 1;
        let mut moved_sq = 0.0;
        for (i, v) in vertices.iter().enumerate() {
            let p = transformed(optimizer.x(), v, i) + centroid;
            moved_sq += (p - positions[i]).norm_squared();
            positions[i] = p;
        }
        if round > 0
            && last_stiffness <= 1.0
            && (moved_sq / n as f64).sqrt() < params.displacement_tolerance
        {
            converged = true;
            break;
        }
        observer.round(Stage::Base, round, &positions);
        vertex_normals_into(&positions, triangles, &mut normals);
        for_each_pair_mut(&mut targets, &mut coefficients, |i, target, coefficient| {
            *coefficient = 0.0;
            if weights[i] <= 0.0 {
                return;
            }
            let normal = (normals[i] != Vector3::zeros()).then_some(&normals[i]);
            let Some(m) = scan.closest(&positions[i], normal, &query) else {
                return;
            };
            if (params.skip_boundary_matches && m.on_boundary)
                || (m.point - positions[i]).norm() > params.max_match_distance
            {
                return;
            }
            *target = m.point - centroid;
            *coefficient = data_scale * weights[i];
        });
        matched_vertices = coefficients.iter().filter(|c| **c > 0.0).count();
        let anchor_coefficient = data_scale * params.landmark_weight;
        if anchor_coefficient > 0.0 {
            for (i, target) in anchors {
                let i = *i as usize;
                let (alpha, beta) = (coefficients[i], anchor_coefficient);
                let blended = (targets[i].coords * alpha + (target.coords - centroid) * beta)
                    / (alpha + beta);
                targets[i] = Point3::from(blended);
                coefficients[i] = alpha + beta;
            }
        }
        let stiffness =
            (params.initial_stiffness * params.stiffness_decay.powi(round as i32)).max(1.0);
        let scan_samples = scan_term.find(input, &positions, query, centroid, stiffness)?;
        let energy = AlignEnergy {
            vertices: &vertices,
            edges: &edges,
            targets: &targets,
            data_coefficients: &coefficients,
            smoothness_coefficient: params.b * stiffness,
            scan_samples,
            tangential,
        };
        preconditioner.update(&energy, &degrees);
        let mut objective = RoundObjective {
            energy,
            preconditioner: &preconditioner,
            last: EnergyTerms::default(),
        };
        let round_start = optimizer.restart(&mut objective, stiffness != last_stiffness);
        last_stiffness = stiffness;
        if curve.is_empty() {
            curve.push(curve_point(0, now_ms() - start, &objective.last));
        }
        for _ in 0..params.iterations_per_round {
            if iteration >= params.max_iterations {
                break 'rounds;
            }
            if optimizer.step(&mut objective) == Step::Stalled {
                break;
            }
            iteration += 1;
            let t = &objective.last;
            let point = curve_point(iteration, now_ms() - start, t);
            curve.push(point);
            let progress = Progress {
                stage: Stage::Base,
                iteration,
                max_iterations: params.max_iterations,
                round,
                energy: t.total,
                data_error: t.data_weighted / data_scale,
                smoothness_error: t.smoothness,
                rms: point.rms,
                matched: t.matched,
                elapsed_ms: point.elapsed_ms,
            };
            if observer.progress(&progress).is_break() {
                cancelled = true;
                break 'rounds;
            }
        }
        let drop = round_start - optimizer.value();
        if stiffness <= 1.0 && drop <= params.relative_tolerance * round_start.abs() {
            converged = true;
            break;
        }
    }

    let mut x = optimizer.x().to_vec();
    if params.unseen_follow_neighbours && !cancelled {
        let free: Vec<bool> = weights.iter().map(|w| *w <= 0.0).collect();
        follow_neighbours(&mut x, &free, &edges, 1e-9, 5_000);
    }
    for (i, v) in vertices.iter().enumerate() {
        positions[i] = transformed(&x, v, i) + centroid;
    }
    let elapsed_ms = now_ms() - start;
    let per_vertex_distance = template_to_scan_distances(&positions, triangles, scan);
    let scan_distances = scan_to_template_distances(&positions, triangles, scan)?;
    let scan_to_template = DistanceStats::of(scan_distances.iter().map(|s| s.distance));
    let template_to_scan = DistanceStats::of(
        per_vertex_distance
            .iter()
            .zip(weights)
            .filter(|(_, w)| **w > 0.0)
            .map(|(d, _)| *d),
    );
    Ok(FineAlignResult {
        positions,
        report: AlignReport {
            template_vertices: n,
            scan_vertices: scan.vertex_count(),
            scan_to_template,
            template_to_scan,
            matched_vertices,
            iterations: iteration,
            rounds,
            elapsed_ms,
            cancelled,
            converged,
            curve,
            per_vertex_distance,
            scan_distances,
        },
    })
}

fn curve_point(iteration: usize, elapsed_ms: f64, t: &EnergyTerms) -> CurvePoint {
    CurvePoint {
        iteration,
        elapsed_ms,
        energy: t.total,
        rms: if t.matched > 0 {
            (t.matched_sq_sum / t.matched as f64).sqrt()
        } else {
            0.0
        },
    }
}
