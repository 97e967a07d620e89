//! Which way a scan's triangles face: out of the body, into it, or each part its own way.
//!
//! Seen from outside, a body's surface faces the one looking at it. The scan is looked at along
//! the six directions of its bounding box's axes: each view is a grid of `grid` cells across the
//! largest extent, and in each cell the triangle nearest the viewer among those covering the
//! cell's centre is the one seen there (a depth buffer), unless it is seen nearly edge-on
//! (`edge_on`). A coarse mesh and a dense one are seen alike, and what another part hides is not
//! seen. A part (connected component, [`component_labels`]) is wound outwards when at least
//! `agreement` of the cells where it is seen show a triangle facing the viewer (its
//! counter-clockwise normal towards the viewer), inwards when at most `1 − agreement` do. Cells
//! over a hole show the inside of the far side and count against, so an open scan agrees less
//! than fully: the synthetic scanner zoo's body parts 0.69–1.00. A lone sheet (a floor or
//! turntable remnant) is seen from both sides, so it agrees about half overall, but in each view
//! that holds at least `least_view` of its cells all one way or the other: it is one-sided and
//! says nothing either way. A part whose triangles face at random agrees about half in every
//! view. The scan is wound one way when every part seen in at least `least_part` of the seen
//! cells is wound that way or one-sided, and at least one is wound that way; [`Winding::Mixed`]
//! otherwise (smaller pieces — dust, a toe's slice — do not count). Nothing here depends on the
//! body's shape: sheets, closed parts and a body in pieces are looked at alike.
//!
//! The app needs it to tell a click on the body from one that fell through a hole onto the inside
//! of the body's far side: there the triangle faces away from the camera on a scan wound
//! outwards. On a scan whose parts disagree, each part of note still says its own way
//! ([`windings`]), and the app is told each triangle's own ([`facings`]), so it can tell it on
//! every part wound one way, and on a part whose triangles face both ways. The fit and the landmark
//! estimate match the scan's normals against the template's, so a part wound inwards is turned
//! to face out before either runs ([`face_out`]): left as it was, a file wound clockwise matched
//! a tenth of the template, and its estimate ended 129 mm off. A file whose triangles face both
//! ways within a part has them turned to agree with their neighbours first
//! ([`super::orientation`]), and each piece of surface is then judged on its own.

use serde::{Deserialize, Serialize};

use std::borrow::Cow;

use nalgebra::{Point3, Vector3};

use super::bounds::bounding_box;
use super::bvh::TriangleBvh;
use super::orientation::{cohere, Cohered};
use super::topology::{component_labels, triangle_labels};
use super::Mesh;

/// What [`face_out`] turned.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Reorientation {
    /// Parts turned whole, wound inwards.
    pub parts: usize,
    /// The triangles that face otherwise than in the file, all told.
    pub triangles: usize,
    /// Of them, those turned to agree with their neighbours ([`cohere`]).
    pub against_neighbours: usize,
    /// In words, for the report.
    pub words: String,
}

/// Which way a scan's triangles face (module documentation).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Winding {
    /// Every part of note is wound outwards: a triangle's normal (counter-clockwise) points out of
    /// the body.
    Outward,
    /// Every part of note is wound inwards.
    Inward,
    /// The parts disagree, or one faces both ways: a triangle's side says nothing.
    Mixed,
}

/// How the winding is judged (module documentation), with its defaults.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct WindingParams {
    /// Cells of a view across the scan's largest extent; default 128 (14 mm on a standing body).
    pub grid: usize,
    /// A part is wound one way when at least this share of the cells it is seen in agree;
    /// default 0.6 (the zoo's parts agree 0.69–1.00, the least a hand or foot of a coarse scan
    /// seen into where it was cut off the body; a part whose triangles face at random about 0.5).
    pub agreement: f64,
    /// Parts seen in less than this share of the seen cells do not count; default 0.01.
    pub least_part: f64,
    /// A seen triangle counts when its normal's cosine to the view is at least this (nearer
    /// edge-on, its side says nothing); default 0.3.
    pub edge_on: f64,
    /// A view counts in the one-sided test when it holds at least this share of the part's seen
    /// cells; default 0.1 (a floor remnant's rim, seen from the side in a few cells, does not).
    pub least_view: f64,
    /// Rays cast from each triangle of a piece the views cannot judge, in a file not wound one
    /// way ([`face_out`]); default 32.
    pub rays: usize,
}

impl Default for WindingParams {
    fn default() -> Self {
        Self {
            grid: 128,
            agreement: 0.6,
            least_part: 0.01,
            edge_on: 0.3,
            least_view: 0.1,
            rays: 32,
        }
    }
}

/// A part's cells in one view: (seen, facing the viewer).
pub type ViewCount = (usize, usize);

/// Per part (`parts`: each triangle's, `0..count`), per view (+x, −x, +y, −y, +z, −z): the cells
/// it is seen in and how many of them show a triangle facing the viewer (module documentation).
pub fn part_views(
    mesh: &Mesh,
    parts: &[u32],
    count: usize,
    params: &WindingParams,
) -> Vec<[ViewCount; 6]> {
    let mut seen = vec![[(0usize, 0usize); 6]; count];
    let Some((lo, hi)) = bounding_box(&mesh.positions) else {
        return seen;
    };
    let extent = (hi - lo).max();
    if extent <= 0.0 || params.grid == 0 {
        return seen;
    }
    let cell = extent / params.grid as f64;
    let side = params.grid + 1;
    // Per view (+x, −x, +y, −y, +z, −z), per cell: the nearest triangle's depth and index; all six
    // filled in one pass over the triangles.
    let mut nearest = vec![vec![(f64::NEG_INFINITY, u32::MAX); side * side]; 6];
    // Every vertex in cell units, once.
    let at: Vec<[f64; 3]> = mesh
        .positions
        .iter()
        .map(|p| {
            [
                (p.x - lo.x) / cell,
                (p.y - lo.y) / cell,
                (p.z - lo.z) / cell,
            ]
        })
        .collect();
    for (t, triangle) in mesh.triangles.iter().enumerate() {
        let corners = triangle.map(|i| at[i as usize]);
        for axis in 0..3 {
            let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
            // The corners across the view, and their depth along it.
            let q = corners.map(|p| (p[u], p[v], p[axis]));
            let (plus, minus) = nearest[2 * axis..2 * axis + 2].split_at_mut(1);
            let (plus, minus) = (&mut plus[0], &mut minus[0]);
            rasterise(q, params.grid, |at, depth| {
                let at = at.0 * side + at.1;
                if depth > plus[at].0 {
                    plus[at] = (depth, t as u32);
                }
                if -depth > minus[at].0 {
                    minus[at] = (-depth, t as u32);
                }
            });
        }
    }
    for (view, cells) in nearest.iter().enumerate() {
        let (axis, toward) = (view / 2, if view % 2 == 0 { 1.0 } else { -1.0 });
        for &(_, t) in cells.iter().filter(|n| n.1 != u32::MAX) {
            let normal = area_normal(mesh, mesh.triangles[t as usize]);
            let facing = toward * normal[axis];
            // A triangle seen edge-on says nothing about its side.
            if facing.abs() < params.edge_on * normal.norm() {
                continue;
            }
            let part = &mut seen[parts[t as usize] as usize][view];
            part.0 += 1;
            part.1 += usize::from(facing > 0.0);
        }
    }
    seen
}

/// Calls `cover(cell, depth)` for every cell `(a, b)` (`0..=grid` each) whose centre lies in the
/// triangle `q` (corners in cell units across the view, and depth along it), with the depth
/// there.
fn rasterise(q: [(f64, f64, f64); 3], grid: usize, mut cover: impl FnMut((usize, usize), f64)) {
    let [(x0, y0, d0), (x1, y1, d1), (x2, y2, d2)] = q;
    // Most of a dense scan's triangles lie between cell centres: nothing to cover.
    if (x0.min(x1).min(x2) - 0.5).floor() == (x0.max(x1).max(x2) - 0.5).floor()
        || (y0.min(y1).min(y2) - 0.5).floor() == (y0.max(y1).max(y2) - 0.5).floor()
    {
        return;
    }
    let area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
    if area.abs() < 1e-12 {
        return;
    }
    let range = |a: f64, b: f64, c: f64| {
        let first = (a.min(b).min(c) - 0.5).ceil().max(0.0) as usize;
        let last = ((a.max(b).max(c) - 0.5).floor()).min(grid as f64);
        (first, last)
    };
    let ((a0, a1), (b0, b1)) = (range(x0, x1, x2), range(y0, y1, y2));
    if a1 < 0.0 || b1 < 0.0 {
        return;
    }
    for a in a0..=a1 as usize {
        for b in b0..=b1 as usize {
            let (x, y) = (a as f64 + 0.5, b as f64 + 0.5);
            let w1 = ((x - x0) * (y2 - y0) - (x2 - x0) * (y - y0)) / area;
            let w2 = ((x1 - x0) * (y - y0) - (x - x0) * (y1 - y0)) / area;
            let w0 = 1.0 - w1 - w2;
            if w0 >= 0.0 && w1 >= 0.0 && w2 >= 0.0 {
                cover((a, b), w0 * d0 + w1 * d1 + w2 * d2);
            }
        }
    }
}

/// What one part says (module documentation).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum PartSays {
    Outward,
    Inward,
    OneSided,
    Nothing,
}

fn part_says(views: &[ViewCount; 6], params: &WindingParams) -> PartSays {
    let (seen, facing) = views.iter().fold((0, 0), |s, v| (s.0 + v.0, s.1 + v.1));
    let share = facing as f64 / seen.max(1) as f64;
    if share >= params.agreement {
        return PartSays::Outward;
    }
    if share <= 1.0 - params.agreement {
        return PartSays::Inward;
    }
    let extreme = |v: &ViewCount| {
        let s = v.1 as f64 / v.0 as f64;
        s >= params.agreement || s <= 1.0 - params.agreement
    };
    let counted: Vec<&ViewCount> = views
        .iter()
        .filter(|v| v.0 > 0 && v.0 as f64 >= params.least_view * seen as f64)
        .collect();
    if !counted.is_empty() && counted.iter().all(|v| extreme(v)) {
        PartSays::OneSided
    } else {
        PartSays::Nothing
    }
}

/// A triangle's normal (counter-clockwise), twice its area long.
fn area_normal(mesh: &Mesh, [i, j, k]: [u32; 3]) -> Vector3<f64> {
    let (a, b, c) = (
        mesh.positions[i as usize],
        mesh.positions[j as usize],
        mesh.positions[k as usize],
    );
    (b - a).cross(&(c - a))
}

/// Which way `mesh`'s triangles face (module documentation). An empty mesh is `Mixed`.
pub fn winding(mesh: &Mesh, params: &WindingParams) -> Winding {
    let (labels, count) = component_labels(mesh);
    windings(mesh, &triangle_labels(mesh, &labels), count, params).0
}

fn side(w: Winding) -> i8 {
    match w {
        Winding::Outward => 1,
        Winding::Inward => -1,
        Winding::Mixed => 0,
    }
}

/// The scan's [`Winding`] and each part's own way (`parts`: each triangle's, `0..count`). A part
/// seen in at least `least_part` of the seen cells is 1 when it is wound outwards, −1 inwards, 0
/// otherwise (one-sided, facing both ways); a smaller part takes the whole scan's way (0 on a
/// mixed scan). On a scan whose parts disagree, a part wound one way still says which side of its
/// triangles is its outside.
pub fn windings(
    mesh: &Mesh,
    parts: &[u32],
    count: usize,
    params: &WindingParams,
) -> (Winding, Vec<i8>) {
    let (whole, judged) = judge(mesh, parts, count, params);
    let own = judged.iter().map(|j| j.unwrap_or(side(whole))).collect();
    (whole, own)
}

/// [`windings`] before the smaller parts take the whole's way: `None` for them.
fn judge(
    mesh: &Mesh,
    parts: &[u32],
    count: usize,
    params: &WindingParams,
) -> (Winding, Vec<Option<i8>>) {
    let views = part_views(mesh, parts, count, params);
    let seen = |views: &[ViewCount; 6]| views.iter().map(|v| v.0).sum::<usize>();
    let total: usize = views.iter().map(seen).sum();
    let says: Vec<Option<PartSays>> = views
        .iter()
        .map(|views| {
            (seen(views) > 0 && seen(views) as f64 >= params.least_part * total as f64)
                .then(|| part_says(views, params))
        })
        .collect();
    let only = |way: PartSays| {
        let noted = || says.iter().flatten();
        noted().any(|&s| s == way) && noted().all(|&s| s == way || s == PartSays::OneSided)
    };
    let whole = if only(PartSays::Outward) {
        Winding::Outward
    } else if only(PartSays::Inward) {
        Winding::Inward
    } else {
        Winding::Mixed
    };
    let judged = says
        .iter()
        .map(|s| {
            s.map(|s| match s {
                PartSays::Outward => 1,
                PartSays::Inward => -1,
                _ => 0,
            })
        })
        .collect();
    (whole, judged)
}

/// Each part's way, `judged` as [`judge`] gives it, a part left `None` judged by the rays that
/// see it from outside. From each of its triangles rays go out in `rays` directions spread over
/// the sphere; one that meets nothing of the scan sees the triangle from outside, and it votes,
/// by the triangle's area, for the side it leaves from (not when it leaves nearly edge-on,
/// `edge_on`). The sum over the part decides; with no vote it says nothing (0). The views' depth
/// buffer sees a piece of a few triangles in a few cells or in none; these rays look from the
/// piece itself. A ray leaving the inside through a hole (an open sole, a gap between slices)
/// votes wrongly; more leave from outside.
fn seen_from_outside(
    mesh: &Mesh,
    parts: &[u32],
    judged: &[Option<i8>],
    params: &WindingParams,
) -> Vec<i8> {
    let mut score = vec![0.0; judged.len()];
    if judged.iter().any(Option::is_none) {
        let scan = TriangleBvh::new(mesh);
        let directions = sphere_directions(params.rays);
        for (&triangle, &part) in mesh.triangles.iter().zip(parts) {
            if judged[part as usize].is_some() {
                continue;
            }
            let normal = area_normal(mesh, triangle);
            let Some(across) = normal.try_normalize(0.0) else {
                continue;
            };
            let centre = Point3::from(
                triangle.iter().fold(Vector3::zeros(), |c, &v| {
                    c + mesh.positions[v as usize].coords
                }) / 3.0,
            );
            for way in &directions {
                let facing = across.dot(way);
                if facing.abs() >= params.edge_on
                    && scan.cast(&centre, way, f64::INFINITY).is_none()
                {
                    score[part as usize] += facing.signum() * normal.norm();
                }
            }
        }
    }
    judged
        .iter()
        .zip(&score)
        .map(|(j, &s)| j.unwrap_or(if s < 0.0 { -1 } else { i8::from(s > 0.0) }))
        .collect()
}

/// `n` unit directions spread evenly over the sphere (a Fibonacci lattice).
fn sphere_directions(n: usize) -> Vec<Vector3<f64>> {
    let turn = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    (0..n)
        .map(|i| {
            let z = 1.0 - (2 * i + 1) as f64 / n as f64;
            let r = (1.0 - z * z).sqrt();
            let a = turn * i as f64;
            Vector3::new(r * a.cos(), r * a.sin(), z)
        })
        .collect()
}

/// Which way each piece of `mesh` faces once its triangles agree with their neighbours
/// ([`face_out`]'s judgement, before anything is turned to face out).
struct Sides<'a> {
    /// `mesh` with its triangles turned to agree ([`cohere`]), or `mesh` itself.
    agreed: Cow<'a, Mesh>,
    /// Per triangle, its piece: a part of a file wound one way, a piece [`cohere`] joined.
    parts: Vec<u32>,
    /// Per piece, which way its triangles in `agreed` face: 1 out of the body, −1 into it, 0 not
    /// known.
    sides: Vec<i8>,
    /// The triangles [`cohere`] turned.
    against: usize,
    /// The whole `mesh`'s [`Winding`] where no triangle disagreed with its neighbours.
    whole: Option<Winding>,
}

/// The judgement [`face_out`] and [`facings`] share. A file wound one way (`cohered` is `None`)
/// keeps its parts (`parts`: each triangle's connected component, `0..count`), each judged by
/// [`windings`]. A file whose triangles disagree with their neighbours has them turned to agree
/// first (`cohered`: [`cohere`]'s); its pieces of surface are then its parts, each judged by the
/// views where they can; one they cannot, whose triangles the walk turned, by the rays that see
/// it from outside (`seen_from_outside`); any other keeps the file's way.
fn judge_sides<'a>(
    mesh: &'a Mesh,
    (parts, count): (Vec<u32>, usize),
    cohered: Option<Cohered>,
    params: &WindingParams,
) -> Sides<'a> {
    let (agreed, parts, count, against) = match cohered {
        Some(c) => (
            Cow::Owned(Mesh::new(mesh.positions.clone(), c.triangles)),
            c.piece,
            c.pieces,
            c.turned,
        ),
        None => (Cow::Borrowed(mesh), parts, count, 0),
    };
    let (sides, whole) = if against > 0 {
        // A piece [`cohere`] turned triangles of has no way of its own from the file: unless the
        // views judge it, the rays from it do. Any other keeps the file's way, as a part of a
        // file wound one way does.
        let mut touched = vec![false; count];
        for ((t, file), &part) in agreed.triangles.iter().zip(&mesh.triangles).zip(&parts) {
            touched[part as usize] |= t != file;
        }
        let (whole, judged) = judge(&agreed, &parts, count, params);
        let judged: Vec<Option<i8>> = judged
            .iter()
            .zip(&touched)
            .map(|(&j, &touched)| match j {
                Some(s) if s != 0 => Some(s),
                _ if touched => None,
                Some(s) => Some(s),
                None => Some(side(whole)),
            })
            .collect();
        (seen_from_outside(&agreed, &parts, &judged, params), None)
    } else {
        let (whole, own) = windings(&agreed, &parts, count, params);
        (own, Some(whole))
    };
    Sides {
        agreed,
        parts,
        sides,
        against,
        whole,
    }
}

/// The whole file's [`Winding`] and, per triangle as the file has it, which way its front (its
/// counter-clockwise normal) faces: 1 out of the body, −1 into it, 0 not known (its piece
/// one-sided, or judged by nothing). On a file whose triangles face both ways a triangle the
/// walk turned faces opposite to its piece, so the app can tell a click on the body from one
/// through a hole there too. The whole is judged on the file as it is ([`windings`]): `Mixed`
/// where its triangles face both ways. `parts`: each triangle's connected component, `0..count`;
/// `cohered`: [`cohere`]'s answer, `None` also where the caller knows that no edge's two
/// triangles run it the same way ([`super::topology::boundary_edges_and_disagreement`]).
pub fn facings(
    mesh: &Mesh,
    parts: &[u32],
    count: usize,
    cohered: Option<Cohered>,
    params: &WindingParams,
) -> (Winding, Vec<i8>) {
    let judged = judge_sides(mesh, (parts.to_vec(), count), cohered, params);
    let whole = judged
        .whole
        .unwrap_or_else(|| windings(mesh, parts, count, params).0);
    let per_triangle = judged
        .agreed
        .triangles
        .iter()
        .zip(&mesh.triangles)
        .zip(&judged.parts)
        .map(|((agreed, file), &part)| {
            let side = judged.sides[part as usize];
            if agreed == file {
                side
            } else {
                -side
            }
        })
        .collect();
    (whole, per_triangle)
}

/// `triangles` with each whose front faces into the body (`facing` −1, [`facings`]) turned to
/// face out, the rest as they are; `None` where none faces in. What a scan is shaded by: the
/// vertex normals of a file whose triangles face both ways, taken as it is, point every way.
pub fn turned_out(triangles: &[[u32; 3]], facing: &[i8]) -> Option<Vec<[u32; 3]>> {
    if !facing.contains(&-1) {
        return None;
    }
    let turned = triangles
        .iter()
        .zip(facing.iter().chain(std::iter::repeat(&0)))
        .map(|(&t, &f)| if f < 0 { turned_round(t) } else { t })
        .collect();
    Some(turned)
}

/// A triangle with its front turned: the same corners, the other way round.
fn turned_round([a, b, c]: [u32; 3]) -> [u32; 3] {
    [a, c, b]
}

/// `mesh` with its triangles turned to face out of the body, and what was turned; `None` when
/// nothing was. Each piece judged inwards by `judge_sides` is turned whole (on a file wound one
/// way, a part: a part of note judged so, or a smaller piece of a scan wound inwards).
/// Positions and their order stay.
pub fn face_out(mesh: &Mesh, params: &WindingParams) -> Option<(Mesh, Reorientation)> {
    let (labels, count) = component_labels(mesh);
    let Sides {
        agreed,
        parts,
        sides,
        against,
        ..
    } = judge_sides(
        mesh,
        (triangle_labels(mesh, &labels), count),
        cohere(mesh),
        params,
    );
    let turned = sides.iter().filter(|&&side| side < 0).count();
    if turned == 0 && against == 0 {
        return None;
    }
    let inward: Vec<bool> = parts.iter().map(|&p| sides[p as usize] < 0).collect();
    let triangles: Vec<[u32; 3]> = agreed
        .triangles
        .iter()
        .zip(&inward)
        .map(|(&t, &turn)| if turn { turned_round(t) } else { t })
        .collect();
    let changed = triangles
        .iter()
        .zip(&mesh.triangles)
        .filter(|(a, b)| a != b)
        .count();
    let whole = inward.iter().all(|&turn| turn);
    let were = |n: usize| if n == 1 { "it was" } else { "they were" };
    let words = if against > 0 {
        let then = match turned {
            0 => String::new(),
            _ if whole => {
                "; the scan then faced into the body and was turned to face out".to_string()
            }
            n => format!(
                "; {n} of its pieces then faced into the body and {} turned to face out",
                were(n)
            ),
        };
        format!(
            "{against} of the scan's {} triangles faced the other way from their neighbours \
             (the file's triangles are not wound one way); {} turned to agree{then}",
            mesh.triangles.len(),
            were(against)
        )
    } else if whole {
        "the scan's triangles faced into the body (wound clockwise seen from outside); they were \
         turned to face out"
            .to_string()
    } else {
        format!(
            "{turned} of the scan's parts ({changed} triangles) faced into the body; {} turned \
             to face out",
            were(turned)
        )
    };
    Some((
        Mesh::new(mesh.positions.clone(), triangles),
        Reorientation {
            parts: turned,
            triangles: changed,
            against_neighbours: against,
            words,
        },
    ))
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::mesh::topology::tests::cube;
    use nalgebra::Point3;

    /// Each triangle's connected component, and their count.
    fn parts(mesh: &Mesh) -> (Vec<u32>, usize) {
        let (labels, count) = component_labels(mesh);
        (triangle_labels(mesh, &labels), count)
    }

    fn views(mesh: &Mesh, params: &WindingParams) -> Vec<[ViewCount; 6]> {
        let (labels, count) = parts(mesh);
        part_views(mesh, &labels, count, params)
    }

    /// `mesh` with the triangles `flip` picks turned.
    pub(crate) fn flipped(mesh: &Mesh, flip: impl Fn(usize) -> bool) -> Mesh {
        let triangles = mesh
            .triangles
            .iter()
            .enumerate()
            .map(|(t, &tri)| if flip(t) { turned_round(tri) } else { tri })
            .collect();
        Mesh::new(mesh.positions.clone(), triangles)
    }

    /// Two cubes side by side, the second's vertices after the first's.
    pub(crate) fn two_cubes(second_flipped: bool) -> Mesh {
        let one = cube();
        let n = one.positions.len() as u32;
        let mut positions = one.positions.clone();
        positions.extend(
            one.positions
                .iter()
                .map(|p| p + nalgebra::Vector3::new(3.0, 0.0, 0.0)),
        );
        let mut triangles = one.triangles.clone();
        triangles.extend(one.triangles.iter().map(|&[a, b, c]| {
            if second_flipped {
                [a + n, c + n, b + n]
            } else {
                [a + n, b + n, c + n]
            }
        }));
        Mesh::new(positions, triangles)
    }

    #[test]
    fn a_closed_part_wound_outwards_agrees_fully() {
        let parts = {
            let m = cube();
            let (l, n) = parts(&m);
            part_views(&m, &l, n, &WindingParams::default())
        };
        assert_eq!(parts.len(), 1);
        // Each view sees the face towards it (128² cells), facing it; the sides are edge-on.
        assert_eq!(parts[0], [(128 * 128, 128 * 128); 6], "{parts:?}");
        assert_eq!(
            winding(&cube(), &WindingParams::default()),
            Winding::Outward
        );
        assert_eq!(
            winding(&flipped(&cube(), |_| true), &WindingParams::default()),
            Winding::Inward
        );
    }

    #[test]
    fn parts_that_disagree_or_a_part_flipped_in_places_are_mixed() {
        let p = WindingParams::default();
        assert_eq!(winding(&two_cubes(false), &p), Winding::Outward);
        assert_eq!(winding(&two_cubes(true), &p), Winding::Mixed);
        // Every other triangle flipped: the part faces both ways.
        assert_eq!(
            winding(&flipped(&cube(), |t| t % 2 == 0), &p),
            Winding::Mixed
        );
        assert_eq!(winding(&Mesh::default(), &p), Winding::Mixed);
    }

    #[test]
    fn each_part_of_a_mixed_scan_keeps_its_own_way() {
        let p = WindingParams::default();
        let mesh = two_cubes(true);
        let (l, n) = parts(&mesh);
        let (whole, own) = windings(&mesh, &l, n, &p);
        assert_eq!(whole, Winding::Mixed);
        assert_eq!(own, vec![1, -1]);
        // Both one way: each part says so, as the whole does.
        let mesh = two_cubes(false);
        let (l, n) = parts(&mesh);
        assert_eq!(windings(&mesh, &l, n, &p), (Winding::Outward, vec![1, 1]));
        // A part facing both ways says nothing of itself.
        let mesh = flipped(&two_cubes(false), |t| t >= 12 && t % 2 == 0);
        let (l, n) = parts(&mesh);
        assert_eq!(windings(&mesh, &l, n, &p), (Winding::Mixed, vec![1, 0]));
    }

    #[test]
    fn parts_wound_inwards_are_turned_to_face_out() {
        let p = WindingParams::default();
        // Nothing to turn on a scan wound outwards.
        assert!(face_out(&two_cubes(false), &p).is_none());
        // The second cube turned back: the same mesh as both wound outwards.
        let (turned, what) = face_out(&two_cubes(true), &p).unwrap();
        assert_eq!(turned, two_cubes(false));
        assert_eq!((what.parts, what.triangles), (1, 12));
        assert!(
            what.words
                .starts_with("1 of the scan's parts (12 triangles)"),
            "{}",
            what.words
        );
        // A scan wound inwards throughout is turned whole.
        let (turned, what) = face_out(&flipped(&cube(), |_| true), &p).unwrap();
        assert_eq!(turned, cube());
        assert!(what
            .words
            .starts_with("the scan's triangles faced into the body"));
        // A part facing both ways: its triangles turned to agree, then the part to face out.
        let (turned, what) = face_out(&flipped(&cube(), |t| t % 2 == 0), &p).unwrap();
        assert_eq!(turned, cube());
        assert_eq!(
            (what.parts, what.triangles, what.against_neighbours),
            (1, 6, 6)
        );
        assert_eq!(
            what.words,
            "6 of the scan's 12 triangles faced the other way from their neighbours (the file's \
             triangles are not wound one way); they were turned to agree; the scan then faced \
             into the body and was turned to face out"
        );
        // The second of two cubes mostly turned: its other three agree with the rest, then it is
        // turned whole; the first is left.
        let (turned, what) = face_out(&flipped(&two_cubes(false), |t| t >= 15), &p).unwrap();
        assert_eq!(turned, two_cubes(false));
        assert_eq!(
            (what.parts, what.triangles, what.against_neighbours),
            (1, 9, 3)
        );
        assert!(
            what.words.ends_with(
                "they were turned to agree; 1 of its pieces then faced into the body and it was \
                 turned to face out"
            ),
            "{}",
            what.words
        );
    }

    #[test]
    fn a_piece_too_small_for_the_views_is_judged_by_the_rays_that_see_it() {
        // A cube with one triangle turned (the file is not wound one way), and a fan of six
        // triangles lying just over its top face near a corner, wound inwards but for one.
        // Agreed, the fan faces into the cube; it is too small for the views to see, and the
        // rays that leave it upwards, seeing it from outside, say so.
        let body = cube();
        let mut positions = body.positions.clone();
        let centre = positions.len() as u32;
        positions.push(Point3::new(0.925, 0.925, 1.01));
        for k in 0..6 {
            let a = std::f64::consts::PI / 3.0 * k as f64;
            positions.push(Point3::new(
                0.925 + 0.03 * a.cos(),
                0.925 + 0.03 * a.sin(),
                1.01,
            ));
        }
        let rim = |k: u32| centre + 1 + k % 6;
        let fan = |inward: &dyn Fn(u32) -> bool| -> Vec<[u32; 3]> {
            (0..6)
                .map(|k| {
                    if inward(k) {
                        [centre, rim(k + 1), rim(k)]
                    } else {
                        [centre, rim(k), rim(k + 1)]
                    }
                })
                .collect()
        };
        let outward = Mesh::new(
            positions.clone(),
            [body.triangles.clone(), fan(&|_| false)].concat(),
        );
        let file = Mesh::new(
            positions.clone(),
            [flipped(&body, |t| t == 3).triangles, fan(&|k| k != 2)].concat(),
        );
        let (turned, what) = face_out(&file, &WindingParams::default()).unwrap();
        assert_eq!(turned, outward);
        assert_eq!(
            (what.parts, what.triangles, what.against_neighbours),
            (1, 6, 2)
        );
        // A fan wound one way in the file keeps it, as in a file wound one way throughout.
        let file = Mesh::new(
            positions,
            [flipped(&body, |t| t == 3).triangles, fan(&|_| true)].concat(),
        );
        let (kept, what) = face_out(&file, &WindingParams::default()).unwrap();
        assert_eq!(kept.triangles[12..], file.triangles[12..]);
        assert_eq!((what.parts, what.triangles), (0, 1));
    }

    #[test]
    fn each_triangle_says_which_way_its_front_faces() {
        let p = WindingParams::default();
        let facings = |mesh: &Mesh, p: &WindingParams| {
            let (labels, count) = parts(mesh);
            super::facings(mesh, &labels, count, cohere(mesh), p)
        };
        let out_in = |n_out: usize, n_in: usize| [vec![1i8; n_out], vec![-1; n_in]].concat();
        // Parts wound each one way: each triangle its part's way.
        assert_eq!(
            facings(&two_cubes(false), &p),
            (Winding::Outward, vec![1; 24])
        );
        assert_eq!(
            facings(&two_cubes(true), &p),
            (Winding::Mixed, out_in(12, 12))
        );
        // A part facing both ways: the file is mixed, and each triangle still says its own way,
        // the turned ones into the body.
        let both = flipped(&cube(), |t| t % 2 == 0);
        let (whole, each) = facings(&both, &p);
        assert_eq!(whole, Winding::Mixed);
        let expected: Vec<i8> = (0..12).map(|t| if t % 2 == 0 { -1 } else { 1 }).collect();
        assert_eq!(each, expected);
        // Agrees with what `face_out` turns: a triangle facing in is turned, one facing out not.
        let (turned, _) = face_out(&both, &p).unwrap();
        for ((file, out), facing) in both.triangles.iter().zip(&turned.triangles).zip(&each) {
            assert_eq!(file == out, *facing == 1);
        }
        // Turned out by what each says, every triangle faces out: each vertex's normal points
        // away from the cube's centre, where the file's own point every way.
        let centre = Point3::new(0.5, 0.5, 0.5);
        let outwards = |triangles: &[[u32; 3]]| {
            let normals = crate::mesh::normals::vertex_normals(&both.positions, triangles);
            both.positions
                .iter()
                .zip(&normals)
                .filter(|(p, n)| n.dot(&(*p - centre).normalize()) > 0.5)
                .count()
        };
        assert_eq!(outwards(&turned_out(&both.triangles, &each).unwrap()), 8);
        assert!(outwards(&both.triangles) < 8);
        // The second of two cubes mostly turned: it faces in but for its first three.
        let (whole, each) = facings(&flipped(&two_cubes(false), |t| t >= 15), &p);
        assert_eq!(whole, Winding::Mixed);
        assert_eq!(each, out_in(15, 9));
    }

    #[test]
    fn an_open_part_with_a_hole_still_agrees() {
        // The cube without one face: open, as a scan is at a hole.
        let mut open = cube();
        open.triangles.truncate(10);
        // Seen from the open side, the inside of the far face: 5 of the 6 views agree.
        let parts = {
            let (l, n) = parts(&open);
            part_views(&open, &l, n, &WindingParams::default())
        };
        let (seen, facing) = parts[0].iter().fold((0, 0), |s, v| (s.0 + v.0, s.1 + v.1));
        assert_eq!((seen, facing), (6 * 128 * 128, 5 * 128 * 128), "{parts:?}");
        assert_eq!(winding(&open, &WindingParams::default()), Winding::Outward);
    }

    #[test]
    fn a_lone_sheet_beside_the_body_is_one_sided_and_says_nothing() {
        // A floor: a 6 × 6 grid of quads under the cube, seen from above facing, from below not.
        let body = cube();
        let mut positions = body.positions.clone();
        let first = positions.len() as u32;
        for i in 0..7 {
            for j in 0..7 {
                positions.push(Point3::new(
                    -1.0 + 0.5 * i as f64,
                    -1.0 + 0.5 * j as f64,
                    -0.5,
                ));
            }
        }
        let mut triangles = body.triangles.clone();
        for i in 0..6u32 {
            for j in 0..6u32 {
                let v = |a: u32, b: u32| first + a * 7 + b;
                triangles.push([v(i, j), v(i + 1, j), v(i + 1, j + 1)]);
                triangles.push([v(i, j), v(i + 1, j + 1), v(i, j + 1)]);
            }
        }
        let mesh = Mesh::new(positions, triangles);
        let p = WindingParams {
            grid: 12,
            ..WindingParams::default()
        };
        let floor = views(&mesh, &p)[1];
        assert_eq!(part_says(&floor, &p), PartSays::OneSided, "{floor:?}");
        assert_eq!(winding(&mesh, &p), Winding::Outward);
        // The floor claims no side of its own; the body keeps its.
        let (l, n) = parts(&mesh);
        assert_eq!(windings(&mesh, &l, n, &p).1, vec![1, 0]);
        // The same floor alone says nothing: no part is wound either way.
        let alone = Mesh::new(mesh.positions.clone(), mesh.triangles[12..].to_vec());
        assert_eq!(winding(&alone, &p), Winding::Mixed);
    }
}
