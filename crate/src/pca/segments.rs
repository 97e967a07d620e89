//! Segment vertex subsets and blend weights (paper §4.2.1: six overlapping segments).

/// Vertices of each segment (weight > 0), ascending, in [`crate::template::Segment::ALL`] order.
pub fn segment_subsets(weights: &[[f32; 6]]) -> Vec<Vec<u32>> {
    (0..6)
        .map(|s| {
            weights
                .iter()
                .enumerate()
                .filter(|(_, w)| w[s] > 0.0)
                .map(|(v, _)| v as u32)
                .collect()
        })
        .collect()
}

/// For each segment, w̃ᵥ,ₛ = wᵥ,ₛ / Σₜ wᵥ,ₜ over its own subset (so Σₛ w̃ᵥ,ₛ = 1 wherever a
/// vertex belongs to any segment).
pub fn normalised_blend(weights: &[[f32; 6]], subsets: &[Vec<u32>]) -> Vec<Vec<f32>> {
    subsets
        .iter()
        .enumerate()
        .map(|(s, subset)| {
            subset
                .iter()
                .map(|&v| {
                    let w = &weights[v as usize];
                    let total: f32 = w.iter().sum();
                    if total > 0.0 {
                        w[s] / total
                    } else {
                        0.0
                    }
                })
                .collect()
        })
        .collect()
}

/// Pairs of segments that share at least one vertex (their overlap band), as index pairs.
pub fn overlapping_pairs(weights: &[[f32; 6]]) -> Vec<(usize, usize)> {
    let mut pairs = Vec::new();
    for a in 0..6 {
        for b in a + 1..6 {
            if weights.iter().any(|w| w[a] > 0.0 && w[b] > 0.0) {
                pairs.push((a, b));
            }
        }
    }
    pairs
}

/// Mesh edges whose two vertices share no segment. Stitching is seamless only across overlap
/// bands: where two segments meet along such an edge without overlapping, different coefficients
/// can tear the body, so a template should have none — except between parts that only touch when
/// they carry the same body's coefficients.
pub fn edges_without_common_segment(
    triangles: &[[u32; 3]],
    weights: &[[f32; 6]],
) -> Vec<(u32, u32)> {
    let mut edges: Vec<(u32, u32)> = triangles
        .iter()
        .flat_map(|t| [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])])
        .map(|(a, b)| (a.min(b), a.max(b)))
        .filter(
            |&(a, b)| match (weights.get(a as usize), weights.get(b as usize)) {
                (Some(wa), Some(wb)) => !(0..6).any(|s| wa[s] > 0.0 && wb[s] > 0.0),
                _ => false,
            },
        )
        .collect();
    edges.sort_unstable();
    edges.dedup();
    edges
}

/// Checks the blend weights: one `[f32; 6]` per vertex, all finite and ≥ 0.
pub fn validate_weights(weights: &[[f32; 6]], vertex_count: usize) -> Result<(), String> {
    if weights.len() != vertex_count {
        return Err(format!(
            "{} weight rows for {vertex_count} template vertices",
            weights.len()
        ));
    }
    if let Some(v) = weights
        .iter()
        .position(|w| w.iter().any(|x| !x.is_finite() || *x < 0.0))
    {
        return Err(format!("vertex {v} has a negative or non-finite weight"));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn blend_weights_sum_to_one_in_overlaps() {
        let w = [
            [1.0, 0.0, 0.0, 1.0, 0.0, 0.0],
            [0.0, 0.0, 0.0, 2.0, 0.0, 0.0],
        ];
        let subsets = segment_subsets(&w);
        assert_eq!(subsets[0], vec![0]);
        assert_eq!(subsets[3], vec![0, 1]);
        let blend = normalised_blend(&w, &subsets);
        assert_eq!(blend[0], vec![0.5]);
        assert_eq!(blend[3], vec![0.5, 1.0]);
        assert_eq!(overlapping_pairs(&w), vec![(0, 3)]);
    }
}
