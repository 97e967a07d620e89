//! The synthetic population: MakeHuman-based subjects, posed, scanned by a virtual body scanner, with ground truth.
