//! Parameters of the estimate's check of itself (`self_check.rs`).

use serde::{Deserialize, Serialize};

/// When an estimate is doubtful or failed, and what that does to its confidences,
/// [`super::EstimateParams::self_check`].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct SelfCheckParams {
    /// How far (RMS, mm) the landmark-free fit may move the template from the segment-wise fit
    /// before the estimate is doubtful. Default 20 mm: good estimates of the synthetic tuning
    /// scans move it 6–10 mm (a turntable under the feet 19 mm), a body fitted upside down or on
    /// its side 30–43 mm (docs/landmarks-estimate.md, "Self-check").
    pub doubtful_moved_mm: f64,
    /// The same, above which it failed. Default 25 mm.
    pub failed_moved_mm: f64,
    /// The fitted body's height (m) outside this range is no person's: the frame is wrong.
    /// Default 0.8–2.4 m.
    pub stature_m: (f64, f64),
    /// The fit's RMS (mm, over the 95 % of the weighted template vertices nearest the scan: a cut
    /// crown or feet leave the template's there far from anything) above which part of the body
    /// is taken to fit badly (doubtful). Default 8 mm: good estimates of coarse synthetic scans
    /// measure 3–7 mm, a real body with its hands on its hips whose arms were posed wrongly 14 mm
    /// (its RMS over all vertices).
    pub doubtful_rms_mm: f64,
    /// The fine fit's RMS at its end above its lowest by more than this fraction (and by more
    /// than `rise_mm`) makes the estimate doubtful: the fit moved away from the scan. Default 0.25.
    pub rise: f64,
    /// The least rise (mm) that counts. Default 0.5 mm.
    pub rise_mm: f64,
    /// More estimated landmarks than this that the check of a given file would flag against the
    /// others of their rigid groups (`check.rs`) make the estimate doubtful. Default 6: good
    /// estimates of clean synthetic scans have 0–1, of scans with a floor or a photogrammetry-like
    /// blob up to 5; wrong frames 0–19 (the bend and the height catch those).
    pub max_contradicting: usize,
    /// A limb segment on one bone (`bilateral.rs`: thigh, lower leg, upper arm, forearm, foot)
    /// longer on one side than on the other by more than this (mm) makes the estimate doubtful,
    /// and its four landmarks' confidences drop to `failed_factor`. Default 40 mm: the synthetic
    /// bodies' own sides differ by at most 14 mm; good estimates of the tuning seeds by up to
    /// 35 mm; a right knee misplaced 71 mm up the leg gave 68 and 93 mm, a radiale misplaced
    /// 99 mm gave 52 mm (docs/landmarks-estimate.md, "Self-check").
    pub max_bilateral_mm: f64,
    /// A limb's part (upper arm, forearm, thigh, lower leg) whose fit's RMS to the scan (the soles
    /// left out) is above `uneven_fit.0` times the other side's and above it by more than
    /// `uneven_fit.1` mm makes the estimate doubtful (`align::uneven_fits`). Default (2.5, 6 mm):
    /// see docs/landmarks-estimate.md, "Self-check".
    pub uneven_fit: (f64, f64),
    /// A scan vertex farther than `uncovered.0` (mm) from the landmark-free fit is uncovered; a
    /// share of the scan above `uncovered.1` uncovered makes the estimate doubtful: part of the
    /// body was not reached by the template (legs fitted too short over cut feet, a forearm
    /// beside its scan). Default (20 mm, 0.003): good estimates leave at most 0.065 % of the scan
    /// on the tuning zoo (a floor's ring) and 0.16 % on the held-out ones (a turntable's rim); legs
    /// fitted too short over cut feet left 0.98 % (docs/landmarks-estimate.md, "The scan the
    /// estimate's fit left uncovered").
    pub uncovered: (f64, f64),
    /// When nothing but the similarity fits chose which way the body faces, fits facing either way
    /// closer than this (their energies' difference over the best's) make the estimate doubtful.
    /// Default 0.03: with both facings fitted on 120 tuning and held-out zoo scans, the fit
    /// facing the wrong way came out best twice, 0.3 % and 1.4 % from the right one, and every
    /// wider gap chose right (docs/landmarks-estimate.md, "Which way the body faces, when only the
    /// fits say").
    pub facing_close: f64,
    /// A head pitched further than this (degrees) from the template's (the Tragions' →
    /// Infraorbitales' line, `landmarks::head_pitch`) makes the estimate doubtful. Default 25°
    /// (docs/landmarks-estimate.md, "A face placed on the throat").
    pub head_pitch_deg: f64,
    /// The confidences of a doubtful estimate are multiplied by this. Default 0.5.
    pub doubtful_factor: f64,
    /// The same for a failed one: none stays above 10 %. Default 0.1.
    pub failed_factor: f64,
}

impl Default for SelfCheckParams {
    fn default() -> Self {
        Self {
            doubtful_moved_mm: 20.0,
            failed_moved_mm: 25.0,
            stature_m: (0.8, 2.4),
            doubtful_rms_mm: 8.0,
            rise: 0.25,
            rise_mm: 0.5,
            max_contradicting: 6,
            max_bilateral_mm: 40.0,
            uneven_fit: (2.5, 6.0),
            uncovered: (20.0, 0.003),
            facing_close: 0.03,
            head_pitch_deg: 25.0,
            doubtful_factor: 0.5,
            failed_factor: 0.1,
        }
    }
}
