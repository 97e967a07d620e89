//! Plane sections of a triangle mesh: the closed loops (and open chains) where a plane cuts it.

use super::vec3::{cross, dot, sub, unit};
use std::collections::hash_map::Entry;
use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};

/// A hash for edge keys (two vertex indices from the mesh): one multiply and rotate per word.
/// The standard library's default (SipHash, built to resist chosen keys) cost more than the
/// section's arithmetic; the chest's apex search sections the torso and arms nine times a body.
#[derive(Default)]
struct EdgeHasher(u64);

impl Hasher for EdgeHasher {
    fn finish(&self) -> u64 {
        self.0
    }
    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.write_u32(b as u32);
        }
    }
    fn write_u32(&mut self, word: u32) {
        self.0 = (self.0.rotate_left(5) ^ word as u64).wrapping_mul(0x517c_c1b7_2722_0a95);
    }
}

type EdgeMap<V> = HashMap<(u32, u32), V, BuildHasherDefault<EdgeHasher>>;

/// A plane through `origin` with unit `normal`, and two unit in-plane axes `u`, `v`
/// (`u × v = normal`) for the section's 2-D coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Plane {
    pub origin: [f64; 3],
    pub normal: [f64; 3],
    u: [f64; 3],
    v: [f64; 3],
}

impl Plane {
    /// The plane through `origin` perpendicular to `normal` (any length); `None` for a zero or
    /// non-finite normal.
    pub fn new(origin: [f64; 3], normal: [f64; 3]) -> Option<Plane> {
        let n = unit(normal)?;
        // The coordinate axis least aligned with n makes a well-conditioned first in-plane axis.
        let k = (0..3)
            .min_by(|&a, &b| n[a].abs().total_cmp(&n[b].abs()))
            .unwrap_or(0);
        let mut e = [0.0; 3];
        e[k] = 1.0;
        let u = unit(cross(e, n))?;
        let v = cross(n, u);
        Some(Plane {
            origin,
            normal: n,
            u,
            v,
        })
    }

    /// The horizontal plane `up = height` (`up_axis` 0, 1 or 2).
    pub fn horizontal(up_axis: usize, height: f64) -> Plane {
        let mut origin = [0.0; 3];
        let mut normal = [0.0; 3];
        origin[up_axis] = height;
        normal[up_axis] = 1.0;
        Plane::new(origin, normal).expect("a unit axis is a valid normal")
    }

    /// Signed distance of `p` from the plane.
    pub fn distance(&self, p: [f64; 3]) -> f64 {
        dot(self.normal, sub(p, self.origin))
    }

    /// In-plane coordinates of `p` (projected onto the plane).
    pub fn to_plane(&self, p: [f64; 3]) -> [f64; 2] {
        let d = sub(p, self.origin);
        [dot(d, self.u), dot(d, self.v)]
    }

    /// The 3-D point of in-plane coordinates `q`.
    pub fn from_plane(&self, q: [f64; 2]) -> [f64; 3] {
        [0, 1, 2].map(|k| self.origin[k] + q[0] * self.u[k] + q[1] * self.v[k])
    }
}

/// One connected piece of a section: points in the plane's coordinates, in order along the cut.
#[derive(Debug, Clone, PartialEq)]
pub struct SectionLoop {
    pub points: Vec<[f64; 2]>,
    /// Whether the piece closes on itself (an open chain ends on a mesh boundary).
    pub closed: bool,
}

fn vertex(positions: &[f32], v: u32) -> Option<[f64; 3]> {
    let i = 3 * v as usize;
    positions
        .get(i..i + 3)
        .map(|p| [p[0] as f64, p[1] as f64, p[2] as f64])
}

/// One mesh edge the plane crosses: where, the (at most two) crossings it is linked to through a
/// cut triangle (indices into the section's list of crossings), and whether a walk has passed it.
#[derive(Clone, Copy)]
struct Crossing {
    /// The edge's two vertices, the smaller first.
    edge: (u32, u32),
    at: [f64; 2],
    links: [u32; 2],
    linked: u8,
    visited: bool,
}

impl Crossing {
    fn links(&self) -> &[u32] {
        &self.links[..self.linked as usize]
    }

    /// A link to another crossing; an edge of a manifold mesh (the template is one) borders two
    /// triangles, so a third link (a non-manifold edge) is dropped.
    fn link(&mut self, to: u32) {
        if (self.linked as usize) < self.links.len() {
            self.links[self.linked as usize] = to;
            self.linked += 1;
        }
    }
}

/// A triangle the plane cuts: its vertices, their positions, their signed distances from the
/// plane and which of them lie in front of it.
struct CutTriangle {
    vertices: [u32; 3],
    points: [[f64; 3]; 3],
    distances: [f64; 3],
    front: [bool; 3],
}

/// The pieces where `plane` cuts the triangles `section_triangles` (indices into `triangles`,
/// `#F` index triples over flat `#V·3` `positions`). Each cut crosses mesh edges; the cut points
/// of one triangle are linked, and the links chained into loops through the edges they share.
/// A vertex exactly on the plane counts as in front of it, so every crossing is a proper edge cut.
/// Indices beyond the arrays are skipped.
///
/// Cost: one pass over `section_triangles`; then per crossed edge one look-up of its edge in a
/// map (as each of its two triangles records it), the walk following the links by index.
pub fn plane_section(
    positions: &[f32],
    triangles: &[[u32; 3]],
    section_triangles: &[u32],
    plane: &Plane,
) -> Vec<SectionLoop> {
    // The cut triangles first, so that the edge map is sized once: about one crossed edge per cut
    // triangle (each has two, each shared by two).
    let mut cut_triangles: Vec<CutTriangle> = Vec::new();
    for &t in section_triangles {
        let Some(tri) = triangles.get(t as usize) else {
            continue;
        };
        let (Some(p0), Some(p1), Some(p2)) = (
            vertex(positions, tri[0]),
            vertex(positions, tri[1]),
            vertex(positions, tri[2]),
        ) else {
            continue;
        };
        // Written out rather than by `[_; 3]::map`, which is not always inlined: this loop runs
        // over every triangle of a region.
        let d = [plane.distance(p0), plane.distance(p1), plane.distance(p2)];
        let front = [d[0] >= 0.0, d[1] >= 0.0, d[2] >= 0.0];
        // Most triangles lie wholly on one side: nothing to record for them.
        if front[0] == front[1] && front[1] == front[2] {
            continue;
        }
        cut_triangles.push(CutTriangle {
            vertices: *tri,
            points: [p0, p1, p2],
            distances: d,
            front,
        });
    }
    let mut crossings: Vec<Crossing> = Vec::with_capacity(cut_triangles.len());
    let mut index: EdgeMap<u32> =
        EdgeMap::with_capacity_and_hasher(cut_triangles.len(), BuildHasherDefault::default());
    for CutTriangle {
        vertices: tri,
        points: p,
        distances: d,
        front,
    } in cut_triangles
    {
        let mut cut = [0u32; 2];
        let mut n = 0;
        for (a, b) in [(0, 1), (1, 2), (2, 0)] {
            if front[a] != front[b] && n < 2 {
                let f = d[a] / (d[a] - d[b]);
                let edge = (tri[a].min(tri[b]), tri[a].max(tri[b]));
                let at = [0, 1, 2].map(|k| p[a][k] + f * (p[b][k] - p[a][k]));
                let at = plane.to_plane(at);
                // The edge's second triangle computes the same point from its own side; the last
                // one computed is kept.
                cut[n] = match index.entry(edge) {
                    Entry::Occupied(e) => {
                        crossings[*e.get() as usize].at = at;
                        *e.get()
                    }
                    Entry::Vacant(e) => {
                        let i = *e.insert(crossings.len() as u32);
                        crossings.push(Crossing {
                            edge,
                            at,
                            links: [0; 2],
                            linked: 0,
                            visited: false,
                        });
                        i
                    }
                };
                n += 1;
            }
        }
        if n == 2 {
            crossings[cut[0] as usize].link(cut[1]);
            crossings[cut[1] as usize].link(cut[0]);
        }
    }
    // Open chains must be walked from an end; sorting by edge keeps the result deterministic.
    let mut starts: Vec<(bool, (u32, u32), u32)> = crossings
        .iter()
        .enumerate()
        .filter(|(_, c)| c.linked > 0)
        .map(|(i, c)| (c.linked != 1, c.edge, i as u32))
        .collect();
    starts.sort_unstable();
    let mut loops = Vec::new();
    for (_, _, start) in starts {
        if crossings[start as usize].visited {
            continue;
        }
        crossings[start as usize].visited = true;
        let mut chain = vec![crossings[start as usize].at];
        let mut current = start;
        while let Some(k) = crossings[current as usize]
            .links()
            .iter()
            .find(|&&k| !crossings[k as usize].visited)
            .copied()
        {
            let c = &mut crossings[k as usize];
            c.visited = true;
            chain.push(c.at);
            current = k;
        }
        let closed = chain.len() > 2 && crossings[current as usize].links().contains(&start);
        loops.push(SectionLoop {
            points: chain,
            closed,
        });
    }
    loops
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plane_coordinates_round_trip() {
        let plane = Plane::new([0.1, 0.2, 0.3], [1.0, 2.0, -0.5]).unwrap();
        let p = [0.4, -0.7, 1.1];
        let q = plane.from_plane(plane.to_plane(p));
        let d = plane.distance(p);
        for k in 0..3 {
            assert!((q[k] + d * plane.normal[k] - p[k]).abs() < 1e-12);
        }
        assert!(Plane::new([0.0; 3], [0.0; 3]).is_none());
    }

    #[test]
    fn a_tetrahedron_cut_in_the_middle_is_one_closed_triangle() {
        let p = [
            0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0f32,
        ];
        let t = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
        let loops = plane_section(&p, &t, &[0, 1, 2, 3], &Plane::horizontal(2, 0.5));
        assert_eq!(loops.len(), 1);
        assert!(loops[0].closed);
        assert_eq!(loops[0].points.len(), 3);
    }
}
