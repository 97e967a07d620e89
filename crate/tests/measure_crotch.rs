//! The crotch found where the legs part (docs/measurements.md, body-defined measurements): on a
//! body with a known answer — two leg tubes under a pelvis tube — the level is found within a
//! millimetre, also with the thighs pressed into each other; and on the template, moving the
//! Crotch landmark 2 cm moves crotch height and thigh girth at most 2 mm.

use bodyspace::measure::parting::{legs_apart, parting_level, PartingSearch};
use bodyspace::measure::{BodyMeasurer, Measure, MeasureParams};
use bodyspace::template::Template;

mod measure_support;
use measure_support::ring_surface;

/// Where the legs end and the pelvis begins, the pelvis's top, the legs' radius.
const CROTCH: f64 = 0.80;
const PELVIS_TOP: f64 = 1.10;
const LEG_R: f64 = 0.07;

/// A closed vertical tube of radius `r` around (x, ·, 0) from `y0` to `y1`, appended to `p`, `t`.
fn tube(p: &mut Vec<f32>, t: &mut Vec<[u32; 3]>, x: f64, r: f64, y0: f64, y1: f64) {
    const RINGS: usize = 61;
    let y = |i: usize| y0 + (y1 - y0) * i as f64 / (RINGS - 1) as f64;
    let (q, tri) = ring_surface(
        RINGS,
        48,
        |i, a| [x + r * a.cos(), y(i), r * a.sin()],
        [x, y0, 0.0],
        [x, y1, 0.0],
    );
    let base = (p.len() / 3) as u32;
    p.extend(q);
    t.extend(tri.into_iter().map(|f| f.map(|v| v + base)));
}

/// The legs' axes at ±`leg_x`, the pelvis above them: positions and triangles.
fn legs_and_pelvis(leg_x: f64) -> (Vec<f32>, Vec<[u32; 3]>) {
    let (mut p, mut t) = (Vec::new(), Vec::new());
    tube(&mut p, &mut t, -leg_x, LEG_R, 0.0, CROTCH);
    tube(&mut p, &mut t, leg_x, LEG_R, 0.0, CROTCH);
    tube(&mut p, &mut t, 0.0, 0.17, CROTCH, PELVIS_TOP);
    (p, t)
}

fn crotch(p: &[f32], t: &[[u32; 3]], guess: f64) -> Option<f64> {
    let region: Vec<u32> = (0..t.len() as u32).collect();
    let params = MeasureParams::default();
    let search = PartingSearch {
        region: &region,
        centre: [0.0, guess, 0.0],
        lateral: [1.0, 0.0, 0.0],
        guess,
        above: params.crotch_band_above,
        below: params.crotch_band_below,
    };
    parting_level(p, t, &search, legs_apart, &params)
}

#[test]
fn the_crotch_is_where_the_legs_part_even_when_the_thighs_press_together() {
    // Legs 4 cm apart, touching, and passing 4 cm into each other.
    for leg_x in [0.09, LEG_R, 0.05] {
        let (p, t) = legs_and_pelvis(leg_x);
        for guess in [CROTCH - 0.03, CROTCH - 0.01, CROTCH + 0.02] {
            let found = crotch(&p, &t, guess).unwrap();
            assert!(
                (found - CROTCH).abs() <= 0.001,
                "legs at ±{leg_x}, guess {guess}: crotch found at {found}, it is at {CROTCH}"
            );
        }
    }
    // A band that does not hold the crotch finds nothing.
    let (p, t) = legs_and_pelvis(0.09);
    let params = MeasureParams::default();
    assert_eq!(
        crotch(&p, &t, CROTCH + params.crotch_band_below + 0.01),
        None
    );
    assert_eq!(
        crotch(&p, &t, CROTCH - params.crotch_band_above - 0.01),
        None
    );
}

#[test]
fn moving_the_crotch_landmark_2_cm_moves_crotch_height_and_thigh_girth_at_most_2_mm() {
    let template = Template::embedded().unwrap();
    let mesh = template.mesh();
    let positions = mesh.flat_positions_f32();
    let measure = |landmarks: &[(String, u32)]| {
        let measurer = BodyMeasurer::new(
            &positions,
            &mesh.triangles,
            template.segment_weight_table(),
            landmarks,
            MeasureParams::default(),
        )
        .unwrap();
        measurer.measure(&positions).unwrap()
    };
    let landmarks = template.landmark_vertices().to_vec();
    let at_rest = measure(&landmarks);
    let crotch = landmarks.iter().position(|(n, _)| n == "Crotch").unwrap();
    let c = mesh.positions[landmarks[crotch].1 as usize];
    // A vertex 1.5–2.5 cm from the Crotch, the farthest up, forward, backward or onto the right
    // thigh (the template faces +z, its left is +x).
    for direction in [
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
        [0.0, 0.0, -1.0],
        [-1.0, 0.0, 0.0],
    ] {
        let direction = nalgebra::Vector3::from(direction);
        let nearest = (0..mesh.positions.len())
            .filter(|&v| (0.015..=0.025).contains(&(mesh.positions[v] - c).norm()))
            .max_by(|&a, &b| {
                let along = |v: usize| (mesh.positions[v] - c).dot(&direction);
                along(a).total_cmp(&along(b))
            })
            .unwrap() as u32;
        let moved_by = mesh.positions[nearest as usize] - c;
        let mut moved = landmarks.clone();
        moved[crotch].1 = nearest;
        let m = measure(&moved);
        for which in [Measure::CrotchHeight, Measure::ThighGirth] {
            let (a, b) = (at_rest.get(which).unwrap(), m.get(which).unwrap());
            assert!(
                (a - b).abs() <= 0.002,
                "{which:?}: {a} with the Crotch, {b} with it moved by {moved_by:?}"
            );
        }
    }
    // The crotch height is the parting's: under the template's Crotch vertex, not far below.
    let h = at_rest.get(Measure::CrotchHeight).unwrap();
    let floor = positions
        .chunks_exact(3)
        .map(|q| q[1] as f64)
        .fold(f64::INFINITY, f64::min);
    let below = c.y - floor - h;
    assert!(
        (-0.001..=0.01).contains(&below),
        "the parting is {below} m under the Crotch vertex"
    );
}
