//! Per-item loops that run on all cores natively (rayon) and in order on wasm32 (no threads
//! without cross-origin isolation). Each item is computed on its own, so results never depend on
//! the number of threads.

/// Calls `f(i, &mut a[i], &mut b[i])` for every `i` of two slices of equal length.
#[cfg(not(target_arch = "wasm32"))]
pub fn for_each_pair_mut<A, B, F>(a: &mut [A], b: &mut [B], f: F)
where
    A: Send,
    B: Send,
    F: Fn(usize, &mut A, &mut B) + Sync,
{
    use rayon::prelude::*;
    a.par_iter_mut()
        .zip(b.par_iter_mut())
        .enumerate()
        .for_each(|(i, (x, y))| f(i, x, y));
}

/// Calls `f(i, &mut a[i], &mut b[i])` for every `i` of two slices of equal length.
#[cfg(target_arch = "wasm32")]
pub fn for_each_pair_mut<A, B, F>(a: &mut [A], b: &mut [B], f: F)
where
    F: Fn(usize, &mut A, &mut B),
{
    for (i, (x, y)) in a.iter_mut().zip(b.iter_mut()).enumerate() {
        f(i, x, y);
    }
}

/// Replaces `out` with `f(item)` of every item for which it is `Some`, in the order of `items`.
#[cfg(not(target_arch = "wasm32"))]
pub fn filter_map_into<T, U, F>(items: &[T], out: &mut Vec<U>, f: F)
where
    T: Sync,
    U: Send,
    F: Fn(&T) -> Option<U> + Sync + Send,
{
    use rayon::prelude::*;
    *out = items.par_iter().filter_map(f).collect();
}

/// Replaces `out` with `f(item)` of every item for which it is `Some`, in the order of `items`.
#[cfg(target_arch = "wasm32")]
pub fn filter_map_into<T, U, F>(items: &[T], out: &mut Vec<U>, f: F)
where
    F: Fn(&T) -> Option<U>,
{
    out.clear();
    out.extend(items.iter().filter_map(f));
}

/// Calls `f(a_part, b_part)` on matching parts of two slices of equal length: natively one part
/// per core when they hold at least `min_len` items (below that a thread costs more than it
/// saves), otherwise — and always on wasm32 — once on the whole slices.
pub fn for_each_chunk_pair<A, B, F>(a: &[A], b: &mut [B], min_len: usize, f: F)
where
    A: Sync,
    B: Send,
    F: Fn(&[A], &mut [B]) + Sync + Send,
{
    #[cfg(not(target_arch = "wasm32"))]
    {
        use rayon::prelude::*;
        let threads = rayon::current_num_threads();
        if threads > 1 && a.len() >= min_len {
            let chunk = a.len().div_ceil(threads);
            a.par_chunks(chunk)
                .zip(b.par_chunks_mut(chunk))
                .for_each(|(x, y)| f(x, y));
            return;
        }
    }
    let _ = min_len;
    f(a, b);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pairs_are_visited_once_each_with_their_index() {
        let mut a = vec![0usize; 1000];
        let mut b = vec![0.0f64; 1000];
        for_each_pair_mut(&mut a, &mut b, |i, x, y| {
            *x = i;
            *y = i as f64 * 0.5;
        });
        assert!(a.iter().enumerate().all(|(i, x)| *x == i));
        assert!(b.iter().enumerate().all(|(i, y)| *y == i as f64 * 0.5));
    }

    #[test]
    fn chunk_pairs_cover_both_slices_in_step() {
        let a: Vec<u32> = (0..50_000).collect();
        let mut b = vec![0u32; 50_000];
        for_each_chunk_pair(&a, &mut b, 1_000, |x, y| {
            for (p, q) in x.iter().zip(y.iter_mut()) {
                *q = p * 2;
            }
        });
        assert!(b.iter().enumerate().all(|(i, v)| *v == 2 * i as u32));
    }

    #[test]
    fn filter_map_keeps_the_order_of_the_items() {
        let items: Vec<u32> = (0..1000).collect();
        let mut out = vec![7u32];
        filter_map_into(&items, &mut out, |&x| (x % 3 == 0).then_some(x * 2));
        let expected: Vec<u32> = (0..1000).filter(|x| x % 3 == 0).map(|x| x * 2).collect();
        assert_eq!(out, expected);
    }
}
