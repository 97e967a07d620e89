//! [`estimate_landmarks`]: the 73 CAESAR landmarks on a bare scan, or the rest of a partial
//! set. Steps (docs/landmarks-estimate.md gives the reasons and the measurements):
//!
//! 1. units from the body's extent (`mesh/units.rs`), the scan in metres, its stray pieces
//!    floating off the body taken off (`mesh/strays.rs`), its parts wound inwards turned to face
//!    out (`mesh/winding.rs`), a closest-point index;
//! 2. frame candidates from the principal axes (`frame.rs`), plus one from the given landmarks
//!    when there are at least four; without those, the head's end from the scan's shape
//!    (`up.rs`) and then the way the feet reach (`facing.rs`) may leave out the candidates
//!    upside down and back to front; each fitted by similarity ICP, the lowest energy kept
//!    (`candidates.rs`);
//!    a floor or turntable remnant under the feet of the kept frame is then taken off the scan
//!    (`mesh/floor.rs`);
//! 3. the segment-wise rigid fit of the template's parts to the scan's pose (`segments.rs`),
//!    then each hand's wrist and turn from the scan's surface beyond the wrist (`hand/`); with
//!    four or more given landmarks from the two best candidates, the one nearer them kept;
//! 4. given landmarks far from where the others of their part (or else the fit) put them are
//!    flagged (`expected.rs`, `suspicious.rs`);
//! 5. the landmark-free fine alignment (paper §3.2, stiff to soft), the unflagged given landmarks
//!    anchored;
//! 6. the landmark vertices read off the fit (the Acromions found on the scan's shoulder near
//!    them, `acromion.rs`), each with a confidence from its typical error on
//!    the development subjects, its definition's spread on a body and the fit's local residual
//!    (`confidence.rs`); given
//!    landmarks are returned exactly as given.

use std::borrow::Cow;

use nalgebra::{Point3, Vector3};

use super::acromion::{place_acromions, RestTemplate};
use super::bilateral::asymmetries;
use super::caesar_points::{given_landmarks, landmark_rest};
use super::candidates::{even_sample, fit_similarity, prefer_torso, FittedCandidate};
use super::check::{judge_given, CheckParams, NEARLY_FULL};
use super::confidence::{confidence, neighbourhoods, residual};
use super::error::EstimateError;
use super::expected::expected_positions;
use super::facing::{body_forward, FacingCue};
use super::foot::pose_feet;
use super::frame::{same_frame, same_up, FrameReport};
use super::hand::pose_hands;
use super::matching::Matching;
use super::orientation::{candidates_for, Orientation};
use super::params::EstimateParams;
use super::report::{CandidateReport, EstimateReport, FrameBasis, LandmarkReport};
use super::segments::fit_segments;
use super::self_check::{self_check, Evidence, SelfCheck};
use super::suspicious::{flag_suspicious, SuspiciousLandmark};
use super::tick::Ticker;
use super::typical_error::{raised_arm_typical_error_mm, typical_error_mm};
use super::up::{head_end, triangulated};
use crate::align::{
    data_weights, fine_align, uncovered_scan, uneven_fits, AlignObserver, FineAlignInput,
    FineAlignParams, SurfaceIndex,
};
use crate::landmarks::head_pitch::head_pitch_deg;
use crate::landmarks::shoulder::{acromion_indices, ShoulderFrame};
use crate::landmarks::{
    definition_sharpness, LandmarkSet, CAESAR_LANDMARKS, CAESAR_LANDMARK_COUNT,
};
use crate::mesh::bounding_extent;
use crate::mesh::floor::remove_floor;
use crate::mesh::similarity::similarity;
use crate::mesh::strays::remove_strays;
use crate::mesh::units::{detect_units, Units};
use crate::mesh::winding::{face_out, WindingParams};
use crate::mesh::Mesh;
use crate::template::foot::feet;
use crate::template::hand::hands;
use crate::template::parts::{dominant_part, parts};
use crate::template::{Resolution, Segment, Template};
use crate::utils::now_ms;

/// The source of the frame candidate taken from the given landmarks' own frame.
const FROM_GIVEN: &str = "given landmarks";

/// What one estimate works on.
#[derive(Debug, Clone, Copy)]
pub struct EstimateInput<'a> {
    /// The template (its base resolution is used).
    pub template: &'a Template,
    /// The scan, in its own frame and units.
    pub scan: &'a Mesh,
    /// Landmarks already placed (scan frame and units; may be empty). Used as given, never moved.
    pub given: &'a LandmarkSet,
    /// The scan's units; `None` detects them from the body's extent.
    pub units: Option<Units>,
    /// Which way is up (and the body faces), when a person said so; `None` finds it.
    pub orientation: Option<Orientation>,
}

/// The 73 landmarks of a scan.
#[derive(Debug, Clone)]
pub struct LandmarkEstimate {
    /// CAESAR order; the scan's frame and units; `None` where no position could be found.
    pub positions: Vec<Option<Point3<f64>>>,
    /// 0..1 per landmark (1 for a given one).
    pub confidence: Vec<f64>,
    /// Whether each landmark was taken from the given set.
    pub given: Vec<bool>,
    /// The fitted base template (`#V` metres, the scan's frame).
    pub fitted: Vec<Point3<f64>>,
    /// Scan units → metres.
    pub scale_to_metres: f64,
    /// Where the segment-wise fit (which uses no given landmark) puts each landmark, CAESAR
    /// order, the scan's frame and units: the prediction [`flag_given`] checks an edit against.
    pub predicted: Vec<Point3<f64>>,
    /// The part (index into `template::parts::parts`) each landmark vertex belongs to, CAESAR order.
    pub part: Vec<usize>,
    pub report: EstimateReport,
}

impl LandmarkEstimate {
    /// The landmarks as a set (scan frame and units), unplaced ones listed as missing.
    pub fn to_set(&self) -> LandmarkSet {
        let mut set = LandmarkSet::default();
        for (l, p) in CAESAR_LANDMARKS.iter().zip(&self.positions) {
            match p {
                Some(p) => set.landmarks.push(crate::landmarks::Landmark {
                    name: l.name.to_string(),
                    position: *p,
                }),
                None => set.missing.push(l.name.to_string()),
            }
        }
        set
    }
}

/// Estimates the 73 CAESAR landmarks of `input.scan` (see the module documentation).
/// `observer` hears every iteration (stage `estimate`); a `Break` cancels.
pub fn estimate_landmarks(
    input: &EstimateInput<'_>,
    params: &EstimateParams,
    observer: &mut dyn AlignObserver,
) -> Result<LandmarkEstimate, EstimateError> {
    let started = now_ms();
    params.fine.validate().map_err(EstimateError::Align)?;
    let template: Cow<Template> = match input.template.resolution() {
        Resolution::Base => Cow::Borrowed(input.template),
        _ => Cow::Owned(input.template.at_resolution(Resolution::Base)),
    };
    let rest = &template.mesh().positions;
    let triangles = &template.mesh().triangles;
    let units = input
        .units
        .unwrap_or_else(|| detect_units(bounding_extent(&input.scan.positions)));
    let to_m = units.scale_to_metres();
    let scan = input.scan.scaled(to_m);
    // Stray pieces floating off the body go first: they widened the extents the frame
    // candidates are scaled by, and a body was fitted at the wrong size (issue 31).
    let (scan, strays) = match remove_strays(&scan, 1.0, &params.strays) {
        Some((kept, removal)) => (kept, Some(removal)),
        None => (scan, None),
    };
    // A part wound inwards has its normals against the template's, and no match is made on it.
    let (scan, turned) = match face_out(&scan, &WindingParams::default()) {
        Some((out, turned)) => (out, Some(turned)),
        None => (scan, None),
    };
    let index = SurfaceIndex::new(&scan).map_err(EstimateError::Scan)?;
    let given = given_landmarks(input.given);
    let given_m: Vec<(usize, Point3<f64>)> = given.iter().map(|(i, p)| (*i, p * to_m)).collect();
    let landmark_vertices: Vec<u32> = template
        .landmark_vertices()
        .iter()
        .map(|(_, v)| *v)
        .collect();

    let weights = data_weights(&template, FineAlignParams::default().sole_weight);
    let rest_normals = template.mesh().vertex_normals();
    let matching = Matching::new(&index, params);
    // The triangulated surface only: lone points (a scanner's dust, no triangle of its own) widened
    // the extents the candidates are scaled by as stray pieces did: the zoo's `stray` scans were
    // fitted 3–6 % larger than the same bodies' `clean` ones (issue 31).
    let mut starts: Vec<(&'static str, _)> = candidates_for(
        rest,
        &triangulated(&scan.positions, &scan.triangles),
        input.orientation.as_ref(),
    )
    .ok_or(EstimateError::NoShape)?
    .into_iter()
    .map(|c| {
        let source = if input.orientation.is_some() {
            "orientation"
        } else {
            "axes"
        };
        (source, c.start)
    })
    .collect();
    // The given landmarks' own frame, when there are four or more spread over at least
    // `given_frame_parts` of the template's parts: four on one bent forearm (the landmarks the
    // self-check names for an arm posed wrongly) set a frame back to front, and the estimate failed
    // (held-out 4242 `crown-cut` subject 1, hands on hips: 522 mm).
    let parts = parts(&template);
    let spread = given_m
        .iter()
        .map(|(i, _)| dominant_part(&parts, landmark_vertices[*i]))
        .collect::<std::collections::BTreeSet<_>>()
        .len();
    let mut given_frame = None;
    if given_m.len() >= 4 && spread >= params.given_frame_parts {
        let from: Vec<_> = given_m
            .iter()
            .map(|(i, _)| rest[landmark_vertices[*i] as usize])
            .collect();
        let to: Vec<_> = given_m.iter().map(|(_, p)| *p).collect();
        if let Some(t) =
            similarity(&from, &to, true).filter(|t| t.scale > 0.0 && t.scale.is_finite())
        {
            starts.push((FROM_GIVEN, t));
            given_frame = Some(t);
        }
    }
    // Whether given landmarks, the person or the scan's shape said which way the body faces;
    // when only the fits did, how close they came is part of the self-check.
    let mut facing_said = given_frame.is_some()
        || input
            .orientation
            .as_ref()
            .is_some_and(|o| o.facing.is_some());
    // Without a frame from given landmarks, the person or else the scan's shape may say which end
    // is the head: the candidates upside down are then not fitted. Nearest points alone chose
    // upside down on a raw scan (parts, slices, the crown cut, floor remnants) by 1 % of the RMS
    // (issue 31).
    let mut up_cue = None;
    let up_said = match (&given_frame, &input.orientation) {
        (Some(_), _) => None,
        (None, Some(o)) => Some(o.up.vector()),
        (None, None) if params.head_end_decisive > 0.0 => {
            head_end(&scan.positions, &scan.triangles, params.head_end_decisive).map(|end| {
                starts.retain(|(_, t)| (t.rotation * Vector3::y()).dot(&end.up) > 0.0);
                up_cue = Some("the scan's shape");
                end.up
            })
        }
        (None, None) => None,
    };
    let mut facing_cue = None;
    // With up known and the facing not said, the feet, or the legs when the feet are cut, may say
    // which way is forward: hair or a pose had made the back-to-front fit the closer one, and a
    // scan without its feet was fitted back to front by 0.6 % (issue 31) — also when the person
    // had chosen only the up axis. The candidates left face either way along one axis, the
    // body's front-back one.
    if let Some(up) = up_said.filter(|_| !facing_said) {
        let depth = starts.first().map(|(_, t)| t.rotation * Vector3::z());
        if let Some(said) = depth.and_then(|d| {
            body_forward(
                &scan.positions,
                &scan.triangles,
                &up,
                &d,
                params.feet_forward_decisive,
                params.legs_forward_decisive,
            )
        }) {
            starts.retain(|(_, t)| (t.rotation * Vector3::z()).dot(&said.forward) > 0.0);
            facing_said = true;
            facing_cue = Some(match said.cue {
                FacingCue::Feet => "the feet",
                FacingCue::Legs => "the legs",
            });
        }
    }
    let segment_starts = if given_m.len() >= 4 {
        params.segment_starts
    } else {
        1
    };
    let max_iterations = starts.len() * (params.candidate_iterations + 1)
        + params.segment_iterations * segment_starts
        // The knees tried at each other's distance (`knees.rs`): two more runs of the last
        // iterations.
        + 2 * params.segments.profile_iterations * segment_starts
        + params.segments.swing.iterations
            * (params.segments.swing.turns_deg.len()
                + params.segments.swing.raised_turns_deg.len())
        + params.fine.max_iterations;
    let mut ticker = Ticker::new(observer, max_iterations);

    let sample = even_sample(&weights, params.candidate_samples);
    let mut fitted: Vec<(&'static str, FittedCandidate)> = Vec::new();
    for (source, start) in &starts {
        let fit = fit_similarity(
            *start,
            rest,
            &rest_normals,
            &sample,
            &matching,
            params.candidate_iterations,
            &mut ticker,
        )
        .ok_or(EstimateError::Cancelled)?;
        fitted.push((source, fit));
    }
    // Given landmarks say which way is up and which way the body faces: a candidate turned
    // away from them is not taken, however well it fits (a body with its hands on its hips fitted
    // back to front best, held-out seed 6420).
    let given_ruled = given_frame.as_ref().is_some_and(|frame| {
        fitted
            .iter()
            .any(|(_, f)| same_frame(frame, &f.transform, params.same_frame_deg))
    });
    if let Some(frame) = given_frame.as_ref().filter(|_| given_ruled) {
        fitted.retain(|(_, f)| same_frame(frame, &f.transform, params.same_frame_deg));
    }
    fitted.sort_by(|a, b| a.1.energy.total_cmp(&b.1.energy));
    let torso: Vec<u32> = sample
        .iter()
        .copied()
        .filter(|&v| template.segment_weights(v)[Segment::Torso.index()] >= 0.5)
        .collect();
    prefer_torso(
        &mut fitted,
        rest,
        &rest_normals,
        &torso,
        &matching,
        params.same_frame_deg,
        params.torso_close,
    );
    if fitted.first().is_none_or(|(_, f)| f.matched == 0.0) {
        return Err(EstimateError::NoMatch);
    }
    let facing_margin = if facing_said {
        None
    } else {
        facing_margin(&fitted, params.same_frame_deg)
    };
    // With the frame known, a floor or turntable remnant under the feet is taken off the scan
    // before the body's fit: left in, it was matched as the soles (issue 31).
    let up = fitted[0].1.transform.rotation * Vector3::y();
    let (scan, floor) = match remove_floor(&scan, &up, 1.0, &params.floor) {
        Some((kept, removal)) => (kept, Some(removal)),
        None => (scan, None),
    };
    let index = match floor {
        Some(_) => SurfaceIndex::new(&scan).map_err(EstimateError::Scan)?,
        None => index,
    };
    let matching = Matching::new(&index, params);
    let candidates_ms = now_ms() - started;

    // The best similarity fit decides the frame. Giving the two best the segment-wise fit and
    // keeping the lower energy chose the back-to-front frame on 2 of 10 subjects that this gets
    // right: the segment-wise fit can turn the limbs to fit a body the wrong way round. (Given
    // landmarks have already ruled out the candidates turned away from them.)
    let segments_start = now_ms();
    let all: Vec<u32> = (0..rest.len() as u32)
        .filter(|&v| weights[v as usize] >= 0.5)
        .step_by(2)
        .collect();
    // With given landmarks the best `params.segment_starts` are fitted: first the best candidate
    // from the scan's own axes (the one the estimate without landmarks fits), and a later one
    // kept only when its landmarks lie nearer the given ones by more than
    // `segment_start_margin` on average. A limb the fit folds against the body from one start it
    // can find from the other (held-out seed 4848 subject 21, arms down, 10 given: a wrist 45 cm
    // off); but a start nearer by a millimetre or two, or the given landmarks' own frame
    // winning the similarity fit by a little, fitted the rest of the body worse, and a partial
    // file of correct landmarks made the fit worse than none (held-out seed 5151 subject 0:
    // 4–10 given, +0.8 to +3.3 mm of correspondence error).
    let hands = hands(&template);
    let feet = feet(&template);
    let mut order: Vec<usize> = (0..fitted.len()).collect();
    if let Some(k) = fitted.iter().position(|(source, _)| *source != FROM_GIVEN) {
        order.remove(k);
        order.insert(0, k);
    }
    let given_vertices: Vec<(u32, Point3<f64>)> = given_m
        .iter()
        .map(|(i, p)| (landmark_vertices[*i], *p))
        .collect();
    let mut posed: Option<(f64, Vec<Point3<f64>>, _)> = None;
    for (_, candidate) in order.iter().take(segment_starts).map(|&k| &fitted[k]) {
        let mut fit = fit_segments(
            &template,
            &parts,
            &scan,
            candidate.transform,
            &all,
            &matching,
            &given_vertices,
            params.segment_iterations,
            &params.segments,
            &params.profile,
            &mut ticker,
        )
        .ok_or(EstimateError::Cancelled)?;
        pose_hands(&hands, &mut fit, triangles, &scan, &matching, params);
        pose_feet(&feet, &mut fit, &matching, &params.foot);
        let apart = given_m
            .iter()
            .map(|(i, p)| (fit[landmark_vertices[*i] as usize] - p).norm())
            .sum::<f64>()
            / given_m.len().max(1) as f64;
        if posed
            .as_ref()
            .is_none_or(|(nearest, _, _)| apart < *nearest - params.segment_start_margin)
        {
            posed = Some((apart, fit, candidate.transform));
        }
    }
    let Some((_, posed, best)) = posed else {
        return Err(EstimateError::NoMatch);
    };
    let posed_normals = crate::mesh::normals::vertex_normals(&posed, triangles);
    let segment_rms = Matching::rms(&matching.pairs(&all, &posed, &posed_normals));
    let fit_predicted: Vec<Point3<f64>> = landmark_vertices
        .iter()
        .map(|&v| posed[v as usize] / to_m)
        .collect();
    let landmark_rest = landmark_rest(&template);
    let landmark_part: Vec<usize> = landmark_vertices
        .iter()
        .map(|&v| dominant_part(&parts, v))
        .collect();
    let flagged = flag_given(
        &landmark_rest,
        &landmark_part,
        &given,
        &fit_predicted,
        params,
        to_m,
    );
    let segments_ms = now_ms() - segments_start;

    let fine_start = now_ms();
    let anchors: Vec<(u32, Point3<f64>)> = given_m
        .iter()
        .filter(|(i, _)| !flagged.iter().any(|f| f.name == CAESAR_LANDMARKS[*i].name))
        .map(|(i, p)| (landmark_vertices[*i], *p))
        .collect();
    ticker.start_fine();
    let fine = fine_align(
        &FineAlignInput {
            positions: &posed,
            triangles,
            scan: &index,
            weights: &weights,
            anchors: &anchors,
        },
        &params.fine,
        &mut ticker,
    )
    .map_err(EstimateError::Align)?;
    if fine.report.cancelled || ticker.cancelled {
        return Err(EstimateError::Cancelled);
    }
    let fine_ms = now_ms() - fine_start;

    // Per side (right, left): whether the fit holds that arm raised (`raised_arm_deg`).
    let raised = ShoulderFrame::both(&|k| fine.positions[landmark_vertices[k] as usize])
        .map(|frames| frames.map(|f| f.abduction_deg().is_some_and(|a| a > params.raised_arm_deg)))
        .unwrap_or([false, false]);
    let checked = check_itself(
        &fine,
        raised,
        &best,
        (&landmark_rest, &landmark_vertices),
        &parts,
        (&weights, &data_weights(&template, 0.0)),
        moved_rms_mm(&posed, &fine.positions, &weights),
        facing_margin,
        params,
    );
    let rest_template = RestTemplate {
        positions: rest,
        triangles,
        landmark_vertices: &landmark_vertices,
    };
    let acromions = place_acromions(
        &rest_template,
        &fine.positions,
        &scan,
        best.scale,
        &params.acromion,
    );
    let near = neighbourhoods(rest, &landmark_vertices, params.confidence_radius);
    let mut positions = Vec::with_capacity(CAESAR_LANDMARK_COUNT);
    let mut confidences = Vec::with_capacity(CAESAR_LANDMARK_COUNT);
    let mut is_given = Vec::with_capacity(CAESAR_LANDMARK_COUNT);
    let mut landmarks = Vec::with_capacity(CAESAR_LANDMARK_COUNT);
    for (k, &v) in landmark_vertices.iter().enumerate() {
        let name = CAESAR_LANDMARKS[k].name;
        let sharpness =
            definition_sharpness(name).expect("every CAESAR landmark has a definition sharpness");
        let given_here = given.iter().find(|(i, _)| *i == k).map(|(_, p)| *p);
        let (position, c) = match given_here {
            Some(p) => (Some(p), 1.0),
            None => {
                // The Acromions on the scan's shoulder where the search is sure (`acromion.rs`).
                let side = acromion_indices().iter().position(|&a| a == k);
                let found = side.and_then(|s| acromions[s]);
                let p = found.unwrap_or(fine.positions[v as usize]);
                let unsure = if side.is_some() && found.is_none() {
                    params.acromion.fallback_confidence
                } else {
                    1.0
                };
                let finite = p.coords.iter().all(|c| c.is_finite());
                let r = residual(
                    &fine.report.per_vertex_distance,
                    &near[k],
                    params.outlier_distance,
                );
                let arm_side = match name.get(..3) {
                    Some("Rt.") => Some(0),
                    Some("Lt.") => Some(1),
                    _ => None,
                };
                let typical = arm_side
                    .filter(|&s| raised[s])
                    .and_then(|_| raised_arm_typical_error_mm(k))
                    .unwrap_or_else(|| typical_error_mm(k));
                let c = confidence(typical / 1000.0, sharpness.spread(), r, params)
                    * checked.factor_for(name)
                    * unsure;
                (finite.then(|| p / to_m), if finite { c } else { 0.0 })
            }
        };
        landmarks.push(LandmarkReport {
            name,
            confidence: c,
            sharpness: sharpness.name(),
            given: given_here.is_some(),
            flagged: flagged.iter().any(|f| f.name == name),
        });
        positions.push(position);
        confidences.push(c);
        is_given.push(given_here.is_some());
    }

    let candidates = fitted
        .iter()
        .map(|(source, f)| CandidateReport {
            frame: FrameReport::of(&f.transform),
            source,
            rms_mm: f.energy.sqrt() * 1000.0,
            matched: f.matched,
        })
        .collect();
    let frame = FrameReport::of(&best);
    let report = EstimateReport {
        units,
        units_detected: input.units.is_none(),
        strays,
        turned,
        frame_from: FrameBasis::of(
            &frame,
            input.orientation.as_ref(),
            given_ruled,
            up_cue,
            facing_cue,
        ),
        frame,
        candidates,
        given: given.len(),
        estimated: positions.iter().flatten().count() - given.len(),
        landmarks,
        flagged,
        floor,
        self_check: checked,
        segment_rms_mm: segment_rms * 1000.0,
        fit_rms_mm: fine.report.template_to_scan.rms * 1000.0,
        iterations: ticker.iterations(),
        candidates_ms,
        segments_ms,
        fine_ms,
        total_ms: now_ms() - started,
    };
    Ok(LandmarkEstimate {
        positions,
        confidence: confidences,
        given: is_given,
        fitted: fine.positions,
        scale_to_metres: to_m,
        predicted: fit_predicted,
        part: landmark_part,
        report,
    })
}

/// The estimate's check of itself (`self_check.rs`) from its landmark-free fit `fine`, the
/// chosen frame `best`, the template's landmark vertices (at rest, and their indices), its
/// parts, its data weights (and the same without the soles, which no scanner sees: the limbs are
/// compared without them), how far the fine fit moved the template (`moved_mm`) and, when only
/// the fits chose which way the body faces, how close they came (`facing_margin`). The
/// Acromion of an arm `raised` (right, left) is left out of the sides' comparison: it is the
/// fit's guess on a shoulder with no shoulder point (`acromion.rs`), 74 mm off on average on
/// the zoo's raised arms and its confidence saying so, and the upper arm measured through it
/// called every raised-arm estimate doubtful (docs/landmarks-estimate.md).
#[allow(clippy::too_many_arguments)]
fn check_itself(
    fine: &crate::align::FineAlignResult,
    raised: [bool; 2],
    best: &crate::mesh::similarity::Similarity,
    (landmark_rest, landmark_vertices): (&[Point3<f64>], &[u32]),
    parts: &[crate::template::parts::Part],
    (weights, without_soles): (&[f64], &[f64]),
    moved_mm: f64,
    facing_margin: Option<f64>,
    params: &EstimateParams,
) -> SelfCheck {
    let part_of: Vec<usize> = (0..weights.len() as u32)
        .map(|v| dominant_part(parts, v))
        .collect();
    let part_names: Vec<&str> = parts.iter().map(|p| p.name).collect();
    let estimated: Vec<(usize, Point3<f64>)> = landmark_vertices
        .iter()
        .enumerate()
        .map(|(k, &v)| (k, fine.positions[v as usize]))
        .collect();
    let contradicting = judge_given(landmark_rest, &estimated, 1000.0, &CheckParams::default())
        .flagged
        .into_iter()
        .map(|f| f.name)
        .collect();
    let mut positions: Vec<Option<Point3<f64>>> = estimated.iter().map(|&(_, p)| Some(p)).collect();
    for (k, raised) in acromion_indices().into_iter().zip(raised) {
        if raised {
            positions[k] = None;
        }
    }
    let evidence = Evidence {
        asymmetric: asymmetries(&positions, 1000.0, params.self_check.max_bilateral_mm),
        uneven: uneven_fits(
            &fine.report.per_vertex_distance,
            without_soles,
            &part_of,
            &part_names,
            params.self_check.uneven_fit,
        ),
        fit_rms_mm: trimmed_rms_mm(&fine.report.per_vertex_distance, weights, 0.95),
        stature_m: {
            let up = best.rotation * Vector3::y();
            let heights = fine.positions.iter().map(|p| p.coords.dot(&up));
            heights.clone().fold(f64::NEG_INFINITY, f64::max)
                - heights.fold(f64::INFINITY, f64::min)
        },
        fit_moved_mm: moved_mm,
        fit_curve_mm: fine.report.curve.iter().map(|c| c.rms * 1000.0).collect(),
        contradicting,
        facing_margin,
        uncovered: Some(uncovered_scan(
            &fine.report.scan_distances,
            (parts, &part_of),
            params.self_check.uncovered.0,
        )),
        head_pitch_deg: head_pitch_deg(&|k| Some(estimated[k].1), &(best.rotation * Vector3::y()))
            .zip(head_pitch_deg(&|k| Some(landmark_rest[k]), &Vector3::y()))
            .map(|(fit, template)| fit - template),
        landmark_parts: landmark_vertices
            .iter()
            .map(|&v| part_names[dominant_part(parts, v)])
            .collect(),
    };
    self_check(&evidence, &params.self_check)
}

/// How close the best similarity fit of `fitted` (sorted, the chosen one first) and the best one
/// facing the other way with the same up came: the difference of their energies over the chosen
/// one's; `None` without such a pair.
fn facing_margin<S>(fitted: &[(S, FittedCandidate)], same_frame_deg: f64) -> Option<f64> {
    let (_, best) = fitted.first()?;
    let (_, other) = fitted.iter().skip(1).find(|(_, f)| {
        same_up(&best.transform, &f.transform, same_frame_deg)
            && !same_frame(&best.transform, &f.transform, same_frame_deg)
    })?;
    Some((other.energy - best.energy).abs() / best.energy)
}

/// RMS (m → mm) of `distance` over the `share` of the vertices with a data weight that lie
/// nearest.
fn trimmed_rms_mm(distance: &[f64], weights: &[f64], share: f64) -> f64 {
    let mut d: Vec<f64> = distance
        .iter()
        .zip(weights)
        .filter(|(_, w)| **w > 0.0)
        .map(|(d, _)| d * d)
        .collect();
    d.sort_by(f64::total_cmp);
    let kept = ((d.len() as f64 * share).ceil() as usize).clamp(1, d.len().max(1));
    (d.iter().take(kept).sum::<f64>() / kept as f64).sqrt() * 1000.0
}

/// RMS (m → mm) of `after − before` over the vertices with a data weight.
fn moved_rms_mm(before: &[Point3<f64>], after: &[Point3<f64>], weights: &[f64]) -> f64 {
    let (sum, n) = before
        .iter()
        .zip(after)
        .zip(weights)
        .filter(|(_, w)| **w > 0.0)
        .fold((0.0, 0usize), |(s, n), ((b, a), _)| {
            (s + (a - b).norm_squared(), n + 1)
        });
    (sum / n.max(1) as f64).sqrt() * 1000.0
}

/// The given landmarks (CAESAR index, position in scan units) that look wrong. A nearly full
/// set ([`NEARLY_FULL`] or more) is judged on its own by the check of a given file
/// ([`judge_given`], `check.rs`: each landmark against the other given landmarks of its rigid
/// groups, pose and all). A smaller one: each predicted from the other given landmarks of its
/// part (`landmark_rest`: the template's landmark vertices at rest, `landmark_part`: their
/// parts), or else taken from `fit_predicted` (scan units), and flagged beyond the parameters'
/// distances; twice, as a wrong landmark spoils the prediction of the others of its part, so
/// the second pass predicts from the landmarks the first did not flag. `to_m`: scan units →
/// metres. Cheap (no fit): an edit can be re-checked against the last estimate's `predicted`
/// and `part`.
pub fn flag_given(
    landmark_rest: &[Point3<f64>],
    landmark_part: &[usize],
    given: &[(usize, Point3<f64>)],
    fit_predicted: &[Point3<f64>],
    params: &EstimateParams,
    to_m: f64,
) -> Vec<SuspiciousLandmark> {
    if given.len() >= NEARLY_FULL {
        return judge_given(landmark_rest, given, to_m * 1000.0, &CheckParams::default()).flagged;
    }
    let flag = |trusted: &[(usize, Point3<f64>)]| {
        let expected = expected_positions(landmark_rest, landmark_part, trusted, fit_predicted);
        let expected: Vec<_> = expected
            .iter()
            .map(|e| {
                let metres = if e.from_given {
                    params.suspicious_distance
                } else {
                    params.suspicious_distance_fit
                };
                Some((e.position, metres / to_m))
            })
            .collect();
        flag_suspicious(given, &expected, to_m * 1000.0)
    };
    let first = flag(given);
    let trusted: Vec<(usize, Point3<f64>)> = given
        .iter()
        .filter(|(i, _)| !first.iter().any(|f| f.name == CAESAR_LANDMARKS[*i].name))
        .copied()
        .collect();
    flag(&trusted)
}
