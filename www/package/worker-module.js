// Which module a worker runs: the threaded one (one synthesis on every core) or the
// single-threaded one. The worker's creator asks for `threads`: 'auto' (the threaded module with
// every core where it can run, the single-threaded one elsewhere), a number of threads (the
// threaded module, or an error saying why it cannot run), or false (the single-threaded module),
// in the first message it sends: { type: 'init', threads }. The answer, `{ threaded, threads, reason }`, goes out with the worker's `ready` message;
// `reason` says why 'auto' fell back.

/**
 * Loads the module `threads` asks for. `single()` resolves to the single-threaded entry, ready;
 * `threadsUrl` is the threaded entry's URL; `unavailable` is why this environment cannot run it
 * (null when it can).
 */
export async function loadModule(threads, { single, threadsUrl, unavailable }) {
  let reason = null;
  if (threads !== false) {
    reason = unavailable;
    if (reason === null) {
      try {
        // A computed specifier: bundlers leave it alone, and a bundle without the threaded
        // module falls back (with 'auto') instead of failing to build.
        const lib = await import(/* @vite-ignore */ threadsUrl.href);
        if (typeof threads === 'number') await lib.initThreadPool(threads);
        return { lib, info: { threaded: true, threads: lib.threadCount(), reason: null } };
      } catch (error) {
        reason = `the threaded module did not load: ${error?.message ?? error}`;
      }
    }
    if (threads !== 'auto') throw new Error(`${threads} threads were asked for, but ${reason}`);
  }
  return { lib: await single(), info: { threaded: false, threads: 1, reason } };
}
