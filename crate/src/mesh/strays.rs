//! Stray pieces of a scan: small connected pieces floating apart from the body — dust, a
//! reflection, a bit of the booth — which a scanner exports with the body (issue 31). Left in,
//! the fit's scan → template distances counted them, and a good fit was reported as far from
//! its scan (25 mm RMS against 1.2).
//!
//! The scan's pieces are its connected components ([`component_labels`]). The body's pieces are
//! the largest and every piece holding at least `max_share` of the triangulated vertices (a body
//! exported in parts: torso, arms, legs); a smaller piece is stray when every vertex of it lies
//! farther than the gap from every vertex of the body's pieces: `min_gap` (8 cm), or `gap_edges`
//! times the scan's median edge length where that is more (a coarse scan leaves its toes and
//! hands in pieces several centimetres apart). A small piece close to the body (the toes' or
//! fingertips' slices of a slice scanner, 37–52 mm from the rest; a finger or an ear cut off by
//! a hole; a floor remnant under a foot) stays. Vertices no triangle uses are not pieces and stay as they
//! are (nothing matches or measures them).

use kiddo::{ImmutableKdTree, SquaredEuclidean};
use serde::{Deserialize, Serialize};

use super::topology::component_labels;
use super::Mesh;

/// What makes a piece stray (module documentation), with its defaults.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct StrayParams {
    /// A piece with at least this share of the triangulated vertices is the body's; default
    /// 0.01.
    pub max_share: f64,
    /// A smaller piece is stray when all of it lies farther than this from the body's pieces
    /// (m); default 0.08 (a slice scanner leaves the toes' and fingertips' slices in pieces
    /// 37–52 mm from the rest of the body; the zoo's stray pieces float at least 10 cm off).
    pub min_gap: f64,
    /// …or farther than this many times the scan's median edge length, where that is more;
    /// default 4 (a scan at 3–4 mm keeps the 8 cm).
    pub gap_edges: f64,
}

impl Default for StrayParams {
    fn default() -> Self {
        Self {
            max_share: 0.01,
            min_gap: 0.08,
            gap_edges: 4.0,
        }
    }
}

/// What [`remove_strays`] took off the scan.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StrayRemoval {
    /// Stray pieces removed.
    pub pieces: usize,
    /// Their vertices.
    pub vertices: usize,
    /// In words, for the report.
    pub words: String,
}

/// The scan without its stray pieces (module documentation), and what was removed: `mesh` in its
/// own frame and units, `to_m` its units → metres. `None` when no piece is stray; else the mesh
/// with the kept vertices in their order and the kept triangles re-indexed.
pub fn remove_strays(mesh: &Mesh, to_m: f64, params: &StrayParams) -> Option<(Mesh, StrayRemoval)> {
    if !(to_m > 0.0 && to_m.is_finite()) {
        return None;
    }
    let (labels, count) = component_labels(mesh);
    if count < 2 {
        return None;
    }
    let mut sizes = vec![0usize; count];
    for &l in labels.iter().filter(|&&l| l != u32::MAX) {
        sizes[l as usize] += 1;
    }
    let used: usize = sizes.iter().sum();
    let largest = (0..count).max_by_key(|&c| sizes[c])?;
    let body: Vec<bool> = (0..count)
        .map(|c| c == largest || sizes[c] as f64 >= params.max_share * used as f64)
        .collect();
    if body.iter().all(|&b| b) {
        return None;
    }
    let coords: Vec<[f64; 3]> = mesh
        .positions
        .iter()
        .zip(&labels)
        .filter(|&(_, &l)| l != u32::MAX && body[l as usize])
        .map(|(p, _)| [p.x * to_m, p.y * to_m, p.z * to_m])
        .collect();
    let gap = params
        .min_gap
        .max(params.gap_edges * median_edge(mesh) * to_m);
    let tree: ImmutableKdTree<f64, 3> = ImmutableKdTree::new_from_slice(&coords).ok()?;
    // A small piece is near the body when any of its vertices is.
    let mut near = body.clone();
    for (p, &l) in mesh.positions.iter().zip(&labels) {
        if l == u32::MAX || near[l as usize] {
            continue;
        }
        let q = [p.x * to_m, p.y * to_m, p.z * to_m];
        let d2 = tree
            .query(&q)
            .nearest_one::<SquaredEuclidean<f64>>()
            .execute()
            .distance;
        if d2 <= gap * gap {
            near[l as usize] = true;
        }
    }
    let stray = |l: u32| l != u32::MAX && !near[l as usize];
    let pieces = (0..count).filter(|&c| !near[c]).count();
    if pieces == 0 {
        return None;
    }
    let keep: Vec<bool> = labels.iter().map(|&l| !stray(l)).collect();
    let kept = mesh.with_vertices(&keep);
    let vertices = mesh.positions.len() - kept.positions.len();
    let gap_cm = gap * 100.0;
    let words = format!(
        "{pieces} stray piece{} of the scan ({vertices} vertices), each more than {gap_cm:.0} cm \
         from the body, {} left out",
        if pieces == 1 { "" } else { "s" },
        if pieces == 1 { "was" } else { "were" },
    );
    Some((
        kept,
        StrayRemoval {
            pieces,
            vertices,
            words,
        },
    ))
}

/// The median length of the triangles' first edges (the mesh's units; 0 without triangles).
fn median_edge(mesh: &Mesh) -> f64 {
    let mut lengths: Vec<f64> = mesh
        .triangles
        .iter()
        .map(|t| (mesh.positions[t[1] as usize] - mesh.positions[t[0] as usize]).norm())
        .collect();
    if lengths.is_empty() {
        return 0.0;
    }
    let k = lengths.len() / 2;
    *lengths.select_nth_unstable_by(k, |a, b| a.total_cmp(b)).1
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Point3;

    /// A closed box (the unit cube's 8 vertices and 12 triangles) from `lo` to `hi`, appended
    /// to `mesh`.
    fn add_box(mesh: &mut Mesh, lo: [f64; 3], hi: [f64; 3]) {
        let base = mesh.positions.len() as u32;
        let cube = crate::mesh::topology::tests::cube();
        mesh.positions.extend(cube.positions.iter().map(|p| {
            Point3::new(
                lo[0] + p.x * (hi[0] - lo[0]),
                lo[1] + p.y * (hi[1] - lo[1]),
                lo[2] + p.z * (hi[2] - lo[2]),
            )
        }));
        mesh.triangles
            .extend(cube.triangles.iter().map(|t| t.map(|v| base + v)));
    }

    /// A speck: one triangle (3 vertices) at `at`, 10 mm across, appended to `mesh`.
    fn add_speck(mesh: &mut Mesh, at: [f64; 3]) {
        let base = mesh.positions.len() as u32;
        for d in [[0.0, 0.0], [10.0, 0.0], [0.0, 10.0]] {
            mesh.positions
                .push(Point3::new(at[0] + d[0], at[1] + d[1], at[2]));
        }
        mesh.triangles.push([base, base + 1, base + 2]);
    }

    /// A "body" of `n` stacked boxes (each its own piece, touching the next: a body in parts,
    /// 8·n vertices), in millimetres.
    fn body(parts: usize) -> Mesh {
        let mut mesh = Mesh::default();
        for i in 0..parts {
            let z = 300.0 * i as f64;
            add_box(&mut mesh, [0.0, 0.0, z], [300.0, 200.0, z + 300.0]);
        }
        mesh
    }

    #[test]
    fn far_small_pieces_go_and_near_ones_stay() {
        // 40 parts of 8 vertices (2.5 % of the vertices each: the body's at a 2 % share) and
        // specks of 3 (0.9 %): one 10 cm off the body, one 2 cm off (a bit cut off a foot).
        let mut mesh = body(40);
        let body_vertices = mesh.positions.len();
        add_speck(&mut mesh, [400.0, 0.0, 0.0]);
        add_speck(&mut mesh, [320.0, 0.0, 0.0]);
        // A lone vertex: no triangle, stays.
        mesh.positions.push(Point3::new(5000.0, 0.0, 0.0));
        // Edges of 30 cm: the gap from the edges is left out here (next test).
        let params = StrayParams {
            max_share: 0.02,
            gap_edges: 0.0,
            ..StrayParams::default()
        };
        let (kept, removal) = remove_strays(&mesh, 0.001, &params).expect("one stray piece");
        assert_eq!(removal.pieces, 1);
        assert_eq!(removal.vertices, 3);
        assert_eq!(kept.positions.len(), body_vertices + 3 + 1);
        assert_eq!(kept.triangles.len(), mesh.triangles.len() - 1);
        assert!(kept.positions.iter().all(|p| p.x < 400.0 || p.x > 1000.0));
        assert!(removal
            .words
            .contains("1 stray piece of the scan (3 vertices)"));
    }

    #[test]
    fn a_body_in_large_parts_or_one_piece_loses_nothing() {
        assert!(remove_strays(&body(1), 0.001, &StrayParams::default()).is_none());
        // Parts far apart (a scan split at the joints and moved) are all large: all the body's.
        let mut mesh = body(1);
        add_box(&mut mesh, [2000.0, 0.0, 0.0], [2300.0, 200.0, 300.0]);
        assert!(remove_strays(&mesh, 0.001, &StrayParams::default()).is_none());
    }

    #[test]
    fn the_gap_is_in_metres_whatever_the_units() {
        for (scale, to_m) in [(1.0, 0.001), (0.1, 0.01), (0.001, 1.0)] {
            let mut mesh = body(40);
            add_speck(&mut mesh, [400.0, 0.0, 0.0]);
            add_speck(&mut mesh, [320.0, 0.0, 0.0]);
            for p in &mut mesh.positions {
                *p = Point3::from(p.coords * scale);
            }
            let params = StrayParams {
                max_share: 0.02,
                gap_edges: 0.0,
                ..StrayParams::default()
            };
            let (_, removal) = remove_strays(&mesh, to_m, &params).expect("the speck is stray");
            assert_eq!(removal.pieces, 1, "scale {scale}");
        }
    }

    #[test]
    fn on_a_coarse_mesh_the_gap_grows_with_its_edges() {
        // The body's edges are 30 cm (median), so the gap is 4 × 0.3 = 1.2 m: a speck 10 cm off
        // stays, one 2 m off goes.
        let mut mesh = body(40);
        add_speck(&mut mesh, [400.0, 0.0, 0.0]);
        add_speck(&mut mesh, [2300.0, 0.0, 0.0]);
        let params = StrayParams {
            max_share: 0.02,
            ..StrayParams::default()
        };
        let (kept, removal) = remove_strays(&mesh, 0.001, &params).expect("the far speck");
        assert_eq!(removal.pieces, 1);
        assert!(kept.positions.iter().all(|p| p.x < 1000.0));
        assert!(
            removal.words.contains("more than 120 cm"),
            "{}",
            removal.words
        );
    }
}
