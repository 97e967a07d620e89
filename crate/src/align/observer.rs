//! What an alignment tells its caller while it runs, and how the caller answers: [`Progress`]
//! after every L-BFGS iteration (the caller may cancel), the current surface at the start of every
//! correspondence round (so a caller that may be stopped abruptly holds the last good state).

use std::ops::ControlFlow;

use nalgebra::Point3;
use serde::Serialize;

/// Which stage of an alignment a report belongs to. A `base` template has only the base stage; a
/// `fine` template is aligned coarse to fine: the base template is fitted first, carried to fine
/// by the subdivision operator and fitted briefly there (`coarse_to_fine.rs`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Stage {
    /// Fine alignment of the base-resolution template.
    Base,
    /// The short fine alignment of the subdivided fit.
    Fine,
    /// Estimating landmarks on a bare scan (`estimate/`): frame candidates, the
    /// segment-wise fit and its landmark-free fine alignment.
    Estimate,
}

impl Stage {
    /// "base", "fine" or "estimate".
    pub fn name(self) -> &'static str {
        match self {
            Stage::Base => "base",
            Stage::Fine => "fine",
            Stage::Estimate => "estimate",
        }
    }
}

/// Sent after every L-BFGS iteration. Iterations, rounds and time count on across the stages of
/// a coarse-to-fine run.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Progress {
    /// The stage this iteration belongs to.
    pub stage: Stage,
    /// Iterations done so far (1 after the first).
    pub iteration: usize,
    /// The most iterations this run can take (both stages of coarse to fine).
    pub max_iterations: usize,
    /// Correspondence round (0-based).
    pub round: usize,
    /// The minimised objective E (with this round's weights).
    pub energy: f64,
    /// E_d = Σ w_i dist² (m²) over vertices with a data term this round (paper eq. 6).
    pub data_error: f64,
    /// E_s = Σ_edges ‖T_i − T_j‖²_F (paper eq. 7).
    pub smoothness_error: f64,
    /// RMS distance (m) of matched template vertices to their closest scan points.
    pub rms: f64,
    /// Template vertices with a data term this round.
    pub matched: usize,
    /// Milliseconds since the start of the alignment.
    pub elapsed_ms: f64,
}

/// The caller's side of a running alignment. Both methods have do-nothing defaults; `()` observes
/// nothing, and a closure `FnMut(&Progress) -> ControlFlow<()>` is an observer of progress alone.
pub trait AlignObserver {
    /// After every L-BFGS iteration; `Break` cancels, and the alignment then returns its last
    /// accepted iterate with `cancelled = true`.
    fn progress(&mut self, _progress: &Progress) -> ControlFlow<()> {
        ControlFlow::Continue(())
    }

    /// At the start of every correspondence round: the current surface (`#V` metres, template
    /// order, at the resolution being aligned — a coarse-to-fine run hands its base stage's
    /// surface carried to fine).
    fn round(&mut self, _stage: Stage, _round: usize, _positions: &[Point3<f64>]) {}
}

impl AlignObserver for () {}

impl<F: FnMut(&Progress) -> ControlFlow<()>> AlignObserver for F {
    fn progress(&mut self, progress: &Progress) -> ControlFlow<()> {
        self(progress)
    }
}
