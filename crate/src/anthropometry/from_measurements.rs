//! The most likely body of a model that has given measurements: whole-body coefficients, in σ
//! units z (bₖ = zₖ·√λₖ), that meet target values with the least Mahalanobis norm ‖z‖.
//!
//! The measurements m(z) are linearised around the current body, J = ∂m/∂z by forward
//! differences (each a rank-1 change of the body), and each Gauss–Newton step solves the
//! Tikhonov problem
//!
//! z⁺ = argmin ‖W·(J·z⁺ − (t − m(z) + J·z))‖² + μ·‖z⁺‖²,
//!
//! W = diag(1 / tolerance) putting lengths, girths, volume and area on one scale, μ small: among
//! the bodies that meet the targets, the one nearest the mean in σ units. Iterates until every
//! target is within a quarter of its tolerance or `max_iterations`. A step that raises the cost
//! ‖W·(m(z) − t)‖² + μ·‖z‖² or makes a body without one of the sections is refused and retried
//! with Levenberg–Marquardt damping: targets no body of the model has (all 19 values of a
//! person outside the population) end at the nearest body the model can make instead of at a
//! degenerate one. (A segment model with the body held, [`super::segment_targets`], runs the
//! same iteration from and towards its starting coefficients.)

use crate::measure::{BodyMeasurer, Kind, Measure};
use crate::pca::error::PcaError;
use crate::pca::shape_model::ShapeModel;
use nalgebra::{DMatrix, DVector};
use serde::Serialize;

/// Parameters of [`body_from_measurements`], with their defaults.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FromMeasurementsParams {
    /// Gauss–Newton iterations (each a step tried) at most; default 16.
    pub max_iterations: usize,
    /// Forward-difference step in σ units; default 0.05.
    pub step: f64,
    /// Tikhonov weight μ on ‖z‖² against the tolerance-scaled residual; default 10⁻⁴ (a target
    /// off by its tolerance costs as much as 100σ of norm, so targets win).
    pub regularisation: f64,
    /// How close "met" is, per kind: lengths 2 mm, girths 5 mm, volume 0.5 L, area 0.005 m².
    pub length_tolerance: f64,
    pub girth_tolerance: f64,
    pub volume_tolerance: f64,
    pub area_tolerance: f64,
}

impl Default for FromMeasurementsParams {
    fn default() -> Self {
        Self {
            max_iterations: 16,
            step: 0.05,
            regularisation: 1e-4,
            length_tolerance: 0.002,
            girth_tolerance: 0.005,
            volume_tolerance: 0.0005,
            area_tolerance: 0.005,
        }
    }
}

impl FromMeasurementsParams {
    /// The tolerance of a measurement of `kind`.
    pub fn tolerance(&self, kind: Kind) -> f64 {
        match kind {
            Kind::Length => self.length_tolerance,
            Kind::Girth => self.girth_tolerance,
            Kind::Volume => self.volume_tolerance,
            Kind::Area => self.area_tolerance,
        }
    }
}

/// One target and what the body achieved.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Achieved {
    pub name: &'static str,
    pub target: f64,
    pub achieved: f64,
    /// Whether |achieved − target| ≤ the kind's tolerance.
    pub met: bool,
}

/// The body found: σ-unit whole-body coefficients, each target's achieved value, iterations.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BodyFromMeasurements {
    pub sigma: Vec<f64>,
    pub achieved: Vec<Achieved>,
    pub iterations: usize,
    /// ‖z‖, the body's Mahalanobis distance from the mean.
    pub mahalanobis: f64,
}

/// A body parameterised by σ-unit coefficients z of one model: what the solver moves.
/// [`WholeBody`] here; a segment model with the rest of the body held is
/// [`super::segment_targets`].
pub(crate) trait MeasuredBody {
    /// The model's standard deviations √λₖ (one per coefficient).
    fn standard_deviations(&self) -> Vec<f64>;
    /// The body at `z` as flat f32 positions (3V).
    fn body(&self, z: &[f64]) -> Result<Vec<f32>, PcaError>;
    /// `out` = the body `at` (at some z) moved by `delta` σ along coefficient `k`.
    fn moved(&self, at: &[f32], k: usize, delta: f64, out: &mut [f32]) -> Result<(), PcaError>;
}

/// The whole-body model: x = S̄ + Φ·(√λ ⊙ z).
struct WholeBody<'a> {
    model: &'a ShapeModel,
    sd: Vec<f64>,
}

impl MeasuredBody for WholeBody<'_> {
    fn standard_deviations(&self) -> Vec<f64> {
        self.sd.clone()
    }

    fn body(&self, z: &[f64]) -> Result<Vec<f32>, PcaError> {
        self.model.body_at_sigma(z)
    }

    fn moved(&self, at: &[f32], k: usize, delta: f64, out: &mut [f32]) -> Result<(), PcaError> {
        let d = (delta * self.sd[k]) as f32;
        for (p, (&x, &phi)) in out.iter_mut().zip(at.iter().zip(self.model.mode(k))) {
            *p = x + d * phi;
        }
        Ok(())
    }
}

/// The whole-body coefficients of `model` meeting `targets` (measurement, value in m, m³, m²)
/// with the least Mahalanobis norm, measured by `measurer` (the model's base template). Fails on
/// an empty or repeated target, a non-finite value, or a body that cannot be measured.
pub fn body_from_measurements(
    model: &ShapeModel,
    measurer: &BodyMeasurer,
    targets: &[(Measure, f64)],
    params: &FromMeasurementsParams,
) -> Result<BodyFromMeasurements, PcaError> {
    let start = vec![0.0; model.mode_count()];
    let whole = WholeBody {
        model,
        sd: model.standard_deviations(),
    };
    solve(&whole, start, measurer, targets, params)
}

/// The Gauss–Newton iteration of the module doc on any [`MeasuredBody`], from σ-unit `start`
/// and regularised towards it: z⁺ = argmin ‖W·(J·z⁺ − r)‖² + μ·‖z⁺ − start‖² (start 0: the
/// least Mahalanobis norm).
pub(crate) fn solve(
    model: &dyn MeasuredBody,
    start: Vec<f64>,
    measurer: &BodyMeasurer,
    targets: &[(Measure, f64)],
    params: &FromMeasurementsParams,
) -> Result<BodyFromMeasurements, PcaError> {
    let bad = |s: String| PcaError::BadParameter(s);
    if targets.is_empty() {
        return Err(bad("no target measurements".into()));
    }
    for (i, (m, v)) in targets.iter().enumerate() {
        let name = m.definition().name;
        if !v.is_finite() || *v <= 0.0 {
            return Err(bad(format!(
                "target {name} = {v}: expected a positive number"
            )));
        }
        if targets[..i].iter().any(|(n, _)| n == m) {
            return Err(bad(format!("target {name} is given twice")));
        }
    }
    let which: Vec<Measure> = targets.iter().map(|(m, _)| *m).collect();
    let weights: Vec<f64> = which
        .iter()
        .map(|m| 1.0 / params.tolerance(m.definition().kind))
        .collect();
    let measure = |positions: &[f32]| -> Result<DVector<f64>, PcaError> {
        let m = measurer
            .measure_some(positions, &which)
            .map_err(|e| bad(e.to_string()))?;
        which
            .iter()
            .map(|&k| {
                m.get(k)
                    .ok_or_else(|| bad(format!("{}: no section on this body", k.definition().name)))
            })
            .collect::<Result<Vec<f64>, _>>()
            .map(DVector::from_vec)
    };
    let modes = model.standard_deviations().len();
    let target = DVector::from_iterator(targets.len(), targets.iter().map(|(_, v)| *v));
    let w = DVector::from_vec(weights);
    let prior = DVector::from_vec(start.clone());
    let mut z = start;
    let mut positions = model.body(&z)?;
    let mut values = measure(&positions)?;
    let mut iterations = 0;
    let done = |values: &DVector<f64>| {
        values
            .iter()
            .zip(target.iter())
            .zip(w.iter())
            .all(|((v, t), w)| (v - t).abs() * w <= 0.25)
    };
    let cost = |values: &DVector<f64>, z: &DVector<f64>| {
        (values - &target).component_mul(&w).norm_squared()
            + params.regularisation * (z - &prior).norm_squared()
    };
    let mut current = cost(&values, &DVector::from_vec(z.clone()));
    // Levenberg–Marquardt damping λ towards the current z: 0 while Gauss–Newton steps lower the
    // cost; raised when a step raises it or makes a body that cannot be measured (targets no body
    // of the model has, e.g. a held-out subject's 19 values), lowered again after a success.
    let mut damping = 0.0;
    // The Jacobian by forward differences (one body measured per mode) only at the start and
    // after a failed step; a successful step updates it by Broyden's rank-one rule, since the
    // measurements are close to linear in z. `fresh`: made by differences at the current z.
    let mut jacobian: Option<(DMatrix<f64>, bool)> = None;
    while iterations < params.max_iterations && !done(&values) {
        iterations += 1;
        let (j, fresh) = match jacobian.take() {
            Some(j) => j,
            None => {
                let mut j = DMatrix::zeros(targets.len(), modes);
                let mut moved = positions.clone();
                for k in 0..modes {
                    // A forward step that loses a section falls back to a backward one.
                    for h in [params.step, -params.step] {
                        model.moved(&positions, k, h, &mut moved)?;
                        if let Ok(m) = measure(&moved) {
                            j.set_column(k, &((m - &values) / h));
                            break;
                        }
                    }
                }
                (j, true)
            }
        };
        let zv = DVector::from_vec(z.clone());
        let rhs = &target - &values + &j * &zv;
        let wj = DMatrix::from_fn(targets.len(), modes, |i, k| w[i] * j[(i, k)]);
        let wr = rhs.component_mul(&w);
        let normal = wj.transpose() * &wj
            + DMatrix::identity(modes, modes) * (params.regularisation + damping);
        let next = normal
            .lu()
            .solve(&(wj.transpose() * wr + &prior * params.regularisation + &zv * damping))
            .ok_or_else(|| bad("the linearised system is singular".into()))?;
        let trial = model.body(next.as_slice())?;
        match measure(&trial) {
            Ok(m) if cost(&m, &next) < current => {
                current = cost(&m, &next);
                let dz = &next - &zv;
                let predicted = &j * &dz;
                let moved = dz.norm_squared();
                let broyden = if moved > 0.0 {
                    j + (&m - &values - predicted) * dz.transpose() / moved
                } else {
                    j
                };
                jacobian = Some((broyden, false));
                z = next.iter().copied().collect();
                positions = trial;
                values = m;
                damping /= 10.0;
            }
            // An updated Jacobian may be what failed: the step is tried again from a fresh one.
            _ if !fresh => jacobian = None,
            _ => {
                let scale = (wj.transpose() * &wj).trace() / modes as f64;
                damping = (10.0 * damping).max(1e-2 * scale);
                jacobian = Some((j, true));
            }
        }
    }
    let achieved = targets
        .iter()
        .zip(values.iter())
        .zip(w.iter())
        .map(|(((m, t), &v), w)| Achieved {
            name: m.definition().name,
            target: *t,
            achieved: v,
            met: (v - t).abs() * w <= 1.0 + 1e-9,
        })
        .collect();
    let mahalanobis = z.iter().map(|x| x * x).sum::<f64>().sqrt();
    Ok(BodyFromMeasurements {
        sigma: z,
        achieved,
        iterations,
        mahalanobis,
    })
}
