//! Triangles wound as their neighbours are: a patch of triangles turned against the surface
//! around it is turned back to agree.
//!
//! Two triangles that share an edge agree when they run along it in opposite directions (one
//! a → b, the other b → a): their counter-clockwise normals then lie on the same side of the
//! surface. Some files break this: a mesh stitched from patches, a reconstruction that never
//! oriented its triangles, an STL whose facets were written in any order. There a part's
//! triangles face both ways, the scan's normals say nothing, and [`super::winding`] cannot say
//! which way the part faces. But an edge run the same way by its two triangles also comes of two
//! surfaces welded where they touch, both facing right: a decimated scan's arm fused to the body
//! at a few edges (the zoo's `decimated` class: 32–45 such edges among 1,100–1,400 edges three or
//! more triangles share). A walk that turned every triangle to agree with the one it came from
//! turned 978 triangles of such a scan and took its landmark estimate from 15.0 to 40.4 mm
//! (2026-12-07).
//!
//! So [`cohere`] first joins the triangles across every edge they agree on into regions (a
//! region is never split: where the file disagrees with itself inside one, around a pinch, it
//! stays as it is). A region is *enclosed* when more of its rim runs along regions it disagrees
//! with than along pinches (edges three or more triangles share); the scan's border says
//! nothing either way (a turned patch at a hole or a slice's edge is bordered by it as much as a
//! welded sheet). A triangle turned in a surface is enclosed by it, a patch of them too, and so
//! is every patch of a file whose triangles face at random. Smallest first, an enclosed set of
//! regions is joined to every set across its seams, turned to agree with them, and the joined
//! set is looked at again; where the regions do not close up (a Möbius strip) the first join
//! stands. Of the two ways a joined set can face, the one turning fewer triangles is kept;
//! which of them faces out of the body is for [`super::winding::face_out`] to judge. Welded
//! surfaces meet along pinches as much as along disagreeing edges, so neither is enclosed: on the
//! zoo's five `decimated` scans 3–11 triangles are turned, their landmark estimates within
//! −1.2…+0.2 mm of before. Welded with no pinch, two surfaces cannot be told from a patch turned
//! in a surface, and one is turned. Nothing here looks at positions: only which triangles share
//! which edges.

use std::cmp::Reverse;
use std::collections::BinaryHeap;

use super::topology::for_each_edge;
use super::Mesh;

/// What [`cohere`] did: the triangles wound as their neighbours, how many were turned, and the
/// pieces of surface it joined.
#[derive(Debug, Clone, PartialEq)]
pub struct Cohered {
    /// `#F` triangles, the enclosed regions turned to agree.
    pub triangles: Vec<[u32; 3]>,
    /// How many were turned.
    pub turned: usize,
    /// Per triangle, its piece of surface (regions joined): `0..pieces`.
    pub piece: Vec<u32>,
    /// Number of pieces.
    pub pieces: usize,
}

/// `mesh`'s triangles with every enclosed region turned to agree with the regions around it
/// (module documentation); `None` when nothing is turned. Vertices and the triangles' order
/// stay.
pub fn cohere(mesh: &Mesh) -> Option<Cohered> {
    let triangles = &mesh.triangles;
    // Every edge's uses: the triangles of a manifold edge and whether they disagree, or the
    // triangles along a pinch (the scan's border says nothing).
    let mut pairs: Vec<(u32, u32, bool)> = Vec::with_capacity(3 * triangles.len() / 2);
    let mut pinch_uses: Vec<u32> = Vec::new();
    for_each_edge(mesh.positions.len(), triangles, |uses| match uses {
        [(_, s, [a, _]), (_, t, [c, _])] => pairs.push((*s, *t, a == c)),
        [_] => {}
        _ => pinch_uses.extend(uses.iter().map(|u| u.1)),
    });
    if !pairs.iter().any(|p| p.2) {
        return None;
    }
    // Regions: triangles joined across the edges they agree on, numbered 0..count.
    let mut joined = Joined::new(triangles.len());
    for &(s, t, disagree) in &pairs {
        if !disagree {
            joined.union(s, t, false);
        }
    }
    let mut number = vec![u32::MAX; triangles.len()];
    let mut count = 0u32;
    let region: Vec<u32> = (0..triangles.len() as u32)
        .map(|t| {
            let root = joined.find(t).0 as usize;
            if number[root] == u32::MAX {
                number[root] = count;
                count += 1;
            }
            number[root]
        })
        .collect();
    // Seams: the edges two regions disagree on.
    let seams: Vec<[u32; 2]> = pairs
        .iter()
        .filter(|p| p.2)
        .map(|&(s, t, _)| [region[s as usize], region[t as usize]])
        .filter(|[a, b]| a != b)
        .collect();
    let n = count as usize;
    let mut sets = Joined::new(n);
    // Each region's triangles; a set's, at its root, as regions are joined.
    let mut own = vec![0usize; n];
    for &r in &region {
        own[r as usize] += 1;
    }
    let mut size = own.clone();
    let mut pinched = vec![0usize; n];
    for &t in &pinch_uses {
        pinched[region[t as usize] as usize] += 1;
    }
    let mut against = vec![0usize; n];
    let mut at: Vec<Vec<u32>> = vec![Vec::new(); n];
    for (e, &[a, b]) in seams.iter().enumerate() {
        for r in [a, b] {
            against[r as usize] += 1;
            at[r as usize].push(e as u32);
        }
    }
    // Smallest first, an enclosed set of regions is joined to every set across its seams, turned
    // against them; the joined set is looked at again.
    let mut closed = vec![false; seams.len()];
    let mut queue: BinaryHeap<Reverse<(usize, u32)>> = (0..n as u32)
        .map(|r| Reverse((size[r as usize], r)))
        .collect();
    while let Some(Reverse((was, r))) = queue.pop() {
        let ru = r as usize;
        if sets.find(r).0 != r || size[ru] != was || against[ru] <= pinched[ru] {
            continue;
        }
        // Seams that fell inside the set when regions beside it were joined through another
        // are closed first; then it is looked at again.
        let mut open = std::mem::take(&mut at[ru]);
        open.retain(|&e| {
            let [x, y] = seams[e as usize];
            let inner = !closed[e as usize] && sets.find(x).0 == sets.find(y).0;
            if inner {
                closed[e as usize] = true;
                against[ru] -= 2;
            }
            !closed[e as usize]
        });
        if against[ru] <= pinched[ru] {
            at[ru] = open;
            continue;
        }
        let mut root = r;
        for e in open {
            if closed[e as usize] {
                continue;
            }
            closed[e as usize] = true;
            let [x, y] = seams[e as usize];
            let [a, b] = [x, y].map(|r| sets.find(r).0);
            if a == b {
                against[a as usize] -= 2;
                continue;
            }
            let (ua, ub) = (a as usize, b as usize);
            let (sum_size, sum_pinched) = (size[ua] + size[ub], pinched[ua] + pinched[ub]);
            let sum_against = against[ua] + against[ub] - 2;
            let (mut kept, mut moved) = (std::mem::take(&mut at[ua]), std::mem::take(&mut at[ub]));
            if kept.len() < moved.len() {
                std::mem::swap(&mut kept, &mut moved);
            }
            kept.append(&mut moved);
            // The seam's two regions disagree: one turned against the other.
            root = sets.union(x, y, true);
            let u = root as usize;
            (size[u], pinched[u], against[u], at[u]) = (sum_size, sum_pinched, sum_against, kept);
        }
        queue.push(Reverse((size[root as usize], root)));
    }
    // Each set of regions a piece, facing the way that turns fewer of its triangles.
    let mut turned_in = vec![0usize; n];
    let side: Vec<(u32, bool)> = (0..n as u32).map(|r| sets.find(r)).collect();
    for (r, &(root, turned)) in side.iter().enumerate() {
        if turned {
            turned_in[root as usize] += own[r];
        }
    }
    let mut piece_of = vec![u32::MAX; n];
    let mut pieces = 0u32;
    let mut turn = vec![false; n];
    for (r, &(root, turned)) in side.iter().enumerate() {
        let u = root as usize;
        turn[r] = turned ^ (2 * turned_in[u] > size[u]);
        if piece_of[u] == u32::MAX {
            piece_of[u] = pieces;
            pieces += 1;
        }
    }
    let turned = region.iter().filter(|&&r| turn[r as usize]).count();
    (turned > 0).then(|| Cohered {
        triangles: triangles
            .iter()
            .zip(&region)
            .map(|(&[a, b, c], &r)| {
                if turn[r as usize] {
                    [a, c, b]
                } else {
                    [a, b, c]
                }
            })
            .collect(),
        turned,
        piece: region
            .iter()
            .map(|&r| piece_of[side[r as usize].0 as usize])
            .collect(),
        pieces: pieces as usize,
    })
}

/// Disjoint sets that remember, for each member, whether it is turned against its set's root.
struct Joined {
    parent: Vec<u32>,
    /// Turned against the parent.
    turned: Vec<bool>,
    rank: Vec<u8>,
}

impl Joined {
    fn new(n: usize) -> Self {
        Self {
            parent: (0..n as u32).collect(),
            turned: vec![false; n],
            rank: vec![0; n],
        }
    }

    /// `x`'s root, and whether `x` is turned against it; the way there is pointed at the root.
    fn find(&mut self, x: u32) -> (u32, bool) {
        let (mut root, mut turned) = (x, false);
        while self.parent[root as usize] != root {
            turned ^= self.turned[root as usize];
            root = self.parent[root as usize];
        }
        let (mut at, mut along) = (x, turned);
        while self.parent[at as usize] != at {
            let (next, own) = (self.parent[at as usize], self.turned[at as usize]);
            self.parent[at as usize] = root;
            self.turned[at as usize] = along;
            along ^= own;
            at = next;
        }
        (root, turned)
    }

    /// Joins the sets of `a` and `b`, `b` turned against `a` when `turned`; the new root.
    fn union(&mut self, a: u32, b: u32, turned: bool) -> u32 {
        let (ra, pa) = self.find(a);
        let (rb, pb) = self.find(b);
        if ra == rb {
            return ra;
        }
        let (root, child) = if self.rank[ra as usize] >= self.rank[rb as usize] {
            (ra, rb)
        } else {
            (rb, ra)
        };
        self.parent[child as usize] = root;
        self.turned[child as usize] = pa ^ pb ^ turned;
        if self.rank[ra as usize] == self.rank[rb as usize] {
            self.rank[root as usize] += 1;
        }
        root
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::topology::tests::cube;
    use crate::mesh::winding::tests::{flipped, two_cubes};

    #[test]
    fn triangles_facing_against_their_neighbours_are_turned_back() {
        // A cube wound one way throughout: nothing to do, whichever way that is.
        assert!(cohere(&cube()).is_none());
        assert!(cohere(&flipped(&cube(), |_| true)).is_none());
        // Two of its twelve turned, each enclosed by the rest: turned back, the fewer.
        let c = cohere(&flipped(&cube(), |t| t == 3 || t == 8)).unwrap();
        assert_eq!((c.triangles, c.turned, c.pieces), (cube().triangles, 2, 1));
        // Nine of twelve turned: the three that were not are the fewer; the cube comes out
        // wound one way, inwards, for the winding to turn.
        let c = cohere(&flipped(&cube(), |t| t >= 3)).unwrap();
        assert_eq!(c.turned, 3);
        assert_eq!(c.triangles, flipped(&cube(), |_| true).triangles);
        // Each part alone: the second cube's one turned triangle, not the first's.
        let c = cohere(&flipped(&two_cubes(false), |t| t == 13)).unwrap();
        assert_eq!((c.triangles, c.turned), (two_cubes(false).triangles, 1));
        assert_eq!(c.piece, [vec![0; 12], vec![1; 12]].concat());
        // A part wound one way throughout, whichever way, is left as it is.
        assert!(cohere(&two_cubes(true)).is_none());
    }

    #[test]
    fn a_sheet_with_triangles_turned_at_random_comes_back_one_way() {
        // A 12 × 12 sheet of quads (288 triangles), some turned by a fixed scramble: patches of
        // every size, joined in many steps. A third turned: they come back. Two thirds: the
        // third not turned is the fewer, so the sheet comes back wound the other way throughout
        // (a count of the joined sets' sizes instead of their regions' once got this wrong).
        let side = 13u32;
        let positions = (0..side * side)
            .map(|i| nalgebra::Point3::new(f64::from(i % side), f64::from(i / side), 0.0))
            .collect();
        let at = |x: u32, y: u32| y * side + x;
        let triangles: Vec<[u32; 3]> = (0..side - 1)
            .flat_map(|y| (0..side - 1).map(move |x| (x, y)))
            .flat_map(|(x, y)| {
                [
                    [at(x, y), at(x + 1, y), at(x + 1, y + 1)],
                    [at(x, y), at(x + 1, y + 1), at(x, y + 1)],
                ]
            })
            .collect();
        let sheet = Mesh::new(positions, triangles);
        let third = |t: usize| (t as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15) % 3;
        let c = cohere(&flipped(&sheet, |t| third(t) == 0)).unwrap();
        assert_eq!(c.triangles, sheet.triangles);
        assert_eq!(c.turned, (0..288).filter(|&t| third(t) == 0).count());
        assert_eq!(c.pieces, 1);
        let c = cohere(&flipped(&sheet, |t| third(t) < 2)).unwrap();
        assert_eq!(c.triangles, flipped(&sheet, |_| true).triangles);
        assert_eq!(c.turned, (0..288).filter(|&t| third(t) == 2).count());
    }

    #[test]
    fn surfaces_welded_where_they_pinch_keep_their_ways() {
        // Two strips of four triangles, each wound one way, welded along their common line: the
        // edge 3–4 run the same way by a triangle of each, the edge 4–5 a pinch (a third sheet's
        // triangle shares it). Each strip's rim runs as far along the pinch as along the other
        // strip, so neither is enclosed, and nothing is turned.
        let mut positions: Vec<nalgebra::Point3<f64>> = (0..9)
            .map(|i| nalgebra::Point3::new(f64::from(i % 3), f64::from(i / 3), 0.0))
            .collect();
        positions.push(nalgebra::Point3::new(1.5, 1.0, 1.0));
        let one = [[0, 1, 4], [0, 4, 3], [1, 2, 5], [1, 5, 4]];
        let other = [[3, 7, 4], [3, 6, 7], [4, 8, 5], [4, 7, 8]];
        let mesh = Mesh::new(positions, [&one[..], &other, &[[4, 5, 9]]].concat());
        assert!(cohere(&mesh).is_none());
        // One of the first strip's triangles turned as well: enclosed by its strip (two of its
        // edges; the third is the scan's border, which says nothing), it is turned back, and the
        // strips stay as they are.
        let turned = flipped(&mesh, |t| t == 0);
        let c = cohere(&turned).unwrap();
        assert_eq!((c.triangles, c.turned), (mesh.triangles.clone(), 1));
        // Welded with no pinch, the strips cannot be told from a patch turned in a surface: the
        // one reached second is turned to agree.
        let seamless = Mesh::new(mesh.positions.clone(), mesh.triangles[..8].to_vec());
        let c = cohere(&seamless).unwrap();
        assert_eq!(c.turned, 4);
    }

    #[test]
    fn an_edge_shared_by_three_triangles_joins_nothing() {
        // Three triangles round one edge (0, 1), the third turned: no neighbour says which way
        // it should face, so nothing is turned.
        let positions = vec![
            nalgebra::Point3::new(0.0, 0.0, 0.0),
            nalgebra::Point3::new(1.0, 0.0, 0.0),
            nalgebra::Point3::new(0.5, 1.0, 0.0),
            nalgebra::Point3::new(0.5, -1.0, 0.0),
            nalgebra::Point3::new(0.5, 0.0, 1.0),
        ];
        let mesh = Mesh::new(positions, vec![[0, 1, 2], [1, 0, 3], [0, 1, 4]]);
        assert!(cohere(&mesh).is_none());
    }
}
