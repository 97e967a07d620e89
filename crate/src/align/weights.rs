//! Per-vertex data weights w_i of E_d (paper §3.2.1) from the template's region flags.

use crate::template::Template;

/// Data weight of hands and ears: the paper gives them 0.1 (§3.2.1, "a lower weight (e.g., 0.1)").
pub const HAND_EAR_WEIGHT: f64 = 0.1;

/// `#V` data weights: 0 for regions no scanner sees (the inner mouth, nostrils), so smoothness
/// alone moves them; [`HAND_EAR_WEIGHT`] for hands and ears; `sole_weight` for the soles (a
/// standing subject's are never scanned); 1 elsewhere.
pub fn data_weights(template: &Template, sole_weight: f64) -> Vec<f64> {
    (0..template.mesh().positions.len() as u32)
        .map(|v| {
            let flags = template.flags(v);
            if flags.unseen() {
                0.0
            } else if flags.hand() || flags.ear() {
                HAND_EAR_WEIGHT
            } else if flags.sole() {
                sole_weight
            } else {
                1.0
            }
        })
        .collect()
}
