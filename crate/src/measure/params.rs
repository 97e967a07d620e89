//! Parameters of the measurements, with their defaults.

use serde::{Deserialize, Serialize};

/// Offsets that place section planes where the template has no landmark, the up axis, and the
/// search for the body-defined points around their landmarks' guesses (`surface.rs`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct MeasureParams {
    /// Index of the up axis (0 = x, 1 = y, 2 = z); default 1 (y up: the template's frame).
    pub up_axis: usize,
    /// Least height of the hip plane above the Crotch (the template's Trochanterions sit within
    /// millimetres of the crotch, where a plane may pass between the legs); default 0.02 m.
    pub hip_above_crotch: f64,
    /// Depth of the thigh plane below the crotch (the level found on the surface, below):
    /// ISO 8559-1 takes thigh girth just below the gluteal fold, for which the template has no
    /// landmark; default 0.03 m.
    pub thigh_below_crotch: f64,
    /// The head girth's level (ISO 7250-1 head circumference: the greatest, above the eyebrow
    /// ridges) is the cranium's widest horizontal section, found walking down from
    /// `head_search_above` over the Sellion's height every `head_step` until the girth stops
    /// growing, never below `head_search_below` under it (`surface.rs`, [`fullest_head`]);
    /// defaults 0.05 m, 0.01 m and 0.01 m.
    ///
    /// [`fullest_head`]: super::surface::fullest_head
    pub head_search_above: f64,
    pub head_search_below: f64,
    pub head_step: f64,
    /// Where the neck plane sits between the neck base (Cervicale–Suprasternale, 0) and the ears
    /// (Tragions, 1), perpendicular to that axis: ISO 8559-1 neck girth is taken just below the
    /// Adam's apple; default 0.25.
    pub neck_fraction: f64,
    /// The neck girth is the least girth perpendicular to the neck axis over fractions
    /// `neck_fraction ± neck_band` of the axis, sampled every `neck_step` and refined by a parabola
    /// through the least sample and its neighbours (ISO 8559-1 5.3.2: just below the Adam's
    /// apple, where the neck is narrowest); defaults 0.2 and 0.025.
    pub neck_band: f64,
    pub neck_step: f64,
    /// The neck girth's tape, through the narrowest level on that axis, is square to the neck
    /// as the body holds it, not to the landmarks' axis: the least of the planes tilted from
    /// square to the axis by up to `neck_tilt_max_deg`, in steps of `neck_tilt_step_deg` walked
    /// downhill from square (first along the neck's lean, then across), cut from the triangles
    /// within `neck_tilt_radius` of the point (`surface.rs`, `squarest_neck`); defaults 20°, 5°
    /// and 0.12 m (twice a neck's radius).
    pub neck_tilt_max_deg: f64,
    pub neck_tilt_step_deg: f64,
    pub neck_tilt_radius: f64,
    /// The hip level is the level of greatest buttock prominence (ISO 8559-1 5.3.13) among the
    /// torso's and legs' vertices from `hip_band_below` under to `hip_band_above` over the
    /// landmarks' guess (never under `hip_above_crotch` over the Crotch); defaults 0.06 m and
    /// 0.10 m.
    pub hip_band_below: f64,
    pub hip_band_above: f64,
    /// The bust girth's level is the bust points' (ISO 8559-1 5.3.4: the breasts' most prominent
    /// points), each the prominence forward of the torso's vertices on its side from
    /// `bust_band_below` under to `bust_band_above` over the Thelions' mean height
    /// (`surface.rs`, `bust_level`); defaults 0.04 m and 0.04 m.
    pub bust_band_below: f64,
    pub bust_band_above: f64,
    /// The chest girth's level (ISO 8559-1 chest girth: under the armpits, the torso alone) is
    /// `chest_below_armpit` under the armpits' apex, the highest level at which a horizontal
    /// section of the torso and arms has the torso's loop apart from both arms; the apex is
    /// sought from `armpit_band_above` over to `armpit_band_below` under the axilla landmarks'
    /// mean level; defaults 0.05 m, 0.08 m and 0.01 m.
    pub armpit_band_above: f64,
    pub armpit_band_below: f64,
    pub chest_below_armpit: f64,
    /// The crotch (ISO 7250-1 crotch height; the thigh girth's level) is the highest level at
    /// which a horizontal section of the torso and legs has parted into the two legs, sought
    /// from `crotch_band_above` over to `crotch_band_below` under the Crotch landmark's height;
    /// defaults 0.05 m and 0.05 m.
    pub crotch_band_above: f64,
    pub crotch_band_below: f64,
    /// The armpits' apex and the crotch are bisected until their bracket is narrower than
    /// `parting_resolution` (`parting.rs`); default 0.001 m.
    pub parting_resolution: f64,
    /// Cap depth δ of a prominence (`surface.rs`): the vertices within δ of the extreme one make
    /// its point; default 0.005 m.
    pub prominence_depth: f64,
    /// The acromia (ISO 7250-1 biacromial breadth: `acromion.rs`, the shoulder's rule of
    /// `landmarks::shoulder`) are sought among the surface points `acromion_spacing` apart within
    /// `acromion_radius` of the Acromion vertex (each triangle's grid laid on the template at rest
    /// and carried by the body, so the points move with the body); the shoulder point is the
    /// centroid of those within `acromion_cap` of the furthest reach, weighted down linearly over
    /// `acromion_cap_taper` about that depth (`landmarks::shoulder::Cap`: bodies a little apart
    /// get acromia a little apart), not sure nearer than `acromion_edge` to the
    /// window's edge, where the search starts again around it, `acromion_searches` searches in
    /// all; fewer than `acromion_min_points` points, no search; an upper arm raised more than
    /// `acromion_max_abduction_deg` from hanging down has no shoulder point. Defaults 0.045 m,
    /// 0.003 m, 0.004 m, 0.001 m, 0.01 m, 4, 50 and 60°: the estimate's (`AcromionParams`) but for
    /// the taper (none there: its points are the scan's) and the
    /// window (35 mm there: the climb from the fit's vertex needs room) and the arm (30° there:
    /// the held-out bodies hold their arms out 3–49°).
    pub acromion_radius: f64,
    pub acromion_spacing: f64,
    pub acromion_cap: f64,
    pub acromion_cap_taper: f64,
    pub acromion_edge: f64,
    pub acromion_searches: usize,
    pub acromion_min_points: usize,
    pub acromion_max_abduction_deg: f64,
    /// The found shoulder point is taken only on the shoulder's turn: along the search's
    /// direction the surface may rise at most `acromion_turn_rise` above it within
    /// `acromion_turn_reach` to either side in the frontal plane (towards the neck and towards
    /// the arm; its profile in bins `acromion_turn_band` wide, within that of the point front to
    /// back, `acromion::turn_rises`); otherwise the Acromion vertex stands. Defaults 0.04 m,
    /// 0.003 m and 0.003 m.
    pub acromion_turn_reach: f64,
    pub acromion_turn_band: f64,
    pub acromion_turn_rise: f64,
    /// The cervicale (ISO 8559-1 cervicale height) is found on the body's back profile
    /// (`cervicale.rs`): its mid-sagittal section's rearmost point every `cervicale_step` from
    /// `cervicale_band_below` under to `cervicale_band_above` over the Cervicale vertex's height;
    /// the upper back's peak is sought under that height, the back of the neck's trough over the
    /// peak. Defaults 0.25 m, 0.08 m and 0.002 m: the peak lies 11 cm under the template's
    /// Cervicale and 13–22 cm under the tuning bodies' (at 15 cm the band cut it off on half of
    /// them), the trough 1–7 cm over it, so a guess 2 cm off still holds both. The cervicale is the first level over the peak where the profile has come
    /// `cervicale_fraction` of the way from the peak to the trough: default 0.874, where the
    /// template's own Cervicale vertex stands at rest (`crate/tests/measure_cervicale.rs` holds
    /// it).
    pub cervicale_fraction: f64,
    pub cervicale_band_below: f64,
    pub cervicale_band_above: f64,
    pub cervicale_step: f64,
}

impl Default for MeasureParams {
    fn default() -> Self {
        Self {
            up_axis: 1,
            hip_above_crotch: 0.02,
            thigh_below_crotch: 0.03,
            head_search_above: 0.04,
            head_search_below: 0.01,
            head_step: 0.005,
            neck_fraction: 0.25,
            neck_band: 0.2,
            neck_step: 0.025,
            neck_tilt_max_deg: 20.0,
            neck_tilt_step_deg: 5.0,
            neck_tilt_radius: 0.12,
            hip_band_below: 0.06,
            hip_band_above: 0.10,
            bust_band_below: 0.04,
            bust_band_above: 0.04,
            armpit_band_above: 0.05,
            armpit_band_below: 0.08,
            chest_below_armpit: 0.01,
            crotch_band_above: 0.05,
            crotch_band_below: 0.05,
            parting_resolution: 0.001,
            prominence_depth: 0.005,
            acromion_radius: 0.045,
            acromion_spacing: 0.003,
            acromion_cap: 0.004,
            acromion_cap_taper: 0.001,
            acromion_edge: 0.01,
            acromion_searches: 4,
            acromion_min_points: 50,
            acromion_max_abduction_deg: 60.0,
            acromion_turn_reach: 0.04,
            acromion_turn_band: 0.003,
            acromion_turn_rise: 0.003,
            cervicale_fraction: 0.874,
            cervicale_band_below: 0.25,
            cervicale_band_above: 0.08,
            cervicale_step: 0.002,
        }
    }
}
