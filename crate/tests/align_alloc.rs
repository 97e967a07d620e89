//! The hot loops of fine alignment allocate nothing: an L-BFGS iteration on the energy (value,
//! gradient, curvature, preconditioner, two-loop recursion), the iterations of a round inside
//! `fine_align`, and a closest-point query whose nearest scan vertex has a compatible normal.
//! Counted by a global allocator that counts the calling thread's allocations.

mod align_support;

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::ops::ControlFlow;

use align_support::{agreement_case, map, uv_sphere};
use bodyspace::align::energy::{
    identity_transforms, AlignEnergy, BlockPreconditioner, TangentialTerm,
};
use bodyspace::align::lbfgs::{Lbfgs, Objective, Step};
use bodyspace::align::scan_term::ScanSample;
use bodyspace::align::{
    fine_align, CorrespondenceMode, FineAlignInput, FineAlignParams, MatchQuery, Progress,
    SurfaceIndex,
};
use bodyspace::mesh::topology::unique_edges;
use nalgebra::{Point3, Vector3};

struct CountingAllocator;

thread_local! {
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

fn count_one() {
    let _ = ALLOCATIONS.try_with(|c| c.set(c.get() + 1));
}

// SAFETY: forwards every call to the system allocator unchanged; only counts.
unsafe impl GlobalAlloc for CountingAllocator {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        count_one();
        unsafe { System.alloc(layout) }
    }
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        count_one();
        unsafe { System.alloc_zeroed(layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        count_one();
        unsafe { System.realloc(ptr, layout, new_size) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static COUNTING: CountingAllocator = CountingAllocator;

/// Allocations made by this thread so far.
fn allocations() -> usize {
    ALLOCATIONS.with(Cell::get)
}

/// One correspondence round's energy with its preconditioner, as `fine_align` builds it.
struct RoundObjective<'a> {
    energy: AlignEnergy<'a>,
    preconditioner: &'a BlockPreconditioner,
}

impl Objective for RoundObjective<'_> {
    fn value_and_gradient(&mut self, x: &[f64], grad: &mut [f64]) -> f64 {
        self.energy.evaluate(x, grad).total
    }
    fn curvature(&self, d: &[f64]) -> Option<f64> {
        Some(self.energy.curvature(d))
    }
    fn precondition(&self, q: &mut [f64]) -> bool {
        self.preconditioner.apply(q);
        true
    }
}

#[test]
fn lbfgs_iterations_on_the_energy_allocate_nothing() {
    let template = uv_sphere(24, 48);
    let n = template.positions.len();
    let vertices: Vec<[f64; 4]> = template
        .positions
        .iter()
        .map(|p| [p.x, p.y, p.z, 1.0])
        .collect();
    let edges = unique_edges(&template.triangles);
    let mut degrees = vec![0u32; n];
    for &[i, j] in &edges {
        degrees[i as usize] += 1;
        degrees[j as usize] += 1;
    }
    let targets: Vec<Point3<f64>> = template
        .positions
        .iter()
        .map(|p| Point3::from(p.coords * 1.1 + Vector3::new(0.01, 0.0, 0.0)))
        .collect();
    let coefficients = vec![1.0; n];
    // Scan-to-template samples at the triangles' centroids, pulled the same way.
    let samples: Vec<ScanSample> = template
        .triangles
        .iter()
        .map(|t| {
            let c = t.iter().fold(Vector3::zeros(), |acc, &v| {
                acc + template.positions[v as usize].coords / 3.0
            });
            ScanSample {
                corners: *t,
                barycentric: [1.0 / 3.0; 3],
                target: Point3::from(c * 1.1 + Vector3::new(0.01, 0.0, 0.0)),
                coefficient: 0.5,
            }
        })
        .collect();
    let energy = AlignEnergy {
        vertices: &vertices,
        edges: &edges,
        targets: &targets,
        data_coefficients: &coefficients,
        smoothness_coefficient: 0.04,
        scan_samples: &samples,
        tangential: TangentialTerm::default(),
    };
    let mut preconditioner = BlockPreconditioner::default();
    preconditioner.update(&energy, &degrees);
    let mut optimizer = Lbfgs::new(identity_transforms(n), 7);
    let mut objective = RoundObjective {
        energy,
        preconditioner: &preconditioner,
    };
    let start_value = optimizer.restart(&mut objective, true);

    let before = allocations();
    for _ in 0..20 {
        assert_eq!(optimizer.step(&mut objective), Step::Improved);
    }
    // A new round with the same buffers: re-evaluation keeps the pairs, allocates nothing either.
    optimizer.restart(&mut objective, false);
    let after = allocations();
    assert_eq!(after - before, 0, "allocations in 20 L-BFGS iterations");
    assert!(optimizer.value() < 1e-3 * start_value);
}

#[test]
fn iterations_within_a_round_of_fine_align_allocate_nothing() {
    let (scan, template) = agreement_case();
    let index = SurfaceIndex::new(&scan).unwrap();
    let weights = vec![1.0; template.positions.len()];
    // Several iterations per round, so there are pairs of iterations without a search between.
    let params = FineAlignParams {
        iterations_per_round: 5,
        max_iterations: 40,
        ..FineAlignParams::default()
    };
    let mut seen: Vec<(usize, usize)> = Vec::with_capacity(1024);
    fine_align(
        &FineAlignInput::of_mesh(&template, &index, &weights),
        &params,
        &mut |p: &Progress| {
            seen.push((p.round, allocations()));
            ControlFlow::Continue(())
        },
    )
    .unwrap();
    let pairs: Vec<_> = seen.windows(2).filter(|w| w[0].0 == w[1].0).collect();
    assert!(
        pairs.len() >= 10,
        "{} pairs of iterations in one round",
        pairs.len()
    );
    for w in pairs {
        assert_eq!(
            w[1].1 - w[0].1,
            0,
            "allocations between two iterations of round {}",
            w[0].0
        );
    }
}

#[test]
fn closest_point_queries_with_a_compatible_nearest_vertex_allocate_nothing() {
    let scan = map(&uv_sphere(40, 80), |p| Point3::from(p.coords * 0.2));
    let index = SurfaceIndex::new(&scan).unwrap();
    let queries: Vec<(Point3<f64>, Vector3<f64>)> = uv_sphere(12, 24)
        .positions
        .iter()
        .map(|p| (Point3::from(p.coords * 0.21), p.coords.normalize()))
        .collect();
    for mode in [
        CorrespondenceMode::NearestVertex,
        CorrespondenceMode::VertexOneRing,
    ] {
        let query = MatchQuery {
            mode,
            min_cos: Some(0.5),
            candidates: 8,
        };
        // The k-d tree's per-thread scratch is made by the first query.
        let _ = index.closest(&queries[0].0, Some(&queries[0].1), &query);
        let before = allocations();
        for (p, n) in &queries {
            assert!(index.closest(p, Some(n), &query).is_some());
        }
        assert_eq!(allocations() - before, 0, "{mode:?}");
    }
}
