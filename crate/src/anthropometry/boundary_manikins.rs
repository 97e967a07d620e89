//! Boundary manikins (Reed & Flannagan's method of vehicle and workspace design, after
//! Bittner's principal-component families): the bodies at the edge of the region holding a share
//! p of a population in 2–4 chosen measurements, which a design must fit to fit that share.
//!
//! The chosen measurements y (k of them) are modelled as normal, y ~ N(μ, Σ), with μ and Σ
//! estimated from bodies sampled from the model ([`super::measurement_distribution`]). The
//! region holding p of the population is the ellipsoid (y − μ)ᵀΣ⁻¹(y − μ) ≤ r²,
//! r² = χ²ₖ(p) ([`super::chi_square`]). With Σ = V·Λ·Vᵀ its boundary points are
//! y = μ + r·V·√Λ·u for unit vectors u ([`boundary_directions`]): for k = 2, `ellipse_points`
//! equally spaced angles starting on the first principal axis (8: the four axis ends and the four
//! diagonals); for k = 3 and 4, the 2k ends of the principal axes and the 2ᵏ diagonals
//! (±1, …, ±1)/√k (14 and 24 manikins). Each point's manikin is the most likely body with those
//! measurement values ([`super::from_measurements::body_from_measurements`]).

use super::chi_square::chi_square_quantile;
use super::from_measurements::{
    body_from_measurements, BodyFromMeasurements, FromMeasurementsParams,
};
use super::measurement_distribution::{measure_at_sigma, PopulationMeasurements};
use crate::measure::{BodyMeasurer, Measure, Measurements};
use crate::pca::error::PcaError;
use crate::pca::shape_model::ShapeModel;
use nalgebra::{DMatrix, DVector, SymmetricEigen};
use serde::Serialize;

/// Parameters of [`boundary_manikins`], with their defaults.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ManikinParams {
    /// Share of the population inside the boundary; default 0.9.
    pub coverage: f64,
    /// Points around the ellipse for two measurements; default 8.
    pub ellipse_points: usize,
}

impl Default for ManikinParams {
    fn default() -> Self {
        Self {
            coverage: 0.9,
            ellipse_points: 8,
        }
    }
}

/// One boundary manikin.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Manikin {
    /// `manikin_01`, `manikin_02`, … in the order of [`boundary_directions`].
    pub name: String,
    /// Its unit direction u in the principal axes of the chosen measurements (whitened).
    pub direction: Vec<f64>,
    /// The body found: σ-unit whole-body coefficients, and target vs achieved of each chosen
    /// measurement.
    pub body: BodyFromMeasurements,
    /// Mahalanobis distance of the achieved chosen values from μ under Σ (r on the boundary).
    pub distance: f64,
    /// All measurements of the body.
    pub measurements: Measurements,
}

/// The boundary manikins of a coverage region.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BoundaryManikins {
    /// The chosen measurements' names.
    pub measures: Vec<&'static str>,
    pub coverage: f64,
    /// The Mahalanobis radius r = √χ²ₖ(coverage).
    pub radius: f64,
    /// μ (k) and Σ (k × k row-major) of the chosen measurements over the population.
    pub mean: Vec<f64>,
    pub covariance: Vec<f64>,
    pub manikins: Vec<Manikin>,
}

impl BoundaryManikins {
    /// One row per manikin: `name`, `distance` (achieved Mahalanobis distance; `radius` on the
    /// boundary), `mahalanobis` (‖z‖ of the body), `target_M` and `achieved_M` of each chosen
    /// measurement, then all 20 measurements by name (m, m³, m²; empty where not taken).
    pub fn to_csv(&self) -> String {
        use std::fmt::Write;
        let mut out = String::from("name,distance,mahalanobis");
        for m in &self.measures {
            write!(out, ",target_{m}").ok();
        }
        for m in &self.measures {
            write!(out, ",achieved_{m}").ok();
        }
        for m in Measure::ALL {
            write!(out, ",{}", m.definition().name).ok();
        }
        out.push('\n');
        for k in &self.manikins {
            write!(
                out,
                "{},{:.4},{:.4}",
                k.name, k.distance, k.body.mahalanobis
            )
            .ok();
            for a in &k.body.achieved {
                write!(out, ",{:.6}", a.target).ok();
            }
            for a in &k.body.achieved {
                write!(out, ",{:.6}", a.achieved).ok();
            }
            for m in Measure::ALL {
                out.push(',');
                if let Some(v) = k.measurements.get(m) {
                    write!(out, "{v:.6}").ok();
                }
            }
            out.push('\n');
        }
        out
    }
}

/// The unit directions u of the module doc for `k` measurements (2, 3 or 4); `ellipse_points`
/// is used for k = 2. Empty for another k.
pub fn boundary_directions(k: usize, ellipse_points: usize) -> Vec<Vec<f64>> {
    match k {
        2 => (0..ellipse_points)
            .map(|i| {
                let a = std::f64::consts::TAU * i as f64 / ellipse_points as f64;
                vec![a.cos(), a.sin()]
            })
            .collect(),
        3 | 4 => {
            let mut out = Vec::new();
            for axis in 0..k {
                for sign in [1.0, -1.0] {
                    let mut u = vec![0.0; k];
                    u[axis] = sign;
                    out.push(u);
                }
            }
            let s = 1.0 / (k as f64).sqrt();
            for corner in 0..1usize << k {
                out.push(
                    (0..k)
                        .map(|j| if corner >> j & 1 == 0 { s } else { -s })
                        .collect(),
                );
            }
            out
        }
        _ => Vec::new(),
    }
}

/// The points y = μ + r·V·√Λ·u of each direction u, for `mean` (k) and `covariance` (k × k
/// row-major, symmetric positive definite) with eigen-decomposition V·Λ·Vᵀ, principal axes in
/// order of decreasing variance. Fails when Σ is not positive definite.
pub fn boundary_points(
    mean: &[f64],
    covariance: &[f64],
    radius: f64,
    directions: &[Vec<f64>],
) -> Result<Vec<Vec<f64>>, PcaError> {
    let k = mean.len();
    let eigen = SymmetricEigen::new(DMatrix::from_row_slice(k, k, covariance));
    let mut order: Vec<usize> = (0..k).collect();
    order.sort_by(|&a, &b| eigen.eigenvalues[b].total_cmp(&eigen.eigenvalues[a]));
    if order.iter().any(|&j| eigen.eigenvalues[j] <= 0.0) {
        return Err(PcaError::BadParameter(
            "the chosen measurements vary together without spread in some direction (covariance not positive definite); choose measurements that are not tied to each other".into(),
        ));
    }
    // Columns √λⱼ·vⱼ in decreasing λ.
    let axes = DMatrix::from_fn(k, k, |i, c| {
        let j = order[c];
        eigen.eigenvectors[(i, j)] * eigen.eigenvalues[j].sqrt()
    });
    Ok(directions
        .iter()
        .map(|u| {
            let y = DVector::from_row_slice(mean) + &axes * DVector::from_row_slice(u) * radius;
            y.iter().copied().collect()
        })
        .collect())
}

/// The Mahalanobis distance √((y − μ)ᵀΣ⁻¹(y − μ)); NaN when Σ is singular.
pub fn mahalanobis(y: &[f64], mean: &[f64], covariance: &[f64]) -> f64 {
    let k = mean.len();
    let d = DVector::from_iterator(k, y.iter().zip(mean).map(|(a, b)| a - b));
    match DMatrix::from_row_slice(k, k, covariance).cholesky() {
        Some(c) => d.dot(&c.solve(&d)).sqrt(),
        None => f64::NAN,
    }
}

/// The boundary manikins of `measures` (2–4, distinct) at `params.coverage` in the whole-body
/// `model`, their population modelled from `population` (normally the model's sampled bodies,
/// [`super::measurement_distribution::MeasurementDistribution::samples`]). `progress` gets the
/// fraction done after each manikin.
pub fn boundary_manikins(
    model: &ShapeModel,
    measurer: &BodyMeasurer,
    population: &PopulationMeasurements,
    measures: &[Measure],
    params: &ManikinParams,
    solver: &FromMeasurementsParams,
    progress: &mut dyn FnMut(f64),
) -> Result<BoundaryManikins, PcaError> {
    let bad = |s: String| PcaError::BadParameter(s);
    let k = measures.len();
    if !(2..=4).contains(&k) {
        return Err(bad(format!(
            "{k} measurements: boundary manikins take 2, 3 or 4"
        )));
    }
    for (i, m) in measures.iter().enumerate() {
        if measures[..i].contains(m) {
            return Err(bad(format!("{} is chosen twice", m.definition().name)));
        }
    }
    if !(params.coverage > 0.0 && params.coverage < 1.0) {
        return Err(bad(format!(
            "coverage {}: expected a share between 0 and 1 (e.g. 0.9)",
            params.coverage
        )));
    }
    if k == 2 && params.ellipse_points < 3 {
        return Err(bad(format!(
            "{} points around the ellipse: at least 3",
            params.ellipse_points
        )));
    }
    let (mean, covariance) = population.mean_and_covariance(measures).ok_or_else(|| {
        bad(format!(
            "{} bodies with all of the chosen measurements: too few for their covariance",
            population.bodies
        ))
    })?;
    let radius = chi_square_quantile(k, params.coverage).sqrt();
    let directions = boundary_directions(k, params.ellipse_points);
    let points = boundary_points(&mean, &covariance, radius, &directions)?;
    let mut manikins = Vec::with_capacity(points.len());
    for (i, (u, y)) in directions.into_iter().zip(&points).enumerate() {
        let targets: Vec<(Measure, f64)> =
            measures.iter().copied().zip(y.iter().copied()).collect();
        let body = body_from_measurements(model, measurer, &targets, solver)?;
        let achieved: Vec<f64> = body.achieved.iter().map(|a| a.achieved).collect();
        manikins.push(Manikin {
            name: format!("manikin_{:02}", i + 1),
            direction: u,
            distance: mahalanobis(&achieved, &mean, &covariance),
            measurements: measure_at_sigma(model, measurer, &body.sigma)?,
            body,
        });
        progress((i + 1) as f64 / points.len() as f64);
    }
    Ok(BoundaryManikins {
        measures: measures.iter().map(|m| m.definition().name).collect(),
        coverage: params.coverage,
        radius,
        mean,
        covariance,
        manikins,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ellipse_points_lie_on_the_coverage_boundary() {
        let mean = [1.7, 0.8];
        let covariance = [0.0049, 0.0021, 0.0021, 0.0064];
        let r = chi_square_quantile(2, 0.9).sqrt();
        let directions = boundary_directions(2, 8);
        assert_eq!(directions.len(), 8);
        let points = boundary_points(&mean, &covariance, r, &directions).unwrap();
        for p in &points {
            assert!(
                (mahalanobis(p, &mean, &covariance) - r).abs() < 1e-9,
                "{p:?}"
            );
        }
        // Opposite directions give points symmetric about the mean.
        for i in 0..4 {
            for j in 0..2 {
                assert!((points[i][j] + points[i + 4][j] - 2.0 * mean[j]).abs() < 1e-12);
            }
        }
        // The first point lies along the major axis: the farthest from the mean in metres.
        let dist = |p: &Vec<f64>| ((p[0] - mean[0]).powi(2) + (p[1] - mean[1]).powi(2)).sqrt();
        assert!(points.iter().all(|p| dist(p) <= dist(&points[0]) + 1e-12));
    }

    #[test]
    fn three_and_four_measurements_take_axes_and_diagonals() {
        for (k, n) in [(3, 14), (4, 24)] {
            let d = boundary_directions(k, 8);
            assert_eq!(d.len(), n);
            for u in &d {
                assert!((u.iter().map(|x| x * x).sum::<f64>() - 1.0).abs() < 1e-12);
            }
            let mean = vec![1.0; k];
            let covariance: Vec<f64> = (0..k * k)
                .map(|i| if i % (k + 1) == 0 { 0.01 } else { 0.004 })
                .collect();
            let r = chi_square_quantile(k, 0.95).sqrt();
            for p in boundary_points(&mean, &covariance, r, &d).unwrap() {
                assert!((mahalanobis(&p, &mean, &covariance) - r).abs() < 1e-9);
            }
        }
        assert!(boundary_directions(5, 8).is_empty());
        let singular = [1.0, 1.0, 1.0, 1.0];
        assert!(boundary_points(&[0.0, 0.0], &singular, 1.0, &boundary_directions(2, 8)).is_err());
    }
}
