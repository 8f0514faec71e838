// The threaded entry point: every class and function of the default one, on a thread pool.
export * from './index.js';

/** Whether this environment can run the threaded module (shared memory and workers). */
export function threadsSupported(): boolean;

/** Every core the environment reports: `os.availableParallelism()` or `navigator.hardwareConcurrency`. */
export function defaultThreadCount(): Promise<number>;

/**
 * Starts a pool of `threads` threads (1 to 64; default: every core) and resolves to its size once
 * every thread runs; it replaces the pool the import started. The thread count changes the time,
 * never the output.
 */
export function initThreadPool(threads?: number): Promise<number>;
