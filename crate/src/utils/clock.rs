//! Milliseconds on a monotonic-enough clock: `std::time::Instant` natively, `Date.now()` on
//! wasm32-unknown-unknown (where `Instant` does not exist).

/// Milliseconds since an arbitrary fixed point; only differences mean anything.
pub fn now_ms() -> f64 {
    #[cfg(target_arch = "wasm32")]
    {
        js_sys::Date::now()
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        use std::sync::OnceLock;
        use std::time::Instant;
        static START: OnceLock<Instant> = OnceLock::new();
        START.get_or_init(Instant::now).elapsed().as_secs_f64() * 1e3
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_clock_does_not_run_backwards() {
        let a = now_ms();
        let b = now_ms();
        assert!(b >= a);
    }
}
