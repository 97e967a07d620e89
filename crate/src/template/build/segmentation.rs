//! Six overlapping segments with smooth blend weights.
//!
//! 1. Hard labels: each vertex goes to the segment whose bones carry most of its MakeHuman skin
//!    weight ([`super::context::bone_segment`]).
//! 2. Signed edge distance to each segment's hard boundary: `sd_s(v) = d(v, S) − d(v, ¬S)`
//!    (Dijkstra along mesh edges; negative inside).
//! 3. Raw weight `w_s = smoothstep((h − sd_s) / 2h)` with half-width `h`: 1 deeper than `h` inside,
//!    0 farther than `h` outside, ½ on the boundary; then normalised to sum 1. A segment's vertex
//!    set is where its weight is > 0, so neighbours overlap in a band `2h` wide.

use super::super::segment::Segment;
use super::super::topology::edge_distance;
use super::context::BuildContext;

/// Parameters of the segmentation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SegmentationParams {
    /// Half-width `h` of the overlap band, metres. Default 0.03 (a 6 cm band).
    pub half_band: f64,
}

impl Default for SegmentationParams {
    fn default() -> Self {
        Self { half_band: 0.03 }
    }
}

/// Per-vertex hard labels and blend weights (`#V × 6`, summing to 1).
pub fn segment_weights(
    ctx: &BuildContext,
    params: &SegmentationParams,
) -> (Vec<Segment>, Vec<[f32; 6]>) {
    let n = ctx.vertex_count();
    let hard: Vec<Segment> = (0..n as u32)
        .map(|v| {
            let w = ctx.segment_skin_weights(v);
            let best = (0..6).max_by(|&a, &b| w[a].total_cmp(&w[b])).unwrap_or(3);
            Segment::ALL[best]
        })
        .collect();
    let h = params.half_band;
    let mut raw = vec![[0f64; 6]; n];
    for s in Segment::ALL {
        let inside = (0..n as u32).filter(|&v| hard[v as usize] == s);
        let outside = (0..n as u32).filter(|&v| hard[v as usize] != s);
        let d_in = edge_distance(&ctx.mesh.positions, &ctx.neighbours, inside);
        let d_out = edge_distance(&ctx.mesh.positions, &ctx.neighbours, outside);
        for v in 0..n {
            let sd = d_in[v] - d_out[v];
            let t = ((h - sd) / (2.0 * h)).clamp(0.0, 1.0);
            raw[v][s.index()] = if sd.is_finite() {
                t * t * (3.0 - 2.0 * t)
            } else if hard[v] == s {
                1.0
            } else {
                0.0
            };
        }
    }
    let weights = raw
        .iter()
        .zip(&hard)
        .map(|(w, &s)| {
            let sum: f64 = w.iter().sum();
            if sum > 0.0 {
                w.map(|x| (x / sum) as f32)
            } else {
                let mut one = [0f32; 6];
                one[s.index()] = 1.0;
                one
            }
        })
        .collect();
    (hard, weights)
}
