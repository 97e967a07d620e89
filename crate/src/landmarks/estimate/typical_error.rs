//! Each landmark's typical estimate error: the mean distance (mm) of the estimate from the true
//! landmark on the development subjects, the prior of the confidence (`confidence.rs`). Measured
//! 2026-11-24 with `cargo run --release --example landmarks_estimate -- --n 10` (10 synthetic
//! subjects of the `tuning` profile, 8 poses, 2 frames, no landmarks given), the segment-wise
//! fit with stretching legs. Regenerate it with the same command when the method or the
//! template's landmark vertices change; the held-out figures in docs/landmarks-estimate.md say
//! how well it ranks the errors of subjects it was not measured on.

use crate::landmarks::CAESAR_LANDMARK_COUNT;

/// Typical error (mm) per CAESAR landmark, CAESAR order.
pub const TYPICAL_ERROR_MM: [f64; CAESAR_LANDMARK_COUNT] = [
    14.1, // Sellion
    19.1, // Rt. Infraorbitale
    19.2, // Lt. Infraorbitale
    15.6, // Supramenton
    12.4, // Rt. Tragion
    11.9, // Rt. Gonion
    13.1, // Lt. Tragion
    13.4, // Lt. Gonion
    18.5, // Nuchale
    14.3, // Rt. Clavicale
    15.4, // Suprasternale
    14.4, // Lt. Clavicale
    23.4, // Rt. Thelion/Bustpoint
    23.4, // Lt. Thelion/Bustpoint
    16.5, // Substernale
    15.6, // Rt. 10th Rib
    13.5, // Rt. ASIS
    15.1, // Lt. 10th Rib
    14.1, // Lt. ASIS
    13.4, // Rt. Iliocristale
    17.2, // Rt. Trochanterion
    14.6, // Lt. Iliocristale
    17.9, // Lt. Trochanterion
    23.4, // Cervicale
    9.8,  // 10th Rib Midspine
    11.6, // Rt. PSIS
    12.1, // Lt. PSIS
    16.0, // Waist, Preferred, Post.
    19.1, // Rt. Acromion
    14.0, // Rt. Axilla, Ant.
    32.6, // Rt. Radial Styloid
    13.1, // Rt. Axilla, Post.
    25.6, // Rt. Olecranon
    31.8, // Rt. Humeral Lateral Epicn
    26.7, // Rt. Humeral Medial Epicn
    31.2, // Rt. Radiale
    37.6, // Rt. Metacarpal Phal. II
    47.5, // Rt. Dactylion
    36.3, // Rt. Ulnar Styloid
    43.1, // Rt. Metacarpal Phal. V
    18.4, // Lt. Acromion
    14.5, // Lt. Axilla, Ant.
    33.0, // Lt. Radial Styloid
    13.8, // Lt. Axilla, Post.
    26.6, // Lt. Olecranon
    32.1, // Lt. Humeral Lateral Epicn
    27.3, // Lt. Humeral Medial Epicn
    31.3, // Lt. Radiale
    38.0, // Lt. Metacarpal Phal. II
    44.0, // Lt. Dactylion
    36.7, // Lt. Ulnar Styloid
    43.5, // Lt. Metacarpal Phal. V
    34.0, // Rt. Knee Crease
    28.1, // Rt. Femoral Lateral Epicn
    31.3, // Rt. Femoral Medial Epicn
    6.8,  // Rt. Metatarsal Phal. V
    7.2,  // Rt. Lateral Malleolus
    12.4, // Rt. Medial Malleolus
    17.9, // Rt. Sphyrion
    8.1,  // Rt. Metatarsal Phal. I
    8.1,  // Rt. Calcaneous, Post.
    4.6,  // Rt. Digit II
    34.0, // Lt. Knee Crease
    28.2, // Lt. Femoral Lateral Epicn
    31.4, // Lt. Femoral Medial Epicn
    8.3,  // Lt. Metatarsal Phal. V
    8.5,  // Lt. Lateral Malleolus
    13.4, // Lt. Medial Malleolus
    18.6, // Lt. Sphyrion
    8.6,  // Lt. Metatarsal Phal. I
    8.6,  // Lt. Calcaneous, Post.
    4.8,  // Lt. Digit II
    20.2, // Crotch
];
