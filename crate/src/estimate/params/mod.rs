//! Parameters of the landmark estimate, each with its documented default (the one place they
//! live): [`EstimateParams`] and the parameter structs it holds for the segment-wise fit
//! ([`SegmentParams`], `segments.rs`), the limbs' profiles ([`ProfileParams`]) and the hands
//! ([`HandParams`]) and the feet ([`FootParams`]), the Acromions on the surface ([`AcromionParams`]), the estimate's check of itself ([`SelfCheckParams`]) and the check of a given
//! file ([`CheckParams`]). Lengths are metres (the check's millimetres), angles degrees.

pub mod acromion;
pub mod check;
pub mod foot;
pub mod hand;
pub mod profile;
pub mod segments;
pub mod self_check;

pub use acromion::AcromionParams;
pub use check::CheckParams;
pub use foot::FootParams;
pub use hand::{HandParams, LaidHandParams, WristProfileParams};
pub use profile::ProfileParams;
pub use segments::{
    ArmSwingParams, BentArmParams, ButtocksParams, FaceParams, KneeParams, SegmentParams,
};
pub use self_check::SelfCheckParams;

use serde::{Deserialize, Serialize};

use crate::align::FineAlignParams;
use crate::mesh::floor::FloorParams;
use crate::mesh::strays::StrayParams;

/// Parameters of [`super::estimate_landmarks`].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct EstimateParams {
    /// Template vertices sampled (evenly by index) for the similarity fit of each frame
    /// candidate. Default 1,500: the candidates differ by metres, not millimetres.
    pub candidate_samples: usize,
    /// Similarity ICP iterations per frame candidate. Default 12.
    pub candidate_iterations: usize,
    /// Two frame candidates are the same frame when they take the template's up (+y) and its
    /// facing (+z) each within this angle (degrees) of the same direction (the candidates differ
    /// by 90° or more); with four or more given landmarks, candidates farther from the given
    /// landmarks' own frame are not taken. Default 60°.
    pub same_frame_deg: f64,
    /// When the two best candidates agree on which way is up but face different ways, and their
    /// energies lie within this fraction of each other, the one whose torso matches better goes
    /// first (arms and legs pose freely, the torso does not). Default 0.1.
    pub torso_close: f64,
    /// Without given landmarks, when the scan's shape says which end is the head (`up.rs`: the
    /// head's end narrower than the shoulders below it, its width ratio below this fraction of
    /// the feet's end's), only the candidates with that end up are fitted; 0 turns it off.
    /// Default 0.75.
    pub head_end_decisive: f64,
    /// The floor or turntable remnant under the feet, taken off the scan once the frame is
    /// known (`mesh/floor.rs`; its defaults there).
    pub floor: FloorParams,
    /// When the shape says which end is the head, the feet say which way the body faces when
    /// they reach at least this share of the body's extent forward of the lower legs (`facing.rs`;
    /// on the template ≈ 0.03); only the candidates facing that way are then fitted. 0 turns it
    /// off. Default 0.015 (2.5 cm on a 1.7 m body).
    pub feet_forward_decisive: f64,
    /// When the feet do not say (cut off, or reaching too little), the legs do when the
    /// thighs' points lie at least this share of the extent forward of the calves' along the
    /// plumb line (`facing.rs`; 1.25–2.83 % on the tuning zoo seed 31, 32 subjects, always the
    /// right way; 1.01–3.22 % on 88 held-out ones). 0 turns it off. Default 0.006 (1 cm on a
    /// 1.7 m body).
    pub legs_forward_decisive: f64,
    /// With given landmarks, the segment-wise fit runs from this many of the best candidates and
    /// the one whose landmarks lie nearer the given ones is kept. Default 2.
    pub segment_starts: usize,
    /// A later start of the segment-wise fit is kept only when its landmarks lie nearer the
    /// given ones than the best candidate's by more than this (m, the mean over the given
    /// landmarks): a folded limb puts one landmark decimetres off, while a few millimetres
    /// nearer was a worse fit of the rest (a partial file of correct landmarks then made the fit
    /// worse than none). Default 10 mm.
    pub segment_start_margin: f64,
    /// Four or more given landmarks set a frame of their own only when they lie on at least this
    /// many of the template's parts (head, torso, the limbs' parts). Default 3: landmarks on one
    /// limb posed otherwise than the template's, or on one small part, say nothing of the body's
    /// frame (four on a bent forearm set it back to front).
    pub given_frame_parts: usize,
    /// Iterations of the segment-wise (articulated) fit after the best candidate. Default 20.
    pub segment_iterations: usize,
    /// The segment-wise fit's own parameters (stretch, bends, the arms' swing, the bent elbow,
    /// the buttocks).
    pub segments: SegmentParams,
    /// The limbs' cross-section profiles (knees, elbows).
    pub profile: ProfileParams,
    /// The hands' pose about the wrist.
    pub hand: HandParams,
    /// The feet's pose about the ankle.
    pub foot: FootParams,
    /// The Acromions placed on the scan's shoulder after the fine fit.
    pub acromion: AcromionParams,
    /// Largest angle (degrees) between template and scan normals of a match in the ICP stages.
    /// Default 60°, fine alignment's value.
    pub max_normal_angle_deg: f64,
    /// A match farther than this (m) counts as this far in a candidate's energy and is left out
    /// of the transform fit: it is the other arm, a hole or clutter. Default 0.1 m.
    pub outlier_distance: f64,
    /// The landmark-free fine alignment after the segment-wise fit (paper §3.2 energy, stiff
    /// first: fine alignment's own annealing). Default: fine alignment's defaults with 80
    /// iterations and the given landmarks anchored at weight 1.
    pub fine: FineAlignParams,
    /// A given landmark farther than this (m) from where the other given landmarks of its part
    /// predict it is flagged suspicious. Default 60 mm: body shapes differ by less within one
    /// rigid part, a swapped Lt./Rt. pair by 25 cm or more (docs/landmarks-estimate.md).
    pub suspicious_distance: f64,
    /// The same for a landmark whose part has too few other given landmarks, judged against the
    /// segment-wise fit. Default 120 mm: above the fit's worst error on the synthetic subjects
    /// (≈ 9 cm, fingertips), below a swapped pair's distance.
    pub suspicious_distance_fit: f64,
    /// Radius (m) around a landmark vertex over which the fit's residual is taken for the
    /// confidence. Default 25 mm.
    pub confidence_radius: f64,
    /// The typical error (m) at which the confidence falls to e⁻¹. Default 30 mm (the hands'
    /// typical error: ≈ 0.3; the feet's 8 mm: ≈ 0.75).
    pub confidence_error: f64,
    /// The local residual (m) that lowers the confidence by a further factor e⁻¹. Default 10 mm:
    /// above the fit's usual 3–5 mm, so only a landmark over a hole or a failed fit drops.
    pub confidence_residual: f64,
    /// An arm raised more than this (degrees from hanging down, the upper arm in the trunk's
    /// frontal plane, as the fit placed it) takes its landmarks' typical errors from the raised
    /// arm's table (`typical_error.rs`), so their confidence says how far off such an arm is
    /// placed. Default 75°: the held-out profile's arms reach 60° from the body, the zoo's raised
    /// arms measured 83–149° (docs/landmarks-estimate.md, "Every elbow where its axes meet; a
    /// raised arm").
    pub raised_arm_deg: f64,
    /// When the estimate calls itself doubtful or failed (`self_check.rs`).
    pub self_check: SelfCheckParams,
    /// Small pieces floating off the body, taken off the scan first (`mesh/strays.rs`; its
    /// defaults there).
    pub strays: StrayParams,
}

impl Default for EstimateParams {
    fn default() -> Self {
        Self {
            candidate_samples: 1_500,
            candidate_iterations: 12,
            same_frame_deg: 60.0,
            torso_close: 0.1,
            head_end_decisive: 0.75,
            floor: FloorParams::default(),
            feet_forward_decisive: 0.015,
            legs_forward_decisive: 0.006,
            segment_starts: 2,
            segment_start_margin: 0.01,
            given_frame_parts: 3,
            segment_iterations: 20,
            segments: SegmentParams::default(),
            profile: ProfileParams::default(),
            hand: HandParams::default(),
            foot: FootParams::default(),
            acromion: AcromionParams::default(),
            max_normal_angle_deg: 60.0,
            outlier_distance: 0.1,
            fine: FineAlignParams {
                max_iterations: 80,
                landmark_weight: 1.0,
                ..FineAlignParams::default()
            },
            suspicious_distance: 0.06,
            suspicious_distance_fit: 0.12,
            confidence_radius: 0.025,
            confidence_error: 0.03,
            confidence_residual: 0.01,
            raised_arm_deg: 75.0,
            self_check: SelfCheckParams::default(),
            strays: StrayParams::default(),
        }
    }
}
