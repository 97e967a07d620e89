//! Each landmark's typical estimate error: the mean distance (mm) of the estimate from the true
//! landmark on the development subjects, the prior of the confidence (`confidence.rs`). Measured
//! 2026-11-24 with `cargo run --release --example landmarks_estimate -- --n 10` (10 synthetic
//! subjects of the `tuning` profile, 8 poses, 2 frames, no landmarks given), the segment-wise
//! fit with stretching legs and the knees and elbows placed by the limbs' profiles. Regenerate
//! it with the same command when the method or the template's landmark vertices change; the
//! held-out figures in docs/landmarks-estimate.md say how well it ranks the errors of subjects
//! it was not measured on.

use crate::landmarks::CAESAR_LANDMARK_COUNT;

/// Typical error (mm) per CAESAR landmark, CAESAR order.
pub const TYPICAL_ERROR_MM: [f64; CAESAR_LANDMARK_COUNT] = [
    14.2, // Sellion
    19.2, // Rt. Infraorbitale
    19.2, // Lt. Infraorbitale
    15.8, // Supramenton
    12.4, // Rt. Tragion
    11.4, // Rt. Gonion
    13.0, // Lt. Tragion
    13.3, // Lt. Gonion
    18.3, // Nuchale
    14.2, // Rt. Clavicale
    15.1, // Suprasternale
    14.3, // Lt. Clavicale
    23.5, // Rt. Thelion/Bustpoint
    23.1, // Lt. Thelion/Bustpoint
    16.3, // Substernale
    15.5, // Rt. 10th Rib
    15.4, // Rt. ASIS
    15.0, // Lt. 10th Rib
    16.8, // Lt. ASIS
    11.7, // Rt. Iliocristale
    18.8, // Rt. Trochanterion
    12.3, // Lt. Iliocristale
    19.3, // Lt. Trochanterion
    12.5, // Cervicale
    9.8,  // 10th Rib Midspine
    11.5, // Rt. PSIS
    12.1, // Lt. PSIS
    12.2, // Waist, Preferred, Post.
    17.6, // Rt. Acromion
    14.5, // Rt. Axilla, Ant.
    16.2, // Rt. Radial Styloid
    13.6, // Rt. Axilla, Post.
    8.6,  // Rt. Olecranon
    13.2, // Rt. Humeral Lateral Epicn
    9.9,  // Rt. Humeral Medial Epicn
    12.5, // Rt. Radiale
    22.7, // Rt. Metacarpal Phal. II
    24.9, // Rt. Dactylion
    17.0, // Rt. Ulnar Styloid
    23.1, // Rt. Metacarpal Phal. V
    17.2, // Lt. Acromion
    14.8, // Lt. Axilla, Ant.
    16.2, // Lt. Radial Styloid
    14.0, // Lt. Axilla, Post.
    10.9, // Lt. Olecranon
    12.8, // Lt. Humeral Lateral Epicn
    9.8,  // Lt. Humeral Medial Epicn
    12.2, // Lt. Radiale
    21.6, // Lt. Metacarpal Phal. II
    23.2, // Lt. Dactylion
    16.5, // Lt. Ulnar Styloid
    22.4, // Lt. Metacarpal Phal. V
    28.9, // Rt. Knee Crease
    22.2, // Rt. Femoral Lateral Epicn
    25.5, // Rt. Femoral Medial Epicn
    6.8,  // Rt. Metatarsal Phal. V
    7.2,  // Rt. Lateral Malleolus
    12.2, // Rt. Medial Malleolus
    17.5, // Rt. Sphyrion
    8.1,  // Rt. Metatarsal Phal. I
    8.1,  // Rt. Calcaneous, Post.
    4.6,  // Rt. Digit II
    28.3, // Lt. Knee Crease
    22.9, // Lt. Femoral Lateral Epicn
    25.5, // Lt. Femoral Medial Epicn
    8.3,  // Lt. Metatarsal Phal. V
    8.5,  // Lt. Lateral Malleolus
    13.6, // Lt. Medial Malleolus
    18.8, // Lt. Sphyrion
    8.6,  // Lt. Metatarsal Phal. I
    8.6,  // Lt. Calcaneous, Post.
    4.8,  // Lt. Digit II
    20.2, // Crotch
];
