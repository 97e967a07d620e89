//! Segment vertex subsets and blend weights (paper §4.2.1: six overlapping segments).

use crate::mesh::topology::unique_edges;

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

/// The triangles with all three vertices in `subset` (ascending template indices, of a template
/// with `vertex_count` vertices), as flat indices into the subset: a segment's own mesh.
pub fn segment_triangles(triangles: &[[u32; 3]], subset: &[u32], vertex_count: usize) -> Vec<u32> {
    let mut local = vec![u32::MAX; vertex_count];
    for (j, &v) in subset.iter().enumerate() {
        local[v as usize] = j as u32;
    }
    triangles
        .iter()
        .map(|t| t.map(|v| local[v as usize]))
        .filter(|t| t.iter().all(|&j| j != u32::MAX))
        .flatten()
        .collect()
}

/// Mesh edges whose two vertices share no segment. Stitching is seamless only across overlap
/// bands: where two segments meet along such an edge without overlapping, different coefficients
/// can tear the body, so a template should have none — except between parts that only touch when
/// they carry the same body's coefficients.
pub fn edges_without_common_segment(
    triangles: &[[u32; 3]],
    weights: &[[f32; 6]],
) -> Vec<(u32, u32)> {
    unique_edges(triangles)
        .into_iter()
        .filter(
            |&[a, b]| match (weights.get(a as usize), weights.get(b as usize)) {
                (Some(wa), Some(wb)) => !(0..6).any(|s| wa[s] > 0.0 && wb[s] > 0.0),
                _ => false,
            },
        )
        .map(|[a, b]| (a, b))
        .collect()
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
    }
}
