//! ISO 20685-1's tolerance for a scan-derived measurement: the largest difference from a skilled
//! anthropometrist's measurement the standard allows, per class of measurement, and its verdict
//! on a set of differences.
//!
//! The standard's classes: heights, body breadths and small girths 4 mm; segment lengths and
//! body depths 5 mm; large girths (chest, waist, hip) 9 mm; head dimensions 2 mm. A method passes
//! on a measurement when the 95 % interval of the mean difference, mean ± 1.96·sd/√n, lies inside
//! ± that limit.
//!
//! [`chance_over`]: the chance that one body's error, of a given mean, exceeds a limit
//! (`trust.rs`).

use super::definitions::Measure;
use serde::Serialize;

/// The class of a measurement in ISO 20685-1, which fixes its limit.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum IsoClass {
    /// Heights above the floor: 4 mm.
    Height,
    /// Body breadths: 4 mm.
    Breadth,
    /// Small girths (thigh, upper arm, neck, neck base): 4 mm.
    SmallGirth,
    /// Segment lengths and body depths: 5 mm.
    SegmentLength,
    /// Large girths (chest, bust, underbust, waist, hip): 9 mm.
    LargeGirth,
    /// Head dimensions: 2 mm.
    HeadDimension,
}

impl IsoClass {
    /// The class's limit, metres.
    pub fn limit(self) -> f64 {
        match self {
            IsoClass::Height | IsoClass::Breadth | IsoClass::SmallGirth => 0.004,
            IsoClass::SegmentLength => 0.005,
            IsoClass::LargeGirth => 0.009,
            IsoClass::HeadDimension => 0.002,
        }
    }
}

impl Measure {
    /// The measurement's ISO 20685-1 class; `None` for volume and surface area, which the
    /// standard does not judge.
    pub fn iso_class(self) -> Option<IsoClass> {
        use IsoClass::*;
        Some(match self {
            Measure::Stature
            | Measure::CervicaleHeight
            | Measure::AcromionHeight
            | Measure::CrotchHeight
            | Measure::KneeHeight => Height,
            Measure::ShoulderBreadth => Breadth,
            Measure::ChestGirth
            | Measure::BustGirth
            | Measure::UnderbustGirth
            | Measure::WaistGirth
            | Measure::HipGirth => LargeGirth,
            Measure::ThighGirth
            | Measure::UpperArmGirth
            | Measure::NeckGirth
            | Measure::NeckBaseGirth => SmallGirth,
            Measure::HeadGirth => HeadDimension,
            Measure::ArmLength | Measure::WaistToHipBack => SegmentLength,
            Measure::Volume | Measure::SurfaceArea => return None,
        })
    }
}

/// Differences (measured − reference, metres) of one measurement over n subjects, summarised as
/// ISO 20685-1 judges them.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Agreement {
    pub n: usize,
    /// Mean difference d̄.
    pub mean: f64,
    /// Sample standard deviation sd (n − 1 in the denominator; 0 for n = 1).
    pub sd: f64,
    /// Mean absolute difference.
    pub mae: f64,
    /// Half-width of the 95 % interval of the mean difference, 1.96·sd/√n.
    pub half_interval: f64,
}

impl Agreement {
    /// The summary of `differences` (metres); `None` when there are none.
    pub fn of(differences: &[f64]) -> Option<Agreement> {
        let n = differences.len();
        if n == 0 {
            return None;
        }
        let nf = n as f64;
        let mean = differences.iter().sum::<f64>() / nf;
        let sd = if n > 1 {
            (differences.iter().map(|d| (d - mean).powi(2)).sum::<f64>() / (nf - 1.0)).sqrt()
        } else {
            0.0
        };
        Some(Agreement {
            n,
            mean,
            sd,
            mae: differences.iter().map(|d| d.abs()).sum::<f64>() / nf,
            half_interval: 1.96 * sd / nf.sqrt(),
        })
    }

    /// Whether the 95 % interval of the mean difference lies inside ± `limit`.
    pub fn within(&self, limit: f64) -> bool {
        self.mean.abs() + self.half_interval <= limit
    }
}

/// P(|x| > `limit`) for a half-normal error x of mean `expected`: erfc(limit / (expected·√π)).
pub fn chance_over(limit: f64, expected: f64) -> f64 {
    if expected <= 0.0 {
        return if limit < 0.0 { 1.0 } else { 0.0 };
    }
    erfc(limit / (expected * std::f64::consts::PI.sqrt()))
}

/// erfc(x) for x ≥ 0 (Abramowitz & Stegun 7.1.26, absolute error < 1.5·10⁻⁷). A negative x
/// (never here: the argument is a ratio of lengths) is taken as 0, giving erfc(0) = 1.
fn erfc(x: f64) -> f64 {
    let x = x.max(0.0);
    let t = 1.0 / (1.0 + 0.327_591_1 * x);
    let poly = t
        * (0.254_829_592
            + t * (-0.284_496_736
                + t * (1.421_413_741 + t * (-1.453_152_027 + t * 1.061_405_429))));
    poly * (-x * x).exp()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn classes_and_limits() {
        assert_eq!(Measure::HipGirth.iso_class(), Some(IsoClass::LargeGirth));
        assert_eq!(
            Measure::Stature.iso_class().map(IsoClass::limit),
            Some(0.004)
        );
        assert_eq!(
            Measure::ArmLength.iso_class().map(IsoClass::limit),
            Some(0.005)
        );
        assert_eq!(Measure::Volume.iso_class(), None);
        let judged = Measure::ALL.iter().filter(|m| m.iso_class().is_some());
        assert_eq!(judged.count(), 18);
    }

    #[test]
    fn the_interval_of_a_known_sample() {
        // d = 1, 2, 3 mm: mean 2, sd 1, half-interval 1.96/√3 = 1.1316 mm.
        let a = Agreement::of(&[0.001, 0.002, 0.003]).unwrap();
        assert!((a.mean - 0.002).abs() < 1e-12);
        assert!((a.sd - 0.001).abs() < 1e-12);
        assert!((a.mae - 0.002).abs() < 1e-12);
        assert!((a.half_interval - 0.001_131_6).abs() < 1e-7);
        assert!(a.within(0.004));
        assert!(!a.within(0.003));
        // A bias of −4 mm fails a 4 mm limit however small the spread.
        assert!(!Agreement::of(&[-0.0041, -0.0041]).unwrap().within(0.004));
        assert!(Agreement::of(&[]).is_none());
    }

    #[test]
    fn the_chance_over_the_limit_of_a_half_normal_error() {
        // erfc(0) = 1, erfc(1) = 0.157299, erfc(2) = 0.004678.
        assert!((erfc(0.0) - 1.0).abs() < 1e-6);
        assert!((erfc(1.0) - 0.157_299).abs() < 1e-6);
        assert!((erfc(2.0) - 0.004_678).abs() < 1e-6);
        // Mean 1 and limit √π: one σ·√2 out.
        let p = chance_over(std::f64::consts::PI.sqrt(), 1.0);
        assert!((p - 0.157_299).abs() < 1e-6);
        assert_eq!(chance_over(4.0, 0.0), 0.0);
        // The default's threshold, E = 0.407·L: P = 5 %.
        assert!((chance_over(1.0, 0.407) - 0.05).abs() < 2e-3);
    }
}
