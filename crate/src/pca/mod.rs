//! PCA shape spaces (paper §4): S = S̄ + Φ·B for the whole body and six overlapping segments.
