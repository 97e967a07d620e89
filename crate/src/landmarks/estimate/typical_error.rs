//! Each landmark's typical estimate error: the mean distance (mm) of the estimate from the true
//! landmark on the development subjects, the prior of the confidence (`confidence.rs`). Measured
//! 2026-11-25 with `cargo run --release --example landmarks_estimate -- --n 10` (10 synthetic
//! subjects of the `tuning` profile, 9 poses, 2 frames, no landmarks given), the segment-wise
//! fit with stretching legs, the arms' swing (raised too), no limb folded past 145°, the knees
//! and elbows placed by the limbs' profiles (the knees by the front of the knee), the elbow of a
//! bent arm, the hands' pose about the wrist and the resting hand of a bent arm. Regenerate it
//! with the same command when the method or the template's landmark vertices change; the
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
    12.5, // Lt. Tragion
    12.6, // Lt. Gonion
    18.1, // Nuchale
    14.2, // Rt. Clavicale
    14.9, // Suprasternale
    14.1, // Lt. Clavicale
    23.3, // Rt. Thelion/Bustpoint
    22.8, // Lt. Thelion/Bustpoint
    16.2, // Substernale
    15.5, // Rt. 10th Rib
    15.1, // Rt. ASIS
    15.7, // Lt. 10th Rib
    16.4, // Lt. ASIS
    12.7, // Rt. Iliocristale
    19.4, // Rt. Trochanterion
    13.1, // Lt. Iliocristale
    20.6, // Lt. Trochanterion
    12.2, // Cervicale
    9.2,  // 10th Rib Midspine
    10.8, // Rt. PSIS
    11.4, // Lt. PSIS
    11.3, // Waist, Preferred, Post.
    20.8, // Rt. Acromion
    14.8, // Rt. Axilla, Ant.
    4.6,  // Rt. Radial Styloid
    13.9, // Rt. Axilla, Post.
    9.6,  // Rt. Olecranon
    12.0, // Rt. Humeral Lateral Epicn
    9.8,  // Rt. Humeral Medial Epicn
    12.2, // Rt. Radiale
    9.5,  // Rt. Metacarpal Phal. II
    8.0,  // Rt. Dactylion
    6.8,  // Rt. Ulnar Styloid
    8.5,  // Rt. Metacarpal Phal. V
    20.3, // Lt. Acromion
    14.8, // Lt. Axilla, Ant.
    4.6,  // Lt. Radial Styloid
    13.8, // Lt. Axilla, Post.
    10.7, // Lt. Olecranon
    12.1, // Lt. Humeral Lateral Epicn
    10.4, // Lt. Humeral Medial Epicn
    12.2, // Lt. Radiale
    9.8,  // Lt. Metacarpal Phal. II
    8.4,  // Lt. Dactylion
    6.4,  // Lt. Ulnar Styloid
    8.5,  // Lt. Metacarpal Phal. V
    13.3, // Rt. Knee Crease
    7.0,  // Rt. Femoral Lateral Epicn
    8.7,  // Rt. Femoral Medial Epicn
    7.6,  // Rt. Metatarsal Phal. V
    7.0,  // Rt. Lateral Malleolus
    12.7, // Rt. Medial Malleolus
    16.8, // Rt. Sphyrion
    6.2,  // Rt. Metatarsal Phal. I
    6.9,  // Rt. Calcaneous, Post.
    4.1,  // Rt. Digit II
    12.8, // Lt. Knee Crease
    8.0,  // Lt. Femoral Lateral Epicn
    8.6,  // Lt. Femoral Medial Epicn
    7.2,  // Lt. Metatarsal Phal. V
    8.4,  // Lt. Lateral Malleolus
    14.9, // Lt. Medial Malleolus
    19.0, // Lt. Sphyrion
    6.5,  // Lt. Metatarsal Phal. I
    8.1,  // Lt. Calcaneous, Post.
    5.1,  // Lt. Digit II
    19.2, // Crotch
];
