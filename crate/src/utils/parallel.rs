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
    fn filter_map_keeps_the_order_of_the_items() {
        let items: Vec<u32> = (0..1000).collect();
        let mut out = vec![7u32];
        filter_map_into(&items, &mut out, |&x| (x % 3 == 0).then_some(x * 2));
        let expected: Vec<u32> = (0..1000).filter(|x| x % 3 == 0).map(|x| x * 2).collect();
        assert_eq!(out, expected);
    }
}
