//! The three radial basis functions of paper §3.1.3 (eq. 3–5).

use serde::{Deserialize, Serialize};

use super::error::RbfError;

/// A radial basis function Φ(r) with its parameter, in the units of the points it is applied to.
///
/// Evaluated from the squared distance r² so that the warp loop needs no square root for the
/// Gaussian and the thin-plate spline.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum Kernel {
    /// Thin-plate spline Φ(r) = r² log r, Φ(0) = 0 (paper eq. 3). No parameter.
    ThinPlate,
    /// Multiquadric Φ(r) = √(r² + s²) with stiffness s ≥ 0 (paper eq. 4).
    Multiquadric { s: f64 },
    /// Gaussian Φ(r) = exp(−r²/c²) with width c > 0 (paper eq. 5).
    Gaussian { c: f64 },
}

impl Kernel {
    /// Φ as a function of the squared distance `r2` = r².
    #[inline(always)]
    pub fn eval_r2(self, r2: f64) -> f64 {
        match self {
            // r² log r = ½ r² ln r²; the limit at r = 0 is 0 (and ln 0 would give NaN).
            Kernel::ThinPlate => {
                if r2 > 0.0 {
                    0.5 * r2 * r2.ln()
                } else {
                    0.0
                }
            }
            Kernel::Multiquadric { s } => (r2 + s * s).sqrt(),
            Kernel::Gaussian { c } => (-r2 / (c * c)).exp(),
        }
    }

    /// The kernel named `name` (`gaussian`, `thin-plate`, `multiquadric`) with parameter
    /// `param` (c or s; ignored by the thin-plate spline), or its default parameter when `None`.
    pub fn from_name(name: &str, param: Option<f64>) -> Option<Kernel> {
        match name {
            "gaussian" => Some(Kernel::Gaussian {
                c: param.unwrap_or(DEFAULT_GAUSSIAN_C),
            }),
            "thin-plate" | "thin_plate" | "tps" => Some(Kernel::ThinPlate),
            "multiquadric" | "multiquadrics" => Some(Kernel::Multiquadric {
                s: param.unwrap_or(DEFAULT_MULTIQUADRIC_S),
            }),
            _ => None,
        }
    }

    /// The kebab-case name used on the command line and in reports.
    pub fn name(self) -> &'static str {
        match self {
            Kernel::ThinPlate => "thin-plate",
            Kernel::Multiquadric { .. } => "multiquadric",
            Kernel::Gaussian { .. } => "gaussian",
        }
    }

    /// The kernel's parameter (s or c), `None` for the thin-plate spline.
    pub fn param(self) -> Option<f64> {
        match self {
            Kernel::ThinPlate => None,
            Kernel::Multiquadric { s } => Some(s),
            Kernel::Gaussian { c } => Some(c),
        }
    }

    /// Checks the parameter: c finite and > 0, s finite and ≥ 0.
    pub fn validate(self) -> Result<(), RbfError> {
        match self {
            Kernel::ThinPlate => Ok(()),
            Kernel::Multiquadric { s } if !(s.is_finite() && s >= 0.0) => {
                Err(RbfError::BadParameter {
                    name: "s",
                    value: s,
                    reason: "the multiquadric stiffness must be finite and >= 0",
                })
            }
            Kernel::Gaussian { c } if !(c.is_finite() && c > 0.0) => Err(RbfError::BadParameter {
                name: "c",
                value: c,
                reason: "the Gaussian width must be finite and > 0",
            }),
            _ => Ok(()),
        }
    }
}

/// Default Gaussian width c in template units (metres); see docs/rbf.md for the measurement.
pub const DEFAULT_GAUSSIAN_C: f64 = 0.1;

/// Default multiquadric stiffness s in template units (metres): the paper's largest value.
pub const DEFAULT_MULTIQUADRIC_S: f64 = 0.01;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn thin_plate_matches_hand_values() {
        let k = Kernel::ThinPlate;
        assert_eq!(k.eval_r2(0.0), 0.0);
        assert_eq!(k.eval_r2(1.0), 0.0);
        // 2² ln 2 = 2.772588722239781
        assert!((k.eval_r2(4.0) - 2.772_588_722_239_781).abs() < 1e-14);
        // 0.5² ln 0.5 = −0.17328679513998632
        assert!((k.eval_r2(0.25) + 0.173_286_795_139_986_3).abs() < 1e-15);
    }

    #[test]
    fn multiquadric_matches_hand_values() {
        let k = Kernel::Multiquadric { s: 4.0 };
        assert_eq!(k.eval_r2(9.0), 5.0);
        assert_eq!(Kernel::Multiquadric { s: 0.0 }.eval_r2(6.25), 2.5);
    }

    #[test]
    fn gaussian_matches_hand_values() {
        let k = Kernel::Gaussian { c: 2.0 };
        assert_eq!(k.eval_r2(0.0), 1.0);
        // exp(−1) at r = c
        assert!((k.eval_r2(4.0) - 0.367_879_441_171_442_33).abs() < 1e-16);
        // exp(−4/9) for c = 3, r = 2
        let k3 = Kernel::Gaussian { c: 3.0 };
        assert!((k3.eval_r2(4.0) - 0.641_180_388_429_954_6).abs() < 1e-15);
    }

    #[test]
    fn names_round_trip_and_bad_parameters_are_rejected() {
        for k in [
            Kernel::ThinPlate,
            Kernel::Multiquadric { s: 0.01 },
            Kernel::Gaussian { c: 0.3 },
        ] {
            assert_eq!(Kernel::from_name(k.name(), k.param()), Some(k));
        }
        assert!(Kernel::from_name("cubic", None).is_none());
        assert!(Kernel::Gaussian { c: 0.0 }.validate().is_err());
        assert!(Kernel::Gaussian { c: f64::NAN }.validate().is_err());
        assert!(Kernel::Multiquadric { s: -1.0 }.validate().is_err());
    }
}
