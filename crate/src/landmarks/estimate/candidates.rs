//! The similarity fit of each frame candidate by iterative closest points, and the choice of
//! the candidate with the lowest energy: front/back and up/down are told apart by the fit, not
//! by a rule about bodies.

use std::ops::ControlFlow;

use nalgebra::{Point3, Vector3};

use super::matching::Matching;
use super::tick::Ticker;
use crate::mesh::similarity::{similarity, Similarity};

/// A candidate after its fit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FittedCandidate {
    /// Template → scan after the fit.
    pub transform: Similarity,
    /// Mean squared match distance (m²), unmatched vertices counting as the outlier distance.
    pub energy: f64,
    /// Fraction of the sampled vertices with a match.
    pub matched: f64,
}

/// Fits `start` by similarity ICP: each iteration matches the `sample` vertices of the template
/// (`rest` positions and unit `normals`, metres, template frame) to the scan and solves the
/// least-squares similarity (Umeyama) from their rest positions to their matches. `Break` from
/// the ticker stops the fit (`None`).
pub fn fit_similarity(
    start: Similarity,
    rest: &[Point3<f64>],
    normals: &[Vector3<f64>],
    sample: &[u32],
    matching: &Matching<'_>,
    iterations: usize,
    ticker: &mut Ticker<'_>,
) -> Option<FittedCandidate> {
    let mut transform = start;
    let mut positions = rest.to_vec();
    let mut turned = normals.to_vec();
    let mut energy = f64::INFINITY;
    let mut matched = 0.0;
    for _ in 0..=iterations {
        for &v in sample {
            let v = v as usize;
            positions[v] = transform.apply(&rest[v]);
            turned[v] = transform.rotation * normals[v];
        }
        let pairs = matching.pairs(sample, &positions, &turned);
        energy = matching.energy(&pairs, sample.len());
        matched = pairs.len() as f64 / sample.len().max(1) as f64;
        if ticker.tick(energy.sqrt(), pairs.len()) == ControlFlow::Break(()) {
            return None;
        }
        if pairs.len() < 10 {
            break;
        }
        let from: Vec<_> = pairs.iter().map(|p| rest[p.vertex as usize]).collect();
        let to: Vec<_> = pairs.iter().map(|p| p.target).collect();
        match similarity(&from, &to, true) {
            Some(t) if t.scale.is_finite() && t.scale > 0.0 => transform = t,
            _ => break,
        }
    }
    Some(FittedCandidate {
        transform,
        energy,
        matched,
    })
}

/// `count` template vertices spread evenly by index over those with a data weight of at least
/// ½ (no hands, ears or unseen parts: they are the least reliable on scans).
pub fn even_sample(weights: &[f64], count: usize) -> Vec<u32> {
    let eligible: Vec<u32> = (0..weights.len() as u32)
        .filter(|&v| weights[v as usize] >= 0.5)
        .collect();
    let step = (eligible.len() / count.max(1)).max(1);
    eligible.into_iter().step_by(step).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn even_sample_skips_low_weights_and_spreads() {
        let mut w = vec![1.0; 100];
        w[0] = 0.1;
        w[1] = 0.0;
        let s = even_sample(&w, 10);
        assert!(!s.contains(&0) && !s.contains(&1));
        assert!((10..=11).contains(&s.len()), "{}", s.len());
        assert!(s.windows(2).all(|p| p[1] - p[0] == 9));
    }
}
