//! Each landmark's typical estimate error: the mean distance (mm) of the estimate from the true
//! landmark on the development subjects, the prior of the confidence (`confidence.rs`). Measured
//! 2026-11-26 with `cargo run --release --example landmarks_estimate -- --n 10` (10 synthetic
//! subjects of the `tuning` profile, 9 poses, 2 frames, no landmarks given), the segment-wise
//! fit with stretching legs, the arms' swing (raised too), no limb folded past 145°, the knees
//! and elbows placed by the limbs' profiles (the knees by the front of the knee), the elbow of a
//! bent arm, the hands' pose about the wrist (its turn kept when the hand then matches better),
//! the hand of a bent arm laid on the body (its palm across the knuckles' line, its turn about
//! the forearm carried down the forearm), a bent elbow's hinge across the arm's plane, every
//! wrist placed by the forearm's profile and the torso's length from the buttocks; the
//! hands-on-hips subject has its hands laid on the hips (the generator's pose since the
//! afternoon of 2026-11-25). Regenerate it with the same command when the method or the
//! template's landmark vertices change; the held-out figures in docs/landmarks-estimate.md say
//! how well it ranks the errors of subjects it was not measured on.

use crate::landmarks::CAESAR_LANDMARK_COUNT;

/// Typical error (mm) per CAESAR landmark, CAESAR order.
pub const TYPICAL_ERROR_MM: [f64; CAESAR_LANDMARK_COUNT] = [
    13.5, // Sellion
    18.6, // Rt. Infraorbitale
    18.7, // Lt. Infraorbitale
    15.3, // Supramenton
    11.9, // Rt. Tragion
    12.3, // Rt. Gonion
    12.4, // Lt. Tragion
    13.2, // Lt. Gonion
    18.4, // Nuchale
    14.5, // Rt. Clavicale
    15.3, // Suprasternale
    14.6, // Lt. Clavicale
    21.1, // Rt. Thelion/Bustpoint
    20.6, // Lt. Thelion/Bustpoint
    10.7, // Substernale
    14.9, // Rt. 10th Rib
    14.0, // Rt. ASIS
    15.0, // Lt. 10th Rib
    15.3, // Lt. ASIS
    11.9, // Rt. Iliocristale
    17.5, // Rt. Trochanterion
    12.3, // Lt. Iliocristale
    18.5, // Lt. Trochanterion
    12.4, // Cervicale
    6.1,  // 10th Rib Midspine
    10.4, // Rt. PSIS
    10.8, // Lt. PSIS
    8.2,  // Waist, Preferred, Post.
    23.6, // Rt. Acromion
    17.3, // Rt. Axilla, Ant.
    2.6,  // Rt. Radial Styloid
    15.2, // Rt. Axilla, Post.
    9.7,  // Rt. Olecranon
    10.3, // Rt. Humeral Lateral Epicn
    10.1, // Rt. Humeral Medial Epicn
    11.0, // Rt. Radiale
    7.6,  // Rt. Metacarpal Phal. II
    6.8,  // Rt. Dactylion
    3.9,  // Rt. Ulnar Styloid
    7.9,  // Rt. Metacarpal Phal. V
    22.6, // Lt. Acromion
    17.4, // Lt. Axilla, Ant.
    2.9,  // Lt. Radial Styloid
    15.3, // Lt. Axilla, Post.
    11.7, // Lt. Olecranon
    10.7, // Lt. Humeral Lateral Epicn
    10.6, // Lt. Humeral Medial Epicn
    11.3, // Lt. Radiale
    8.8,  // Lt. Metacarpal Phal. II
    6.5,  // Lt. Dactylion
    4.3,  // Lt. Ulnar Styloid
    7.6,  // Lt. Metacarpal Phal. V
    12.9, // Rt. Knee Crease
    7.4,  // Rt. Femoral Lateral Epicn
    8.4,  // Rt. Femoral Medial Epicn
    7.5,  // Rt. Metatarsal Phal. V
    7.1,  // Rt. Lateral Malleolus
    12.8, // Rt. Medial Malleolus
    17.0, // Rt. Sphyrion
    6.0,  // Rt. Metatarsal Phal. I
    6.8,  // Rt. Calcaneous, Post.
    4.0,  // Rt. Digit II
    12.4, // Lt. Knee Crease
    8.2,  // Lt. Femoral Lateral Epicn
    8.5,  // Lt. Femoral Medial Epicn
    7.2,  // Lt. Metatarsal Phal. V
    8.4,  // Lt. Lateral Malleolus
    15.1, // Lt. Medial Malleolus
    19.5, // Lt. Sphyrion
    6.7,  // Lt. Metatarsal Phal. I
    8.2,  // Lt. Calcaneous, Post.
    5.1,  // Lt. Digit II
    13.7, // Crotch
];
