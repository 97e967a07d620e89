//! Quality flags of one finished alignment, for screening a population without looking at every
//! fit: a fit is *flagged* when one of the measures below passes its threshold. Pure functions of
//! an [`Alignment`] (and the base template's triangles); thresholds, their reasons and the
//! measurements behind them are in docs/batch.md.
//!
//! 1. [`QualityFlag::HighRms`] — scan → template RMS (the paper's Table 1 measure) above
//!    `max_rms_mm`: the template missed part of the body.
//! 2. [`QualityFlag::Unmatched`] — too many weighted template vertices had no usable scan match
//!    (incompatible normal, hole rim, too far) in the last correspondence round: those vertices
//!    were only carried by smoothness, so a large share means the scan is missing a region or
//!    the fit slid off it.
//! 3. [`QualityFlag::FoldOvers`] — template triangles whose normal turned against the same
//!    triangle of the RBF-warped template: fine alignment folded the surface over itself.
//! 4. [`QualityFlag::UncoveredScan`] — too large a share of the scan's vertices lies farther than
//!    `uncovered_mm` from the fit: part of the body (a hand, a forearm) was not reached by the
//!    template, which lies on the scan elsewhere; the template → scan measures cannot see it, and
//!    the RMS hardly moves (0.4 mm on the case that found it). Its report names the template part
//!    nearest most of the uncovered scan.
//! 5. [`QualityFlag::UnevenLimb`] — a limb's part (upper arm, forearm with the hand, thigh, lower
//!    leg with the foot) lies much farther from the scan than the same part on the other side
//!    (`uneven_fit.rs`; the soles, which no scanner sees, left out): a foot left beside its scan, an
//!    arm posed wrongly. The body's RMS hides it (+0.07 mm on the case that found it); the report
//!    names the part and both sides' RMS.
//! 6. [`QualityFlag::SuspiciousLandmarks`] — given landmarks far from where the others of their
//!    part (or the landmark estimate's fit) put them (`estimate/suspicious.rs`): a
//!    swapped Lt./Rt. pair, a typo, a landmark on the wrong body part. The caller that checked the
//!    landmarks adds it with [`QualityReport::add_suspicious_landmarks`]; the warp ran without
//!    them.

use nalgebra::Point3;
use serde::{Deserialize, Serialize};

use super::pipeline::Alignment;
use super::report::ScanDistance;
use super::uneven_fit::{uneven_fits, UnevenFit};
use super::weights::data_weights;
use crate::template::parts::{dominant_part, parts, Part};
use crate::template::Template;

/// Thresholds of the quality flags, with the defaults docs/batch.md justifies.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct QualityThresholds {
    /// Flag a fit whose scan → template RMS exceeds this (mm). Default 2 mm: good fits of the
    /// synthetic subjects (1 mm scanner noise) measure 0.95–0.99 mm (20 subjects), a fit driven
    /// by left/right-swapped landmarks 7.1 mm; 2 mm is twice the noise floor of a good fit.
    pub max_rms_mm: f64,
    /// Flag a fit where more than this fraction of the weighted template vertices had no data
    /// match in the last round. Default 0.65: good fits of the synthetic scans leave 0.48–0.53
    /// unmatched (their many small holes: matches on hole rims are skipped), the swapped-landmark
    /// fit 0.92. Depends on the scanner: calibrate on a few good fits of yours (docs/batch.md).
    pub max_unmatched_fraction: f64,
    /// Flag a fit where more than this fraction of the (base) template triangles flipped
    /// against the RBF-warped template. Default 0.03 (3 %, ≈ 800 of 26,756 triangles): good
    /// fits flip 0.5–1.3 %, a scan missing a leg 6.6 %, swapped landmarks 7.1 %.
    pub max_folded_fraction: f64,
    /// A scan vertex farther than this from the fit is uncovered (mm). Default 20 mm: on good
    /// fits of the tuning seeds (2026, 101, 202 and the zoo's 4242) at most 6 scan vertices lie
    /// that far, from scans of 13K to 820K vertices.
    pub uncovered_mm: f64,
    /// Flag a fit where more than this share of the scan's vertices is uncovered. Default 0.0004
    /// (0.4 ‰): good tuning fits 0–0.09 ‰, a fit whose left hand missed the scan's 0.89 ‰
    /// (docs/batch.md).
    pub max_uncovered_share: f64,
    /// Flag a fit where a limb's part lies more than this many times farther from the scan (RMS
    /// over its vertices, soles left out) than the same part on the other side, ...
    pub uneven_limb_ratio: f64,
    /// ... and farther by more than this (mm). Defaults 2.5 and 5 mm: good fits of the tuning
    /// seeds differ by at most 1.8 times and 2.4 mm; a foot the fit left beside its scan 3.1
    /// times and 13 mm (docs/batch.md).
    pub uneven_limb_mm: f64,
}

impl Default for QualityThresholds {
    fn default() -> Self {
        Self {
            max_rms_mm: 2.0,
            max_unmatched_fraction: 0.65,
            max_folded_fraction: 0.03,
            uncovered_mm: 20.0,
            max_uncovered_share: 0.0004,
            uneven_limb_ratio: 2.5,
            uneven_limb_mm: 5.0,
        }
    }
}

/// One reason to look at a fit again.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum QualityFlag {
    /// Scan → template RMS above [`QualityThresholds::max_rms_mm`].
    HighRms,
    /// Unmatched weighted vertices above [`QualityThresholds::max_unmatched_fraction`].
    Unmatched,
    /// Flipped triangles above [`QualityThresholds::max_folded_fraction`].
    FoldOvers,
    /// Uncovered scan above [`QualityThresholds::max_uncovered_share`].
    UncoveredScan,
    /// A limb's part much farther from the scan than on the other side
    /// ([`QualityThresholds::uneven_limb_ratio`], [`QualityThresholds::uneven_limb_mm`]).
    UnevenLimb,
    /// Given landmarks that look wrong (listed in [`QualityReport::suspicious_landmarks`]).
    SuspiciousLandmarks,
    /// The landmark estimate the warp used called itself doubtful or failed (its reasons in
    /// [`QualityReport::landmark_estimate`]).
    LandmarkEstimate,
}

impl QualityFlag {
    /// The flag's name as written in reports and manifests.
    pub fn name(self) -> &'static str {
        match self {
            Self::HighRms => "high_rms",
            Self::Unmatched => "unmatched",
            Self::FoldOvers => "fold_overs",
            Self::UncoveredScan => "uncovered_scan",
            Self::UnevenLimb => "uneven_limb",
            Self::SuspiciousLandmarks => "suspicious_landmarks",
            Self::LandmarkEstimate => "landmark_estimate",
        }
    }
}

/// The measures behind the flags, and the flags raised.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct QualityReport {
    /// Scan → template RMS (mm); `None` without fine alignment.
    pub rms_mm: Option<f64>,
    /// Template vertices with a data weight.
    pub weighted_vertices: usize,
    /// Of those, the ones without a data match in the last round.
    pub unmatched_vertices: usize,
    pub unmatched_fraction: f64,
    /// Base template triangles compared with the warped template.
    pub compared_triangles: usize,
    /// Of those, the ones whose normal points against the warped triangle's.
    pub folded_triangles: usize,
    pub folded_fraction: f64,
    /// Scan vertices compared with the fit.
    pub scan_vertices: usize,
    /// Of those, the ones farther than [`QualityThresholds::uncovered_mm`] from it.
    pub uncovered_scan_vertices: usize,
    pub uncovered_share: f64,
    /// The template part (`template::parts`: `left forearm`, `head`, …) nearest most of the
    /// uncovered scan vertices; `None` when there are none.
    pub uncovered_near: Option<String>,
    /// The limb parts that fit much farther from the scan than on the other side, with both
    /// sides' RMS (mm).
    pub uneven_limbs: Vec<UnevenFit>,
    /// Given landmarks that looked wrong and were left out of the warp (names).
    pub suspicious_landmarks: Vec<String>,
    /// Why the landmark estimate the warp used doubts itself, in words, and the landmarks to
    /// check first ("check first: …", `SelfCheck::check_first`) (empty: it did not, or none ran).
    pub landmark_estimate: Vec<String>,
    /// The flags raised, in [`QualityFlag`] order (empty: the fit looks good).
    pub flags: Vec<QualityFlag>,
    pub thresholds: QualityThresholds,
}

impl QualityReport {
    /// Records the given landmarks found suspicious (by name) and raises
    /// [`QualityFlag::SuspiciousLandmarks`] when there are any.
    pub fn add_suspicious_landmarks(&mut self, names: Vec<String>) {
        if !names.is_empty() && !self.flags.contains(&QualityFlag::SuspiciousLandmarks) {
            self.flags.push(QualityFlag::SuspiciousLandmarks);
        }
        self.suspicious_landmarks = names;
    }

    /// Records why the landmark estimate the warp used doubts itself and raises
    /// [`QualityFlag::LandmarkEstimate`] when it does.
    pub fn add_landmark_estimate(&mut self, reasons: Vec<String>) {
        if !reasons.is_empty() && !self.flags.contains(&QualityFlag::LandmarkEstimate) {
            self.flags.push(QualityFlag::LandmarkEstimate);
        }
        self.landmark_estimate = reasons;
    }
}

/// Counts the triangles of `triangles` (indices into both position lists) whose normal in
/// `fitted` points against (dot product < 0) their normal in `warped`; triangles degenerate in
/// either are not compared. Returns (compared, folded).
///
/// `warped` and `fitted` are `#V` positions of the same vertices; `fitted` may be longer (the
/// fine template, whose base vertices come first): only the first `warped.len()` are read.
pub fn folded_triangles(
    triangles: &[[u32; 3]],
    warped: &[Point3<f64>],
    fitted: &[Point3<f64>],
) -> (usize, usize) {
    let n = warped.len().min(fitted.len());
    let normal = |p: &[Point3<f64>], t: &[u32; 3]| {
        let [a, b, c] = t.map(|i| p[i as usize]);
        (b - a).cross(&(c - a))
    };
    let (mut compared, mut folded) = (0, 0);
    for t in triangles {
        if t.iter().any(|&i| i as usize >= n) {
            continue;
        }
        let (w, f) = (normal(warped, t), normal(fitted, t));
        if w.norm_squared() == 0.0 || f.norm_squared() == 0.0 {
            continue;
        }
        compared += 1;
        if w.dot(&f) < 0.0 {
            folded += 1;
        }
    }
    (compared, folded)
}

/// The quality of `alignment`: its fine report's RMS and matched vertices, fold-overs of the
/// `base` template's triangles (which index the warped template and the first vertices of the fit
/// at either resolution) between `alignment.warped` and `alignment.positions`, and the scan the
/// fit left uncovered, named by `base`'s parts, and each limb part's distance to the scan against
/// the other side's.
pub fn assess(
    alignment: &Alignment,
    base: &Template,
    thresholds: &QualityThresholds,
) -> QualityReport {
    let fine = alignment.report.fine.as_ref();
    let rms_mm = fine.map(|f| f.scan_to_template.rms_mm);
    let weighted_vertices = fine.map_or(0, |f| f.template_to_scan.count);
    let unmatched_vertices = fine.map_or(0, |f| {
        f.template_to_scan.count.saturating_sub(f.matched_vertices)
    });
    let fraction = |part: usize, whole: usize| {
        if whole == 0 {
            0.0
        } else {
            part as f64 / whole as f64
        }
    };
    let unmatched_fraction = fraction(unmatched_vertices, weighted_vertices);
    let (compared_triangles, folded) = folded_triangles(
        &base.mesh().triangles,
        &alignment.warped,
        &alignment.positions,
    );
    let folded_fraction = fraction(folded, compared_triangles);
    let parts = parts(base);
    let part_of: Vec<usize> = (0..base.mesh().vertex_count() as u32)
        .map(|v| dominant_part(&parts, v))
        .collect();
    let uncovered = uncovered_scan(
        &alignment.scan_distances,
        (&parts, &part_of),
        thresholds.uncovered_mm,
    );
    let uneven_limbs = uneven_limbs(alignment, base, (&parts, &part_of), thresholds);
    let flags = [
        (
            rms_mm.is_some_and(|r| r.is_nan() || r > thresholds.max_rms_mm),
            QualityFlag::HighRms,
        ),
        (
            unmatched_fraction > thresholds.max_unmatched_fraction,
            QualityFlag::Unmatched,
        ),
        (
            folded_fraction > thresholds.max_folded_fraction,
            QualityFlag::FoldOvers,
        ),
        (
            uncovered.share > thresholds.max_uncovered_share,
            QualityFlag::UncoveredScan,
        ),
        (!uneven_limbs.is_empty(), QualityFlag::UnevenLimb),
    ]
    .into_iter()
    .filter_map(|(raised, flag)| raised.then_some(flag))
    .collect();
    QualityReport {
        rms_mm,
        weighted_vertices,
        unmatched_vertices,
        unmatched_fraction,
        compared_triangles,
        folded_triangles: folded,
        folded_fraction,
        scan_vertices: alignment.scan_distances.len(),
        uncovered_scan_vertices: uncovered.vertices,
        uncovered_share: uncovered.share,
        uncovered_near: uncovered.near,
        uneven_limbs,
        suspicious_landmarks: Vec::new(),
        landmark_estimate: Vec::new(),
        flags,
        thresholds: *thresholds,
    }
}

/// The limb parts of `base` (its `parts`, and each vertex's dominant part `part_of`) whose fit in
/// `alignment` lies much farther from the scan than on the other side: the RMS of the template →
/// scan distances over each part's vertices with a data weight, the soles left out (no scanner
/// sees them; on good fits they make a lower leg's RMS 4–7 mm).
fn uneven_limbs(
    alignment: &Alignment,
    base: &Template,
    (parts, part_of): (&[Part], &[usize]),
    thresholds: &QualityThresholds,
) -> Vec<UnevenFit> {
    let names: Vec<&str> = parts.iter().map(|p| p.name).collect();
    uneven_fits(
        &alignment.per_vertex_distance,
        &data_weights(base, 0.0),
        part_of,
        &names,
        (thresholds.uneven_limb_ratio, thresholds.uneven_limb_mm),
    )
}

/// The scan a fit left uncovered: its vertices farther than `uncovered_mm` from the fit, of
/// `scan_distances` (each scan vertex's distance to the fit and the template vertex nearest it).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Uncovered {
    pub vertices: usize,
    /// `vertices` as a share of the scan's vertices (0 for no scan).
    pub share: f64,
    /// The template part (of `parts`) nearest most of them; `None` when there are none.
    pub near: Option<String>,
}

/// The scan the fit left uncovered ([`Uncovered`]), with `part_of` each template vertex's
/// dominant part of `parts`.
pub fn uncovered_scan(
    scan_distances: &[ScanDistance],
    (parts, part_of): (&[Part], &[usize]),
    uncovered_mm: f64,
) -> Uncovered {
    let nearest: Vec<u32> = scan_distances
        .iter()
        .filter(|s| s.distance.abs() * 1000.0 > uncovered_mm)
        .map(|s| s.nearest_vertex)
        .collect();
    Uncovered {
        vertices: nearest.len(),
        share: if scan_distances.is_empty() {
            0.0
        } else {
            nearest.len() as f64 / scan_distances.len() as f64
        },
        near: nearest_part((parts, part_of), &nearest),
    }
}

/// The name of the part (of `parts`, each vertex in its dominant part `part_of`) that holds most
/// of `vertices` (template indices; others are ignored); `None` when none does.
fn nearest_part((parts, part_of): (&[Part], &[usize]), vertices: &[u32]) -> Option<String> {
    let mut count = vec![0usize; parts.len()];
    for &v in vertices {
        if let Some(&p) = part_of.get(v as usize) {
            count[p] += 1;
        }
    }
    let most = (0..parts.len()).max_by_key(|&p| count[p])?;
    (count[most] > 0).then(|| parts[most].name.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square() -> (Vec<[u32; 3]>, Vec<Point3<f64>>) {
        let p = vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(1.0, 1.0, 0.0),
            Point3::new(0.0, 1.0, 0.0),
        ];
        (vec![[0, 1, 2], [0, 2, 3]], p)
    }

    #[test]
    fn an_unchanged_or_moved_surface_has_no_fold_overs() {
        let (t, p) = square();
        assert_eq!(folded_triangles(&t, &p, &p), (2, 0));
        let moved: Vec<_> = p.iter().map(|q| q * 2.0 + nalgebra::Vector3::z()).collect();
        assert_eq!(folded_triangles(&t, &p, &moved), (2, 0));
    }

    #[test]
    fn a_vertex_pulled_across_its_opposite_edge_folds_one_triangle() {
        let (t, p) = square();
        let mut fitted = p.clone();
        // Vertex 3 crosses the diagonal 0–2: triangle [0, 2, 3] turns over, [0, 1, 2] does not.
        fitted[3] = Point3::new(0.8, 0.2, 0.0);
        assert_eq!(folded_triangles(&t, &p, &fitted), (2, 1));
    }

    #[test]
    fn degenerate_and_out_of_range_triangles_are_not_compared() {
        let (mut t, p) = square();
        t.push([0, 0, 1]);
        t.push([0, 1, 7]);
        assert_eq!(folded_triangles(&t, &p, &p), (2, 0));
        // A longer fit (fine template): only the first warped.len() vertices are read.
        let mut longer = p.clone();
        longer.push(Point3::new(9.0, 9.0, 9.0));
        assert_eq!(folded_triangles(&t, &p, &longer), (2, 0));
    }

    #[test]
    fn thresholds_survive_partial_json() {
        let t: QualityThresholds = serde_json::from_str(r#"{"max_rms_mm": 3.5}"#).unwrap();
        assert_eq!(t.max_rms_mm, 3.5);
        assert_eq!(
            t.max_folded_fraction,
            QualityThresholds::default().max_folded_fraction
        );
        assert_eq!(QualityFlag::FoldOvers.name(), "fold_overs");
    }
}
