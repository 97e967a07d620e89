//! Parameters of the alignment, each with its documented default (the one place the defaults
//! live): [`FineAlignParams`] (fine alignment, paper §3.2, with the paper's values where it gives
//! them), [`FineStageParams`] (the fine stage of coarse to fine) and [`AlignParams`] (the whole
//! pipeline: RBF warp, fine alignment, fine stage).

use super::error::AlignError;
use crate::rbf::RbfParams;
use serde::{Deserialize, Serialize};

/// How the closest point on the scan is found for a template vertex.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum CorrespondenceMode {
    /// The nearest compatible scan *vertex* (k-d tree, `kiddo`) — what the paper does with ANN.
    NearestVertex,
    /// The nearest compatible scan vertex, then the closest point on the triangles around it:
    /// point-on-surface accuracy for the price of a k-d tree query (the default; see
    /// docs/fine-alignment.md for the measurements).
    VertexOneRing,
    /// The exact closest point on any scan triangle (BVH, `parry3d-f64`); when its triangle's
    /// normal is incompatible, falls back to [`CorrespondenceMode::VertexOneRing`].
    ClosestOnTriangle,
}

/// Parameters of [`crate::align::fine_align`], with the defaults of the pipeline. Lengths are in
/// metres.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct FineAlignParams {
    /// Weight `a` of the data error E_d (paper eq. 8, Fig. 9: 0.96).
    pub a: f64,
    /// Weight `b` of the smoothness error E_s (paper eq. 8, Fig. 9: 0.04).
    pub b: f64,
    /// Mean template edge length (m) at which `a`, `b` mean exactly what they mean in the paper;
    /// E_d is scaled by (h̄ / reference_edge_length)² so the balance carries across resolutions
    /// (docs/fine-alignment.md derives it). Default 3.7 mm, the paper's 328K-triangle template.
    pub reference_edge_length: f64,
    /// Limit on L-BFGS iterations over all rounds (each reports progress once).
    pub max_iterations: usize,
    /// L-BFGS iterations between two correspondence searches. Default 2: re-finding matches
    /// often keeps vertices from sliding along stale targets (10 subjects: correspondence 6.70 →
    /// 6.01 mm against 10 per round, with the tolerance below; docs/fine-alignment.md).
    pub iterations_per_round: usize,
    /// Stop when a round lowers E by less than this fraction of E.
    pub relative_tolerance: f64,
    /// Stop when the RMS displacement of the template vertices over one round falls below this
    /// (metres): the surface has stopped moving even if E still creeps down by sliding. Default
    /// 1 mm: after annealing a round moves the surface ≈ 0.3 mm, almost all tangential sliding
    /// that makes the correspondence worse, so the fit stops as soon as annealing is over
    /// (≈ 28 iterations instead of 200 on the synthetic subjects).
    pub displacement_tolerance: f64,
    /// L-BFGS memory m (pairs of correction vectors kept).
    pub lbfgs_memory: usize,
    /// How correspondences are searched.
    pub correspondence: CorrespondenceMode,
    /// Reject a match whose scan normal is more than `max_normal_angle_deg` from the template
    /// vertex normal (paper §3.2.1, "to avoid the two legs get bridged").
    pub normal_compatibility: bool,
    /// Largest angle (degrees) between template and scan normals of a match.
    pub max_normal_angle_deg: f64,
    /// How many nearest scan vertices are tried, nearest first, for a compatible normal.
    pub candidates: usize,
    /// A vertex whose match lies on a hole rim gets no data term that round (paper §3.2.1).
    pub skip_boundary_matches: bool,
    /// Matches farther than this (m) are ignored that round; `f64::INFINITY` keeps all (JSON
    /// writes infinity as `null` and reads `null` back as infinity).
    #[serde(deserialize_with = "infinity_if_null")]
    pub max_match_distance: f64,
    /// Stiffness annealing (Amberg et al. 2007 style; not in the paper): E_s is weighted by b·s_r
    /// in round r, with s_r = max(1, initial_stiffness·stiffness_decay^r); 1.0 switches annealing
    /// off. Default 100 with decay 0.7 (13 stiff rounds ending at the paper's b): measured on 10
    /// synthetic subjects it lowers the scan→template RMS 1.65 → 1.43 mm (docs/fine-alignment.md).
    pub initial_stiffness: f64,
    /// Factor by which the stiffness multiplier shrinks per round (0 < decay ≤ 1). Default 0.7.
    pub stiffness_decay: f64,
    /// Weight of the landmark anchors ([`crate::align::FineAlignInput::anchors`]) relative to
    /// the data weight 1 of a vertex: an anchored vertex is also pulled towards its landmark by
    /// a·κ·landmark_weight·‖T_i v_i − L_i‖² (an addition to the paper, which drops the markers
    /// after the RBF warp; docs/fine-alignment.md measures it). Default 0: anchoring off.
    pub landmark_weight: f64,
    /// Weight of the scan-to-template term E_r (`scan_term.rs`; not in the paper) relative to
    /// E_d: its samples together carry `scan_term_weight` times the total data weight of the
    /// template vertices. 0 switches it off (the paper's energy). Default 1: on 10 synthetic
    /// subjects it lowers the scan→template RMS 1.44 → 0.97 mm (the mean signed error 0.55 →
    /// 0.06 mm) and the correspondence error 6.01 → 5.85 mm (docs/fine-alignment.md).
    pub scan_term_weight: f64,
    /// Scan vertices sampled for E_r (every k-th surface vertex, at most this many). Default
    /// 20,000: 40,000 gave 0.93 mm instead of 0.97 for twice the search time.
    pub scan_term_samples: usize,
    /// E_r is used from the round whose stiffness multiplier has fallen to this value or below
    /// (1.0: only once annealing is over; `initial_stiffness` or more: from the first round, the
    /// default — from the first round the correspondence error is 0.06 mm lower than from 1.0).
    pub scan_term_from_stiffness: f64,
    /// Scan samples farther than this (m) from the template get no E_r term that round.
    pub scan_term_max_distance: f64,
    /// Weight μ/(a·κ) of the tangential term (`energy.rs`, not in the paper): each vertex is held
    /// along the surface near where the RBF warp put it, free across it. 0 switches it off.
    pub tangential_weight: f64,
    /// Data weight of the soles (region flag `sole`; never seen by a standing scanner). 1 in the
    /// paper's method; 0 lets them follow their neighbours through E_s alone.
    pub sole_weight: f64,
    /// After the fit, vertices with data weight 0 (never-scanned regions) take the harmonic
    /// extension of their neighbours' transforms (`follow.rs`): they move rigidly with what
    /// surrounds them instead of lagging. Off in the paper's method.
    pub unseen_follow_neighbours: bool,
}

/// Reads a length where JSON `null` (how serde_json writes infinity) means infinity.
fn infinity_if_null<'de, D: serde::Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
    Ok(Option::<f64>::deserialize(d)?.unwrap_or(f64::INFINITY))
}

impl Default for FineAlignParams {
    fn default() -> Self {
        Self {
            a: 0.96,
            b: 0.04,
            reference_edge_length: 0.0037,
            max_iterations: 200,
            iterations_per_round: 2,
            relative_tolerance: 1e-4,
            displacement_tolerance: 1e-3,
            lbfgs_memory: 7,
            correspondence: CorrespondenceMode::VertexOneRing,
            normal_compatibility: true,
            max_normal_angle_deg: 60.0,
            candidates: 8,
            skip_boundary_matches: true,
            max_match_distance: f64::INFINITY,
            initial_stiffness: 100.0,
            stiffness_decay: 0.7,
            landmark_weight: 0.0,
            scan_term_weight: 1.0,
            scan_term_samples: 20_000,
            scan_term_from_stiffness: 100.0,
            scan_term_max_distance: 0.02,
            tangential_weight: 0.0,
            sole_weight: 1.0,
            unseen_follow_neighbours: false,
        }
    }
}

impl FineAlignParams {
    /// Checks every parameter's range; the first bad one is reported. Lengths are metres.
    pub fn validate(&self) -> Result<(), AlignError> {
        let p = self;
        positive("a", p.a)?;
        positive("b", p.b)?;
        positive("reference_edge_length", p.reference_edge_length)?;
        within(
            "iterations_per_round",
            p.iterations_per_round as f64,
            1.0,
            1e9,
        )?;
        within("lbfgs_memory", p.lbfgs_memory as f64, 1.0, 64.0)?;
        at_least("relative_tolerance", p.relative_tolerance, 0.0)?;
        at_least("displacement_tolerance", p.displacement_tolerance, 0.0)?;
        within("max_normal_angle_deg", p.max_normal_angle_deg, 0.0, 180.0)?;
        within("candidates", p.candidates as f64, 1.0, 256.0)?;
        positive_or_infinite("max_match_distance", p.max_match_distance)?;
        at_least("initial_stiffness", p.initial_stiffness, 1.0)?;
        within("stiffness_decay", p.stiffness_decay, f64::MIN_POSITIVE, 1.0)?;
        at_least("landmark_weight", p.landmark_weight, 0.0)?;
        at_least("scan_term_weight", p.scan_term_weight, 0.0)?;
        at_least("scan_term_from_stiffness", p.scan_term_from_stiffness, 1.0)?;
        at_least("tangential_weight", p.tangential_weight, 0.0)?;
        within("sole_weight", p.sole_weight, 0.0, 1.0)?;
        positive_or_infinite("scan_term_max_distance", p.scan_term_max_distance)
    }
}

/// `Ok` when `ok`, else the error naming the parameter, its value and `reason()`.
fn check(
    name: &'static str,
    value: f64,
    ok: bool,
    reason: impl FnOnce() -> String,
) -> Result<(), AlignError> {
    match ok {
        true => Ok(()),
        false => Err(AlignError::BadParameter {
            name,
            value,
            reason: reason(),
        }),
    }
}

/// `value` is finite and > 0.
fn positive(name: &'static str, value: f64) -> Result<(), AlignError> {
    let ok = value.is_finite() && value > 0.0;
    check(name, value, ok, || "must be finite and > 0".into())
}

/// `value` is finite and ≥ `min`.
fn at_least(name: &'static str, value: f64, min: f64) -> Result<(), AlignError> {
    let ok = value.is_finite() && value >= min;
    check(name, value, ok, || format!("must be finite and ≥ {min}"))
}

/// `lo` ≤ `value` ≤ `hi` (`lo` = `f64::MIN_POSITIVE` reads as "> 0").
fn within(name: &'static str, value: f64, lo: f64, hi: f64) -> Result<(), AlignError> {
    check(name, value, (lo..=hi).contains(&value), || {
        match lo == f64::MIN_POSITIVE {
            true => format!("must be > 0 and ≤ {hi}"),
            false => format!("must be ≥ {lo} and ≤ {hi}"),
        }
    })
}

/// `value` is > 0, infinity allowed.
fn positive_or_infinite(name: &'static str, value: f64) -> Result<(), AlignError> {
    let ok = !value.is_nan() && value > 0.0;
    check(name, value, ok, || "must be > 0 or infinity".into())
}

/// The schedule of the fine stage. Its energy (a, b, the treatments, the landmark and
/// scan-to-template weights, the correspondence search) is the base stage's; how long and how
/// stiffly it runs, and how strongly it holds vertices along the surface, differ. Defaults: no
/// stiffness annealing (the base stage has done it), 2 iterations per round, at most 8
/// iterations, stop when a round moves the surface by less than 0.1 mm RMS, L-BFGS memory 3 (the
/// fine level has 16× the unknowns; memory 7 would hold ≈ 390 MB of correction pairs),
/// tangential term 10 (vertices held along the carried base fit: the fine stage adds detail
/// across the surface without sliding the base correspondence).
/// Measured in docs/fine-alignment.md, "Coarse to fine", and docs/benchmarks.md, "Held-out
/// population".
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct FineStageParams {
    /// Limit on the fine stage's L-BFGS iterations.
    pub max_iterations: usize,
    /// L-BFGS iterations between two correspondence searches.
    pub iterations_per_round: usize,
    /// Stop when a round moves the surface by less than this RMS (metres).
    pub displacement_tolerance: f64,
    /// L-BFGS memory m.
    pub lbfgs_memory: usize,
    /// Stiffness annealing of the fine stage (1.0: none), as in [`FineAlignParams`].
    pub initial_stiffness: f64,
    /// Factor by which the stiffness multiplier shrinks per round.
    pub stiffness_decay: f64,
    /// Weight of the tangential term in the fine stage (replaces the base stage's
    /// [`FineAlignParams::tangential_weight`]): each vertex is held along the carried base fit,
    /// free across it, so the fine stage adds detail without sliding the base correspondence.
    pub tangential_weight: f64,
}

impl Default for FineStageParams {
    fn default() -> Self {
        Self {
            max_iterations: 8,
            iterations_per_round: 2,
            displacement_tolerance: 1e-4,
            lbfgs_memory: 3,
            initial_stiffness: 1.0,
            stiffness_decay: 0.7,
            tangential_weight: 10.0,
        }
    }
}

impl FineStageParams {
    /// The fine stage's full parameters: `base`'s energy with this schedule.
    pub fn around(&self, base: &FineAlignParams) -> FineAlignParams {
        FineAlignParams {
            max_iterations: self.max_iterations,
            iterations_per_round: self.iterations_per_round,
            displacement_tolerance: self.displacement_tolerance,
            lbfgs_memory: self.lbfgs_memory,
            initial_stiffness: self.initial_stiffness,
            stiffness_decay: self.stiffness_decay,
            tangential_weight: self.tangential_weight,
            ..base.clone()
        }
    }
}

/// A named starting set of parameters, so a user can compare the paper's method with ours; the
/// report carries the name ([`AlignParams::preset`]).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Preset {
    /// The paper's energy E = a·E_d + b·E_s with its special treatments (data weight 0.1 on hands
    /// and ears, normal compatibility, no matches on hole rims), with the schedule and the
    /// scan-to-template term E_r this project added before issue 12 (stiffness annealing,
    /// 2 iterations per round, displacement stop). The default: today's figures.
    #[default]
    Paper,
    /// `paper` plus what issue 12 kept: head and arms posed to the scan's landmarks before the
    /// RBF warp (`pose_parts`), the tangential term (weight 0.1) holding vertices along the
    /// RBF-warped surface, never-scanned regions following their neighbours, b = 0.1, no match
    /// farther than 20 mm (a vertex the scanner never saw, e.g. under the chin, is not pulled
    /// across the gap to the neck). Lower mean, 95th percentile and largest correspondence errors
    /// on the held-out population (docs/benchmarks.md, "Held-out population").
    Anchored,
}

impl Preset {
    pub const ALL: [Preset; 2] = [Preset::Paper, Preset::Anchored];

    /// The preset's name on the command line and in reports.
    pub fn name(self) -> &'static str {
        match self {
            Preset::Paper => "paper",
            Preset::Anchored => "anchored",
        }
    }

    /// The preset called `name`.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|p| p.name() == name)
    }

    /// The preset's parameters.
    pub fn params(self) -> AlignParams {
        let paper = AlignParams::default();
        match self {
            Preset::Paper => paper,
            Preset::Anchored => AlignParams {
                preset: self,
                pose_parts: true,
                fine: FineAlignParams {
                    b: 0.1,
                    tangential_weight: 0.1,
                    unseen_follow_neighbours: true,
                    max_match_distance: 0.02,
                    ..paper.fine
                },
                ..paper
            },
        }
    }
}

/// Every parameter of the pipeline, each with its documented default (the defaults live in the
/// `Default` impls of the parts, and nowhere else: the CLI and the app read them from here).
/// Absent fields of a JSON object keep their defaults.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct AlignParams {
    /// The preset these parameters started from (`paper` by default).
    pub preset: Preset,
    /// Pose the template's parts to the scan's landmarks before the RBF warp
    /// ([`crate::align::part_pose`]; not in the paper). Off in `paper`.
    pub pose_parts: bool,
    /// The RBF warp (paper §3.1).
    pub rbf: RbfParams,
    /// Fine alignment (paper §3.2) — at `fine`, of its base stage.
    pub fine: FineAlignParams,
    /// At `fine`: the schedule of the short fine stage after the base fit.
    pub fine_stage: FineStageParams,
    /// Stop after the RBF warp.
    pub rough_only: bool,
}

impl AlignParams {
    /// Checks the fine-alignment parameters of both stages (the RBF parameters are checked by
    /// the warp itself, before any work).
    pub fn validate(&self) -> Result<(), AlignError> {
        self.fine.validate()?;
        self.fine_stage.around(&self.fine).validate()
    }
}
