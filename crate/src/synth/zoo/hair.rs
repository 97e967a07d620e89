//! Hair volume: a smooth cap over the skull, thick at the back and the top, thinner at the sides,
//! none on the face, the ears left out. The scanner sees the hair's surface, so the crown a scan
//! shows is the hair's; the truth (landmarks, template vertices) stays the body's, as a real
//! scan's would (a landmark is placed on the skin, felt through the hair).
//!
//! In the head's frame — centre `c` (the tragions' midpoint), `u` up (towards the top of the head),
//! `f` forward (towards the sellion, across `u`) — a vertex `p` with direction `d = (p − c)/|p − c|`
//! moves out along `d` by
//!
//! `t(d) = (t_side + (t_top − t_side)·s(max(d·u, −d·f))) · s((d·u − h(d·f)) / w + ½) · w_head(p)`
//!
//! with `s(x) = 3x² − 2x³` on [0, 1] (clamped), the hairline `h` piecewise linear in `d·f`
//! ([`HAIRLINE`]: low at the nape, above the ears at the sides, high on the forehead), its soft
//! band `w` ([`HAIRLINE_BAND`]) and `w_head` the vertex's head-segment weight (the hair fades out
//! down the neck). The cap is as smooth as the skull under it.

use nalgebra::{Point3, Unit, Vector3};

use crate::mesh::Mesh;

/// Hair's thickness (m): at the top and the back, and at the sides (drawn per subject from
/// `ZooParams::hair_top` and `ZooParams::hair_side`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hair {
    pub top: f64,
    pub side: f64,
}

/// The hairline: `(d·f, d·u)` knots, from the nape (behind, low) over the ears (across, above
/// them) to the forehead (in front, high); linear between, constant beyond.
pub const HAIRLINE: [(f64, f64); 3] = [(-1.0, -0.55), (0.0, 0.4), (0.8, 0.6)];

/// The hairline's soft band, in `d·u`.
pub const HAIRLINE_BAND: f64 = 0.12;

/// The head's frame: centre, up and forward (unit, across each other).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HeadFrame {
    pub centre: Point3<f64>,
    pub up: Unit<Vector3<f64>>,
    pub forward: Unit<Vector3<f64>>,
}

impl HeadFrame {
    /// The frame of a head with tragions `left` and `right`, sellion `sellion` and top `top`.
    pub fn from_points(
        left: Point3<f64>,
        right: Point3<f64>,
        sellion: Point3<f64>,
        top: Point3<f64>,
    ) -> Self {
        let centre = nalgebra::center(&left, &right);
        let up = Unit::new_normalize(top - centre);
        let f = sellion - centre;
        let forward = Unit::new_normalize(f - up.into_inner() * f.dot(&up));
        Self {
            centre,
            up,
            forward,
        }
    }
}

fn smoothstep(x: f64) -> f64 {
    let x = x.clamp(0.0, 1.0);
    x * x * (3.0 - 2.0 * x)
}

/// The hairline's height `h(d·f)` ([`HAIRLINE`]).
fn hairline(forward: f64) -> f64 {
    let k = &HAIRLINE;
    if forward <= k[0].0 {
        return k[0].1;
    }
    for w in k.windows(2) {
        let ((f0, h0), (f1, h1)) = (w[0], w[1]);
        if forward <= f1 {
            return h0 + (h1 - h0) * (forward - f0) / (f1 - f0);
        }
    }
    k[k.len() - 1].1
}

/// The hair's thickness over `p` (see the module documentation), before the head weight.
pub fn thickness(frame: &HeadFrame, hair: &Hair, p: &Point3<f64>) -> f64 {
    let Some(d) = Unit::try_new(p - frame.centre, 1e-9) else {
        return 0.0;
    };
    let (du, df) = (d.dot(&frame.up), d.dot(&frame.forward));
    let thick = hair.side + (hair.top - hair.side) * smoothstep(du.max(-df));
    thick * smoothstep((du - hairline(df)) / HAIRLINE_BAND + 0.5)
}

/// `surface` with hair over the head: every vertex moved out from the head's centre by its
/// [`thickness`] times `head_weight[v]` (its head-segment weight, 0–1).
pub fn add_hair(surface: &Mesh, frame: &HeadFrame, hair: &Hair, head_weight: &[f64]) -> Mesh {
    let positions = surface
        .positions
        .iter()
        .zip(head_weight)
        .map(|(p, &w)| {
            if w <= 0.0 {
                return *p;
            }
            let out = Unit::try_new(p - frame.centre, 1e-9).map_or(Vector3::zeros(), |d| *d);
            p + out * (w * thickness(frame, hair, p))
        })
        .collect();
    Mesh::new(positions, surface.triangles.clone())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A sphere of radius 0.1 m centred at the origin, as latitude rings.
    fn ball() -> Mesh {
        let mut positions = Vec::new();
        for i in 1..40 {
            let theta = std::f64::consts::PI * i as f64 / 40.0;
            for j in 0..80 {
                let phi = std::f64::consts::TAU * j as f64 / 80.0;
                positions.push(Point3::new(
                    0.1 * theta.sin() * phi.cos(),
                    0.1 * theta.cos(),
                    0.1 * theta.sin() * phi.sin(),
                ));
            }
        }
        Mesh::new(positions, Vec::new())
    }

    #[test]
    fn a_head_gets_a_thick_top_and_back_thin_sides_and_a_bare_face() {
        let head = ball();
        let frame = HeadFrame::from_points(
            Point3::new(0.1, 0.0, 0.0),
            Point3::new(-0.1, 0.0, 0.0),
            Point3::new(0.0, 0.01, 0.1),
            Point3::new(0.0, 0.1, 0.0),
        );
        let hair = Hair {
            top: 0.03,
            side: 0.008,
        };
        let haired = add_hair(&head, &frame, &hair, &vec![1.0; head.positions.len()]);
        let lift = |dir: Vector3<f64>| {
            // The vertex nearest the direction, and how far it moved.
            let (v, _) = head
                .positions
                .iter()
                .enumerate()
                .map(|(v, p)| (v, (p.coords.normalize() - dir.normalize()).norm()))
                .min_by(|a, b| a.1.total_cmp(&b.1))
                .unwrap();
            (haired.positions[v] - head.positions[v]).norm()
        };
        let top = lift(Vector3::y());
        assert!((top - 0.03).abs() < 0.002, "top {top}");
        let back = lift(Vector3::new(0.0, 0.2, -1.0));
        assert!(back > 0.02, "back {back}");
        let side = lift(Vector3::new(1.0, 0.45, 0.0));
        assert!(side > 0.004 && side < 0.015, "side {side}");
        // The face (in front, below the forehead's hairline) and the ears do not move.
        for face in [
            Vector3::new(0.0, 0.0, 1.0),
            Vector3::new(0.3, -0.3, 1.0),
            Vector3::new(0.0, 0.4, 1.0),
            Vector3::new(1.0, 0.0, 0.0),
            Vector3::new(-1.0, 0.1, 0.0),
        ] {
            assert!(lift(face) < 1e-6, "{face:?}: {}", lift(face));
        }
        // Above the hairline the cap is smooth: along the midline from the top to behind,
        // directions 1° apart change the lift by under 1.5 mm.
        for i in 0..100 {
            let a = (i as f64).to_radians();
            let b = ((i + 1) as f64).to_radians();
            let at = |a: f64| {
                thickness(
                    &frame,
                    &hair,
                    &Point3::new(0.0, 0.1 * a.cos(), -0.1 * a.sin()),
                )
            };
            assert!((at(a) - at(b)).abs() < 0.0015, "{i}°");
        }
    }
}
