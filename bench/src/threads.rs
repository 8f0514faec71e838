//! The threads texsynth's methods are timed on: a rayon pool of exactly the asked size with the
//! `parallel` feature (so the machine's core count never leaks into the figures), the calling
//! thread without it.

pub struct Pool {
    #[cfg(feature = "parallel")]
    pool: rayon::ThreadPool,
}

impl Pool {
    /// A pool of `threads` threads; `args::parse` has refused more than one without the feature.
    pub fn new(threads: usize) -> Result<Pool, String> {
        #[cfg(feature = "parallel")]
        {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .map_err(|e| format!("cannot start {threads} threads: {e}"))?;
            Ok(Pool { pool })
        }
        #[cfg(not(feature = "parallel"))]
        {
            assert_eq!(
                threads, 1,
                "more than one thread needs the parallel feature"
            );
            Ok(Pool {})
        }
    }

    /// Runs `work` with the pool's threads as the ones texsynth's parallel loops use.
    pub fn install<R: Send>(&self, work: impl FnOnce() -> R + Send) -> R {
        #[cfg(feature = "parallel")]
        return self.pool.install(work);
        #[cfg(not(feature = "parallel"))]
        work()
    }
}
