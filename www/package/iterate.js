// The standard JS protocols on every session (DESIGN.md, "Progressive refinement is the API"):
//   for (const event of session) { ... }            // synchronous, one step per event
//   await session.run({ signal, onEvent })          // async, yields to the event loop between steps
// Cancellation is by AbortSignal: `run` rejects with `signal.reason` (an AbortError by default)
// before the next step once the signal is aborted. Steps themselves are never interrupted.
// Every exported class with a `step()` method gets them, so a session added in Rust needs nothing
// here; each module (the single-threaded one, the threaded one) installs them on its own classes.

/**
 * The exported classes of a generated module `lib` that have a `step()` method, by their export
 * names (a bundler's minifier renames the classes themselves).
 */
export function sessionClasses(lib) {
  return Object.entries(lib)
    .filter(([name, value]) => /^[A-Z]/.test(name) && typeof value === 'function' && typeof value.prototype?.step === 'function')
    .map(([, value]) => value);
}

/** Resolves on the next turn of the event loop, without the 4 ms clamp of nested timeouts. */
export function yieldToEventLoop() {
  if (typeof globalThis.setImmediate === 'function') return new Promise((r) => globalThis.setImmediate(r));
  if (typeof MessageChannel === 'function') {
    return new Promise((resolve) => {
      const channel = new MessageChannel();
      channel.port1.onmessage = () => {
        channel.port1.close();
        resolve();
      };
      channel.port2.postMessage(null);
    });
  }
  return new Promise((r) => setTimeout(r, 0));
}

function throwIfAborted(signal) {
  if (!signal?.aborted) return;
  if (typeof signal.throwIfAborted === 'function') signal.throwIfAborted();
  throw signal.reason ?? new DOMException('The operation was aborted.', 'AbortError');
}

function* steps() {
  while (!this.done) {
    const event = this.step();
    yield event;
    if (event?.done) return;
  }
}

async function run({ signal, onEvent, maxSteps = Infinity } = {}) {
  let last = null;
  let count = 0;
  throwIfAborted(signal);
  while (!this.done && count < maxSteps) {
    last = this.step();
    count++;
    onEvent?.(last, this);
    if (last?.done) break;
    await yieldToEventLoop();
    throwIfAborted(signal);
  }
  return last;
}

/** Gives every session class of the generated module `lib` iteration and `run()`. */
export function installProtocols(lib) {
  for (const cls of sessionClasses(lib)) {
    if (Object.hasOwn(cls.prototype, 'run')) continue;
    Object.defineProperty(cls.prototype, Symbol.iterator, { value: steps, writable: true, configurable: true });
    Object.defineProperty(cls.prototype, 'run', { value: run, writable: true, configurable: true });
  }
}
