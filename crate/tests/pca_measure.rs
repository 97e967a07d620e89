//! End-to-end: measurements on analytic shapes.

use bodyspace::pca::measure::{girth_at, measure, MeasureLandmarks, MeasureParams};

/// A closed cylinder of radius r (64 around, 20 rings, y from 0 to h), flat positions.
fn cylinder(r: f64, h: f64) -> (Vec<f32>, Vec<[u32; 3]>) {
    let (rings, around) = (20usize, 64usize);
    let mut p = Vec::new();
    for i in 0..rings {
        let y = h * i as f64 / (rings - 1) as f64;
        for a in 0..around {
            let t = std::f64::consts::TAU * a as f64 / around as f64;
            p.extend([(r * t.cos()) as f32, y as f32, (r * t.sin()) as f32]);
        }
    }
    let mut t = Vec::new();
    for i in 0..rings - 1 {
        for a in 0..around {
            let v = |i: usize, a: usize| (i * around + a % around) as u32;
            t.push([v(i, a), v(i + 1, a), v(i + 1, a + 1)]);
            t.push([v(i, a), v(i + 1, a + 1), v(i, a + 1)]);
        }
    }
    (p, t)
}

#[test]
fn cylinder_girth_is_two_pi_r() {
    let r = 0.15;
    let (p, t) = cylinder(r, 1.0);
    let all: Vec<u32> = (0..t.len() as u32).collect();
    for h in [0.1, 0.37, 0.5, 0.93] {
        let g = girth_at(&p, &t, &all, 1, h).unwrap();
        let expected = std::f64::consts::TAU * r;
        assert!(
            (g.girth - expected).abs() < 0.01 * expected,
            "girth {} at {h}",
            g.girth
        );
        assert!((g.loop_length - g.girth).abs() < 1e-6);
    }
    // Above the top there is nothing to cut.
    assert!(girth_at(&p, &t, &all, 1, 1.5).is_none());
}

#[test]
fn concave_section_is_measured_like_a_tape() {
    // Two cylinders side by side (touching at x = 0) cut together: the loops are separate, the
    // largest is one cylinder; the convex hull of one circle is the circle itself.
    let (mut p, mut t) = cylinder(0.1, 1.0);
    let n = (p.len() / 3) as u32;
    let (q, u) = cylinder(0.12, 1.0);
    p.extend(q.chunks_exact(3).flat_map(|c| [c[0] + 0.5, c[1], c[2]]));
    t.extend(u.iter().map(|tri| tri.map(|i| i + n)));
    let all: Vec<u32> = (0..t.len() as u32).collect();
    let g = girth_at(&p, &t, &all, 1, 0.5).unwrap();
    assert!((g.girth - std::f64::consts::TAU * 0.12).abs() < 0.01 * std::f64::consts::TAU * 0.12);
}

#[test]
fn stature_inseam_and_arm_length_from_landmark_vertices() {
    let (p, t) = cylinder(0.15, 1.8);
    let all: Vec<u32> = (0..t.len() as u32).collect();
    // Ring i starts at vertex 64·i; ring 10 is at 1.8·10/19 m.
    let landmarks = MeasureLandmarks {
        chest: vec![64 * 15, 64 * 15 + 32],
        waist: vec![64 * 12],
        hip: vec![64 * 9],
        arm: vec![0, 64 * 19, 64 * 19 + 32],
        crotch: 64 * 10,
    };
    let m = measure(&p, &t, &all, &landmarks, &MeasureParams::default()).unwrap();
    assert!((m.stature - 1.8).abs() < 1e-6);
    assert!((m.inseam - 1.8 * 10.0 / 19.0).abs() < 1e-6);
    assert!(
        (m.arm_length - (1.8f64.hypot(0.0) + 0.3)).abs() < 1e-5,
        "arm {}",
        m.arm_length
    );
    let chest = m.chest.unwrap();
    assert!((chest.height - 1.8 * 15.0 / 19.0).abs() < 1e-6);
    assert!(
        (chest.girth - std::f64::consts::TAU * 0.15).abs() < 0.01 * std::f64::consts::TAU * 0.15
    );
    assert!(m.waist.is_some() && m.hip.is_some());
    let bad = MeasureLandmarks {
        crotch: 1_000_000,
        ..landmarks
    };
    assert!(measure(&p, &t, &all, &bad, &MeasureParams::default()).is_err());
}
