//! Parameters of the segment-wise fit (`segments.rs`) and of what it calls: the arms' swing
//! (`arm_swing.rs`), the bent arm's elbow (`bent_arm.rs`), the torso's length from the buttocks
//! (`buttocks.rs`). Lengths are metres, angles degrees.

use serde::{Deserialize, Serialize};

/// Parameters of the segment-wise (articulated) fit, [`super::EstimateParams::segments`].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct SegmentParams {
    /// The range of a limb part's stretch along its axis, times the template's length at the
    /// body's scale. Default 0.75–1.33: a quarter shorter to a third longer.
    pub stretch_range: (f64, f64),
    /// Iterations of the fit after the knees and elbows are placed by the limbs' profiles, the
    /// thighs' and upper arms' stretches then held (out of the fit's iterations). Default 5.
    pub profile_iterations: usize,
    /// Spacing (m) of the points on the template's and the scan's surface the limbs' profiles
    /// and the back's are taken from. Default 4 mm: a coarse mesh's vertices lie in rings too
    /// far apart.
    pub surface_spacing: f64,
    /// A limb bent more than this (degrees) at the elbow or knee is not placed by its profile
    /// (the profile is taken across the straight root → end line), an arm's elbow hinge is
    /// turned across the plane of its axes (`bent_arm.rs`) and its hand laid on the body
    /// (`hand/laid.rs`). Default 60°. (Every arm bent more than `bent_arm.min_bend_deg` has its
    /// elbow where its axes meet.)
    pub max_bend_deg: f64,
    /// No elbow or knee bends further than this (degrees from the template's limb; an elbow's
    /// full flexion is ≈ 145°, hands on hips ≈ 80–105°): a fit folded past it is straightened.
    /// Default 145°.
    pub max_fold_deg: f64,
    /// Scan points farther than this (m) from a leg's line are not the leg. Default 14 cm (a
    /// thigh's radius is up to ≈ 10 cm).
    pub leg_radius: f64,
    /// The same for an arm: narrower, so that an arm held against the trunk takes less of it.
    /// Default 8 cm.
    pub arm_radius: f64,
    /// The arm's line runs on beyond the wrist by this fraction of the forearm, over the hand,
    /// so that a hand beside the thigh is not taken for the thigh. Default 0.7.
    pub hand_reach: f64,
    /// The given landmarks of a part count, together, as this share of the part's matched
    /// vertices in its rigid fit (0 leaves them out): a few landmarks a person placed re-pose
    /// the part they lie on. Default 0.5 (the nose tip counts as 0.2); not tuned
    /// (docs/landmarks-estimate.md, "Given landmarks re-pose their part").
    pub given_share: f64,
    /// A part is pulled by its given landmarks only when it has at least this many. Default 3,
    /// as many as fix a rigid pose: Sellion alone on the head, in place of its nose tip, or an
    /// Acromion alone pulling the upper arm left a partial file worse than none (held-out 5151
    /// subject 0: 13.7 → 21.1 mm of correspondence error with Sellion, the Acromions and Crotch).
    /// The torso is never pulled: its pose is the frame, which four given landmarks already set.
    pub given_min: usize,
    /// The arms' swing about the shoulder.
    pub swing: ArmSwingParams,
    /// The elbow of an arm bent at it.
    pub bent_arm: BentArmParams,
    /// The torso's length from the height of the buttocks.
    pub buttocks: ButtocksParams,
    /// The head's nose tip pulled to the scan's.
    pub face: FaceParams,
    /// The two knees compared side against side (`knees.rs`).
    pub knees: KneeParams,
}

impl Default for SegmentParams {
    fn default() -> Self {
        Self {
            stretch_range: (0.75, 1.33),
            profile_iterations: 5,
            surface_spacing: 0.004,
            max_bend_deg: 60.0,
            max_fold_deg: 145.0,
            leg_radius: 0.14,
            arm_radius: 0.08,
            hand_reach: 0.7,
            given_share: 0.5,
            given_min: 3,
            swing: ArmSwingParams::default(),
            bent_arm: BentArmParams::default(),
            buttocks: ButtocksParams::default(),
            face: FaceParams::default(),
            knees: KneeParams::default(),
        }
    }
}

/// Parameters of the arms' swing about the shoulder (`arm_swing.rs`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct ArmSwingParams {
    /// The turns tried about each shoulder (degrees, positive towards the body) from where the
    /// fit has the arm. Default −15°, 0°, 15°, 30°: arms from down along the body to raised (the
    /// issue's A-poses reach 60° from the body, 20° above the template's), as people are
    /// scanned.
    pub turns_deg: Vec<f64>,
    /// Further turns (degrees, as `turns_deg`) tried only for an arm that every turn of
    /// `turns_deg` leaves badly matched (`raise_when`): an arm raised beside or above the head,
    /// 90–150° from the body (issue 31's "one arm raised"). Default −45°, −75°, −105° (from the
    /// template's 39.6°: 85–145° from the body, each reaching ≈ 20° either way).
    pub raised_turns_deg: Vec<f64>,
    /// An arm whose lowest capped energy over `turns_deg` is above this fraction of `cap`² is
    /// badly matched and tried at `raised_turns_deg`. Default 0.5: arms the ordinary turns find
    /// measure 0.21–0.33 on development held-out subjects, raised arms 0.60–1.0
    /// (docs/landmarks-estimate.md, "One arm raised, found").
    pub raise_when: f64,
    /// Iterations of the segment-wise fit run from each turn before the turns are compared.
    /// Default 3.
    pub iterations: usize,
    /// Iterations of the segment-wise fit before the arms are swung (the torso settled first).
    /// Default 5.
    pub after: usize,
    /// A match farther than this (m) counts as this far in a turn's energy, an unmatched vertex
    /// too: the arm's inner side, pressed against the trunk, has no surface of its own on the
    /// scan, and must not count against the right turn more than a wrong turn's far matches.
    /// Default 3 cm.
    pub cap: f64,
    /// Side (m) of the cells of the surface the rest of the body already explains (a match
    /// there counts as unmatched). Default 1.5 cm.
    pub claim_cell: f64,
}

impl Default for ArmSwingParams {
    fn default() -> Self {
        Self {
            turns_deg: vec![-15.0, 0.0, 15.0, 30.0],
            raised_turns_deg: vec![-45.0, -75.0, -105.0],
            raise_when: 0.5,
            iterations: 3,
            after: 5,
            cap: 0.03,
            claim_cell: 0.015,
        }
    }
}

/// Parameters of the elbow of an arm bent at it (`bent_arm.rs`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct BentArmParams {
    /// An arm bent more than this (degrees, the angle at the elbow between the shoulder joint →
    /// elbow and the elbow → wrist lines: ≈ 39° on the template's straight A-pose arm, its
    /// shoulder joint sitting inside the shoulder) has its elbow placed where its upper arm's
    /// and forearm's axes meet, not by the limb's profile. Default 20°: on the development
    /// subjects the arms are fitted at 24–36° (hands on hips 80–106°, raised arms alike), and
    /// their elbows placed by the axes were 13.1 mm off against 16.3 by the profile
    /// (docs/landmarks-estimate.md, "Every elbow where its axes meet; a raised arm"); below it
    /// the two axes run nearly in line and meet nowhere sure. The elbow's hinge is turned across
    /// the axes' plane only past `SegmentParams::max_bend_deg`.
    pub min_bend_deg: f64,
    /// The forearm's own fit takes its vertices (and the hand's) from this fraction of the way
    /// from the elbow to the wrist on: the elbow's blend with the upper arm is left out.
    /// Default 0.25.
    pub forearm_start: f64,
    /// Iterations of the forearm's own fit. Default 20: an arm bent as the template's slides
    /// along its forearm slowly (on the template posed with 15% longer upper arms, 5 iterations
    /// found a stretch of 1.105, 10 1.138, 20 1.150; the development subjects' elbows 13.1, 15.3,
    /// 11.9 mm with 5, 12.4, 14.8, 12.1 with 20).
    pub forearm_iterations: usize,
}

impl Default for BentArmParams {
    fn default() -> Self {
        Self {
            min_bend_deg: 20.0,
            forearm_start: 0.25,
            forearm_iterations: 20,
        }
    }
}

/// Parameters of the torso's length from the buttocks (`buttocks.rs`). Lengths are metres at
/// the template's size.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct ButtocksParams {
    /// Half-width of the band about the midline the back is taken from. Default 4 cm.
    pub across: f64,
    /// The heights searched, from the midpoint of the PSIS. Default −25 cm to +10 cm.
    pub window: (f64, f64),
    /// Height of a bin of the back's profile. Default 5 mm.
    pub bin: f64,
    /// The peak must stand out of the profile at the window's ends by at least this: a flat
    /// back gives no height. Default 1 cm.
    pub min_prominence: f64,
    /// A bin with fewer points than this has no extent. Default 3.
    pub min_points: usize,
    /// The torso's stretch stays within this range (its length from the neck down). Default
    /// 0.85–1.15.
    pub stretch_range: (f64, f64),
}

impl Default for ButtocksParams {
    fn default() -> Self {
        Self {
            across: 0.04,
            window: (-0.25, 0.10),
            bin: 0.005,
            min_prominence: 0.01,
            min_points: 3,
            stretch_range: (0.85, 1.15),
        }
    }
}

/// The head's nose tip pulled to the scan's in the segment-wise fit (`segments.rs`): the scan's
/// nose tip is the tip (`mesh::tip`) of its surface near where the head's pose puts the
/// template's, seen from the torso's front.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct FaceParams {
    /// The scan's nose tip is looked for within this distance (m) of the posed template's.
    /// Default 6 cm: heads slid down by up to 2.6 cm, and a head tilted back 10–13° (the
    /// head's and the trunk's extension together) started with the template's nose about 5 cm
    /// under the scan's, where a search within 4 cm found the chin (docs/landmarks-estimate.md,
    /// "The nose tip looked for within 6 cm").
    pub radius: f64,
    /// A point's surroundings (m), which its tip stands out from. Default 2 cm: a nose's
    /// half-width.
    pub surroundings: f64,
    /// The nose tip counts as this share of the head's matched vertices (0 leaves it out).
    /// Default 0.2, as the joint.
    pub share: f64,
    /// Only the scan's surface within this distance (m) of where the similarity fit puts the
    /// template's nose tip is looked at, the same points every iteration. Default 20 cm, a
    /// head's height: the segment-wise fit moves the head by a few centimetres.
    pub reach: f64,
}

impl Default for FaceParams {
    fn default() -> Self {
        Self {
            radius: 0.06,
            surroundings: 0.02,
            share: 0.2,
            reach: 0.2,
        }
    }
}

/// Parameters of the knees' comparison side against side (`knees.rs`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct KneeParams {
    /// Knees whose distances from their hips differ by more than this (mm) are each tried at
    /// the other's distance too, and the fit keeps the placement whose legs lie nearest the
    /// scan. Default 40 mm: the synthetic bodies' thighs differ by at most 14 mm, a misplaced
    /// knee by 50–90 mm (docs/landmarks-estimate.md, "The knees side against side").
    pub apart_mm: f64,
}

impl Default for KneeParams {
    fn default() -> Self {
        Self { apart_mm: 40.0 }
    }
}
