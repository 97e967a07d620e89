//! A limb's part fits the scan about as closely on one side as on the other. An arm laid against
//! the torso and posed wrongly, or a foot the fit left beside its scan, lies far from the scan
//! while the other side and the rest of the body fit, which the RMS over the whole body hides. Both
//! self-checks ask this: the landmark estimate's of its own fit (`estimate/self_check.rs`) and the
//! final fit's ([`super::quality`], `uneven_limb`), each with its own thresholds.

use serde::{Deserialize, Serialize};

/// A limb's part whose fit lies much farther from the scan on one side than on the other.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct UnevenFit {
    /// The part without its side (`upper arm`, `lower leg`, …).
    pub part: String,
    pub left_rms_mm: f64,
    pub right_rms_mm: f64,
}

impl UnevenFit {
    /// The sentence a person reads.
    pub fn sentence(&self) -> String {
        let (worse, better, side) = if self.left_rms_mm > self.right_rms_mm {
            (self.left_rms_mm, self.right_rms_mm, "left")
        } else {
            (self.right_rms_mm, self.left_rms_mm, "right")
        };
        format!(
            "the {side} {} lies far from the scan (RMS {worse:.1} mm, the other side {better:.1} mm): \
             it was probably posed wrongly; place its landmarks by hand",
            self.part
        )
    }
}

/// The parts named `left X` and `right X` in `part_names` whose fits' RMS distance to the scan
/// (`distance`, metres, per template vertex, over the vertices of `part_of` that part with a
/// positive `weight`) is above `ratio` times the other side's and above it by more than `min_mm`.
pub fn uneven_fits(
    distance: &[f64],
    weight: &[f64],
    part_of: &[usize],
    part_names: &[&str],
    (ratio, min_mm): (f64, f64),
) -> Vec<UnevenFit> {
    let mut sum = vec![(0.0, 0usize); part_names.len()];
    for ((&d, &w), &p) in distance.iter().zip(weight).zip(part_of) {
        if w > 0.0 && d.is_finite() {
            sum[p].0 += d * d;
            sum[p].1 += 1;
        }
    }
    let rms_mm = |p: usize| (sum[p].1 > 0).then(|| (sum[p].0 / sum[p].1 as f64).sqrt() * 1000.0);
    part_names
        .iter()
        .enumerate()
        .filter_map(|(l, name)| {
            let part = name.strip_prefix("left ")?;
            let r = part_names
                .iter()
                .position(|n| *n == format!("right {part}"))?;
            let (left, right) = (rms_mm(l)?, rms_mm(r)?);
            let (worse, better) = (left.max(right), left.min(right));
            (worse > ratio * better && worse - better > min_mm).then(|| UnevenFit {
                part: part.to_string(),
                left_rms_mm: left,
                right_rms_mm: right,
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_limb_fitted_far_from_its_scan_on_one_side_only_is_named() {
        let names = ["torso", "left arm", "right arm", "left leg", "right leg"];
        // Vertices: 2 per part; the right arm 30 mm from the scan, everything else 3 mm, the
        // torso's second vertex unweighted (its 1 m does not count).
        let part_of = [0, 0, 1, 1, 2, 2, 3, 3, 4, 4];
        let mut distance = [0.003; 10];
        distance[1] = 1.0;
        distance[4] = 0.03;
        distance[5] = 0.03;
        let mut weight = [1.0; 10];
        weight[1] = 0.0;
        let found = uneven_fits(&distance, &weight, &part_of, &names, (2.5, 5.0));
        assert_eq!(found.len(), 1, "{found:?}");
        assert_eq!(found[0].part, "arm");
        assert!((found[0].right_rms_mm - 30.0).abs() < 1e-9);
        assert!(found[0]
            .sentence()
            .starts_with("the right arm lies far from the scan (RMS 30.0 mm"));
        // Both sides alike (a feet-cut scan's lower legs), or a small difference: nothing.
        distance[2] = 0.03;
        distance[3] = 0.03;
        assert!(uneven_fits(&distance, &weight, &part_of, &names, (2.5, 5.0)).is_empty());
        assert!(uneven_fits(&distance, &weight, &part_of, &names, (2.5, 30.0)).is_empty());
    }
}
