//! RBF rough deformation (paper §3.1): landmark pairs fit one RBF network per coordinate, which warps the template.
