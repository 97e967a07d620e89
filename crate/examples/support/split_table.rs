//! The common / own split of correspondence ([`correspondence_split`]) printed as a table, for
//! the accuracy examples.

use bodyspace::align::{CorrespondenceSplit, PartSplit};

/// One row per body part and one for all vertices: mean / p95 (mm) of the total, the common
/// part and the subject's own part, on all subjects and leave one out ("others").
pub fn print_split(split: &CorrespondenceSplit) {
    println!(
        "part     total mean/p95 | common (all) mean/p95 | own (all) mean/p95 | common (others) mean/p95 | own (others) mean/p95   (mm, mean over {} subjects)",
        split.subjects
    );
    for row in split.parts.iter().chain([&split.all]) {
        print_row(row);
    }
}

fn print_row(row: &PartSplit) {
    let cells = [
        row.total,
        row.common,
        row.own,
        row.common_others,
        row.own_others,
    ];
    println!(
        "{:<8} {}",
        row.part,
        cells
            .iter()
            .map(|s| format!("{:>6.2} / {:>5.1}", s.mean_mm, s.p95_mm))
            .collect::<Vec<_>>()
            .join(" | ")
    );
}
