//! Where a body sits in its population: every measurement ([`crate::measure`]) over the model's
//! training subjects (each rebuilt from its stored whole-body scores) and over bodies sampled
//! from the model (z ~ N(0, I) in σ units, seeded), as sorted values (histogram-ready),
//! percentiles, mean and standard deviation, the correlation matrix between measurements, and a
//! body's percentile on each.
//!
//! Bodies are measured in the model frame, which is the template's (y up): the build moves every
//! fit onto the template before GPA, and [`super::from_measurements`] measures the same way.

use crate::measure::{BodyMeasurer, Kind, Measure, Measurements};
use crate::pca::error::PcaError;
use crate::pca::random::NormalRng;
use crate::pca::shape_model::ShapeModel;
use serde::Serialize;

/// The percentile levels every distribution reports (%).
pub const PERCENTILE_LEVELS: [f64; 5] = [5.0, 25.0, 50.0, 75.0, 95.0];

/// Parameters of [`measurement_distribution`], with their defaults.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DistributionParams {
    /// Bodies sampled from the model; default 300. A sampled body costs one reconstruction and
    /// one measurement of all 20 values (~6 ms at `base`, docs/benchmarks.md), so 300 take about
    /// 2 s in the worker; the 5th and 95th percentiles of 300 draws have a standard error of
    /// ~0.013 in probability (√(p(1−p)/N)), about 1.5 % of the 5–95 % range of a normal.
    pub samples: usize,
    /// Seed of the normal draws; default 1 (the same bodies every time).
    pub seed: u64,
}

impl Default for DistributionParams {
    fn default() -> Self {
        Self {
            samples: 300,
            seed: 1,
        }
    }
}

/// One measurement over one population.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MeasureDistribution {
    pub name: &'static str,
    pub kind: Kind,
    /// The values of the bodies where it could be taken, ascending (m, m³, m²).
    pub values: Vec<f64>,
    /// Mean and standard deviation (N − 1) of `values`; NaN when there are none.
    pub mean: f64,
    pub sd: f64,
    /// The values at [`PERCENTILE_LEVELS`] (linear interpolation between order statistics).
    pub percentiles: [f64; 5],
}

impl MeasureDistribution {
    /// The percentile (0–100) of `value` in this population: the share of values below it, ties
    /// counted half ([`percentile_of`]).
    pub fn percentile_of(&self, value: f64) -> f64 {
        percentile_of(&self.values, value)
    }
}

/// Every measurement over one population of bodies.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PopulationMeasurements {
    /// Bodies measured.
    pub bodies: usize,
    /// One entry per measurement, [`Measure::ALL`] order.
    pub measures: Vec<MeasureDistribution>,
    /// Pearson correlation between measurements, 19 × 19 row-major in [`Measure::ALL`] order,
    /// over the bodies where both were taken (NaN where fewer than 3 or a value is constant).
    pub correlation: Vec<f64>,
    /// Each body's measurements, in body order (for covariances of chosen measurements).
    #[serde(skip)]
    pub table: Vec<Measurements>,
}

/// A model's measurement distributions: over its training subjects and over sampled bodies.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MeasurementDistribution {
    pub params: DistributionParams,
    pub training: PopulationMeasurements,
    pub samples: PopulationMeasurements,
}

/// The percentile (0–100) of `value` among `sorted` (ascending): 100·(below + ½·equal)/N; NaN
/// for an empty population.
pub fn percentile_of(sorted: &[f64], value: f64) -> f64 {
    if sorted.is_empty() {
        return f64::NAN;
    }
    let below = sorted.partition_point(|&x| x < value);
    let not_above = sorted.partition_point(|&x| x <= value);
    100.0 * (below as f64 + 0.5 * (not_above - below) as f64) / sorted.len() as f64
}

/// The value at percentile `level` (0–100) of `sorted` (ascending): linear interpolation between
/// the order statistics at rank (N − 1)·level/100; NaN for an empty population.
pub fn value_at_percentile(sorted: &[f64], level: f64) -> f64 {
    if sorted.is_empty() {
        return f64::NAN;
    }
    let rank = (sorted.len() - 1) as f64 * (level / 100.0).clamp(0.0, 1.0);
    let (lo, hi) = (rank.floor() as usize, rank.ceil() as usize);
    sorted[lo] + (rank - lo as f64) * (sorted[hi] - sorted[lo])
}

impl PopulationMeasurements {
    /// The distributions and correlations of a population's measurements.
    pub fn of_bodies(table: Vec<Measurements>) -> Self {
        let n = Measure::ALL.len();
        let measures = Measure::ALL
            .into_iter()
            .map(|m| {
                let mut values: Vec<f64> = table.iter().filter_map(|b| b.get(m)).collect();
                values.sort_by(f64::total_cmp);
                let (mean, sd) = mean_and_sd(&values);
                let d = m.definition();
                MeasureDistribution {
                    name: d.name,
                    kind: d.kind,
                    percentiles: PERCENTILE_LEVELS.map(|l| value_at_percentile(&values, l)),
                    values,
                    mean,
                    sd,
                }
            })
            .collect();
        let mut correlation = vec![f64::NAN; n * n];
        for a in Measure::ALL {
            for b in Measure::ALL {
                let pairs: Vec<(f64, f64)> = table
                    .iter()
                    .filter_map(|t| Some((t.get(a)?, t.get(b)?)))
                    .collect();
                correlation[a.index() * n + b.index()] = pearson(&pairs);
            }
        }
        Self {
            bodies: table.len(),
            measures,
            correlation,
            table,
        }
    }

    /// The distribution of one measurement.
    pub fn of(&self, m: Measure) -> &MeasureDistribution {
        &self.measures[m.index()]
    }

    /// A body's percentile (0–100) on each measurement, [`Measure::ALL`] order (`None` where the
    /// body has no value or the population none).
    pub fn percentiles_of(&self, body: &Measurements) -> Vec<Option<f64>> {
        Measure::ALL
            .into_iter()
            .map(|m| {
                let d = self.of(m);
                body.get(m)
                    .filter(|_| !d.values.is_empty())
                    .map(|v| d.percentile_of(v))
            })
            .collect()
    }

    /// Mean (k) and covariance (k × k row-major, N − 1) of the measurements `which` over the
    /// bodies where all of them were taken; `None` with fewer than k + 1 such bodies.
    pub fn mean_and_covariance(&self, which: &[Measure]) -> Option<(Vec<f64>, Vec<f64>)> {
        let rows: Vec<Vec<f64>> = self
            .table
            .iter()
            .filter_map(|t| which.iter().map(|&m| t.get(m)).collect())
            .collect();
        let k = which.len();
        if rows.len() <= k {
            return None;
        }
        let n = rows.len() as f64;
        let mean: Vec<f64> = (0..k)
            .map(|i| rows.iter().map(|r| r[i]).sum::<f64>() / n)
            .collect();
        let mut cov = vec![0.0; k * k];
        for r in &rows {
            for i in 0..k {
                for j in 0..k {
                    cov[i * k + j] += (r[i] - mean[i]) * (r[j] - mean[j]) / (n - 1.0);
                }
            }
        }
        Some((mean, cov))
    }
}

fn mean_and_sd(values: &[f64]) -> (f64, f64) {
    let n = values.len() as f64;
    let mean = values.iter().sum::<f64>() / n;
    let var = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0);
    (mean, var.sqrt())
}

fn pearson(pairs: &[(f64, f64)]) -> f64 {
    if pairs.len() < 3 {
        return f64::NAN;
    }
    let n = pairs.len() as f64;
    let (ma, mb) = pairs
        .iter()
        .fold((0.0, 0.0), |(a, b), &(x, y)| (a + x / n, b + y / n));
    let (mut sab, mut saa, mut sbb) = (0.0, 0.0, 0.0);
    for &(x, y) in pairs {
        sab += (x - ma) * (y - mb);
        saa += (x - ma) * (x - ma);
        sbb += (y - mb) * (y - mb);
    }
    if saa <= 0.0 || sbb <= 0.0 {
        return f64::NAN;
    }
    sab / (saa * sbb).sqrt()
}

/// Every measurement of the body of `model` at σ-unit coefficients `sigma`.
pub fn measure_at_sigma(
    model: &ShapeModel,
    measurer: &BodyMeasurer,
    sigma: &[f64],
) -> Result<Measurements, PcaError> {
    measurer
        .measure(&model.body_at_sigma(sigma)?)
        .map_err(|e| PcaError::BadParameter(e.to_string()))
}

/// The measurements of every training subject of `model`, rebuilt from its stored scores.
pub fn training_measurements(
    model: &ShapeModel,
    measurer: &BodyMeasurer,
) -> Result<Vec<Measurements>, PcaError> {
    let modes = model.mode_count();
    let subjects = model.scores.len().checked_div(modes).unwrap_or(0);
    (0..subjects)
        .map(|i| {
            let b: Vec<f64> = model.scores[i * modes..(i + 1) * modes]
                .iter()
                .map(|&x| x as f64)
                .collect();
            measure_at_sigma(model, measurer, &model.sigma_from_coefficients(&b))
        })
        .collect()
}

/// The measurements of `count` bodies sampled from `model` (σ-unit coefficients drawn from
/// N(0, 1) by one [`NormalRng`] seeded with `seed`, body after body); `progress` gets the
/// fraction done after each body.
pub fn sampled_measurements(
    model: &ShapeModel,
    measurer: &BodyMeasurer,
    count: usize,
    seed: u64,
    progress: &mut dyn FnMut(f64),
) -> Result<Vec<Measurements>, PcaError> {
    let mut rng = NormalRng::new(seed);
    let modes = model.mode_count();
    let mut out = Vec::with_capacity(count);
    for i in 0..count {
        let z: Vec<f64> = (0..modes).map(|_| rng.next_normal()).collect();
        out.push(measure_at_sigma(model, measurer, &z)?);
        progress((i + 1) as f64 / count as f64);
    }
    Ok(out)
}

/// The distributions of every measurement of the whole-body `model` over its training subjects
/// and over `params.samples` sampled bodies. `progress` gets the fraction done (0–1).
pub fn measurement_distribution(
    model: &ShapeModel,
    measurer: &BodyMeasurer,
    params: &DistributionParams,
    progress: &mut dyn FnMut(f64),
) -> Result<MeasurementDistribution, PcaError> {
    if params.samples < 2 {
        return Err(PcaError::BadParameter(format!(
            "{} samples: at least 2 are needed for a distribution",
            params.samples
        )));
    }
    let training = training_measurements(model, measurer)?;
    let share = training.len() as f64 / (training.len() + params.samples) as f64;
    progress(share);
    let samples = sampled_measurements(model, measurer, params.samples, params.seed, &mut |f| {
        progress(share + (1.0 - share) * f)
    })?;
    Ok(MeasurementDistribution {
        params: *params,
        training: PopulationMeasurements::of_bodies(training),
        samples: PopulationMeasurements::of_bodies(samples),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn percentiles_count_ties_half_and_interpolate() {
        let v = [1.0, 2.0, 2.0, 3.0, 4.0];
        assert_eq!(percentile_of(&v, 0.5), 0.0);
        assert_eq!(percentile_of(&v, 2.0), 40.0);
        assert_eq!(percentile_of(&v, 2.5), 60.0);
        assert_eq!(percentile_of(&v, 9.0), 100.0);
        assert!(percentile_of(&[], 1.0).is_nan());
        assert_eq!(value_at_percentile(&v, 0.0), 1.0);
        assert_eq!(value_at_percentile(&v, 50.0), 2.0);
        assert_eq!(value_at_percentile(&v, 87.5), 3.5);
        assert_eq!(value_at_percentile(&v, 100.0), 4.0);
    }

    #[test]
    fn correlation_and_covariance_of_a_known_table() {
        // Stature s and waist 0.5·s (correlation 1), hip 2 − s (correlation −1).
        let table: Vec<Measurements> = [1.6, 1.7, 1.8, 1.9]
            .iter()
            .map(|&s| {
                let mut values = [None; Measure::ALL.len()];
                values[Measure::Stature.index()] = Some(s);
                values[Measure::WaistGirth.index()] = Some(0.5 * s);
                values[Measure::HipGirth.index()] = Some(2.0 - s);
                Measurements { values }
            })
            .collect();
        let p = PopulationMeasurements::of_bodies(table);
        let n = Measure::ALL.len();
        let r = |a: Measure, b: Measure| p.correlation[a.index() * n + b.index()];
        assert!((r(Measure::Stature, Measure::WaistGirth) - 1.0).abs() < 1e-12);
        assert!((r(Measure::Stature, Measure::HipGirth) + 1.0).abs() < 1e-12);
        assert!(r(Measure::Stature, Measure::ChestGirth).is_nan());
        let s = p.of(Measure::Stature);
        assert!((s.mean - 1.75).abs() < 1e-12);
        assert!((s.percentiles[2] - 1.75).abs() < 1e-12);
        let (mean, cov) = p
            .mean_and_covariance(&[Measure::Stature, Measure::WaistGirth])
            .unwrap();
        assert!((mean[1] - 0.875).abs() < 1e-12);
        // var(s) = 0.0166…, cov(s, w) = var(s)/2.
        assert!((cov[0] - 0.05f64 / 3.0).abs() < 1e-12);
        assert!((cov[1] - cov[0] / 2.0).abs() < 1e-12 && cov[1] == cov[2]);
        assert!(p.mean_and_covariance(&[Measure::ChestGirth]).is_none());
        let mut body = p.table[1].clone();
        body.values[Measure::Stature.index()] = Some(1.7);
        assert_eq!(
            p.percentiles_of(&body)[Measure::Stature.index()],
            Some(37.5)
        );
        assert_eq!(p.percentiles_of(&body)[Measure::ChestGirth.index()], None);
    }
}
