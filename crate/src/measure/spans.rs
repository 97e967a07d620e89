//! Each triangle's lowest and highest corner along the up axis, found once for a body
//! ([`TriangleSpans`]), so that a horizontal section is cut from only the triangles that can reach
//! its plane instead of from every triangle of its region.
//!
//! A horizontal plane at height h ([`super::section::Plane::horizontal`]) puts a corner at height
//! y in front of it exactly when y − h ≥ 0, i.e. y ≥ h (the plane's normal is the up axis
//! itself, so the signed distance is y − h to the last bit). A triangle is cut when its corners
//! lie on both sides, so its span [lo, hi] holds h; the triangles whose span holds h are a superset
//! of those cut, and in the region's order the section of them is the section of the region.

/// The span along the up axis of every triangle of a body: `[lo, hi]`, its lowest and highest
/// corner (metres; the body's own `f32` heights).
#[derive(Debug, Clone)]
pub(super) struct TriangleSpans {
    spans: Vec<[f32; 2]>,
}

impl TriangleSpans {
    /// The spans of `triangles` (`#F`, indices checked against `#V`) of the body at flat `#V·3`
    /// `positions`, heights along `up_axis`.
    pub(super) fn new(positions: &[f32], triangles: &[[u32; 3]], up_axis: usize) -> TriangleSpans {
        let height = |v: u32| positions[3 * v as usize + up_axis];
        let spans = triangles
            .iter()
            .map(|t| {
                let [a, b, c] = [height(t[0]), height(t[1]), height(t[2])];
                [a.min(b).min(c), a.max(b).max(c)]
            })
            .collect();
        TriangleSpans { spans }
    }

    /// The triangles of `region` (indices into the triangles) whose span reaches into
    /// `low..=high`, in `region`'s order: with `low = high = h`, every triangle a horizontal plane
    /// at h can cut.
    pub(super) fn reaching(&self, region: &[u32], low: f64, high: f64) -> Vec<u32> {
        region
            .iter()
            .copied()
            .filter(|&t| {
                let [lo, hi] = self.spans[t as usize];
                lo as f64 <= high && hi as f64 >= low
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::measure::section::{plane_section, Plane};

    #[test]
    fn a_level_section_of_the_triangles_reaching_it_is_the_regions() {
        // A strip of triangles climbing in y, with corners exactly on the levels tried.
        let mut positions = Vec::new();
        for i in 0..12 {
            let y = 0.1 * i as f32;
            positions.extend([0.0, y, 0.0, 1.0, y, 0.5]);
        }
        let triangles: Vec<[u32; 3]> = (0..11)
            .flat_map(|i| {
                [
                    [2 * i, 2 * i + 1, 2 * i + 2],
                    [2 * i + 1, 2 * i + 3, 2 * i + 2],
                ]
            })
            .collect();
        let region: Vec<u32> = (0..triangles.len() as u32).rev().collect();
        let spans = TriangleSpans::new(&positions, &triangles, 1);
        for h in [0.0, 0.05, 0.3f32 as f64, 0.55, 1.0f32 as f64, 1.2] {
            let plane = Plane::horizontal(1, h);
            let near = spans.reaching(&region, h, h);
            assert!(near.len() < region.len());
            assert_eq!(
                plane_section(&positions, &triangles, &near, &plane),
                plane_section(&positions, &triangles, &region, &plane),
                "at {h}"
            );
        }
        assert_eq!(spans.reaching(&region, 0.25, 0.35), [7, 6, 5, 4]);
    }
}
