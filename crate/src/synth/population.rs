//! The distributions of the synthetic population: body shape (macro and local targets), pose and
//! scanner, as named **population profiles** ([`PopulationProfile`]).
//!
//! * `tuning` (the default) — the population the aligner's defaults were tuned on;
//! * `held-out` — other modifier ranges and combinations, other poses, another scanner step and
//!   noise: the aligner is never tuned on it, so its figures are the honest ones.
//!
//! `tuning`:
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
//! | elbows, hips, trunk turn | not moved |
//! | scanner | [`ScannerParams::default`]: 3 mm steps, 1 mm noise, heads at 45° + k·90°, 1.2 m |
//!
//! `held-out` (see [`sample_held_out`]; angles of the arm are from the model's A-pose, whose upper
//! arm hangs [`A_POSE_ARM_DEG`] from the body):
//!
//! | parameter | distribution |
//! | --- | --- |
//! | sex | female / male with probability ½ each |
//! | gender value | female U(0.05, 0.3), male U(0.7, 0.95) |
//! | age | U(20, 80) years |
//! | muscle | N(0.55, 0.18²) clipped to [0.1, 0.95] |
//! | weight | N(0.55, 0.2²) clipped to [0.1, 1.0] |
//! | stature | female N(1.600 m, 0.075²), male N(1.780 m, 0.080²), clipped to [1.45, 2.00] m |
//! | proportions | U(0.1, 1.0) |
//! | ethnic mix | Dirichlet(½, ½, ½) |
//! | each local target pair | N(0, 0.25²) plus, for the girth targets ([`GIRTH_TARGETS`]), one shared N(0, 0.2²) per subject; clipped to [−0.7, 0.7] |
//! | arms | per subject one of: down (⅕; each arm U(8°, 15°) from the body), hands on hips (⅕; U(35°, 50°) from the body, elbow bent U(80°, 105°) — less where the wrist would enter the body — the hand laid on the hip), raised (⅗; U(20°, 60°) from the body, the two arms within ±8° of each other) |
//! | hip abduction (stance) | U(−3°, 8°) for both legs, plus N(0, 0.7°²) per leg |
//! | trunk flexion / lateral tilt / turn | N(0, 3°²) clipped ±6° / N(0, 2°²) clipped ±4° / N(0, 4°²) clipped ±8° |
//! | head flexion / lateral tilt / turn | N(0, 6°²) clipped ±12° / N(0, 3°²) clipped ±6° / N(0, 6°²) clipped ±12° |
//! | scanner | 4 mm vertical and 3.5 mm horizontal steps, 1.3 mm noise, heads at 30° + k·90°, 1.3 m |

use rand::Rng;
use rand_distr::{Distribution, Exp1, Gamma, Normal};

use super::macros::MacroParams;
use super::scanner::ScannerParams;

/// A named set of distributions subjects (and their scans) are drawn from.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum PopulationProfile {
    /// The population the aligner's defaults were tuned on.
    #[default]
    Tuning,
    /// Other shapes, poses and scanner: never tuned on.
    HeldOut,
}

impl PopulationProfile {
    pub const ALL: [PopulationProfile; 2] = [PopulationProfile::Tuning, PopulationProfile::HeldOut];

    /// The profile's name on the command line and in `subjects.json`.
    pub fn name(self) -> &'static str {
        match self {
            PopulationProfile::Tuning => "tuning",
            PopulationProfile::HeldOut => "held-out",
        }
    }

    /// The profile called `name`.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|p| p.name() == name)
    }

    /// The profile's scanner.
    pub fn scanner(self) -> ScannerParams {
        match self {
            PopulationProfile::Tuning => ScannerParams::default(),
            PopulationProfile::HeldOut => ScannerParams {
                first_azimuth_deg: 30.0,
                head_distance: 1.3,
                vertical_step: 0.004,
                horizontal_step: 0.0035,
                noise_sigma: 0.0013,
                ..ScannerParams::default()
            },
        }
    }

    /// Draws one subject's shape and pose.
    pub fn sample_subject<R: Rng>(self, rng: &mut R) -> SubjectParams {
        match self {
            PopulationProfile::Tuning => sample_tuning(rng),
            PopulationProfile::HeldOut => sample_held_out(rng),
        }
    }
}

/// Angle between the upper arm and the body in the model's rest (A-)pose, degrees (measured on
/// the MakeHuman base mesh: shoulder to elbow joint, in the frontal plane).
pub const A_POSE_ARM_DEG: f64 = 39.6;

/// Local target pairs (names in [`LOCAL_TARGETS`]) that a `held-out` subject's shared girth
/// value moves together.
pub const GIRTH_TARGETS: [&str; 9] = [
    "buttocks-volume",
    "stomach-pregnant",
    "measure-bust",
    "measure-waist",
    "measure-hips",
    "measure-thighcirc",
    "measure-calf",
    "measure-upperarm",
    "measure-neckcirc",
];

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

/// The pose of a subject (degrees; positive = abduction / forward / to the subject's left /
/// elbow bent). Shoulder and hip abduction are from the model's rest pose.
#[derive(Debug, Clone, Copy, Default, PartialEq, serde::Serialize)]
pub struct PoseParams {
    pub left_shoulder_abduction: f64,
    pub right_shoulder_abduction: f64,
    /// Elbow flexion, the hand laid on the hip (hands on hips; `super::hand_on_hip`).
    pub left_elbow_flexion: f64,
    pub right_elbow_flexion: f64,
    /// Hip abduction: the foot away from the body's midline (feet apart; < 0 together).
    pub left_hip_abduction: f64,
    pub right_hip_abduction: f64,
    pub trunk_flexion: f64,
    pub trunk_lateral: f64,
    pub trunk_turn: f64,
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

/// Draws one subject of `profile` (see the module documentation).
pub fn sample_subject<R: Rng>(profile: PopulationProfile, rng: &mut R) -> SubjectParams {
    profile.sample_subject(rng)
}

/// The macro distributions of a profile (the module documentation's tables).
struct BodyDistributions {
    /// Gender value U(lo, hi) for males and females.
    gender_male: (f64, f64),
    gender_female: (f64, f64),
    age_years: (f64, f64),
    /// Normal (mean, sd) clipped to [lo, hi].
    muscle: [f64; 4],
    weight: [f64; 4],
    stature_male: [f64; 4],
    stature_female: [f64; 4],
    proportions: (f64, f64),
    /// Dirichlet concentration of the ethnic mix (1: drawn with `Exp1`, as `tuning` always was).
    ethnic_concentration: f64,
}

const TUNING_BODY: BodyDistributions = BodyDistributions {
    gender_male: (0.9, 1.0),
    gender_female: (0.0, 0.1),
    age_years: (18.0, 65.0),
    muscle: [0.5, 0.12, 0.2, 0.85],
    weight: [0.5, 0.15, 0.15, 0.9],
    stature_male: [1.760, 0.070, 1.50, 1.95],
    stature_female: [1.625, 0.065, 1.50, 1.95],
    proportions: (0.3, 0.9),
    ethnic_concentration: 1.0,
};

const HELD_OUT_BODY: BodyDistributions = BodyDistributions {
    gender_male: (0.7, 0.95),
    gender_female: (0.05, 0.3),
    age_years: (20.0, 80.0),
    muscle: [0.55, 0.18, 0.1, 0.95],
    weight: [0.55, 0.2, 0.1, 1.0],
    stature_male: [1.780, 0.080, 1.45, 2.00],
    stature_female: [1.600, 0.075, 1.45, 2.00],
    proportions: (0.1, 1.0),
    ethnic_concentration: 0.5,
};

/// Draws sex, macro values and target stature, in this order (the order fixes every seed's
/// subjects): sex, gender, age, muscle, weight, stature, proportions, ethnic mix.
fn draw_body<R: Rng>(rng: &mut R, d: &BodyDistributions) -> (bool, MacroParams, f64) {
    let normal = |rng: &mut R, [mean, sd, lo, hi]: [f64; 4]| clipped(rng, mean, sd, lo, hi);
    let male = rng.gen_bool(0.5);
    let (lo, hi) = if male { d.gender_male } else { d.gender_female };
    let gender = rng.gen_range(lo..=hi);
    let age_years = rng.gen_range(d.age_years.0..=d.age_years.1);
    let muscle = normal(rng, d.muscle);
    let weight = normal(rng, d.weight);
    let stature_target = normal(
        rng,
        if male {
            d.stature_male
        } else {
            d.stature_female
        },
    );
    let proportions = rng.gen_range(d.proportions.0..=d.proportions.1);
    let e: [f64; 3] = if d.ethnic_concentration == 1.0 {
        [Exp1.sample(rng), Exp1.sample(rng), Exp1.sample(rng)]
    } else {
        let gamma = Gamma::new(d.ethnic_concentration, 1.0).expect("a positive shape");
        [gamma.sample(rng), gamma.sample(rng), gamma.sample(rng)]
    };
    let esum: f64 = e.iter().sum::<f64>().max(1e-12);
    let shape = MacroParams {
        gender,
        age_years,
        muscle,
        weight,
        height: 0.5,
        proportions,
        ethnic: [e[0] / esum, e[1] / esum, e[2] / esum],
    };
    (male, shape, stature_target)
}

fn subject_params(
    (male, shape, stature_target): (bool, MacroParams, f64),
    local: Vec<f64>,
    pose: PoseParams,
) -> SubjectParams {
    SubjectParams {
        sex: if male { "male" } else { "female" },
        shape,
        local,
        pose,
        stature_target,
    }
}

/// Draws one `tuning` subject. Its draw order is fixed: subjects of a seed stay bit-identical.
fn sample_tuning<R: Rng>(rng: &mut R) -> SubjectParams {
    let body = draw_body(rng, &TUNING_BODY);
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
        ..PoseParams::default()
    };
    subject_params(body, local, pose)
}

/// Draws one `held-out` subject (see the module documentation).
pub fn sample_held_out<R: Rng>(rng: &mut R) -> SubjectParams {
    let body = draw_body(rng, &HELD_OUT_BODY);
    let girth = clipped(rng, 0.0, 0.2, -1.0, 1.0);
    let local = LOCAL_TARGETS
        .iter()
        .map(|(name, _, _)| {
            let shared = if GIRTH_TARGETS.contains(name) {
                girth
            } else {
                0.0
            };
            (clipped(rng, 0.0, 0.25, -1.0, 1.0) + shared).clamp(-0.7, 0.7)
        })
        .collect();
    subject_params(body, local, held_out_pose(rng))
}

/// The `held-out` pose: arms down, hands on hips or raised; a stance; trunk and head turned.
fn held_out_pose<R: Rng>(rng: &mut R) -> PoseParams {
    // Arm angles from the body, converted to abduction from the A-pose.
    let (left, right, elbow) = match rng.gen_range(0..5) {
        0 => (
            rng.gen_range(8.0..=15.0),
            rng.gen_range(8.0..=15.0),
            (0.0, 0.0),
        ),
        1 => (
            rng.gen_range(35.0..=50.0),
            rng.gen_range(35.0..=50.0),
            (rng.gen_range(80.0..=105.0), rng.gen_range(80.0..=105.0)),
        ),
        _ => {
            let left: f64 = rng.gen_range(20.0..=60.0);
            let right = (left + rng.gen_range(-8.0..=8.0)).clamp(20.0, 60.0);
            (left, right, (0.0, 0.0))
        }
    };
    let stance = rng.gen_range(-3.0..=8.0);
    PoseParams {
        left_shoulder_abduction: left - A_POSE_ARM_DEG,
        right_shoulder_abduction: right - A_POSE_ARM_DEG,
        left_elbow_flexion: elbow.0,
        right_elbow_flexion: elbow.1,
        left_hip_abduction: stance + clipped(rng, 0.0, 0.7, -2.0, 2.0),
        right_hip_abduction: stance + clipped(rng, 0.0, 0.7, -2.0, 2.0),
        trunk_flexion: clipped(rng, 0.0, 3.0, -6.0, 6.0),
        trunk_lateral: clipped(rng, 0.0, 2.0, -4.0, 4.0),
        trunk_turn: clipped(rng, 0.0, 4.0, -8.0, 8.0),
        head_flexion: clipped(rng, 0.0, 6.0, -12.0, 12.0),
        head_lateral: clipped(rng, 0.0, 3.0, -6.0, 6.0),
        head_turn: clipped(rng, 0.0, 6.0, -12.0, 12.0),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;
    use rand_chacha::ChaCha8Rng;

    #[test]
    fn profiles_round_trip_by_name() {
        for p in PopulationProfile::ALL {
            assert_eq!(PopulationProfile::from_name(p.name()), Some(p));
        }
        assert_eq!(PopulationProfile::from_name("tuned"), None);
        assert_eq!(PopulationProfile::default(), PopulationProfile::Tuning);
    }

    #[test]
    fn held_out_poses_cover_the_arm_modes_and_stay_in_range() {
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        let (mut down, mut hips, mut raised) = (0, 0, 0);
        for _ in 0..200 {
            let p = sample_held_out(&mut rng).pose;
            for a in [p.left_shoulder_abduction, p.right_shoulder_abduction] {
                let from_body = a + A_POSE_ARM_DEG;
                assert!((8.0..=60.0).contains(&from_body), "{from_body}");
            }
            let from_body = p.left_shoulder_abduction + A_POSE_ARM_DEG;
            if p.left_elbow_flexion > 0.0 {
                hips += 1;
                assert!((80.0..=105.0).contains(&p.left_elbow_flexion));
            } else if from_body < 20.0 {
                down += 1;
            } else {
                raised += 1;
            }
            assert!((-5.0..=10.0).contains(&p.left_hip_abduction));
            assert!(p.head_turn.abs() <= 12.0 && p.trunk_turn.abs() <= 8.0);
        }
        assert!(
            down > 20 && hips > 20 && raised > 80,
            "{down} {hips} {raised}"
        );
    }

    #[test]
    fn tuning_subjects_keep_the_unused_joints_still() {
        let mut rng = ChaCha8Rng::seed_from_u64(4);
        let p = sample_subject(PopulationProfile::Tuning, &mut rng).pose;
        assert_eq!(
            (p.left_elbow_flexion, p.left_hip_abduction, p.trunk_turn),
            (0.0, 0.0, 0.0)
        );
        assert!(p.left_shoulder_abduction.abs() <= 10.0);
    }
}
