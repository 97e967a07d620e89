//! A closest-point index over a triangle surface (the scan, or the moving template for the
//! scan-to-template term): a k-d tree of its vertices with their normals and rim flags, one-rings,
//! and on demand a triangle BVH. Built once per surface and queried every correspondence round.

use super::error::AlignError;
use super::params::CorrespondenceMode;
use super::surface::{barycentric, closest_point_on_triangle, OneRings};
use crate::mesh::normals::{face_normals, vertex_normals};
use crate::mesh::topology::boundary_vertices;
use crate::mesh::Mesh;
use kiddo::{ImmutableKdTree, SquaredEuclidean};
use nalgebra::{Point3, Vector3};
use parry3d_f64::query::PointQueryWithLocation;
use parry3d_f64::shape::TriMesh;
use std::num::NonZero;
use std::sync::OnceLock;

/// A candidate of the one-ring search replaces the best one only when it is closer by more than
/// this share of the squared distance (plus [`TIE_FLOOR_M2`]). A point on an edge two triangles
/// share, or at the ring's own vertex, is found by several candidates at one distance up to
/// rounding, and their hole-rim flags differ (a triangle touching a rim, the vertex itself):
/// rounding must not choose among them, or a fit changes with the scan's frame and units (issue
/// 31: 2–6 of 12,816 matches flipped by a 1e-16 m change of the scan, the fit 1–3 mm p99 apart).
/// The first candidate in the ring's fixed order wins a tie.
pub const TIE_SHARE: f64 = 1e-9;

/// The squared distance (m², (0.1 nm)²) below which candidates of the one-ring search tie
/// whatever their share ([`TIE_SHARE`]).
pub const TIE_FLOOR_M2: f64 = 1e-20;

/// Whether a candidate at squared distance `d2` beats the best so far at `best_d2`: closer by
/// more than rounding ([`TIE_SHARE`]).
fn closer(d2: f64, best_d2: f64) -> bool {
    d2 < best_d2 * (1.0 - TIE_SHARE) - TIE_FLOOR_M2
}

/// A closest point on the scan for one template vertex.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Match {
    /// The point on the scan (vertex or point on a triangle), metres.
    pub point: Point3<f64>,
    /// The scan's unit normal there (vertex normal or face normal).
    pub normal: Vector3<f64>,
    /// Whether the match lies on a hole rim (boundary vertex, or triangle touching one).
    pub on_boundary: bool,
}

/// A closest point on a mesh expressed by the triangle corners it interpolates, so an energy can
/// follow the point as the corners move (used on the fitted template by the scan-to-template term).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FaceMatch {
    /// Corner vertices of the triangle the point lies on (a vertex match repeats its vertex).
    pub corners: [u32; 3],
    /// Barycentric coordinates of the point in `corners`, summing to 1.
    pub barycentric: [f64; 3],
    /// The point, metres.
    pub point: Point3<f64>,
    /// The mesh's unit normal there.
    pub normal: Vector3<f64>,
    /// Whether the point lies on a hole rim (boundary vertex, or triangle touching one).
    pub on_boundary: bool,
}

/// How one query is answered.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MatchQuery {
    /// Search strategy.
    pub mode: CorrespondenceMode,
    /// Minimum cosine between query normal and scan normal; `None` accepts any normal.
    pub min_cos: Option<f64>,
    /// Nearest scan vertices tried for a compatible normal.
    pub candidates: usize,
}

/// A scan prepared for closest-point queries: a k-d tree over its vertices (`kiddo`), vertex and
/// face normals, one-rings, boundary flags, and — built on first use — a BVH over its triangles
/// (`parry3d-f64`). Build it once per scan; [`crate::align::fine_align`] only reads it.
pub struct SurfaceIndex {
    positions: Vec<Point3<f64>>,
    triangles: Vec<[u32; 3]>,
    vertex_normals: Vec<Vector3<f64>>,
    face_normals: Vec<Vector3<f64>>,
    boundary_vertex: Vec<bool>,
    boundary_triangle: Vec<bool>,
    rings: OneRings,
    tree: ImmutableKdTree<f64, 3>,
    /// Tree item → scan vertex: only vertices used by a triangle are indexed, so stray points
    /// (unreferenced vertices, common in raw scans) are never matched.
    tree_vertex: Vec<u32>,
    bvh: OnceLock<Option<TriMesh>>,
}

impl std::fmt::Debug for SurfaceIndex {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SurfaceIndex")
            .field("vertices", &self.positions.len())
            .field("triangles", &self.triangles.len())
            .finish()
    }
}

/// Checks a mesh's indices and coordinates; `what` names it in the error.
pub(crate) fn validate_mesh(
    what: &'static str,
    positions: &[Point3<f64>],
    triangles: &[[u32; 3]],
) -> Result<(), AlignError> {
    if let Some(vertex) = positions
        .iter()
        .position(|p| !p.coords.iter().all(|c| c.is_finite()))
    {
        return Err(AlignError::NonFinite { what, vertex });
    }
    for (triangle, t) in triangles.iter().enumerate() {
        if let Some(&index) = t.iter().find(|&&i| i as usize >= positions.len()) {
            return Err(AlignError::IndexOutOfRange {
                what,
                triangle,
                index,
                vertices: positions.len(),
            });
        }
    }
    Ok(())
}

impl SurfaceIndex {
    /// Indexes `scan` (metres). Fails on a point cloud, bad indices or non-finite coordinates.
    pub fn new(scan: &Mesh) -> Result<Self, AlignError> {
        Self::from_parts("scan", &scan.positions, &scan.triangles)
    }

    /// Indexes any triangle mesh (also used on the fitted template for scan-to-template distances).
    pub(crate) fn from_parts(
        what: &'static str,
        positions: &[Point3<f64>],
        triangles: &[[u32; 3]],
    ) -> Result<Self, AlignError> {
        if triangles.is_empty() {
            return Err(AlignError::ScanHasNoTriangles {
                vertices: positions.len(),
            });
        }
        validate_mesh(what, positions, triangles)?;
        let mut used = vec![false; positions.len()];
        triangles
            .iter()
            .flatten()
            .for_each(|&v| used[v as usize] = true);
        let tree_vertex: Vec<u32> = (0..positions.len() as u32)
            .filter(|&v| used[v as usize])
            .collect();
        let coords: Vec<[f64; 3]> = tree_vertex
            .iter()
            .map(|&v| {
                let p = &positions[v as usize];
                [p.x, p.y, p.z]
            })
            .collect();
        let tree = ImmutableKdTree::new_from_slice(&coords).map_err(|_| {
            AlignError::ScanHasNoTriangles {
                vertices: positions.len(),
            }
        })?;
        let boundary_vertex = boundary_vertices(positions.len(), triangles);
        let boundary_triangle = triangles
            .iter()
            .map(|t| t.iter().any(|&v| boundary_vertex[v as usize]))
            .collect();
        Ok(Self {
            positions: positions.to_vec(),
            triangles: triangles.to_vec(),
            vertex_normals: vertex_normals(positions, triangles),
            face_normals: face_normals(positions, triangles),
            boundary_vertex,
            boundary_triangle,
            rings: OneRings::new(positions.len(), triangles),
            tree,
            tree_vertex,
            bvh: OnceLock::new(),
        })
    }

    /// Moves the indexed mesh's vertices to `positions` (same count, same triangles), keeping
    /// its topology (one-rings, boundary flags): the k-d tree and normals are rebuilt. Used on the
    /// template, whose surface moves every round while its connectivity does not.
    pub(crate) fn move_vertices(&mut self, positions: &[Point3<f64>]) {
        debug_assert_eq!(positions.len(), self.positions.len());
        self.positions.clear();
        self.positions.extend_from_slice(positions);
        let coords: Vec<[f64; 3]> = self
            .tree_vertex
            .iter()
            .map(|&v| {
                let p = &positions[v as usize];
                [p.x, p.y, p.z]
            })
            .collect();
        if let Ok(tree) = ImmutableKdTree::new_from_slice(&coords) {
            self.tree = tree;
        }
        self.vertex_normals = vertex_normals(positions, &self.triangles);
        self.face_normals = face_normals(positions, &self.triangles);
        self.bvh = OnceLock::new();
    }

    /// Number of scan vertices.
    pub fn vertex_count(&self) -> usize {
        self.positions.len()
    }

    /// Scan vertex positions (metres).
    pub fn positions(&self) -> &[Point3<f64>] {
        &self.positions
    }

    /// Scan vertices used by at least one triangle (the points that are matched and measured).
    pub fn surface_vertices(&self) -> impl Iterator<Item = &Point3<f64>> + '_ {
        self.tree_vertex
            .iter()
            .map(|&v| &self.positions[v as usize])
    }

    /// Per-vertex boundary flags (`true` on hole rims and open borders).
    pub fn boundary_vertices(&self) -> &[bool] {
        &self.boundary_vertex
    }

    /// Builds the triangle BVH now (otherwise it is built by the first
    /// [`CorrespondenceMode::ClosestOnTriangle`] query).
    pub fn prepare_triangle_bvh(&self) {
        let _ = self.bvh();
    }

    fn bvh(&self) -> Option<&TriMesh> {
        self.bvh
            .get_or_init(|| {
                let vertices = self
                    .positions
                    .iter()
                    .map(|p| parry3d_f64::math::Vector::new(p.x, p.y, p.z))
                    .collect();
                TriMesh::new(vertices, self.triangles.clone()).ok()
            })
            .as_ref()
    }

    fn compatible(min_cos: Option<f64>, query: Option<&Vector3<f64>>, n: &Vector3<f64>) -> bool {
        match (min_cos, query) {
            (Some(c), Some(q)) => q.dot(n) >= c,
            _ => true,
        }
    }

    /// The closest compatible point on the scan to `p`, whose own unit normal is `normal` (used
    /// only when `query.min_cos` is set). `None` when no candidate has a compatible normal.
    pub fn closest(
        &self,
        p: &Point3<f64>,
        normal: Option<&Vector3<f64>>,
        query: &MatchQuery,
    ) -> Option<Match> {
        match query.mode {
            CorrespondenceMode::NearestVertex => {
                let v = self.nearest_compatible_vertex(p, normal, query)?;
                Some(Match {
                    point: self.positions[v],
                    normal: self.vertex_normals[v],
                    on_boundary: self.boundary_vertex[v],
                })
            }
            CorrespondenceMode::VertexOneRing => self.one_ring_match(p, normal, query),
            CorrespondenceMode::ClosestOnTriangle => {
                let exact = self.bvh().and_then(|mesh| {
                    let q = parry3d_f64::math::Vector::new(p.x, p.y, p.z);
                    let (proj, (tri, _)) = mesh.project_local_point_and_get_location(q, false);
                    let tri = tri as usize;
                    let n = self.face_normals.get(tri)?;
                    Self::compatible(query.min_cos, normal, n).then(|| Match {
                        point: Point3::new(proj.point.x, proj.point.y, proj.point.z),
                        normal: *n,
                        on_boundary: self.boundary_triangle[tri],
                    })
                });
                exact.or_else(|| self.one_ring_match(p, normal, query))
            }
        }
    }

    /// The closest compatible point to `p` on the triangles around its nearest compatible vertex
    /// (the [`CorrespondenceMode::VertexOneRing`] search), with its triangle and barycentric
    /// coordinates. `None` when no candidate has a compatible normal.
    pub fn closest_face(
        &self,
        p: &Point3<f64>,
        normal: Option<&Vector3<f64>>,
        query: &MatchQuery,
    ) -> Option<FaceMatch> {
        let v = self.nearest_compatible_vertex(p, normal, query)?;
        let mut best = FaceMatch {
            corners: [v as u32; 3],
            barycentric: [1.0, 0.0, 0.0],
            point: self.positions[v],
            normal: self.vertex_normals[v],
            on_boundary: self.boundary_vertex[v],
        };
        let mut best_d2 = (best.point - p).norm_squared();
        for &f in self.rings.triangles_of(v) {
            let f = f as usize;
            let n = &self.face_normals[f];
            if !Self::compatible(query.min_cos, normal, n) {
                continue;
            }
            let corners = self.triangles[f];
            let [a, b, c] = corners.map(|i| self.positions[i as usize]);
            let x = closest_point_on_triangle(p, &a, &b, &c);
            let d2 = (x - p).norm_squared();
            if closer(d2, best_d2) {
                best_d2 = d2;
                best = FaceMatch {
                    corners,
                    barycentric: barycentric(&x, &a, &b, &c),
                    point: x,
                    normal: *n,
                    on_boundary: self.boundary_triangle[f],
                };
            }
        }
        Some(best)
    }

    /// Unit normal of scan vertex `v`.
    pub fn vertex_normal(&self, v: usize) -> &Vector3<f64> {
        &self.vertex_normals[v]
    }

    /// Indices of the scan vertices used by at least one triangle, in order.
    pub fn surface_vertex_indices(&self) -> &[u32] {
        &self.tree_vertex
    }

    fn nearest_compatible_vertex(
        &self,
        p: &Point3<f64>,
        normal: Option<&Vector3<f64>>,
        query: &MatchQuery,
    ) -> Option<usize> {
        let k = NonZero::new(query.candidates.min(self.tree_vertex.len()))?;
        let q = [p.x, p.y, p.z];
        // The nearest vertex is compatible almost everywhere; only where it is not (legs, folds)
        // is the k-nearest query (which allocates its result) needed.
        let hit = self
            .tree
            .query(&q)
            .nearest_one::<SquaredEuclidean<f64>>()
            .execute();
        let nearest = self.tree_vertex[hit.item as usize] as usize;
        if Self::compatible(query.min_cos, normal, &self.vertex_normals[nearest]) {
            return Some(nearest);
        }
        let hits = self
            .tree
            .query(&q)
            .nearest_n::<SquaredEuclidean<f64>>(k)
            .execute();
        hits.iter()
            .map(|h| self.tree_vertex[h.item as usize] as usize)
            .find(|&v| Self::compatible(query.min_cos, normal, &self.vertex_normals[v]))
    }

    fn one_ring_match(
        &self,
        p: &Point3<f64>,
        normal: Option<&Vector3<f64>>,
        query: &MatchQuery,
    ) -> Option<Match> {
        self.closest_face(p, normal, query).map(|m| Match {
            point: m.point,
            normal: m.normal,
            on_boundary: m.on_boundary,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 4 × 4 grid of vertices 1 cm apart in the plane z = 0, turned by `turn` and moved by
    /// `shift`: only the middle square's two triangles touch no rim vertex.
    fn grid(turn: &nalgebra::Rotation3<f64>, shift: &Vector3<f64>) -> Mesh {
        let positions = (0..16)
            .map(|i| turn * Point3::new(0.01 * (i % 4) as f64, 0.01 * (i / 4) as f64, 0.0) + shift)
            .collect();
        let mut triangles = Vec::new();
        for y in 0..3u32 {
            for x in 0..3u32 {
                let v = 4 * y + x;
                triangles.push([v, v + 1, v + 5]);
                triangles.push([v, v + 5, v + 4]);
            }
        }
        Mesh::new(positions, triangles)
    }

    #[test]
    fn a_point_on_an_edge_two_triangles_share_gets_one_rim_flag_whatever_the_rounding() {
        // Above the edge (1,1)–(2,1), 30 % along it: the nearest vertex is (1,1); the edge is
        // shared by the middle square's triangle (no rim vertex) and the one below it (rim
        // vertices), both at the same distance.
        let query = MatchQuery {
            mode: CorrespondenceMode::VertexOneRing,
            min_cos: None,
            candidates: 1,
        };
        let mut flags = Vec::new();
        for k in 0..200 {
            let turn =
                nalgebra::Rotation3::from_euler_angles(0.37 * k as f64, 0.11 * k as f64, 0.05);
            let shift = Vector3::new(0.1234567 * k as f64, -0.7654321 * k as f64, 0.31 * k as f64);
            let index = SurfaceIndex::new(&grid(&turn, &shift)).unwrap();
            let p = turn * Point3::new(0.013, 0.01, 0.004) + shift;
            let m = index.closest(&p, None, &query).unwrap();
            assert!((m.point - (turn * Point3::new(0.013, 0.01, 0.0) + shift)).norm() < 1e-12);
            flags.push(m.on_boundary);
        }
        assert!(flags.iter().all(|f| *f == flags[0]), "{flags:?}");
    }
}
