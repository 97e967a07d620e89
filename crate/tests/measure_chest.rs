//! The chest girth under the armpits (docs/measurements.md, body-defined measurements) on a body
//! with known answers: a tapering elliptic torso with two cylindrical arms that part from it at
//! a known armpit apex. The apex is found within a millimetre, the tape goes around the torso
//! alone at `chest_below_armpit` under it, and moving the axilla landmarks 2 cm moves the girth
//! at most 2 mm.

use bodyspace::measure::definitions::SHOULDERS;
use bodyspace::measure::parting::{parting_level, torso_alone, PartingSearch};
use bodyspace::measure::tape::{tape, LoopChoice};
use bodyspace::measure::{plane_section, BodyMeasurer, Measure, MeasureParams, Plane};

const STEP: f64 = 0.005;
/// Rings from y = BOTTOM every STEP; ring APEX_RING is the armpits' apex (the arms join the torso
/// there), TOP_RING the last.
const BOTTOM: f64 = 0.9;
const APEX_RING: usize = 80;
const TOP_RING: usize = 110;
/// Vertices around the torso (T) and around each arm (R).
const T: usize = 96;
const R: usize = 24;
/// The arms' radius and their axes' distance from the body's midline.
const ARM_R: f64 = 0.045;
const ARM_X: f64 = 0.23;

fn height(i: usize) -> f64 {
    BOTTOM + STEP * i as f64
}

fn apex() -> f64 {
    height(APEX_RING)
}

/// The torso's semi-axes at height y (x: sideways, z: front–back), tapering downwards.
fn torso_axes(y: f64) -> (f64, f64) {
    (0.13 + 0.1 * (y - 1.0), 0.10 + 0.05 * (y - 1.0))
}

/// A vertex slot of the ring that goes around torso and arms (at and above the apex); the
/// subject's right is +x, the back +z.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Slot {
    /// Torso at angle 2πj/T: (a cos, c sin).
    Torso(usize),
    /// Right (true) or left arm at angle 2πj/R around its axis (±ARM_X, 0).
    Arm(bool, usize),
    /// The armpit's fold between torso and arm (right?, back?).
    Fold(bool, bool),
}

/// The joined ring's slots, counter-clockwise seen from above: torso's back, left arm, torso's
/// front, right arm, each arm's inner vertex and the torso's side vertex replaced by two folds.
fn joined_ring() -> Vec<Slot> {
    let mut s = vec![Slot::Fold(true, true)];
    s.extend((1..T / 2).map(Slot::Torso));
    s.push(Slot::Fold(false, true));
    s.extend((1..R).map(|j| Slot::Arm(false, j)));
    s.push(Slot::Fold(false, false));
    s.extend((T / 2 + 1..T).map(Slot::Torso));
    s.push(Slot::Fold(true, false));
    s.extend((R / 2 + 1..R).chain(0..R / 2).map(|j| Slot::Arm(true, j)));
    s
}

fn position(slot: Slot, i: usize) -> [f64; 3] {
    let y = height(i);
    let (a, c) = torso_axes(y);
    let tau = std::f64::consts::TAU;
    match slot {
        Slot::Torso(j) => {
            let t = tau * j as f64 / T as f64;
            [a * t.cos(), y, c * t.sin()]
        }
        Slot::Arm(right, j) => {
            let t = tau * j as f64 / R as f64;
            let x = if right { ARM_X } else { -ARM_X };
            [x + ARM_R * t.cos(), y, ARM_R * t.sin()]
        }
        Slot::Fold(right, back) => {
            // In the gap between torso and arm; apart above the apex, one point at it.
            let x = (a + ARM_X - ARM_R) / 2.0;
            let z = 0.04 * ((y - apex()) / 0.03).min(1.0);
            [if right { x } else { -x }, y, if back { z } else { -z }]
        }
    }
}

/// Positions, triangles and per-vertex segment weights of the body.
fn body() -> (Vec<f32>, Vec<[u32; 3]>, Vec<[f32; 6]>) {
    const LEFT_ARM: [f32; 6] = [0.0, 1.0, 0.0, 0.0, 0.0, 0.0];
    const RIGHT_ARM: [f32; 6] = [0.0, 0.0, 1.0, 0.0, 0.0, 0.0];
    const TORSO: [f32; 6] = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0];
    let ring = joined_ring();
    let (mut p, mut w): (Vec<f32>, Vec<[f32; 6]>) = (Vec::new(), Vec::new());
    let add = |p: &mut Vec<f32>, w: &mut Vec<[f32; 6]>, q: [f64; 3], weight: [f32; 6]| {
        p.extend(q.map(|x| x as f32));
        w.push(weight);
        (w.len() - 1) as u32
    };
    let weight = |slot: Slot| match slot {
        Slot::Arm(true, _) => RIGHT_ARM,
        Slot::Arm(false, _) => LEFT_ARM,
        _ => TORSO,
    };
    // The joined rings; at the apex ring the back folds are the front ones (the pinch).
    let mut joined: Vec<Vec<u32>> = Vec::new();
    for i in APEX_RING..=TOP_RING {
        let mut ids: Vec<u32> = ring
            .iter()
            .map(|&slot| add(&mut p, &mut w, position(slot, i), weight(slot)))
            .collect();
        if i == APEX_RING {
            for right in [true, false] {
                let front = ring.iter().position(|&s| s == Slot::Fold(right, false));
                let back = ring.iter().position(|&s| s == Slot::Fold(right, true));
                ids[back.unwrap()] = ids[front.unwrap()];
            }
        }
        joined.push(ids);
    }
    // At the apex ring, the torso's and the arms' loops as seen from below.
    let at_apex = |slot: Slot| joined[0][ring.iter().position(|&s| s == slot).unwrap()];
    let torso_top: Vec<u32> = (0..T)
        .map(|j| match j {
            0 => at_apex(Slot::Fold(true, false)),
            j if j == T / 2 => at_apex(Slot::Fold(false, false)),
            j => at_apex(Slot::Torso(j)),
        })
        .collect();
    let arm_top = |right: bool| -> Vec<u32> {
        let inner = if right { R / 2 } else { 0 };
        (0..R)
            .map(|j| match j {
                j if j == inner => at_apex(Slot::Fold(right, false)),
                j => at_apex(Slot::Arm(right, j)),
            })
            .collect()
    };
    let mut parts: Vec<Vec<Vec<u32>>> = Vec::new();
    for (slots, top) in [
        ((0..T).map(Slot::Torso).collect::<Vec<_>>(), torso_top),
        ((0..R).map(|j| Slot::Arm(true, j)).collect(), arm_top(true)),
        (
            (0..R).map(|j| Slot::Arm(false, j)).collect(),
            arm_top(false),
        ),
    ] {
        let mut rings: Vec<Vec<u32>> = (0..APEX_RING)
            .map(|i| {
                slots
                    .iter()
                    .map(|&s| add(&mut p, &mut w, position(s, i), weight(s)))
                    .collect()
            })
            .collect();
        rings.push(top);
        parts.push(rings);
    }
    let mut t: Vec<[u32; 3]> = Vec::new();
    let strip = |t: &mut Vec<[u32; 3]>, lo: &[u32], up: &[u32]| {
        let n = lo.len();
        for a in 0..n {
            let b = (a + 1) % n;
            for tri in [[lo[a], up[a], up[b]], [lo[a], up[b], lo[b]]] {
                if tri[0] != tri[1] && tri[1] != tri[2] && tri[0] != tri[2] {
                    t.push(tri);
                }
            }
        }
    };
    for k in 1..joined.len() {
        strip(&mut t, &joined[k - 1], &joined[k]);
    }
    let top = joined.last().unwrap().clone();
    let top_pole = add(&mut p, &mut w, [0.0, height(TOP_RING) + STEP, 0.0], TORSO);
    for a in 0..top.len() {
        t.push([top_pole, top[(a + 1) % top.len()], top[a]]);
    }
    for rings in &parts {
        for k in 1..rings.len() {
            strip(&mut t, &rings[k - 1], &rings[k]);
        }
        let first = &rings[0];
        let centre = [0, 1, 2].map(|k| {
            first
                .iter()
                .map(|&v| p[3 * v as usize + k] as f64)
                .sum::<f64>()
                / first.len() as f64
        });
        let weight = w[first[0] as usize];
        let pole = add(
            &mut p,
            &mut w,
            [centre[0], centre[1] - STEP, centre[2]],
            weight,
        );
        for a in 0..first.len() {
            t.push([pole, first[a], first[(a + 1) % first.len()]]);
        }
    }
    (p, t, w)
}

/// The nearest vertex to `q`.
fn nearest(p: &[f32], q: [f64; 3]) -> u32 {
    (0..p.len() / 3)
        .min_by(|&a, &b| {
            let d = |v: usize| {
                (0..3)
                    .map(|k| (p[3 * v + k] as f64 - q[k]).powi(2))
                    .sum::<f64>()
            };
            d(a).total_cmp(&d(b))
        })
        .unwrap() as u32
}

/// The torso's point at height y and angle index j (of T).
fn on_torso(y: f64, j: usize) -> [f64; 3] {
    let (a, c) = torso_axes(y);
    let t = std::f64::consts::TAU * j as f64 / T as f64;
    [a * t.cos(), y, c * t.sin()]
}

/// Every landmark the measurer needs, the axillae `moved` metres up from 1 cm over the apex
/// (where the bodies' axilla landmarks sit: 1–4 cm over their apex).
fn landmarks(p: &[f32], moved: f64) -> Vec<(String, u32)> {
    let axilla = apex() + 0.01 + moved;
    let (back, front) = (T / 4, 3 * T / 4);
    let on = |y: f64, j: usize| nearest(p, on_torso(y, j));
    [
        ("Rt. Axilla, Ant.", on(axilla, front + 6)),
        ("Lt. Axilla, Ant.", on(axilla, front - 6)),
        ("Rt. Axilla, Post.", on(axilla, back - 6)),
        ("Lt. Axilla, Post.", on(axilla, back + 6)),
    ]
    .into_iter()
    .map(|(n, v)| (n.to_string(), v))
    .chain(
        // The other measurements' landmarks (and the shoulders' frame, `SHOULDERS`) anywhere on
        // the torso, under the armpits.
        Measure::ALL
            .iter()
            .flat_map(|m| m.definition().landmarks.iter().copied())
            .chain(SHOULDERS.iter().copied())
            .filter(|n| !n.contains("Axilla"))
            .collect::<std::collections::BTreeSet<&str>>()
            .into_iter()
            .enumerate()
            .map(|(k, n)| (n.to_string(), on(1.0 + 0.005 * k as f64, k))),
    )
    .collect()
}

fn chest(moved: f64) -> f64 {
    let (p, t, w) = body();
    let measurer =
        BodyMeasurer::new(&p, &t, &w, &landmarks(&p, moved), MeasureParams::default()).unwrap();
    measurer
        .measure_some(&p, &[Measure::ChestGirth])
        .unwrap()
        .get(Measure::ChestGirth)
        .unwrap()
}

/// The tape around the loop containing the body's axis at height y, of every triangle.
fn tape_at(y: f64) -> f64 {
    let (p, t, _) = body();
    let all: Vec<u32> = (0..t.len() as u32).collect();
    let plane = Plane::horizontal(1, y);
    let loops = plane_section(&p, &t, &all, &plane);
    tape(&loops, LoopChoice::Around([0.0, 0.0])).unwrap().girth
}

/// The armpits' apex sought around `centre` from the landmarks' `guess`, as the chest girth does.
fn armpit_level(
    p: &[f32],
    t: &[[u32; 3]],
    region: &[u32],
    centre: [f64; 3],
    guess: f64,
    params: &MeasureParams,
) -> Option<f64> {
    let search = PartingSearch {
        region,
        centre,
        lateral: [1.0, 0.0, 0.0],
        guess,
        above: params.armpit_band_above,
        below: params.armpit_band_below,
    };
    parting_level(p, t, &search, torso_alone, params)
}

fn mm(x: f64) -> f64 {
    x * 1e3
}

#[test]
fn the_armpits_apex_is_where_the_arms_part_from_the_torso() {
    let (p, t, _) = body();
    let all: Vec<u32> = (0..t.len() as u32).collect();
    let params = MeasureParams::default();
    for guess in [apex() - 0.03, apex() - 0.01, apex() + 0.01] {
        let centre = [0.0, guess, 0.02];
        let found = armpit_level(&p, &t, &all, centre, guess, &params).unwrap();
        assert!(
            (found - apex()).abs() <= 0.001,
            "guess {guess}: apex found at {found}, it is at {}",
            apex()
        );
    }
    // A band that does not hold the apex finds nothing.
    let low = apex() - params.armpit_band_above - 0.01;
    let centre = [0.0, low, 0.0];
    assert_eq!(armpit_level(&p, &t, &all, centre, low, &params), None);
}

#[test]
fn the_chest_girth_is_the_torsos_alone_under_the_armpits() {
    let level = apex() - MeasureParams::default().chest_below_armpit;
    let want = tape_at(level);
    let (a, c) = torso_axes(level);
    // The torso's ellipse (Ramanujan), to the polygon's sampling: no arm in the tape.
    let h = ((a - c) / (a + c)).powi(2);
    let ellipse =
        std::f64::consts::PI * (a + c) * (1.0 + 3.0 * h / (10.0 + (4.0 - 3.0 * h).sqrt()));
    assert!(
        (want - ellipse).abs() < 0.001,
        "{} vs {}",
        mm(want),
        mm(ellipse)
    );
    let got = chest(0.0);
    assert!(
        (got - want).abs() < 0.001,
        "chest {} mm, the torso's girth under the armpits {} mm",
        mm(got),
        mm(want)
    );
    // Just over the apex the loop around the torso goes around both arms too.
    assert!(tape_at(apex() + 0.005) > want + 0.1);
    for moved in [-0.02, 0.02] {
        let m = chest(moved);
        assert!(
            (m - got).abs() <= 0.002,
            "axillae moved {moved} m: chest {} vs {} mm",
            mm(m),
            mm(got)
        );
    }
}
