//! Native fine alignment searches correspondences on all cores; the result must not depend on
//! how many there are.
#![cfg(not(target_arch = "wasm32"))]

mod align_support;

use align_support::agreement_case;
use bodyspace::align::{fine_align, FineAlignInput, FineAlignParams, SurfaceIndex};
use nalgebra::Point3;

fn fit_with_threads(threads: usize) -> Vec<Point3<f64>> {
    let (scan, template) = agreement_case();
    let index = SurfaceIndex::new(&scan).unwrap();
    let weights = vec![1.0; template.positions.len()];
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap();
    pool.install(|| {
        fine_align(
            &FineAlignInput::of_mesh(&template, &index, &weights),
            &FineAlignParams::default(),
            &mut (),
        )
        .unwrap()
        .positions
    })
}

#[test]
fn same_fit_on_one_and_on_four_threads() {
    let one = fit_with_threads(1);
    let four = fit_with_threads(4);
    assert_eq!(one.len(), four.len());
    // Bit for bit: every vertex's match is found independently and written to its own slot.
    assert!(one.iter().zip(&four).all(|(a, b)| a == b));
}
