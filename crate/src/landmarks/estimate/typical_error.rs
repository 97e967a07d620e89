//! Each landmark's typical estimate error: the mean distance (mm) of the estimate from the true
//! landmark on the development subjects, the prior of the confidence (`confidence.rs`). Measured
//! 2026-11-24 with `cargo run --release --example landmarks_estimate -- --n 10` (10 synthetic
//! subjects of the `tuning` profile, 9 poses, 2 frames, no landmarks given), the segment-wise
//! fit with stretching legs, the arms' swing, the knees and elbows placed by the limbs' profiles
//! (the knees by the top of the calf) and the hands' pose about the wrist. Regenerate
//! it with the same command when the method or the template's landmark vertices change; the
//! held-out figures in docs/landmarks-estimate.md say how well it ranks the errors of subjects
//! it was not measured on.

use crate::landmarks::CAESAR_LANDMARK_COUNT;

/// Typical error (mm) per CAESAR landmark, CAESAR order.
pub const TYPICAL_ERROR_MM: [f64; CAESAR_LANDMARK_COUNT] = [
    13.6, // Sellion
    18.5, // Rt. Infraorbitale
    18.5, // Lt. Infraorbitale
    15.1, // Supramenton
    11.9, // Rt. Tragion
    11.7, // Rt. Gonion
    12.4, // Lt. Tragion
    13.0, // Lt. Gonion
    18.1, // Nuchale
    14.2, // Rt. Clavicale
    14.9, // Suprasternale
    14.1, // Lt. Clavicale
    23.3, // Rt. Thelion/Bustpoint
    22.8, // Lt. Thelion/Bustpoint
    16.2, // Substernale
    15.3, // Rt. 10th Rib
    15.1, // Rt. ASIS
    15.7, // Lt. 10th Rib
    16.4, // Lt. ASIS
    12.7, // Rt. Iliocristale
    18.9, // Rt. Trochanterion
    13.0, // Lt. Iliocristale
    19.4, // Lt. Trochanterion
    12.2, // Cervicale
    9.2,  // 10th Rib Midspine
    10.8, // Rt. PSIS
    11.4, // Lt. PSIS
    11.4, // Waist, Preferred, Post.
    20.9, // Rt. Acromion
    15.0, // Rt. Axilla, Ant.
    5.8,  // Rt. Radial Styloid
    13.9, // Rt. Axilla, Post.
    9.8,  // Rt. Olecranon
    13.2, // Rt. Humeral Lateral Epicn
    10.7, // Rt. Humeral Medial Epicn
    12.5, // Rt. Radiale
    11.6, // Rt. Metacarpal Phal. II
    10.9, // Rt. Dactylion
    7.5,  // Rt. Ulnar Styloid
    11.1, // Rt. Metacarpal Phal. V
    20.4, // Lt. Acromion
    14.8, // Lt. Axilla, Ant.
    6.0,  // Lt. Radial Styloid
    13.8, // Lt. Axilla, Post.
    11.7, // Lt. Olecranon
    12.9, // Lt. Humeral Lateral Epicn
    10.7, // Lt. Humeral Medial Epicn
    12.6, // Lt. Radiale
    11.7, // Lt. Metacarpal Phal. II
    11.4, // Lt. Dactylion
    7.4,  // Lt. Ulnar Styloid
    11.0, // Lt. Metacarpal Phal. V
    20.2, // Rt. Knee Crease
    11.7, // Rt. Femoral Lateral Epicn
    14.6, // Rt. Femoral Medial Epicn
    7.0,  // Rt. Metatarsal Phal. V
    7.7,  // Rt. Lateral Malleolus
    12.6, // Rt. Medial Malleolus
    17.3, // Rt. Sphyrion
    6.4,  // Rt. Metatarsal Phal. I
    7.0,  // Rt. Calcaneous, Post.
    4.7,  // Rt. Digit II
    19.1, // Lt. Knee Crease
    11.1, // Lt. Femoral Lateral Epicn
    13.3, // Lt. Femoral Medial Epicn
    7.5,  // Lt. Metatarsal Phal. V
    9.0,  // Lt. Lateral Malleolus
    14.9, // Lt. Medial Malleolus
    19.2, // Lt. Sphyrion
    7.7,  // Lt. Metatarsal Phal. I
    9.0,  // Lt. Calcaneous, Post.
    5.3,  // Lt. Digit II
    19.4, // Crotch
];
