//! The 12 virtual landmarks that complete the 73 CAESAR ones (paper §3.1.2, n = 85): points the
//! RBF needs where anatomy gives no landmark — top of the head, long-bone mid-segments, soles,
//! buttocks. Each is built from the 73 and snapped to the given surface by the same rule on the
//! template and on a scan, so the pair corresponds. Definitions and rules: docs/rbf.md.

use nalgebra::{Point3, Unit, Vector3};

use crate::landmarks::{Landmark, LandmarkSet};
use crate::mesh::Mesh;

/// Prefix of every virtual landmark name, e.g. `virtual: mid-thigh, left`.
pub const VIRTUAL_PREFIX: &str = "virtual: ";

/// Number of virtual landmarks made when all their CAESAR sources are present.
pub const VIRTUAL_LANDMARK_COUNT: usize = 12;

/// A virtual landmark and how it was placed.
#[derive(Debug, Clone, PartialEq)]
pub struct VirtualLandmark {
    pub landmark: Landmark,
    /// False when no surface point satisfied the rule (a hole, e.g. an unscanned head top or
    /// sole) and the constructed point itself was kept.
    pub on_surface: bool,
}

/// The virtual landmarks of `landmarks` on `surface`, in its frame and units.
///
/// A virtual landmark whose CAESAR sources are missing from `landmarks` is left out; one whose
/// snap rule finds no surface point keeps its constructed point (see [`virtual_landmarks_detailed`]).
pub fn virtual_landmarks(landmarks: &LandmarkSet, surface: &Mesh) -> Vec<Landmark> {
    virtual_landmarks_detailed(landmarks, surface)
        .into_iter()
        .map(|v| v.landmark)
        .collect()
}

type Direction = Unit<Vector3<f64>>;

/// How a constructed point becomes a surface point.
enum Snap {
    /// The surface vertex nearest to the constructed point.
    Nearest,
    /// Where the ray from the anchor along `axis` leaves the body: the surface vertex ahead of
    /// the anchor nearest to the ray line, if that distance is below `radius` (a larger one
    /// means the ray leaves through a hole). `radius` is a quarter of a nearby landmark
    /// distance, so the rule has no absolute length. Unlike "the extreme vertex along the
    /// axis" this is well posed on flat parts such as the soles.
    Ray {
        axis: Unit<Vector3<f64>>,
        radius: f64,
    },
}

/// [`virtual_landmarks`] with the on-surface flag of each point.
pub fn virtual_landmarks_detailed(landmarks: &LandmarkSet, surface: &Mesh) -> Vec<VirtualLandmark> {
    let get = |name: &str| landmarks.get(name);
    let mid = |a: &str, b: &str| Some(nalgebra::center(&get(a)?, &get(b)?));
    let frame = body_frame(landmarks);
    let mut out = Vec::with_capacity(VIRTUAL_LANDMARK_COUNT);
    // constructed = (anchor of the snap rule, fallback point, rule)
    let mut push = |name: String, constructed: Option<(Point3<f64>, Point3<f64>, Snap)>| {
        if let Some((anchor, fallback, snap)) = constructed {
            let (position, on_surface) = match snap_point(surface, &anchor, &snap) {
                Some(p) => (p, true),
                None => (fallback, false),
            };
            out.push(VirtualLandmark {
                landmark: Landmark { name, position },
                on_surface,
            });
        }
    };

    // Top of the head: where the ray "up" from between the ears leaves the head (within a
    // quarter head breadth). Fallback 0.85 head breadths above the tragion midpoint (≈ vertex
    // height on adults).
    if let Some((up, _)) = frame {
        let head = (|| {
            let (r, l) = (get("Rt. Tragion")?, get("Lt. Tragion")?);
            let anchor = nalgebra::center(&r, &l);
            let breadth = (l - r).norm();
            let snap = Snap::Ray {
                axis: up,
                radius: 0.25 * breadth,
            };
            Some((anchor, anchor + up.into_inner() * 0.85 * breadth, snap))
        })();
        push(format!("{VIRTUAL_PREFIX}top of head"), head);
    }
    for (side, pre) in [("right", "Rt."), ("left", "Lt.")] {
        let n = |s: &str| format!("{pre} {s}");
        let pairs = [
            // Pairs on the same side of one straight bone, so the midpoint lies just under the
            // skin and its nearest vertex is well defined (the ulna is subcutaneous along its
            // whole back edge).
            ("mid upper arm", "Acromion", "Humeral Lateral Epicn"),
            ("mid forearm", "Olecranon", "Ulnar Styloid"),
            ("mid-thigh", "Trochanterion", "Femoral Lateral Epicn"),
            ("mid-shank", "Femoral Lateral Epicn", "Lateral Malleolus"),
        ];
        for (what, a, b) in pairs {
            let m = mid(&n(a), &n(b));
            push(
                format!("{VIRTUAL_PREFIX}{what}, {side}"),
                m.map(|m| (m, m, Snap::Nearest)),
            );
        }
        // Sole: where the ray "down" from the centroid of the foot's three landmarks leaves the
        // foot (within a quarter forefoot breadth); fallback 0.4 forefoot breadths below them
        // (the landmarks sit ≈ 3–5 cm above the floor).
        if let Some((up, _)) = frame {
            let sole = (|| {
                let (c, m1, m5) = (
                    get(&n("Calcaneous, Post."))?,
                    get(&n("Metatarsal Phal. I"))?,
                    get(&n("Metatarsal Phal. V"))?,
                );
                let anchor = Point3::from((c.coords + m1.coords + m5.coords) / 3.0);
                let breadth = (m1 - m5).norm();
                let snap = Snap::Ray {
                    axis: -up,
                    radius: 0.25 * breadth,
                };
                Some((anchor, anchor - up.into_inner() * 0.4 * breadth, snap))
            })();
            push(format!("{VIRTUAL_PREFIX}sole, {side}"), sole);
        }
    }
    // Buttocks: where the ray "backwards" from halfway between the PSIS midpoint and the
    // crotch leaves the body (within a quarter PSIS distance); fallback that halfway point.
    if let Some((_, forward)) = frame {
        let seat = (|| {
            let (r, l) = (get("Rt. PSIS")?, get("Lt. PSIS")?);
            let a = nalgebra::center(&nalgebra::center(&r, &l), &get("Crotch")?);
            let snap = Snap::Ray {
                axis: -forward,
                radius: 0.25 * (l - r).norm(),
            };
            Some((a, a, snap))
        })();
        push(format!("{VIRTUAL_PREFIX}buttocks"), seat);
    }
    out
}

/// Body axes from the landmarks: up = ankles → ears, forward = left × up with left = right →
/// left acromion. `None` when a source landmark is missing or the axes are degenerate.
fn body_frame(l: &LandmarkSet) -> Option<(Direction, Direction)> {
    let ears = nalgebra::center(&l.get("Rt. Tragion")?, &l.get("Lt. Tragion")?);
    let ankles = nalgebra::center(
        &l.get("Rt. Lateral Malleolus")?,
        &l.get("Lt. Lateral Malleolus")?,
    );
    let up = Unit::try_new(ears - ankles, 1e-12 * (ears - ankles).norm().max(1e-300))?;
    let across = l.get("Lt. Acromion")? - l.get("Rt. Acromion")?;
    let left = across - up.into_inner() * across.dot(&up);
    let forward = Unit::try_new(left.cross(&up), 1e-12 * across.norm().max(1e-300))?;
    Some((up, forward))
}

fn snap_point(surface: &Mesh, anchor: &Point3<f64>, snap: &Snap) -> Option<Point3<f64>> {
    match snap {
        Snap::Nearest => surface
            .positions
            .iter()
            .min_by(|a, b| {
                (*a - anchor)
                    .norm_squared()
                    .total_cmp(&(*b - anchor).norm_squared())
            })
            .copied(),
        Snap::Ray { axis, radius } => {
            let r2_max = radius * radius;
            let mut best: Option<(f64, Point3<f64>)> = None;
            for p in &surface.positions {
                let d = p - anchor;
                let along = d.dot(axis);
                if along <= 0.0 {
                    continue;
                }
                // Squared distance from the ray line.
                let off = d.norm_squared() - along * along;
                if off <= r2_max && best.is_none_or(|(b, _)| off < b) {
                    best = Some((off, *p));
                }
            }
            best.map(|(_, p)| p)
        }
    }
}
