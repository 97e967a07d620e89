//! Readers and writers of the field's file formats: scans (PLY, OBJ, STL, gzip) and landmarks (CSV, CAESAR .lnd, JSON).
