//! The thread pool of the threaded module, as JavaScript drives it (`threads.js` in the package):
//! `prepareThreadPool(n)`, then `n` workers on this module and memory that each call
//! `runPoolThread()`, then `activateThreadPool()` once all have started. The single-threaded
//! module has the same `threaded()` and `threadCount()`, so code can ask either build.

use wasm_bindgen::prelude::*;

/// Whether this module was built with threads (shared memory and a rayon pool).
#[wasm_bindgen]
#[must_use]
pub fn threaded() -> bool {
    cfg!(feature = "parallel")
}

/// Threads a synthesis runs on: the active pool's size, 1 without one.
#[wasm_bindgen(js_name = threadCount)]
#[must_use]
pub fn thread_count() -> usize {
    crate::core::parallel::threads()
}

#[cfg(feature = "parallel")]
mod pool {
    use super::super::error::JsResult;
    use super::*;
    use crate::core::parallel::pool;
    use wasm_bindgen::JsError;

    /// The largest pool the package starts.
    const MAX_THREADS: usize = 64;

    /// Builds a pool of `threads` threads, each waiting for a worker to run it.
    #[wasm_bindgen(js_name = prepareThreadPool)]
    pub fn prepare_thread_pool(threads: usize) -> JsResult<()> {
        if !(1..=MAX_THREADS).contains(&threads) {
            return Err(JsError::new(&format!(
                "threads must be a whole number from 1 to {MAX_THREADS}, got {threads}"
            )));
        }
        pool::prepare(threads).map_err(|e| JsError::new(&e))
    }

    /// The body of one pool thread: called by a worker, returns when its pool is replaced.
    #[wasm_bindgen(js_name = runPoolThread)]
    pub fn run_pool_thread() -> JsResult<()> {
        pool::run_thread().map_err(|e| JsError::new(&e))
    }

    /// Sends work to the prepared pool from now on; returns its thread count.
    #[wasm_bindgen(js_name = activateThreadPool)]
    pub fn activate_thread_pool() -> JsResult<usize> {
        pool::activate().map_err(|e| JsError::new(&e))
    }

    /// This module, for the workers to instantiate.
    #[wasm_bindgen(js_name = threadPoolModule)]
    #[must_use]
    pub fn wasm_module() -> JsValue {
        wasm_bindgen::module()
    }

    /// This module's shared memory, for the workers to instantiate it on.
    #[wasm_bindgen(js_name = threadPoolMemory)]
    #[must_use]
    pub fn wasm_memory() -> JsValue {
        wasm_bindgen::memory()
    }

    /// Runs every later step on the calling thread alone.
    #[wasm_bindgen(js_name = deactivateThreadPool)]
    pub fn deactivate_thread_pool() {
        pool::deactivate();
    }
}
