//! Fine alignment (paper §3.2): per-vertex affine transforms minimising E = a·E_d + b·E_s.
