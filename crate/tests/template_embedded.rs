//! The embedded template: landmarks, segments, flags, resolutions, orientation.
// Native only: reads files and runs the CLI (the browser tests are in web.rs).
#![cfg(not(target_arch = "wasm32"))]

use bodyspace::landmarks::CAESAR_LANDMARKS;
use bodyspace::mesh::normals::vertex_normals;
use bodyspace::mesh::volume::signed_volume;
use bodyspace::template::{Resolution, Segment, Template};

fn base() -> Template {
    Template::embedded().expect("embedded template decodes")
}

#[test]
fn has_the_73_canonical_landmarks_in_caesar_order() {
    let t = base();
    let names: Vec<&str> = t
        .landmark_vertices()
        .iter()
        .map(|(n, _)| n.as_str())
        .collect();
    let canonical: Vec<&str> = CAESAR_LANDMARKS.iter().map(|l| l.name).collect();
    assert_eq!(names, canonical);
    assert_eq!(t.landmark_positions().landmarks.len(), 73);
}

#[test]
fn landmarks_lie_in_their_segment_and_on_their_side() {
    let t = base();
    for (lm, (name, v)) in CAESAR_LANDMARKS.iter().zip(t.landmark_vertices()) {
        let w = t.segment_weights(*v);
        assert!(
            w[lm.segment.index()] > 0.0,
            "{name} (vertex {v}) is not in segment {}: weights {w:?}",
            lm.segment.name()
        );
        let x = t.mesh().positions[*v as usize].x;
        if name.starts_with("Rt. ") {
            assert!(
                x < -0.01,
                "{name} should be on the subject's right (x < 0), x = {x}"
            );
        } else if name.starts_with("Lt. ") {
            assert!(
                x > 0.01,
                "{name} should be on the subject's left (x > 0), x = {x}"
            );
        } else {
            assert!(x.abs() < 0.005, "{name} should be on the midline, x = {x}");
        }
    }
}

#[test]
fn left_right_pairs_mirror_within_3_mm() {
    let t = base();
    let lm = t.landmark_positions();
    for l in &lm.landmarks {
        if let Some(rest) = l.name.strip_prefix("Lt. ") {
            let r = lm.get(&format!("Rt. {rest}")).expect("right twin exists");
            let mirrored = nalgebra::Point3::new(-l.position.x, l.position.y, l.position.z);
            let d = (r - mirrored).norm();
            assert!(
                d < 0.003,
                "{rest}: left and right differ by {d} m from mirror images"
            );
        }
    }
}

#[test]
fn segments_cover_every_vertex_and_weights_sum_to_one() {
    let t = base();
    let n = t.mesh().vertex_count() as u32;
    let mut covered = vec![false; n as usize];
    for s in Segment::ALL {
        let vs = t.segment_vertices(s);
        assert!(vs.len() > 500, "{} has {} vertices", s.name(), vs.len());
        for v in vs {
            covered[v as usize] = true;
        }
    }
    assert!(covered.iter().all(|&c| c));
    let mut overlap = 0;
    for v in 0..n {
        let w = t.segment_weights(v);
        let sum: f32 = w.iter().sum();
        assert!((sum - 1.0).abs() < 1e-3, "vertex {v}: weights sum to {sum}");
        if w.iter().filter(|&&x| x > 0.0).count() > 1 {
            overlap += 1;
        }
    }
    // Bands exist but are bands: a few percent of the vertices.
    assert!(
        overlap > 300 && overlap < n / 3,
        "{overlap} vertices in overlap bands"
    );
    assert!((t.band_width() - 0.12).abs() < 1e-9);
}

#[test]
fn neighbouring_segments_overlap_and_weights_fall_smoothly() {
    let t = base();
    let edges = t.edges();
    let head = Segment::Head.index();
    let torso = Segment::Torso.index();
    let both = (0..t.mesh().vertex_count() as u32)
        .filter(|&v| {
            let w = t.segment_weights(v);
            w[head] > 0.0 && w[torso] > 0.0
        })
        .count();
    assert!(both > 20, "head and torso overlap on {both} vertices");
    // Smooth fall-off: a smoothstep across the band has slope ≤ 1.5 / band width, so no weight
    // may change across an edge by more than that times the edge length (plus slack for the
    // normalisation where segments meet).
    let p = &t.mesh().positions;
    let worst = edges
        .iter()
        .map(|&[a, b]| {
            let (wa, wb) = (t.segment_weights(a), t.segment_weights(b));
            let jump = (0..6).map(|k| (wa[k] - wb[k]).abs()).fold(0f32, f32::max) as f64;
            jump / ((p[a as usize] - p[b as usize]).norm() * 1.5 / t.band_width())
        })
        .fold(0f64, f64::max);
    assert!(
        worst < 3.0,
        "weight changes {worst}x faster than the smoothstep allows"
    );
}

#[test]
fn stature_orientation_and_normals() {
    let t = base();
    let m = t.mesh();
    let (min_y, max_y) = m
        .positions
        .iter()
        .fold((f64::MAX, f64::MIN), |(a, b), p| (a.min(p.y), b.max(p.y)));
    assert!(min_y.abs() < 1e-6, "feet on y = 0, min y = {min_y}");
    assert!((1.6..1.9).contains(&max_y), "stature {max_y} m");
    assert!(
        signed_volume(&m.positions, &m.triangles) > 0.03,
        "outward orientation"
    );
    let n = vertex_normals(&m.positions, &m.triangles);
    let extreme = |key: &dyn Fn(&nalgebra::Point3<f64>) -> f64| {
        (0..m.positions.len())
            .max_by(|&a, &b| key(&m.positions[a]).total_cmp(&key(&m.positions[b])))
            .unwrap()
    };
    assert!(n[extreme(&|p| p.y)].y > 0.5, "top of the head points up");
    assert!(n[extreme(&|p| p.x)].x > 0.5, "left-most point points +x");
    assert!(n[extreme(&|p| -p.x)].x < -0.5, "right-most point points -x");
    assert!(n[extreme(&|p| p.z)].z > 0.5, "front-most point points +z");
    assert!(n[extreme(&|p| -p.z)].z < -0.5, "back-most point points -z");
    // Sellion faces forward (the subject looks along +z).
    let sellion = t.landmark_vertices()[0].1 as usize;
    assert!(n[sellion].z > 0.5);
}

#[test]
fn flags_mark_hands_ears_soles_and_unseen_parts() {
    let t = base();
    let n = t.mesh().vertex_count() as u32;
    let count =
        |f: fn(bodyspace::template::RegionFlags) -> bool| (0..n).filter(|&v| f(t.flags(v))).count();
    let (hand, ear, sole, unseen) = (
        count(|f| f.hand()),
        count(|f| f.ear()),
        count(|f| f.sole()),
        count(|f| f.unseen()),
    );
    assert!(
        hand > 1000 && ear > 100 && sole > 100 && unseen > 100,
        "{hand} {ear} {sole} {unseen}"
    );
    // Hands hang at hip height, soles are on the floor, ears are on the head.
    for v in 0..n {
        let p = t.mesh().positions[v as usize];
        let f = t.flags(v);
        if f.hand() {
            assert!(p.y > 0.7 && p.y < 1.2 && p.x.abs() > 0.3);
        }
        if f.sole() {
            assert!(p.y < 0.016);
        }
        if f.ear() || f.unseen() {
            assert!(p.y > 1.4);
        }
    }
    // No landmark sits on a surface no scanner can see.
    for (name, v) in t.landmark_vertices() {
        assert!(!t.flags(*v).unseen(), "{name} is in an unseen region");
    }
}

#[test]
fn fine_resolution_keeps_base_vertices_and_landmarks() {
    let b = base();
    let f = b.at_resolution(Resolution::Fine);
    assert_eq!(f.resolution(), Resolution::Fine);
    assert!(
        f.mesh().triangle_count() >= 328_000,
        "{}",
        f.mesh().triangle_count()
    );
    assert_eq!(f.mesh().triangle_count(), 16 * b.mesh().triangle_count());
    let nb = b.mesh().vertex_count();
    assert_eq!(&f.mesh().positions[..nb], &b.mesh().positions[..]);
    assert_eq!(f.landmark_vertices(), b.landmark_vertices());
    for (lb, lf) in b
        .landmark_positions()
        .landmarks
        .iter()
        .zip(&f.landmark_positions().landmarks)
    {
        assert_eq!(lb.position, lf.position);
    }
    for v in (0..f.mesh().vertex_count() as u32).step_by(997) {
        let sum: f32 = f.segment_weights(v).iter().sum();
        assert!((sum - 1.0).abs() < 1e-3);
        let prov = f.provenance(v);
        assert!(prov.iter().all(|&(s, _)| (s as usize) < nb));
        let w: f64 = prov.iter().map(|x| x.1).sum();
        assert!((w - 1.0).abs() < 1e-9);
        if (v as usize) < nb {
            assert_eq!(prov, vec![(v, 1.0)]);
            assert_eq!(f.source_vertex(v), b.source_vertex(v));
            assert_eq!(f.flags(v), b.flags(v));
        } else {
            assert_eq!(f.source_vertex(v), None);
        }
    }
    // The subdivision operator maps the base body onto the fine body exactly.
    let s = b.subdivision(Resolution::Fine);
    let mapped = s.apply(&b.mesh().positions);
    assert_eq!(mapped, f.mesh().positions);
    assert!(signed_volume(&f.mesh().positions, &f.mesh().triangles) > 0.03);
    // Back to base gives the base again.
    assert_eq!(f.at_resolution(Resolution::Base).mesh(), b.mesh());
    assert!("medium".parse::<Resolution>().is_err());
    assert_eq!("fine".parse::<Resolution>().unwrap(), Resolution::Fine);
}

#[test]
fn broken_files_are_rejected() {
    assert!(Template::from_bytes(b"").is_err());
    assert!(Template::from_bytes(&[0x1f, 0x8b, 0, 0]).is_err());
    let bytes = base().to_bytes();
    assert!(Template::from_bytes(&bytes[..bytes.len() / 2]).is_err());
    let again = Template::from_bytes(&bytes).unwrap();
    assert_eq!(again.mesh(), base().mesh());
}

#[test]
fn virtual_landmarks_sit_where_their_rules_say() {
    let t = base();
    let v = t.virtual_landmark_vertices().unwrap();
    assert_eq!(v.len(), bodyspace::landmarks::VIRTUAL_LANDMARK_COUNT);
    let p = |name: &str| {
        let (_, vertex) = v
            .iter()
            .find(|(n, _)| n == name)
            .unwrap_or_else(|| panic!("no virtual landmark {name}"));
        t.mesh().positions[*vertex as usize]
    };
    let stature = t
        .mesh()
        .positions
        .iter()
        .map(|p| p.y)
        .fold(f64::MIN, f64::max);
    assert!(stature - p("virtual: top of head").y < 0.01);
    for (side, sign) in [("left", 1.0), ("right", -1.0)] {
        assert!(p(&format!("virtual: sole, {side}")).y < 0.02);
        for limb in [
            "mid upper arm",
            "mid forearm",
            "mid-thigh",
            "mid-shank",
            "sole",
        ] {
            let x = p(&format!("virtual: {limb}, {side}")).x;
            assert!(x * sign > 0.05, "{limb}, {side} at x = {x}");
        }
    }
    let seat = p("virtual: buttocks");
    assert!(seat.x.abs() < 0.03 && seat.z < -0.03, "buttocks at {seat}");
    // The same rules run on the fine template give the same points (base vertices come first
    // and new vertices lie between them).
    let f = t.at_resolution(Resolution::Fine);
    let vf = f.virtual_landmark_vertices().unwrap();
    for ((n, a), (_, b)) in v.iter().zip(&vf) {
        let d = (t.mesh().positions[*a as usize] - f.mesh().positions[*b as usize]).norm();
        assert!(d < 0.02, "{n} moves {d} m between resolutions");
    }
}
