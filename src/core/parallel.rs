//! Data parallelism that cannot change a result: work is split into pieces whose bounds depend on
//! the input alone, never on the thread count, and results are combined in piece order. With the
//! `parallel` feature the pieces run on rayon's threads; without it, or in a wasm module whose
//! thread pool has not been started, they run one after another on the calling thread. Either way
//! the bytes are the same.
//!
//! Natively the pieces run on rayon's current pool (the global one, or the pool of an enclosing
//! `ThreadPool::install`). In wasm there is no `std::thread::spawn`: the pool is one that
//! JavaScript started on Web Workers or Node worker threads (`bindings::threads`), kept here.

#[cfg(feature = "parallel")]
use rayon::prelude::*;

/// Runs `f(piece_index, piece)` over `data` cut into pieces of `piece_len` elements (the last one
/// may be shorter).
pub fn for_each_piece_mut<T, F>(data: &mut [T], piece_len: usize, f: F)
where
    T: Send,
    F: Fn(usize, &mut [T]) + Sync + Send,
{
    let piece_len = piece_len.max(1);
    #[cfg(feature = "parallel")]
    if pool::active() {
        return pool::run(|| {
            data.par_chunks_mut(piece_len)
                .enumerate()
                .for_each(|(i, piece)| f(i, piece))
        });
    }
    data.chunks_mut(piece_len)
        .enumerate()
        .for_each(|(i, piece)| f(i, piece));
}

/// `f(0), f(1), ..., f(n - 1)`, in order.
pub fn map<R, F>(n: usize, f: F) -> Vec<R>
where
    R: Send,
    F: Fn(usize) -> R + Sync + Send,
{
    #[cfg(feature = "parallel")]
    if pool::active() && n > 1 {
        return pool::run(|| (0..n).into_par_iter().map(&f).collect());
    }
    (0..n).map(f).collect()
}

/// The fewest pieces per thread a resumable loop hands to one call when it could stop sooner:
/// with several pieces each, pieces of uneven cost even out over the threads.
pub const MIN_ROUNDS: usize = 4;

/// Threads that pieces may run on: 1 without a pool.
pub fn threads() -> usize {
    #[cfg(feature = "parallel")]
    if pool::active() {
        return pool::run(rayon::current_num_threads);
    }
    1
}

#[cfg(all(feature = "parallel", not(target_arch = "wasm32")))]
mod pool {
    /// Natively rayon's pool always exists (rayon starts the global one on first use).
    pub fn active() -> bool {
        true
    }

    pub fn run<R: Send>(f: impl FnOnce() -> R + Send) -> R {
        f()
    }
}

#[cfg(all(feature = "parallel", target_arch = "wasm32"))]
pub mod pool {
    //! The wasm pool: JavaScript asks for `n` threads ([`prepare`]), starts `n` workers on the
    //! same module and memory, each of which calls [`run_thread`], waits until all have started
    //! and then calls [`activate`]. Work is only sent to a pool whose threads all run, so a caller
    //! never waits on a worker that JavaScript has not started yet.
    use std::sync::{Arc, Mutex, RwLock};

    static ACTIVE: RwLock<Option<Arc<rayon::ThreadPool>>> = RwLock::new(None);
    static PREPARED: Mutex<Option<Arc<rayon::ThreadPool>>> = Mutex::new(None);
    static WAITING: Mutex<Vec<rayon::ThreadBuilder>> = Mutex::new(Vec::new());

    /// Whether a started pool takes work.
    pub fn active() -> bool {
        ACTIVE.read().map(|p| p.is_some()).unwrap_or(false)
    }

    /// Runs `f` inside the active pool (on the calling thread when there is none).
    pub fn run<R: Send>(f: impl FnOnce() -> R + Send) -> R {
        let pool = ACTIVE.read().ok().and_then(|p| p.clone());
        match pool {
            Some(pool) => pool.install(f),
            None => f(),
        }
    }

    /// Builds a pool of `threads` threads whose bodies wait for workers to run them.
    pub fn prepare(threads: usize) -> Result<(), String> {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .spawn_handler(|thread| {
                WAITING.lock().map_err(|_| std::io::Error::other("pool lock"))?.push(thread);
                Ok(())
            })
            .build()
            .map_err(|e| e.to_string())?;
        *PREPARED.lock().map_err(|_| "pool lock".to_string())? = Some(Arc::new(pool));
        Ok(())
    }

    /// The body of one pool thread, run by a worker until the pool is replaced.
    pub fn run_thread() -> Result<(), String> {
        let thread = WAITING
            .lock()
            .map_err(|_| "pool lock".to_string())?
            .pop()
            .ok_or("no pool thread is waiting to be run")?;
        thread.run();
        Ok(())
    }

    /// Makes the prepared pool the one that takes work; the previous pool's threads end.
    pub fn activate() -> Result<usize, String> {
        let pool = PREPARED
            .lock()
            .map_err(|_| "pool lock".to_string())?
            .take()
            .ok_or("no thread pool was prepared")?;
        let threads = pool.current_num_threads();
        *ACTIVE.write().map_err(|_| "pool lock".to_string())? = Some(pool);
        Ok(threads)
    }

    /// Stops sending work to threads: later work runs on the calling thread.
    pub fn deactivate() {
        if let Ok(mut active) = ACTIVE.write() {
            *active = None;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pieces_cover_the_data_in_order() {
        let mut data = vec![0usize; 103];
        for_each_piece_mut(&mut data, 10, |i, piece| {
            for (j, v) in piece.iter_mut().enumerate() {
                *v = i * 10 + j;
            }
        });
        assert_eq!(data, (0..103).collect::<Vec<_>>());
        assert_eq!(map(5, |i| i * i), vec![0, 1, 4, 9, 16]);
    }

    #[cfg(feature = "parallel")]
    #[test]
    fn the_same_result_at_any_thread_count() {
        let work = || {
            let mut data = vec![0f32; 10_000];
            for_each_piece_mut(&mut data, 64, |i, piece| {
                for (j, v) in piece.iter_mut().enumerate() {
                    *v = ((i * 64 + j) as f32).sqrt();
                }
            });
            map(100, |i| data[i * 100..(i + 1) * 100].iter().sum::<f32>())
        };
        let one = rayon::ThreadPoolBuilder::new().num_threads(1).build().unwrap().install(work);
        for threads in [2, 4] {
            let many = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap()
                .install(work);
            assert_eq!(one, many);
        }
    }
}
