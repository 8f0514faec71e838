//! A millisecond clock that works natively and in wasm (where `std::time::Instant` panics): a
//! long-running step uses it to stop at a time budget. Nothing computed depends on it, only
//! where work is cut into steps.

/// Milliseconds since an arbitrary origin.
#[must_use]
pub fn now_ms() -> f64 {
    #[cfg(target_arch = "wasm32")]
    {
        js_sys::Date::now()
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        use std::sync::OnceLock;
        use std::time::Instant;
        static ORIGIN: OnceLock<Instant> = OnceLock::new();
        ORIGIN.get_or_init(Instant::now).elapsed().as_secs_f64() * 1e3
    }
}
