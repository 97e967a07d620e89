//! ISO 8559-1's neck base girth on a torso and neck with a known answer: an upright elliptic neck
//! cylinder (semi-axes NECK_A outward, NECK_B front–back) on a wider torso, under a head, with
//! the Cervicale on its back, the Suprasternale on its front lower down and the Tragions on the
//! head's sides. The neck's axis is vertical, so the back's plane is the horizontal through the
//! Cervicale: the tape is half the ellipse (NECK_A, NECK_B) from one side of the neck round the
//! back to the other, then straight from each side down to the Suprasternale,
//! √(NECK_A² + NECK_B² + Δh²) each (Δh: the landmarks' difference in height) — whatever way the
//! body faces; and it follows the landmarks.

use bodyspace::measure::definitions::SHOULDERS;
use bodyspace::measure::{BodyMeasurer, Measure, MeasureParams};
use std::f64::consts::{PI, TAU};

mod measure_support;
use measure_support::ring_surface;

/// Rings every STEP from BOTTOM, AROUND vertices each.
const STEP: f64 = 0.002;
const BOTTOM: f64 = 1.20;
const RINGS: usize = 301;
const AROUND: usize = 128;
/// The torso's semi-axes (outward, front–back), up to TORSO_TOP, then narrowing into the neck.
const TORSO: (f64, f64) = (0.16, 0.11);
const TORSO_TOP: f64 = 1.38;
/// The neck: an elliptic cylinder from NECK_BOTTOM to NECK_TOP, then the head.
const NECK_A: f64 = 0.055;
const NECK_B: f64 = 0.05;
const NECK_BOTTOM: f64 = 1.42;
const NECK_TOP: f64 = 1.60;

fn height(i: usize) -> f64 {
    BOTTOM + STEP * i as f64
}

/// Semi-axes (outward, front–back) of the ring at height y.
fn radii(y: f64) -> (f64, f64) {
    if y <= TORSO_TOP {
        TORSO
    } else if y < NECK_BOTTOM {
        let f = (y - TORSO_TOP) / (NECK_BOTTOM - TORSO_TOP);
        (
            TORSO.0 + f * (NECK_A - TORSO.0),
            TORSO.1 + f * (NECK_B - TORSO.1),
        )
    } else if y <= NECK_TOP {
        (NECK_A, NECK_B)
    } else {
        // The head: wider, then closing towards the crown.
        let f = ((y - NECK_TOP) / (height(RINGS - 1) - NECK_TOP)).min(1.0);
        let s = (PI * f).sin().max(0.1);
        (NECK_A + 0.03 * s, NECK_B + 0.04 * s)
    }
}

/// The body turned by `turn` radians about the vertical (facing −z at 0): positions, triangles.
fn body(turn: f64) -> (Vec<f32>, Vec<[u32; 3]>) {
    let (c, s) = (turn.cos(), turn.sin());
    let rotate = |p: [f64; 3]| [c * p[0] + s * p[2], p[1], -s * p[0] + c * p[2]];
    ring_surface(
        RINGS,
        AROUND,
        |i, t| {
            let y = height(i);
            let (a, b) = radii(y);
            rotate([a * t.cos(), y, b * t.sin()])
        },
        [0.0, BOTTOM, 0.0],
        [0.0, height(RINGS - 1), 0.0],
    )
}

/// The ring vertex at height `y` and angle index `a` (AROUND/4: the back, +z; 3·AROUND/4: the
/// front).
fn at(y: f64, a: usize) -> u32 {
    let i = ((y - BOTTOM) / STEP).round() as usize;
    (i * AROUND + a) as u32
}

/// The neck base girth with the Cervicale at `cervicale` and the Suprasternale at `front`
/// (heights), the body turned by `turn`. Every other landmark the measurer needs sits on vertex
/// 0: only this measurement is taken.
fn neck_base_girth(cervicale: f64, front: f64, turn: f64) -> f64 {
    let (p, t) = body(turn);
    let mut landmarks = vec![
        ("Cervicale".to_string(), at(cervicale, AROUND / 4)),
        ("Suprasternale".to_string(), at(front, 3 * AROUND / 4)),
        ("Rt. Tragion".to_string(), at(1.66, 0)),
        ("Lt. Tragion".to_string(), at(1.66, AROUND / 2)),
    ];
    // The other measurements' landmarks and the shoulders' frame anywhere: not measured here.
    let others = Measure::ALL
        .into_iter()
        .flat_map(|m| m.definition().landmarks.iter());
    for &name in others.chain(SHOULDERS) {
        if !landmarks.iter().any(|(n, _)| n == name) {
            landmarks.push((name.to_string(), 0));
        }
    }
    let weights = vec![[0.0, 0.0, 0.0, 1.0, 0.0, 0.0f32]; p.len() / 3];
    let measurer =
        BodyMeasurer::new(&p, &t, &weights, &landmarks, MeasureParams::default()).unwrap();
    measurer
        .measure_some(&p, &[Measure::NeckBaseGirth])
        .unwrap()
        .get(Measure::NeckBaseGirth)
        .unwrap()
}

/// The perimeter of the ellipse of semi-axes a, b (Ramanujan's second approximation: relative
/// error below 10⁻⁹ at these eccentricities).
fn ellipse(a: f64, b: f64) -> f64 {
    let h = ((a - b) / (a + b)).powi(2);
    PI * (a + b) * (1.0 + 3.0 * h / (10.0 + (4.0 - 3.0 * h).sqrt()))
}

/// The AROUND-gon inscribed in that ellipse at equal parameter steps: the section of the mesh's
/// prism.
fn inscribed(a: f64, b: f64) -> f64 {
    let p = |k: usize| {
        let t = TAU * k as f64 / AROUND as f64;
        [a * t.cos(), b * t.sin()]
    };
    (0..AROUND)
        .map(|k| {
            let (u, v) = (p(k), p(k + 1));
            (u[0] - v[0]).hypot(u[1] - v[1])
        })
        .sum()
}

/// The known girth with the Cervicale at `cervicale` and the Suprasternale at `front`: the
/// back's half of the AROUND-gon inscribed in the ellipse (the mesh's section) or of the ellipse
/// itself (`smooth`), and the two straight spans to the front.
fn want(cervicale: f64, front: f64, smooth: bool) -> f64 {
    let half = if smooth {
        ellipse(NECK_A, NECK_B) / 2.0
    } else {
        inscribed(NECK_A, NECK_B) / 2.0
    };
    let span = (NECK_A * NECK_A + NECK_B * NECK_B + (cervicale - front).powi(2)).sqrt();
    half + 2.0 * span
}

#[test]
fn the_neck_base_girth_runs_over_its_landmarks_and_the_side_neck_points() {
    for (cervicale, front) in [(1.50, 1.44), (1.51, 1.44), (1.50, 1.43), (1.48, 1.46)] {
        for turn in [0.0, 0.5] {
            let got = neck_base_girth(cervicale, front, turn);
            let mesh = want(cervicale, front, false);
            assert!(
                (got - mesh).abs() < 2e-5,
                "Cervicale {cervicale}, Suprasternale {front}, turned {turn}: {} vs the \
                 mesh's {} mm",
                got * 1e3,
                mesh * 1e3
            );
            let smooth = want(cervicale, front, true);
            assert!(
                (got - smooth).abs() < 1e-3,
                "{} vs {} mm",
                got * 1e3,
                smooth * 1e3
            );
        }
    }
    // The landmarks define it: the Suprasternale 1 cm lower lengthens both spans.
    let moved = neck_base_girth(1.50, 1.43, 0.0) - neck_base_girth(1.50, 1.44, 0.0);
    assert!((moved - (want(1.50, 1.43, true) - want(1.50, 1.44, true))).abs() < 1e-4);
    assert!(moved > 2e-3);
}
