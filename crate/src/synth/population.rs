//! The distributions of the synthetic population: body shape (macro and local targets) and pose.
//!
//! | parameter | distribution |
//! | --- | --- |
//! | sex | female / male with probability ½ each |
//! | gender value | female U(0, 0.1), male U(0.9, 1) |
//! | age | U(18, 65) years |
//! | muscle | N(0.5, 0.12²) clipped to [0.2, 0.85] |
//! | weight | N(0.5, 0.15²) clipped to [0.15, 0.9] |
//! | stature | female N(1.625 m, 0.065²), male N(1.760 m, 0.070²), clipped to [1.50, 1.95] m; MakeHuman's height value is then solved so the morphed body has this stature (see [`super::subject::fit_height`]) |
//! | proportions | U(0.3, 0.9) |
//! | ethnic mix | Dirichlet(1, 1, 1) |
//! | each local target pair | N(0, 0.2²) clipped to [−0.5, 0.5]; < 0 weights the "decrease" target, > 0 the "increase" one |
//! | shoulder abduction, each side | U(−10°, 10°) |
//! | trunk flexion / lateral tilt | N(0, 2°²) clipped ±4° / N(0, 1.5²) clipped ±3° |
//! | head flexion / lateral tilt / turn | N(0, 4°²) clipped ±8° / N(0, 2°²) clipped ±4° / N(0, 3°²) clipped ±6° |

use rand::Rng;
use rand_distr::{Distribution, Exp1, Normal};

use super::macros::MacroParams;

/// Local targets varied per subject, as `(name, decrease target, increase target)`.
pub const LOCAL_TARGETS: [(&str, &str, &str); 18] = [
    (
        "torso-scale-depth",
        "torso/torso-scale-depth-decr",
        "torso/torso-scale-depth-incr",
    ),
    (
        "torso-scale-horiz",
        "torso/torso-scale-horiz-decr",
        "torso/torso-scale-horiz-incr",
    ),
    (
        "torso-vshape",
        "torso/torso-vshape-less",
        "torso/torso-vshape-more",
    ),
    (
        "hip-scale-depth",
        "hip/hip-scale-depth-decr",
        "hip/hip-scale-depth-incr",
    ),
    (
        "hip-scale-horiz",
        "hip/hip-scale-horiz-decr",
        "hip/hip-scale-horiz-incr",
    ),
    (
        "legs-upperlegheight",
        "legs/legs-upperlegheight-decr",
        "legs/legs-upperlegheight-incr",
    ),
    (
        "legs-lowerlegheight",
        "legs/legs-lowerlegheight-decr",
        "legs/legs-lowerlegheight-incr",
    ),
    (
        "buttocks-volume",
        "buttocks/buttocks-volume-decr",
        "buttocks/buttocks-volume-incr",
    ),
    (
        "stomach-pregnant",
        "stomach/stomach-pregnant-decr",
        "stomach/stomach-pregnant-incr",
    ),
    (
        "measure-bust",
        "measure/measure-bust-decrease",
        "measure/measure-bust-increase",
    ),
    (
        "measure-waist",
        "measure/measure-waist-decrease",
        "measure/measure-waist-increase",
    ),
    (
        "measure-hips",
        "measure/measure-hips-decrease",
        "measure/measure-hips-increase",
    ),
    (
        "measure-thighcirc",
        "measure/measure-thighcirc-decrease",
        "measure/measure-thighcirc-increase",
    ),
    (
        "measure-calf",
        "measure/measure-calf-decrease",
        "measure/measure-calf-increase",
    ),
    (
        "measure-upperarm",
        "measure/measure-upperarm-decrease",
        "measure/measure-upperarm-increase",
    ),
    (
        "measure-neckcirc",
        "measure/measure-neckcirc-decrease",
        "measure/measure-neckcirc-increase",
    ),
    (
        "measure-shoulder",
        "measure/measure-shoulder-decrease",
        "measure/measure-shoulder-increase",
    ),
    (
        "measure-napetowaist",
        "measure/measure-napetowaist-decrease",
        "measure/measure-napetowaist-increase",
    ),
];

/// The pose of a subject (degrees; positive = abduction / forward / to the subject's left).
#[derive(Debug, Clone, Copy, Default, PartialEq, serde::Serialize)]
pub struct PoseParams {
    pub left_shoulder_abduction: f64,
    pub right_shoulder_abduction: f64,
    pub trunk_flexion: f64,
    pub trunk_lateral: f64,
    pub head_flexion: f64,
    pub head_lateral: f64,
    pub head_turn: f64,
}

/// Everything that makes one subject.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct SubjectParams {
    pub sex: &'static str,
    pub shape: MacroParams,
    /// One value in [−0.5, 0.5] per entry of [`LOCAL_TARGETS`].
    pub local: Vec<f64>,
    pub pose: PoseParams,
    /// The stature the subject is made to have (m); `shape.height` is solved to reach it.
    pub stature_target: f64,
}

impl SubjectParams {
    /// The local target weights `(target, weight)` of this subject.
    pub fn local_target_weights(&self) -> Vec<(String, f64)> {
        LOCAL_TARGETS
            .iter()
            .zip(&self.local)
            .map(|((_, decr, incr), &v)| {
                if v < 0.0 {
                    (decr.to_string(), -v)
                } else {
                    (incr.to_string(), v)
                }
            })
            .collect()
    }
}

fn clipped<R: Rng>(rng: &mut R, mean: f64, sd: f64, lo: f64, hi: f64) -> f64 {
    let n =
        Normal::new(mean, sd).unwrap_or_else(|_| Normal::new(mean, 0.0).expect("sd 0 is valid"));
    n.sample(rng).clamp(lo, hi)
}

/// Draws one subject from the distributions in the module documentation.
pub fn sample_subject<R: Rng>(rng: &mut R) -> SubjectParams {
    let male = rng.gen_bool(0.5);
    let gender = if male {
        rng.gen_range(0.9..=1.0)
    } else {
        rng.gen_range(0.0..=0.1)
    };
    let age_years = rng.gen_range(18.0..=65.0);
    let muscle = clipped(rng, 0.5, 0.12, 0.2, 0.85);
    let weight = clipped(rng, 0.5, 0.15, 0.15, 0.9);
    let stature_target = if male {
        clipped(rng, 1.760, 0.070, 1.50, 1.95)
    } else {
        clipped(rng, 1.625, 0.065, 1.50, 1.95)
    };
    let proportions = rng.gen_range(0.3..=0.9);
    let e: [f64; 3] = [Exp1.sample(rng), Exp1.sample(rng), Exp1.sample(rng)];
    let esum: f64 = e.iter().sum::<f64>().max(1e-12);
    let local = (0..LOCAL_TARGETS.len())
        .map(|_| clipped(rng, 0.0, 0.2, -0.5, 0.5))
        .collect();
    let pose = PoseParams {
        left_shoulder_abduction: rng.gen_range(-10.0..=10.0),
        right_shoulder_abduction: rng.gen_range(-10.0..=10.0),
        trunk_flexion: clipped(rng, 0.0, 2.0, -4.0, 4.0),
        trunk_lateral: clipped(rng, 0.0, 1.5, -3.0, 3.0),
        head_flexion: clipped(rng, 0.0, 4.0, -8.0, 8.0),
        head_lateral: clipped(rng, 0.0, 2.0, -4.0, 4.0),
        head_turn: clipped(rng, 0.0, 3.0, -6.0, 6.0),
    };
    SubjectParams {
        sex: if male { "male" } else { "female" },
        shape: MacroParams {
            gender,
            age_years,
            muscle,
            weight,
            height: 0.5,
            proportions,
            ethnic: [e[0] / esum, e[1] / esum, e[2] / esum],
        },
        local,
        pose,
        stature_target,
    }
}
