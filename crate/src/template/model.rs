//! [`Template`]: the generic body model every scan is aligned to.

use crate::landmarks::{Landmark, LandmarkSet};
use crate::mesh::Mesh;
use nalgebra::Point3;

use super::error::TemplateError;
use super::flags::RegionFlags;
use super::resolution::Resolution;
use super::segment::Segment;
use super::store::{self, StoredTemplate};
use super::subdivide::Subdivision;
use crate::mesh::topology::unique_edges;

/// The stored base template, embedded in the binary.
pub const EMBEDDED_TEMPLATE: &[u8] =
    include_bytes!("../../../public/template/template_base.bin.gz");

/// The generic template at one resolution: mesh (metres, y up, feet on y = 0, facing +z; the
/// subject's right side is x < 0), 73 CAESAR landmarks as vertex indices, six segment blend
/// weights per vertex, region flags and provenance.
#[derive(Debug, Clone)]
pub struct Template {
    mesh: Mesh,
    resolution: Resolution,
    landmarks: Vec<(String, u32)>,
    segment_weights: Vec<[f32; 6]>,
    flags: Vec<u8>,
    base_vertex_count: usize,
    /// MakeHuman vertex index of each base vertex.
    makehuman_vertex: Vec<u32>,
    base_triangles: Vec<[u32; 3]>,
    /// Fine resolution only: the operator that made this mesh from the base (stencils per
    /// vertex, fine triangles).
    refinement: Option<Subdivision>,
    band_width: f64,
    header: store::StoredHeader,
}

impl Template {
    /// Reads a stored template (gzipped or not); see [`store`] for the format.
    pub fn from_bytes(bytes: &[u8]) -> Result<Template, TemplateError> {
        Ok(Self::from_stored(store::decode(bytes)?))
    }

    /// The embedded base template (`public/template/template_base.bin.gz`).
    pub fn embedded() -> Result<Template, TemplateError> {
        Self::from_bytes(EMBEDDED_TEMPLATE)
    }

    pub(crate) fn from_stored(s: StoredTemplate) -> Template {
        Template {
            base_vertex_count: s.mesh.positions.len(),
            base_triangles: s.mesh.triangles.clone(),
            mesh: s.mesh,
            resolution: Resolution::Base,
            landmarks: s.header.landmarks.clone(),
            segment_weights: s.segment_weights,
            flags: s.flags,
            makehuman_vertex: s.provenance,
            refinement: None,
            band_width: s.header.band_width,
            header: s.header,
        }
    }

    /// The stored form of a base template (for the build tool).
    pub fn to_bytes(&self) -> Vec<u8> {
        store::encode(&self.base_stored())
    }

    /// This template's base resolution as stored: the first `base_vertex_count` vertices with
    /// their weights and flags, and the base triangles.
    fn base_stored(&self) -> StoredTemplate {
        StoredTemplate {
            header: self.header.clone(),
            mesh: Mesh::new(
                self.mesh.positions[..self.base_vertex_count].to_vec(),
                self.base_triangles.clone(),
            ),
            segment_weights: self.segment_weights[..self.base_vertex_count].to_vec(),
            flags: self.flags[..self.base_vertex_count].to_vec(),
            provenance: self.makehuman_vertex.clone(),
        }
    }

    /// The subdivision operator from this template's base resolution to `resolution`.
    pub fn subdivision(&self, resolution: Resolution) -> Subdivision {
        Subdivision::new(
            self.base_vertex_count,
            &self.base_triangles,
            resolution.levels(),
        )
    }

    /// The operator `S` that made this template's mesh from its base (`fine = S · base`), kept
    /// from [`Template::at_resolution`] so it is not rebuilt; `None` at `base`. Its first
    /// [`Template::base_vertex_count`] vertices are the base vertices.
    pub fn refinement(&self) -> Option<&Subdivision> {
        self.refinement.as_ref()
    }

    /// This template at `resolution`. Fine: subdivided mesh (base vertices first with the same
    /// indices, so landmarks and flags carry over), segment weights interpolated by the stencils,
    /// a new vertex flagged where all its source vertices share the flag.
    pub fn at_resolution(&self, resolution: Resolution) -> Template {
        if resolution == self.resolution {
            return self.clone();
        }
        let base = Template::from_stored(self.base_stored());
        if resolution == Resolution::Base {
            return base;
        }
        let sub = base.subdivision(resolution);
        let positions = sub.apply(&base.mesh.positions);
        let segment_weights = sub
            .apply_values(&base.segment_weights)
            .into_iter()
            .map(|w| {
                let s: f32 = w.iter().sum();
                w.map(|x| x / s.max(f32::MIN_POSITIVE))
            })
            .collect();
        let flags = sub
            .stencils
            .iter()
            .map(|s| {
                s.iter()
                    .fold(0xffu8, |f, &(v, _)| f & base.flags[v as usize])
            })
            .collect();
        Template {
            mesh: Mesh::new(positions, sub.triangles.clone()),
            resolution,
            landmarks: self.landmarks.clone(),
            segment_weights,
            flags,
            base_vertex_count: self.base_vertex_count,
            makehuman_vertex: self.makehuman_vertex.clone(),
            base_triangles: self.base_triangles.clone(),
            refinement: Some(sub),
            band_width: self.band_width,
            header: self.header.clone(),
        }
    }

    pub fn resolution(&self) -> Resolution {
        self.resolution
    }

    pub fn mesh(&self) -> &Mesh {
        &self.mesh
    }

    /// Number of base-resolution vertices; these come first at every resolution.
    pub fn base_vertex_count(&self) -> usize {
        self.base_vertex_count
    }

    /// The 73 CAESAR landmarks as (canonical name, vertex index), in CAESAR order.
    pub fn landmark_vertices(&self) -> &[(String, u32)] {
        &self.landmarks
    }

    /// The vertex of the landmark called `name` (canonical CAESAR name), if the template has it.
    pub fn landmark_vertex(&self, name: &str) -> Option<u32> {
        self.landmarks
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, v)| *v)
    }

    /// The landmarks at their vertices' positions.
    pub fn landmark_positions(&self) -> LandmarkSet {
        self.landmarks_at(&self.mesh.positions)
    }

    /// The landmarks at their vertices' positions in `positions` (`#V` of this template, e.g.
    /// the template deformed onto a subject).
    pub fn landmarks_at(&self, positions: &[Point3<f64>]) -> LandmarkSet {
        LandmarkSet {
            landmarks: self
                .landmarks
                .iter()
                .map(|(name, v)| Landmark {
                    name: name.clone(),
                    position: positions[*v as usize],
                })
                .collect(),
            missing: Vec::new(),
            unknown: Vec::new(),
        }
    }

    /// The 12 virtual landmarks (name, vertex), made by the rules of
    /// [`crate::landmarks::virtual_landmarks`] on this template's surface (the same rules run on
    /// every scan), each taken to the template vertex nearest the point the rule gives.
    pub fn virtual_landmark_vertices(&self) -> Result<Vec<(String, u32)>, TemplateError> {
        let made = crate::landmarks::virtual_landmarks(&self.landmark_positions(), &self.mesh);
        if made.len() != crate::landmarks::VIRTUAL_LANDMARK_COUNT {
            return Err(TemplateError::Format(format!(
                "the template's landmarks make {} of the {} virtual landmarks",
                made.len(),
                crate::landmarks::VIRTUAL_LANDMARK_COUNT
            )));
        }
        Ok(made
            .into_iter()
            .map(|l| (l.name, nearest_vertex(&self.mesh.positions, &l.position)))
            .collect())
    }

    /// Blend weights of the six segments (in [`Segment::ALL`] order) at `vertex`; they sum to 1.
    pub fn segment_weights(&self, vertex: u32) -> [f32; 6] {
        self.segment_weights[vertex as usize]
    }

    /// Blend weights of every vertex (`#V` entries, [`Segment::ALL`] order).
    pub fn segment_weight_table(&self) -> &[[f32; 6]] {
        &self.segment_weights
    }

    /// Above base resolution: per vertex, the base vertices and weights it is made from (the
    /// rows of the subdivision operator S, fine = S·base); `None` at base.
    pub fn stencils(&self) -> Option<&[Vec<(u32, f64)>]> {
        self.refinement.as_ref().map(|s| s.stencils.as_slice())
    }

    /// The vertices that belong to `segment` (blend weight > 0), overlap bands included.
    pub fn segment_vertices(&self, segment: Segment) -> Vec<u32> {
        let k = segment.index();
        (0..self.segment_weights.len() as u32)
            .filter(|&v| self.segment_weights[v as usize][k] > 0.0)
            .collect()
    }

    pub fn flags(&self, vertex: u32) -> RegionFlags {
        RegionFlags(self.flags[vertex as usize])
    }

    /// Unique undirected edges `(a, b)`, `a < b` (for the smoothness term).
    pub fn edges(&self) -> Vec<[u32; 2]> {
        unique_edges(&self.mesh.triangles)
    }

    /// Width of the overlap band between neighbouring segments, metres.
    pub fn band_width(&self) -> f64 {
        self.band_width
    }

    /// The MakeHuman base-mesh vertex `vertex` coincides with, if it is an original vertex.
    pub fn source_vertex(&self, vertex: u32) -> Option<u32> {
        self.makehuman_vertex.get(vertex as usize).copied()
    }

    /// The base-template vertices and weights `vertex` was made from (itself with weight 1 for
    /// base vertices).
    pub fn provenance(&self, vertex: u32) -> Vec<(u32, f64)> {
        match &self.refinement {
            Some(s) => s.stencils[vertex as usize].clone(),
            None => vec![(vertex, 1.0)],
        }
    }

    /// The file header (source, licence, flag bits, ...).
    pub fn header(&self) -> &store::StoredHeader {
        &self.header
    }
}

/// Index of the vertex of `positions` nearest to `q` (positions is non-empty for a template).
fn nearest_vertex(positions: &[Point3<f64>], q: &Point3<f64>) -> u32 {
    let mut best = (f64::INFINITY, 0u32);
    for (i, p) in positions.iter().enumerate() {
        let d = (p - q).norm_squared();
        if d < best.0 {
            best = (d, i as u32);
        }
    }
    best.1
}
