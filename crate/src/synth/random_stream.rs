//! Each subject's own random stream, so subject `i` of seed `S` is the same whatever the number
//! of subjects or threads (`population_run`), and the scanner zoo's edits draw from a stream of
//! their own (`zoo::zoo_rng`).

use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// The random stream of subject `index` under `seed` (ChaCha8, stream = index).
pub fn subject_rng(seed: u64, index: u64) -> ChaCha8Rng {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    rng.set_stream(index);
    rng
}
