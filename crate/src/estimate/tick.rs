//! The estimate's progress through the caller's [`AlignObserver`]: one [`Progress`] of stage
//! [`Stage::Estimate`] per ICP iteration and per iteration of the landmark-free fine alignment,
//! counted on across the steps; a `Break` from the caller cancels the estimate.

use std::ops::ControlFlow;

use crate::align::{AlignObserver, Progress, Stage};
use crate::utils::now_ms;

/// Counts iterations across the estimate's steps and forwards them to the caller.
pub struct Ticker<'a> {
    observer: &'a mut dyn AlignObserver,
    iteration: usize,
    /// Iterations already done when the current fine alignment started.
    offset: usize,
    max_iterations: usize,
    started: f64,
    /// Set once the caller asked to stop.
    pub cancelled: bool,
}

impl<'a> Ticker<'a> {
    /// A ticker for an estimate of at most `max_iterations` iterations in all.
    pub fn new(observer: &'a mut dyn AlignObserver, max_iterations: usize) -> Self {
        Self {
            observer,
            iteration: 0,
            offset: 0,
            max_iterations,
            started: now_ms(),
            cancelled: false,
        }
    }

    /// One ICP iteration: `rms` (m) of the matches, `matched` vertices.
    pub fn tick(&mut self, rms: f64, matched: usize) -> ControlFlow<()> {
        self.iteration += 1;
        let progress = Progress {
            stage: Stage::Estimate,
            iteration: self.iteration,
            max_iterations: self.max_iterations,
            round: 0,
            energy: rms * rms,
            data_error: rms * rms,
            smoothness_error: 0.0,
            rms,
            matched,
            elapsed_ms: now_ms() - self.started,
        };
        self.forward(&progress)
    }

    /// Iterations so far.
    pub fn iterations(&self) -> usize {
        self.iteration
    }

    /// Marks the start of a fine alignment, whose own iteration count starts at 1.
    pub fn start_fine(&mut self) {
        self.offset = self.iteration;
    }

    fn forward(&mut self, progress: &Progress) -> ControlFlow<()> {
        let flow = self.observer.progress(progress);
        if flow.is_break() {
            self.cancelled = true;
        }
        flow
    }
}

impl AlignObserver for Ticker<'_> {
    fn progress(&mut self, progress: &Progress) -> ControlFlow<()> {
        self.iteration = self.offset + progress.iteration;
        let relabelled = Progress {
            stage: Stage::Estimate,
            iteration: self.iteration,
            max_iterations: self.max_iterations,
            elapsed_ms: now_ms() - self.started,
            ..*progress
        };
        self.forward(&relabelled)
    }
}
