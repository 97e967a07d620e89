//! The estimate's check of itself: every estimate says whether it can be trusted, and why not, in
//! words. A wrong answer presented as right is the worst bug the product can have, so an
//! estimate whose template had to be bent far out of shape to meet the scan, whose fitted body is
//! no person's height, whose fit lies far from the scan, drifted away from it or left part of the
//! scan uncovered, or whose landmarks contradict each other (against their rigid groups, or a
//! limb's segment much longer on one side than on the other: `bilateral.rs`), or whose facing
//! only the fits chose, by a hair, or whose face is turned far from level, is `doubtful` or
//! `failed`, and its confidences are lowered to say so ([`SelfCheck::confidence_factor`]; the
//! landmarks of a lopsided segment, and the head's when the face is turned, to
//! [`SelfCheckParams::failed_factor`], [`SelfCheck::factor_for`]).

use serde::{Deserialize, Serialize};

use super::bilateral::Asymmetry;
use super::params::SelfCheckParams;
use crate::align::{Uncovered, UnevenFit};
use crate::landmarks::CAESAR_LANDMARKS;
use crate::template::Segment;

/// The estimate's verdict on itself.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    Good,
    Doubtful,
    Failed,
}

impl Verdict {
    pub fn name(self) -> &'static str {
        match self {
            Verdict::Good => "good",
            Verdict::Doubtful => "doubtful",
            Verdict::Failed => "failed",
        }
    }
}

/// The verdict and its reasons, each a sentence for a person.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SelfCheck {
    pub verdict: Verdict,
    pub reasons: Vec<String>,
    /// What the confidences were multiplied by (1 for a good estimate).
    pub confidence_factor: f64,
    /// What the confidences of the landmarks in `lowered` were multiplied by instead.
    pub lopsided_factor: f64,
    /// The landmarks the check takes for misplaced: the ends of a segment much longer on one side
    /// than on the other (`evidence.asymmetric`) and, with the face turned beyond
    /// `SelfCheckParams::head_pitch_deg`, the head's. Their confidences get `lopsided_factor`.
    pub lowered: Vec<String>,
    /// The estimated landmarks a person should look at first when the estimate is not good, most
    /// suspect first: `lowered`, then those of a limb part fitted far from the scan (the worse
    /// side of `evidence.uneven`), then those of the part nearest the scan left uncovered, then
    /// the contradicting ones. Empty for a good estimate.
    #[serde(default)]
    pub check_first: Vec<String>,
    /// Whether the reasons put the frame itself in doubt (a stature no person has, a template
    /// bent beyond the failed limit, a facing the fits chose by a hair): choosing Up and Facing is
    /// the way out, where otherwise placing the landmarks of `check_first` is.
    #[serde(default)]
    pub frame_in_doubt: bool,
    /// What the verdict was drawn from.
    pub evidence: Evidence,
}

impl SelfCheck {
    /// What the confidence of landmark `name` is multiplied by: the lopsided factor for one in
    /// `lowered`, the verdict's factor for the others.
    pub fn factor_for(&self, name: &str) -> f64 {
        if self.lowered.iter().any(|l| l == name) {
            self.lopsided_factor.min(self.confidence_factor)
        } else {
            self.confidence_factor
        }
    }
}

/// What the check looks at, from the estimate's steps.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Evidence {
    /// RMS (mm) of the landmark-free fit, template → scan, over the 95 % of the weighted template
    /// vertices nearest the scan (a limb fitted wrongly weighs in it, a cut crown or feet not).
    pub fit_rms_mm: f64,
    /// RMS (mm) of how far the landmark-free fit moved the weighted template vertices from the
    /// segment-wise fit: how much the body had to be bent out of shape to meet the scan.
    pub fit_moved_mm: f64,
    /// Height (m) of the fitted template along the frame's up: a person's stature, or the sign
    /// that the frame was wrong (a template shrunk to a body's width when up was taken across it).
    pub stature_m: f64,
    /// RMS (mm) after each iteration of that fit (not written to the report).
    #[serde(skip)]
    pub fit_curve_mm: Vec<f64>,
    /// Estimated landmarks the check of a given file flags against their rigid groups (names).
    pub contradicting: Vec<String>,
    /// Limb segments much longer on one side than on the other (`bilateral.rs`).
    #[serde(default)]
    pub asymmetric: Vec<Asymmetry>,
    /// Limb parts whose fit lies much farther from the scan on one side than on the other.
    #[serde(default)]
    pub uneven: Vec<UnevenFit>,
    /// When nothing but the similarity fits chose which way the body faces (no given landmarks,
    /// no facing chosen, neither the feet nor the legs asked or saying: `facing.rs`), the
    /// difference of the energies of the best fit and the best facing the other way, over the
    /// best's.
    #[serde(default)]
    pub facing_margin: Option<f64>,
    /// The scan the landmark-free fit left farther than `SelfCheckParams::uncovered.0` from it
    /// (`None` when not measured).
    #[serde(default)]
    pub uncovered: Option<Uncovered>,
    /// How far (degrees) the estimated head is pitched from the template's own head: the pitch
    /// of the line from the Tragions to the Infraorbitales (`landmarks::head_pitch`) on the fit,
    /// along the frame's up, less the same on the template at rest (positive: the face turned
    /// up). `None` when not measured.
    #[serde(default)]
    pub head_pitch_deg: Option<f64>,
    /// The template part each CAESAR landmark (file order) belongs to (`template::parts` names,
    /// `left forearm`, …): which landmarks an uneven or uncovered part names. Not written.
    #[serde(skip)]
    pub landmark_parts: Vec<&'static str>,
}

/// The estimate's verdict on `evidence` (see the module documentation and [`SelfCheckParams`]).
pub fn self_check(evidence: &Evidence, params: &SelfCheckParams) -> SelfCheck {
    let mut failed = Vec::new();
    let mut doubtful = Vec::new();
    let mut frame_in_doubt = false;
    let (moved, rms, stature) = (
        evidence.fit_moved_mm,
        evidence.fit_rms_mm,
        evidence.stature_m,
    );
    let (low, high) = params.stature_m;
    if !(low..=high).contains(&stature) {
        frame_in_doubt = true;
        failed.push(format!(
            "the fitted body is {stature:.2} m tall, not a person's stature: the frame is wrong; \
             choose which way is up"
        ));
    }
    if !moved.is_finite() || moved > params.failed_moved_mm {
        frame_in_doubt = true;
        failed.push(format!(
            "the template had to be bent {moved:.0} mm out of shape (RMS) to meet the scan: the \
             body's frame or pose was not found; choose which way is up, or place a few \
             landmarks by hand"
        ));
    } else if moved > params.doubtful_moved_mm {
        doubtful.push(format!(
            "the template had to be bent {moved:.0} mm out of shape (RMS) to meet the scan, more \
             than a good estimate ({:.0} mm): the pose may be wrong",
            params.doubtful_moved_mm
        ));
    }
    if rms.is_finite() && rms > params.doubtful_rms_mm {
        doubtful.push(format!(
            "parts of the template lie far from the scan (RMS {rms:.1} mm): a limb may be posed \
             wrongly, or part of the body is missing from the scan"
        ));
    }
    let lowest = evidence
        .fit_curve_mm
        .iter()
        .copied()
        .fold(f64::INFINITY, f64::min);
    if let Some(&last) = evidence.fit_curve_mm.last() {
        if last > lowest * (1.0 + params.rise) && last - lowest > params.rise_mm {
            doubtful.push(format!(
                "the fit moved away from the scan as it went on (RMS {lowest:.1} mm at best, \
                 {last:.1} mm at the end)"
            ));
        }
    }
    for a in &evidence.asymmetric {
        doubtful.push(a.sentence());
    }
    for u in &evidence.uneven {
        doubtful.push(u.sentence());
    }
    if let Some(m) = evidence.facing_margin.filter(|m| *m < params.facing_close) {
        frame_in_doubt = true;
        doubtful.push(format!(
            "only the fits chose which way the body faces, and those facing either way came \
             within {:.1} % of each other: it may face the other way; look at the face, or \
             choose the facing",
            100.0 * m
        ));
    }
    let uncovered = evidence
        .uncovered
        .as_ref()
        .filter(|u| u.share > params.uncovered.1);
    if let Some(u) = uncovered {
        doubtful.push(format!(
            "{:.1} % of the scan lies more than {:.0} mm from the fit{}: the template did not \
             reach that part of the body (a limb fitted too short or beside the scan); check its \
             landmarks",
            100.0 * u.share,
            params.uncovered.0,
            u.near
                .as_ref()
                .map_or(String::new(), |n| format!(", most of it near the {n}"))
        ));
    }
    let mut lowered: Vec<String> = Vec::new();
    for a in &evidence.asymmetric {
        lowered.extend(a.landmarks.iter().cloned());
    }
    if let Some(pitch) = evidence
        .head_pitch_deg
        .filter(|p| p.abs() > params.head_pitch_deg)
    {
        lowered.extend(
            CAESAR_LANDMARKS
                .iter()
                .filter(|l| l.segment == Segment::Head)
                .map(|l| l.name.to_string()),
        );
        doubtful.push(format!(
            "the face is turned {:.0}° {} from the template's (the line from the ears to the \
             eyes), where a person standing to be scanned holds it near level: the head or the \
             face may be placed wrongly; check the face's landmarks, or place Sellion and the \
             Tragions by hand",
            pitch.abs(),
            if pitch < 0.0 { "down" } else { "up" }
        ));
    }
    let contradicting = evidence.contradicting.len() > params.max_contradicting;
    if contradicting {
        doubtful.push(format!(
            "{} estimated landmarks lie far from where the others of their part put them ({})",
            evidence.contradicting.len(),
            evidence.contradicting.join(", ")
        ));
    }
    let (verdict, confidence_factor) = if !failed.is_empty() {
        (Verdict::Failed, params.failed_factor)
    } else if !doubtful.is_empty() {
        (Verdict::Doubtful, params.doubtful_factor)
    } else {
        (Verdict::Good, 1.0)
    };
    failed.extend(doubtful);
    let check_first = if verdict == Verdict::Good {
        Vec::new()
    } else {
        check_first(
            evidence,
            &lowered,
            uncovered.and_then(|u| u.near.as_deref()),
            contradicting,
        )
    };
    SelfCheck {
        verdict,
        reasons: failed,
        confidence_factor,
        lopsided_factor: params.failed_factor,
        lowered,
        check_first,
        frame_in_doubt,
        evidence: evidence.clone(),
    }
}

/// [`SelfCheck::check_first`]: `lowered`, the landmarks of the worse side of each uneven part,
/// those of the part `uncovered_near` (when the uncovered scan is a reason), the contradicting
/// ones (when they are); each once.
fn check_first(
    evidence: &Evidence,
    lowered: &[String],
    uncovered_near: Option<&str>,
    contradicting: bool,
) -> Vec<String> {
    let of_part = |part: String| {
        CAESAR_LANDMARKS
            .iter()
            .zip(&evidence.landmark_parts)
            .filter(move |(_, p)| **p == part)
            .map(|(l, _)| l.name.to_string())
    };
    let uneven = evidence.uneven.iter().flat_map(|u| {
        let side = if u.left_rms_mm > u.right_rms_mm {
            "left"
        } else {
            "right"
        };
        of_part(format!("{side} {}", u.part))
    });
    let uncovered = uncovered_near
        .map(str::to_string)
        .into_iter()
        .flat_map(of_part);
    let contradicting = evidence.contradicting.iter().filter(|_| contradicting);
    let mut names: Vec<String> = Vec::new();
    for name in lowered
        .iter()
        .cloned()
        .chain(uneven)
        .chain(uncovered)
        .chain(contradicting.cloned())
    {
        if !names.contains(&name) {
            names.push(name);
        }
    }
    names
}

#[cfg(test)]
mod tests {
    use super::*;

    fn good() -> Evidence {
        Evidence {
            fit_rms_mm: 4.0,
            fit_moved_mm: 8.0,
            stature_m: 1.7,
            fit_curve_mm: vec![6.0, 3.0, 1.5, 1.2],
            contradicting: vec!["Rt. Dactylion".into()],
            asymmetric: Vec::new(),
            uneven: Vec::new(),
            facing_margin: Some(0.05),
            // A floor ring's worth (good tuning estimates: at most 0.065 %).
            uncovered: Some(Uncovered {
                vertices: 60,
                share: 0.0006,
                near: Some("right lower leg".into()),
            }),
            head_pitch_deg: Some(-8.0),
            landmark_parts: Vec::new(),
        }
    }

    #[test]
    fn a_good_estimate_says_nothing_and_keeps_its_confidences() {
        let c = self_check(&good(), &SelfCheckParams::default());
        assert_eq!(c.verdict, Verdict::Good);
        assert!(c.reasons.is_empty());
        assert_eq!(c.confidence_factor, 1.0);
    }

    #[test]
    fn each_sign_of_trouble_is_said_in_words() {
        let p = SelfCheckParams::default();
        // Bent too far, and too small: each fails with its one reason.
        let failing = [
            (
                Evidence {
                    fit_moved_mm: 40.0,
                    ..good()
                },
                "40 mm",
            ),
            (
                Evidence {
                    stature_m: 0.45,
                    ..good()
                },
                "0.45 m tall",
            ),
        ];
        for (e, reason) in &failing {
            let c = self_check(e, &p);
            assert_eq!(c.verdict, Verdict::Failed);
            assert_eq!(c.reasons.len(), 1, "{:?}", c.reasons);
            assert!(c.reasons[0].contains(reason), "{:?}", c.reasons);
            assert_eq!(c.confidence_factor, p.failed_factor);
        }
        let nan = Evidence {
            fit_moved_mm: f64::NAN,
            ..good()
        };
        assert_eq!(self_check(&nan, &p).verdict, Verdict::Failed);

        let cases = [
            Evidence {
                fit_moved_mm: 22.0,
                ..good()
            },
            Evidence {
                fit_rms_mm: 14.0,
                ..good()
            },
            Evidence {
                fit_curve_mm: vec![6.0, 1.2, 2.5],
                ..good()
            },
            Evidence {
                contradicting: (0..8).map(|i| format!("L{i}")).collect(),
                ..good()
            },
            Evidence {
                asymmetric: vec![Asymmetry {
                    segment: "thigh".into(),
                    left_mm: 440.0,
                    right_mm: 380.0,
                    landmarks: vec!["Rt. Femoral Lateral Epicn".into()],
                }],
                ..good()
            },
            Evidence {
                uneven: vec![UnevenFit {
                    part: "upper arm".into(),
                    left_rms_mm: 3.0,
                    right_rms_mm: 25.0,
                }],
                ..good()
            },
            Evidence {
                facing_margin: Some(0.006),
                ..good()
            },
            Evidence {
                uncovered: Some(Uncovered {
                    vertices: 524,
                    share: 0.0098,
                    near: Some("left lower leg".into()),
                }),
                ..good()
            },
            Evidence {
                head_pitch_deg: Some(-41.0),
                ..good()
            },
        ];
        let uncovered = self_check(&cases[7], &p);
        assert!(self_check(&cases[6], &p).reasons[0].contains("came within 0.6 %"));
        let turned = self_check(&cases[8], &p);
        assert!(turned.reasons[0].starts_with("the face is turned 41° down"));
        // The face's landmarks are taken for misplaced; the rest only doubtful.
        assert_eq!(turned.factor_for("Sellion"), p.failed_factor);
        assert_eq!(turned.factor_for("Rt. Tragion"), p.failed_factor);
        assert_eq!(turned.factor_for("Rt. Acromion"), p.doubtful_factor);
        assert!(
            uncovered.reasons[0].starts_with("1.0 % of the scan lies more than 20 mm from the fit, most of it near the left lower leg"),
            "{:?}",
            uncovered.reasons
        );
        for (k, e) in cases.iter().enumerate() {
            let c = self_check(e, &p);
            assert_eq!(c.verdict, Verdict::Doubtful, "case {k}: {c:?}");
            assert_eq!(c.reasons.len(), 1, "case {k}: {c:?}");
            assert_eq!(c.confidence_factor, p.doubtful_factor);
            let lopsided = !e.asymmetric.is_empty();
            assert_eq!(
                c.factor_for("Rt. Femoral Lateral Epicn"),
                if lopsided {
                    p.failed_factor
                } else {
                    p.doubtful_factor
                },
                "case {k}"
            );
            let face_turned = e.head_pitch_deg.is_some_and(|d| d.abs() > p.head_pitch_deg);
            assert_eq!(
                c.factor_for("Sellion"),
                if face_turned {
                    p.failed_factor
                } else {
                    p.doubtful_factor
                },
                "case {k}"
            );
        }
        // A failed estimate lists its doubts after the failure.
        let both = Evidence {
            fit_moved_mm: 35.0,
            fit_rms_mm: 30.0,
            ..good()
        };
        let c = self_check(&both, &p);
        assert_eq!(c.verdict, Verdict::Failed);
        assert_eq!(c.reasons.len(), 2);
        assert!(c.reasons[1].contains("RMS 30.0 mm"), "{:?}", c.reasons);
    }

    #[test]
    fn a_doubtful_estimate_names_the_landmarks_to_check_first_and_whether_the_frame_is_in_doubt() {
        use crate::landmarks::caesar_index;
        let p = SelfCheckParams::default();
        let mut parts = vec!["torso"; CAESAR_LANDMARKS.len()];
        for (name, part) in [
            ("Rt. Radial Styloid", "right forearm"),
            ("Rt. Ulnar Styloid", "right forearm"),
            ("Lt. Radial Styloid", "left forearm"),
            ("Lt. Lateral Malleolus", "left lower leg"),
        ] {
            parts[caesar_index(name).unwrap()] = part;
        }
        let with = |e: Evidence| Evidence {
            landmark_parts: parts.clone(),
            ..e
        };
        // A good estimate names none, though one landmark contradicts and a floor ring is uncovered.
        let good_one = self_check(&with(good()), &p);
        assert!(good_one.check_first.is_empty() && !good_one.frame_in_doubt);
        // The right forearm fitted far: its landmarks, the worse side's only; the lone
        // contradicting one is no reason, so it is not named.
        let forearm = with(Evidence {
            uneven: vec![UnevenFit {
                part: "forearm".into(),
                left_rms_mm: 4.0,
                right_rms_mm: 20.0,
            }],
            ..good()
        });
        let c = self_check(&forearm, &p);
        assert_eq!(c.check_first, ["Rt. Radial Styloid", "Rt. Ulnar Styloid"]);
        assert!(!c.frame_in_doubt);
        // With the face turned too, the head's landmarks come first; the uncovered part's after.
        let both = with(Evidence {
            head_pitch_deg: Some(40.0),
            uncovered: Some(Uncovered {
                vertices: 524,
                share: 0.0098,
                near: Some("left lower leg".into()),
            }),
            ..forearm.clone()
        });
        let c = self_check(&both, &p);
        assert_eq!(c.check_first[0], "Sellion");
        let at = |name: &str| c.check_first.iter().position(|n| n == name).unwrap();
        assert!(at("Rt. Radial Styloid") > at("Rt. Tragion"));
        assert_eq!(c.check_first.last().unwrap(), "Lt. Lateral Malleolus");
        // A stature no person has, or a facing the fits chose by a hair: the frame is in doubt.
        for e in [
            Evidence {
                stature_m: 0.45,
                ..good()
            },
            Evidence {
                facing_margin: Some(0.006),
                ..good()
            },
        ] {
            assert!(self_check(&with(e), &p).frame_in_doubt);
        }
    }
}
