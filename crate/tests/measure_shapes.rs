//! Measurements on shapes with known answers: girths, volume and area of a cylinder, an
//! ellipsoid and a box (within the polygonal approximation of each mesh: tolerances given per
//! test), and every measurement of a cylinder "body" whose landmarks sit at known heights.

use bodyspace::measure::tape::{tape, LoopChoice};
use bodyspace::measure::{plane_section, BodyMeasurer, Measure, MeasureParams, Plane};
use bodyspace::mesh::volume::volume_and_area_flat;
use std::f64::consts::{PI, TAU};

mod measure_support;
use measure_support::ring_surface;

/// A closed surface of revolution around y: `rings` rings of `around` vertices, ring `i` at
/// height `y(i)` with radii `(rx(i), rz(i))`, plus a bottom and a top pole. Outward triangles.
fn revolution(
    rings: usize,
    around: usize,
    ring: impl Fn(usize) -> (f64, f64, f64),
    bottom: f64,
    top: f64,
) -> (Vec<f32>, Vec<[u32; 3]>) {
    ring_surface(
        rings,
        around,
        |i, t| {
            let (y, rx, rz) = ring(i);
            [rx * t.cos(), y, rz * t.sin()]
        },
        [0.0, bottom, 0.0],
        [0.0, top, 0.0],
    )
}

fn cylinder(r: f64, h: f64, around: usize) -> (Vec<f32>, Vec<[u32; 3]>) {
    let rings = 20;
    revolution(
        rings,
        around,
        |i| (h * i as f64 / (rings - 1) as f64, r, r),
        0.0,
        h,
    )
}

fn ellipsoid(a: f64, b: f64, c: f64) -> (Vec<f32>, Vec<[u32; 3]>) {
    let rings = 127;
    revolution(
        rings,
        256,
        |i| {
            let phi = PI * (i + 1) as f64 / (rings + 1) as f64;
            (-b * phi.cos(), a * phi.sin(), c * phi.sin())
        },
        -b,
        b,
    )
}

fn girth(p: &[f32], t: &[[u32; 3]], plane: &Plane) -> Option<f64> {
    let all: Vec<u32> = (0..t.len() as u32).collect();
    tape(&plane_section(p, t, &all, plane), LoopChoice::Largest).map(|t| t.girth)
}

fn close(got: f64, want: f64, relative: f64) -> bool {
    (got - want).abs() <= relative * want.abs()
}

#[test]
fn cylinder_girth_volume_and_area() {
    let (r, h, n) = (0.15, 1.0, 64);
    let (p, t) = cylinder(r, h, n);
    // The mesh is a 64-gon prism: its exact perimeter, area and volume.
    let polygon = n as f64 * 2.0 * r * (PI / n as f64).sin();
    let section = 0.5 * n as f64 * r * r * (TAU / n as f64).sin();
    for y in [0.1, 0.37, 0.93] {
        let g = girth(&p, &t, &Plane::horizontal(1, y)).unwrap();
        assert!((g - polygon).abs() < 1e-6, "girth {g} at {y}");
        assert!(close(g, TAU * r, 0.002));
    }
    // Tilted by 30° the section is an ellipse with semi-axes r and r / cos 30°.
    let tilt = 30f64.to_radians();
    let g = girth(
        &p,
        &t,
        &Plane::new([0.0, 0.5, 0.0], [tilt.sin(), tilt.cos(), 0.0]).unwrap(),
    );
    let (a, b) = (r / tilt.cos(), r);
    let hh = ((a - b) / (a + b)).powi(2);
    let ramanujan = PI * (a + b) * (1.0 + 3.0 * hh / (10.0 + (4.0 - 3.0 * hh).sqrt()));
    assert!(close(g.unwrap(), ramanujan, 0.003), "tilted girth {g:?}");
    // Above the top there is nothing to cut.
    assert!(girth(&p, &t, &Plane::horizontal(1, 1.5)).is_none());
    let (volume, area) = volume_and_area_flat(&p, &t);
    assert!(close(volume, section * h, 1e-6), "volume {volume}");
    assert!(
        close(area, polygon * h + 2.0 * section, 1e-6),
        "area {area}"
    );
}

#[test]
fn ellipsoid_girth_and_volume() {
    let (a, b, c) = (0.2, 0.5, 0.1);
    let (p, t) = ellipsoid(a, b, c);
    for y in [-0.3, 0.0, 0.25] {
        let s = (1.0 - (y / b) * (y / b)).sqrt();
        let (ra, rc) = (a * s, c * s);
        let hh = ((ra - rc) / (ra + rc)).powi(2);
        let want = PI * (ra + rc) * (1.0 + 3.0 * hh / (10.0 + (4.0 - 3.0 * hh).sqrt()));
        let g = girth(&p, &t, &Plane::horizontal(1, y)).unwrap();
        assert!(close(g, want, 0.002), "girth {g} vs {want} at {y}");
    }
    let (volume, _) = volume_and_area_flat(&p, &t);
    assert!(
        close(volume, 4.0 / 3.0 * PI * a * b * c, 0.002),
        "volume {volume}"
    );
    // A sphere's area is known exactly: 4πr².
    let (p, t) = ellipsoid(0.3, 0.3, 0.3);
    let (_, area) = volume_and_area_flat(&p, &t);
    assert!(close(area, 4.0 * PI * 0.09, 0.002), "sphere area {area}");
}

/// An axis-aligned box `[0, x]·[0, y]·[0, z]`, each face split into 2×2 squares, the faces
/// sharing their edge vertices (a closed surface).
fn boxed(size: [f64; 3]) -> (Vec<f32>, Vec<[u32; 3]>) {
    let mut p: Vec<f32> = Vec::new();
    let mut index = std::collections::HashMap::new();
    let mut tri = Vec::new();
    // Six faces: (fixed axis, at max?, the two in-face axes ordered for an outward normal).
    for (k, high) in [
        (0, false),
        (0, true),
        (1, false),
        (1, true),
        (2, false),
        (2, true),
    ] {
        let (mut u, mut v) = ((k + 1) % 3, (k + 2) % 3);
        if !high {
            std::mem::swap(&mut u, &mut v);
        }
        let mut at = |i: u32, j: u32| {
            let mut q = [0u32; 3];
            q[k] = if high { 2 } else { 0 };
            q[u] = i;
            q[v] = j;
            *index.entry(q).or_insert_with(|| {
                p.extend([0, 1, 2].map(|d| (size[d] * q[d] as f64 / 2.0) as f32));
                (p.len() / 3 - 1) as u32
            })
        };
        for i in 0..2 {
            for j in 0..2 {
                let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
                tri.push([a, b, c]);
                tri.push([a, c, d]);
            }
        }
    }
    (p, tri)
}

#[test]
fn box_girth_volume_and_area() {
    let s = [0.3, 1.2, 0.2];
    let (p, t) = boxed(s);
    let g = girth(&p, &t, &Plane::horizontal(1, 0.4)).unwrap();
    assert!((g - 2.0 * (s[0] + s[2])).abs() < 1e-6, "girth {g}");
    let (volume, area) = volume_and_area_flat(&p, &t);
    assert!(
        (volume - s[0] * s[1] * s[2]).abs() < 1e-7,
        "volume {volume}"
    );
    let want = 2.0 * (s[0] * s[1] + s[1] * s[2] + s[2] * s[0]);
    assert!((area - want).abs() < 1e-6, "area {area}");
}

#[test]
fn every_measurement_of_a_cylinder_body() {
    // A 1.8 m cylinder of radius 0.15 m; ring i (64 vertices from 64·i) at 1.8·i/19 m, every
    // vertex torso: the torso girths, the thigh (cut from torso and legs) and the neck (head and
    // torso) go around the cylinder; the upper arm and the head (no triangles of their segment)
    // must be `None`.
    let (r, h, n) = (0.15, 1.8, 64usize);
    let (p, t) = cylinder(r, h, n);
    let v = p.len() / 3;
    let mut weights = vec![[0.0f32; 6]; v];
    for w in &mut weights {
        w[3] = 1.0;
    }
    let ring = |i: usize, a: usize| (n * i + a) as u32;
    let height = |i: usize| h * i as f64 / 19.0;
    let names: Vec<(String, u32)> = [
        ("Cervicale", ring(17, 16)),
        ("Rt. Acromion", ring(16, 0)),
        ("Lt. Acromion", ring(16, 32)),
        ("Crotch", ring(8, 0)),
        ("Rt. Femoral Lateral Epicn", ring(5, 0)),
        ("Rt. Femoral Medial Epicn", ring(5, 8)),
        ("Rt. Axilla, Ant.", ring(15, 0)),
        ("Lt. Axilla, Ant.", ring(15, 8)),
        ("Rt. Axilla, Post.", ring(15, 16)),
        ("Lt. Axilla, Post.", ring(15, 24)),
        ("Rt. Thelion/Bustpoint", ring(14, 0)),
        ("Lt. Thelion/Bustpoint", ring(14, 8)),
        ("Substernale", ring(13, 0)),
        ("Rt. 10th Rib", ring(12, 0)),
        ("Lt. 10th Rib", ring(12, 8)),
        ("Rt. Iliocristale", ring(10, 0)),
        ("Lt. Iliocristale", ring(10, 8)),
        ("Rt. Trochanterion", ring(9, 0)),
        ("Lt. Trochanterion", ring(9, 32)),
        ("Rt. Olecranon", ring(12, 16)),
        ("Rt. Radiale", ring(10, 0)),
        ("Rt. Radial Styloid", ring(10, 32)),
        ("Suprasternale", ring(17, 48)),
        ("Rt. ASIS", ring(9, 40)),
        ("Lt. ASIS", ring(9, 56)),
        ("Rt. Humeral Lateral Epicn", ring(12, 0)),
        ("Rt. Humeral Medial Epicn", ring(12, 4)),
        ("Lt. Humeral Lateral Epicn", ring(12, 32)),
        ("Lt. Humeral Medial Epicn", ring(12, 28)),
        ("Sellion", ring(18, 0)),
        ("Rt. Tragion", ring(18, 16)),
        ("Lt. Tragion", ring(18, 48)),
    ]
    .into_iter()
    .map(|(s, v)| (s.to_string(), v))
    .collect();
    let measurer = BodyMeasurer::new(&p, &t, &weights, &names, MeasureParams::default()).unwrap();
    let m = measurer.measure(&p).unwrap();
    let get = |k: Measure| m.get(k).unwrap_or(f64::NAN);
    let polygon = n as f64 * 2.0 * r * (PI / n as f64).sin();
    let section = 0.5 * n as f64 * r * r * (TAU / n as f64).sin();
    let exact = [
        (Measure::Stature, h),
        (Measure::CervicaleHeight, height(17)),
        (Measure::AcromionHeight, height(16)),
        (Measure::CrotchHeight, height(8)),
        (Measure::KneeHeight, height(5)),
        (Measure::ShoulderBreadth, 2.0 * r),
        (Measure::ArmLength, height(16) - height(10) + 2.0 * r),
        // Waist: midway between 10th Ribs and Iliocristales; hip: the greatest buttock
        // prominence from 6 cm under to 10 cm over the Trochanterions (ring 9): on a cylinder
        // rings 9 and 10 are equally prominent, and the prominence's cap is centred between them.
        (
            Measure::WaistToHipBack,
            (height(12) + height(10)) / 2.0 - (height(9) + height(10)) / 2.0,
        ),
        (Measure::Volume, section * h),
        (Measure::SurfaceArea, polygon * h + 2.0 * section),
    ];
    for (k, want) in exact {
        assert!((get(k) - want).abs() < 1e-5, "{k:?}: {} vs {want}", get(k));
    }
    for k in [
        Measure::ChestGirth,
        Measure::BustGirth,
        Measure::UnderbustGirth,
        Measure::WaistGirth,
        Measure::HipGirth,
        Measure::ThighGirth,
    ] {
        assert!((get(k) - polygon).abs() < 1e-6, "{k:?}: {}", get(k));
    }
    for k in [Measure::UpperArmGirth, Measure::HeadGirth] {
        assert_eq!(m.get(k), None, "{k:?} has no triangles of its segment");
    }
    // Every girth measured has a closed tape path at its plane.
    let paths = measurer.tape_paths(&p).unwrap();
    assert_eq!(
        paths.len(),
        8,
        "five torso girths, the thigh (torso and legs), the neck and the neck base (head and torso)"
    );
    // Bad input is refused with a message, not a panic.
    assert!(measurer.measure(&p[..p.len() - 3]).is_err());
    let mut nan = p.clone();
    nan[7] = f32::NAN;
    assert!(measurer.measure(&nan).is_err());
    let missing: Vec<(String, u32)> = names[1..].to_vec();
    let e = BodyMeasurer::new(&p, &t, &weights, &missing, MeasureParams::default()).unwrap_err();
    assert!(e.to_string().contains("Cervicale"), "{e}");
}
