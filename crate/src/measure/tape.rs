//! A tape measure around a plane section: the perimeter of the convex hull of the chosen loop, as
//! a tape spans concavities such as the cleft between the breasts or the small of the back
//! (ISO 8559-1 girths are taken with a tape that "follows the body without compressing it").

use super::section::SectionLoop;

/// Which closed loop of a section the tape goes around.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LoopChoice {
    /// The loop enclosing the largest area (a torso section: the body, not a hand beside it).
    Largest,
    /// The loop containing this in-plane point — of several (a body with inner surfaces, such as
    /// the mouth, cut inside its skin), the one enclosing the largest area — or else the loop
    /// whose centroid is nearest to it (a limb, the neck or the head, around an anchor between
    /// its landmarks).
    Around([f64; 2]),
}

/// A tape girth: the convex-hull perimeter (the girth), the loop's own length, and the hull.
#[derive(Debug, Clone, PartialEq)]
pub struct Tape {
    pub girth: f64,
    pub loop_length: f64,
    /// Hull corners in the section plane's coordinates, counter-clockwise.
    pub hull: Vec<[f64; 2]>,
}

/// Area enclosed by a polygon (shoelace formula, absolute value).
pub fn polygon_area(points: &[[f64; 2]]) -> f64 {
    let n = points.len();
    (0..n)
        .map(|i| {
            let (a, b) = (points[i], points[(i + 1) % n]);
            a[0] * b[1] - b[0] * a[1]
        })
        .sum::<f64>()
        .abs()
        / 2.0
}

/// Length of a closed polygon.
pub fn closed_length(points: &[[f64; 2]]) -> f64 {
    let n = points.len();
    (0..n)
        .map(|i| {
            let (a, b) = (points[i], points[(i + 1) % n]);
            (a[0] - b[0]).hypot(a[1] - b[1])
        })
        .sum()
}

/// Convex hull (Andrew's monotone chain), counter-clockwise, collinear points dropped.
pub fn convex_hull(points: &[[f64; 2]]) -> Vec<[f64; 2]> {
    let mut p = points.to_vec();
    p.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
    p.dedup();
    if p.len() < 3 {
        return p;
    }
    let cross = |o: [f64; 2], a: [f64; 2], b: [f64; 2]| {
        (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
    };
    let mut hull: Vec<[f64; 2]> = Vec::with_capacity(2 * p.len());
    let forward = p.iter();
    let backward = p.iter().rev();
    for pass in [forward.collect::<Vec<_>>(), backward.collect::<Vec<_>>()] {
        let start = hull.len();
        for &q in pass {
            while hull.len() >= start + 2
                && cross(hull[hull.len() - 2], hull[hull.len() - 1], q) <= 0.0
            {
                hull.pop();
            }
            hull.push(q);
        }
        hull.pop();
    }
    hull
}

/// Whether `q` lies inside the polygon `points` (even–odd rule).
pub fn contains(points: &[[f64; 2]], q: [f64; 2]) -> bool {
    let n = points.len();
    let mut inside = false;
    for i in 0..n {
        let (a, b) = (points[i], points[(i + n - 1) % n]);
        if (a[1] > q[1]) != (b[1] > q[1])
            && q[0] < a[0] + (q[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
        {
            inside = !inside;
        }
    }
    inside
}

fn centroid_distance(points: &[[f64; 2]], q: [f64; 2]) -> f64 {
    let n = points.len().max(1) as f64;
    let c = points
        .iter()
        .fold([0.0, 0.0], |s, p| [s[0] + p[0] / n, s[1] + p[1] / n]);
    (c[0] - q[0]).hypot(c[1] - q[1])
}

/// The tape around the closed loop of `loops` that `choice` picks; `None` when no loop is closed.
pub fn tape(loops: &[SectionLoop], choice: LoopChoice) -> Option<Tape> {
    let closed = loops.iter().filter(|l| l.closed);
    let chosen = match choice {
        LoopChoice::Largest => {
            closed.max_by(|a, b| polygon_area(&a.points).total_cmp(&polygon_area(&b.points)))
        }
        LoopChoice::Around(q) => {
            let closed: Vec<&SectionLoop> = closed.collect();
            closed
                .iter()
                .filter(|l| contains(&l.points, q))
                .max_by(|a, b| polygon_area(&a.points).total_cmp(&polygon_area(&b.points)))
                .or_else(|| {
                    closed.iter().min_by(|a, b| {
                        centroid_distance(&a.points, q).total_cmp(&centroid_distance(&b.points, q))
                    })
                })
                .copied()
        }
    }?;
    let hull = convex_hull(&chosen.points);
    Some(Tape {
        girth: closed_length(&hull),
        loop_length: closed_length(&chosen.points),
        hull,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(at: [f64; 2], side: f64) -> SectionLoop {
        let [x, y] = at;
        SectionLoop {
            points: vec![[x, y], [x + side, y], [x + side, y + side], [x, y + side]],
            closed: true,
        }
    }

    #[test]
    fn hull_of_a_square_with_an_inner_point() {
        let pts = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.5, 0.5]];
        let hull = convex_hull(&pts);
        assert_eq!(hull.len(), 4);
        assert!((closed_length(&hull) - 4.0).abs() < 1e-12);
        assert!((polygon_area(&hull) - 1.0).abs() < 1e-12);
    }

    #[test]
    fn a_concave_loop_is_measured_around_its_hull() {
        // A "C": the tape spans the notch, the loop itself runs into it.
        let c = SectionLoop {
            points: vec![
                [0.0, 0.0],
                [2.0, 0.0],
                [2.0, 0.5],
                [1.0, 0.5],
                [1.0, 1.5],
                [2.0, 1.5],
                [2.0, 2.0],
                [0.0, 2.0],
            ],
            closed: true,
        };
        let t = tape(&[c], LoopChoice::Largest).unwrap();
        assert!((t.girth - 8.0).abs() < 1e-12);
        assert!((t.loop_length - 10.0).abs() < 1e-12);
    }

    #[test]
    fn the_choice_picks_the_loop() {
        let loops = [square([0.0, 0.0], 1.0), square([5.0, 0.0], 2.0)];
        let largest = tape(&loops, LoopChoice::Largest).unwrap();
        assert!((largest.girth - 8.0).abs() < 1e-12);
        let inside = tape(&loops, LoopChoice::Around([0.5, 0.5])).unwrap();
        assert!((inside.girth - 4.0).abs() < 1e-12);
        let nearest = tape(&loops, LoopChoice::Around([4.0, 1.0])).unwrap();
        assert!((nearest.girth - 8.0).abs() < 1e-12);
        // A loop inside another (the mouth inside the head's skin): the outer one is measured.
        let nested = [square([0.4, 0.4], 0.2), square([0.0, 0.0], 1.0)];
        let outer = tape(&nested, LoopChoice::Around([0.5, 0.5])).unwrap();
        assert!((outer.girth - 4.0).abs() < 1e-12);
        let open = SectionLoop {
            closed: false,
            ..square([0.0, 0.0], 1.0)
        };
        assert!(tape(&[open], LoopChoice::Largest).is_none());
    }
}
