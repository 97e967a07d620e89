//! A one-look summary of a scan: sizes, bounding box in metres, units, holes, components and
//! which way its triangles face.

use nalgebra::Point3;
use serde::Serialize;

use super::bounds::bounding_box;
use super::orientation::cohere;
use super::topology::{
    boundary_edges, boundary_edges_and_disagreement, component_labels, loops_of, triangle_labels,
};
use super::units::{detect_units, Units};
use super::winding::{facings, Winding, WindingParams};
use super::Mesh;

/// What `bodyspace info` and the app show about a loaded scan.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MeshSummary {
    /// `#V`.
    pub vertices: usize,
    /// `#F`.
    pub triangles: usize,
    /// Bounding-box minimum corner in metres (after `scale_to_metres`); zeros for an empty mesh.
    pub bbox_min: [f64; 3],
    /// Bounding-box maximum corner in metres.
    pub bbox_max: [f64; 3],
    /// Units the file was taken to be in, from the largest bounding-box extent.
    pub units_detected: Units,
    /// Factor from file units to metres.
    pub scale_to_metres: f64,
    /// Number of boundary loops (holes and open borders).
    pub boundary_loops: usize,
    /// Number of connected components.
    pub components: usize,
    /// Which way the triangles face ([`super::winding`]).
    pub winding: Winding,
    /// Per triangle as the file has it, which way its front faces ([`facings`]): 1 out of the
    /// body, −1 into it, 0 not known. Not in the summary's JSON (one entry per triangle); the app
    /// takes it as an array.
    #[serde(skip)]
    pub triangle_facing: Vec<i8>,
}

/// Summarises a mesh whose positions are in file units.
pub fn summarise(mesh: &Mesh) -> MeshSummary {
    let bbox = bounding_box(&mesh.positions);
    let extent = bbox.map_or(0.0, |(lo, hi)| (hi - lo).max());
    let units = detect_units(extent);
    let s = units.scale_to_metres();
    let (lo, hi) = bbox.unwrap_or((Point3::origin(), Point3::origin()));
    let (labels, components) = component_labels(mesh);
    // One pass over the edges for the holes and for whether the triangles agree. Where they do
    // not, the holes are traced on the triangles turned to agree: a rim's edges then run head
    // to tail (on a file with half its triangles turned, the sample's 107 holes came out 5,750).
    let n = mesh.positions.len();
    let (mut boundary, disagree) = boundary_edges_and_disagreement(n, &mesh.triangles);
    let cohered = if disagree { cohere(mesh) } else { None };
    if let Some(c) = &cohered {
        boundary = boundary_edges(n, &c.triangles);
    }
    let (winding, triangle_facing) = facings(
        mesh,
        &triangle_labels(mesh, &labels),
        components,
        cohered,
        &WindingParams::default(),
    );
    MeshSummary {
        vertices: mesh.vertex_count(),
        triangles: mesh.triangle_count(),
        bbox_min: [lo.x * s, lo.y * s, lo.z * s],
        bbox_max: [hi.x * s, hi.y * s, hi.z * s],
        units_detected: units,
        scale_to_metres: s,
        boundary_loops: loops_of(&boundary).len(),
        components,
        winding,
        triangle_facing,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn millimetre_body_is_scaled_to_metres() {
        let mesh = Mesh::new(
            vec![
                Point3::new(-200.0, 0.0, -100.0),
                Point3::new(200.0, 1750.0, 100.0),
                Point3::new(0.0, 900.0, 0.0),
            ],
            vec![[0, 1, 2]],
        );
        let s = summarise(&mesh);
        assert_eq!(s.units_detected, Units::Millimetres);
        assert_eq!(s.scale_to_metres, 1e-3);
        assert!((s.bbox_max[1] - 1.75).abs() < 1e-12);
        assert!((s.bbox_min[0] + 0.2).abs() < 1e-12);
        assert_eq!((s.vertices, s.triangles), (3, 1));
        assert_eq!((s.boundary_loops, s.components), (1, 1));
    }

    #[test]
    fn empty_mesh_summarises_to_zeros() {
        let s = summarise(&Mesh::default());
        assert_eq!(s.bbox_min, [0.0; 3]);
        assert_eq!(s.units_detected, Units::Metres);
        assert_eq!(s.components, 0);
        assert_eq!(s.winding, Winding::Mixed);
        assert!(s.triangle_facing.is_empty());
    }

    #[test]
    fn each_triangle_carries_which_way_it_faces() {
        // Two unit cubes apart, the second turned inside out: the scan is mixed, each part not.
        let mut mesh = crate::mesh::winding::tests::two_cubes(true);
        // And a lone point, which no triangle uses.
        mesh.positions.push(Point3::new(0.0, 5.0, 0.0));
        let s = summarise(&mesh);
        assert_eq!(s.winding, Winding::Mixed);
        let expected: Vec<i8> = [vec![1; 12], vec![-1; 12]].concat();
        assert_eq!(s.triangle_facing, expected);
        // A cube whose every other triangle is turned: mixed, and each triangle its own way.
        let both =
            crate::mesh::winding::tests::flipped(&crate::mesh::topology::tests::cube(), |t| {
                t % 2 == 0
            });
        let s = summarise(&both);
        assert_eq!((s.winding, s.boundary_loops), (Winding::Mixed, 0));
        let expected: Vec<i8> = (0..12).map(|t| if t % 2 == 0 { -1 } else { 1 }).collect();
        assert_eq!(s.triangle_facing, expected);
        // Open at one face, with every other triangle turned: one hole, as wound one way (the
        // rim traced on the file's own order breaks where its triangles disagree).
        let mut open = crate::mesh::topology::tests::cube();
        open.triangles.truncate(10);
        let both = crate::mesh::winding::tests::flipped(&open, |t| t % 2 == 0);
        assert!(crate::mesh::topology::boundary_loops(&both).len() > 1);
        assert_eq!(summarise(&both).boundary_loops, 1);
    }
}
