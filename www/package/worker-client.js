// The main-thread side of the worker wrapper, independent of the kind of worker: `spawn()` gives
// { postMessage(message, transfer), onMessage(handler), onError(handler), terminate() }.
const abortError = (signal) =>
  signal?.reason ?? new DOMException('The operation was aborted.', 'AbortError');

/** Checks the `threads` a worker is asked for: 'auto', false, or a whole number from 1 to 64. */
export function checkThreads(threads) {
  if (threads === 'auto' || threads === false || (Number.isInteger(threads) && threads >= 1 && threads <= 64)) return threads;
  throw new Error(`threads must be 'auto', false or a whole number from 1 to 64, got ${String(threads)}`);
}

/**
 * One worker: a message channel with request ids. Hosts any number of sessions. `threads` picks
 * its module (worker-module.js); `ready` resolves to `{ threaded, threads, reason }`, which `info`
 * keeps.
 */
export class TexsynthWorker {
  constructor(spawn, { threads = false } = {}) {
    checkThreads(threads);
    this.port = spawn();
    this.nextId = 1;
    this.pending = new Map();
    this.info = null;
    this.ready = new Promise((resolve, reject) => {
      this.port.onMessage((message) => {
        if (message.type === 'ready') {
          const { threaded, threads: count, reason } = message;
          this.info = { threaded, threads: count, reason };
          return resolve(this.info);
        }
        if (message.type === 'failed') return reject(new Error(`texsynth worker could not start: ${message.message}`));
        const request = this.pending.get(message.id);
        if (!request) return;
        if (message.type === 'event') return request.onEvent?.(message);
        this.pending.delete(message.id);
        if (message.type === 'error') {
          const error = new Error(message.message);
          error.name = message.name;
          request.reject(error);
        } else request.resolve(message.value);
      });
      this.port.onError((error) => {
        reject(error);
        for (const request of this.pending.values()) request.reject(error);
        this.pending.clear();
      });
    });
    this.port.postMessage({ type: 'init', threads });
  }

  request(body, { transfer = [], onEvent } = {}) {
    const id = this.nextId++;
    return new Promise((resolve, reject) => {
      this.pending.set(id, { resolve, reject, onEvent });
      this.port.postMessage({ id, ...body }, transfer);
    });
  }

  /**
   * Creates a session of `kind` ('TextureOptimization', 'GraphcutTextures', ...) in this worker:
   * `new kind(...args)` there, or with `kind` 'Class.factory' the static constructor
   * (`'FeatureSynthesis.withFeatureMap'`). An argument that is a session of this worker (a
   * WorkerSession or its mirror: a FeatureMap made here, say) is passed as that object itself.
   */
  async createSession(kind, ...args) {
    await this.ready;
    const transfer = [];
    const wire = args.map((a) => this.refWire(a) ?? exemplarWire(a, transfer));
    const { session, width, height } = await this.request({ type: 'create', kind, args: wire }, { transfer });
    return new WorkerSession(this, session, kind, width, height);
  }

  /** { ref: id } for a session of this worker (or its mirror); undefined for anything else. */
  refWire(value) {
    const remote = value instanceof MirrorSession ? value.remote : value;
    if (!(remote instanceof WorkerSession)) return undefined;
    if (remote.worker !== this) throw new Error(`${remote.kind} lives in another worker: an argument must be made in the same one`);
    return { ref: remote.id };
  }

  terminate() {
    this.port.terminate();
  }
}

/**
 * Exemplar arguments: an Exemplar instance (sent as PNG, which keeps its channels), PNG/JPEG
 * bytes ({ bytes }), or { rgba, width, height }.
 */
function exemplarWire(value, transfer) {
  if (value && typeof value === 'object' && typeof value.toPng === 'function' && 'width' in value) {
    const bytes = value.toPng();
    transfer.push(bytes.buffer);
    return { bytes };
  }
  return value;
}

/** A session living in a worker. Every method is async; images come back as ImageData-like objects. */
export class WorkerSession {
  constructor(worker, id, kind, width, height) {
    Object.assign(this, { worker, id, kind, width, height, done: false });
  }

  async step({ render = 'renderInto' } = {}) {
    const value = await this.worker.request({ type: 'step', session: this.id, render });
    this.done = Boolean(value.event?.done);
    return { event: value.event, image: value.image && imageOf(value) };
  }

  /**
   * Runs until done, streaming `onEvent(event, image)` (image every `every` steps and at the end,
   * `{ data: Uint8ClampedArray, width, height }`, transferred, yours to keep). Resolves with
   * `{ paused, event }`; an aborted `signal` pauses the session after the current step and rejects
   * with the signal's reason; the session stays usable (run again to continue).
   */
  async run({ signal, onEvent, render = 'renderInto', every = 1 } = {}) {
    if (signal?.aborted) throw abortError(signal);
    const onAbort = () => this.pause();
    signal?.addEventListener('abort', onAbort, { once: true });
    try {
      const result = await this.worker.request(
        { type: 'run', session: this.id, render, every },
        { onEvent: (m) => {
          if (m.event?.done) this.done = true;
          onEvent?.(m.event, m.image ? imageOf(m) : null);
        } },
      );
      if (signal?.aborted) throw abortError(signal);
      return result;
    } finally {
      signal?.removeEventListener('abort', onAbort);
    }
  }

  pause() {
    return this.worker.request({ type: 'pause', session: this.id });
  }

  /** Calls a session method or reads a getter in the worker: call('schedule'), call('field'), call('addSource', { exemplar }, x, y). */
  async call(method, ...args) {
    const transfer = [];
    // A session of the same worker (a FeatureMap made there, say) goes as that object itself.
    const wire = args.map((a) => this.worker.refWire(a)
      ?? (a && typeof a === 'object' && 'exemplar' in a ? { exemplar: exemplarWire(a.exemplar, transfer) } : a));
    return this.worker.request({ type: 'call', session: this.id, method, args: wire }, { transfer });
  }

  /** A rendered view (renderInto, renderOffsetMapInto, renderSeamsInto, renderSeamCostInto, renderLabelsInto, renderNaiveInto, ...). */
  async render(method = 'renderInto', width, height) {
    return imageOf(await this.worker.request({ type: 'render', session: this.id, method, width, height }));
  }

  /**
   * measureQuality of the current output against the exemplar the session was made from. With
   * `maxSide`, an output larger than that is scored on its central `maxSide` x `maxSide` window,
   * which the result names (`window: { x, y, width, height }`).
   */
  quality({ maxSide } = {}) {
    return this.worker.request({ type: 'quality', session: this.id, maxSide });
  }

  free() {
    return this.worker.request({ type: 'free', session: this.id });
  }

  /**
   * A synchronous mirror of this session for a page's drawing code (see MirrorSession).
   */
  mirror(spec) {
    return new MirrorSession(this, spec);
  }
}

/**
 * The view of a worker session that drawing code written for a local session can use unchanged:
 * `await mirror.step()` runs a step in the worker and brings back, in the same reply, the views
 * (`renderInto`, `renderOffsetMapInto`, `renderSeamsInto`, ...: rendered in the worker, transferred), the
 * method results (`energyHistory`, `field`, `schedule`, ...) and the getters the spec names; the
 * mirror then answers `renderInto(buffer)`, `field()`, `done`, ... synchronously from those copies.
 * `spec`: { views, calls, getters } wanted after every step (a function returning them is asked
 * each time), and `finalViews` / `finalCalls` wanted after the last step (default: the same).
 * Other methods (setConstraints, clearConstraints, ...) are sent in order with `send(method, ...args)`.
 */
export class MirrorSession {
  constructor(remote, spec) {
    this.remote = remote;
    this.spec = spec;
    this.state = { views: {}, calls: {}, getters: { done: false, width: remote.width, height: remote.height } };
  }

  wanted() {
    const spec = typeof this.spec === 'function' ? this.spec() : this.spec;
    return { views: [], calls: [], getters: [], ...spec };
  }

  apply(value) {
    Object.assign(this.state.views, value.views);
    Object.assign(this.state.calls, value.calls);
    Object.assign(this.state.getters, value.getters);
  }

  async step() {
    const value = await this.remote.worker.request({ type: 'step', session: this.remote.id, snapshot: this.wanted() });
    this.apply(value);
    return value.event;
  }

  /** Fetches the wanted views again (after a view toggle or a `send`). */
  async refresh(spec = this.wanted()) {
    this.apply(await this.remote.worker.request({ type: 'snapshot', session: this.remote.id, ...spec }));
    return this;
  }

  /** Calls a method in the worker, in order with the steps. */
  send(method, ...args) {
    return this.remote.call(method, ...args);
  }

  /** Whether `view` (e.g. 'renderOffsetMapInto') has been fetched. */
  has(view) {
    return view in this.state.views || view in this.state.calls;
  }

  /** Copies the last fetched `view` into `target` (transparent if it was never fetched). */
  view(name, target) {
    const view = this.state.views[name];
    if (!view) return target.fill(0);
    target.set(new Uint8ClampedArray(view.image));
  }

  /**
   * The last fetched `view` as an ImageData over the transferred pixels (no copy), or null where
   * there is no ImageData (Node) or the view was never fetched. Valid until the next step.
   */
  imageData(name) {
    const view = this.state.views[name];
    if (!view || typeof ImageData === 'undefined') return null;
    view.imageData ??= new ImageData(new Uint8ClampedArray(view.image), view.width, view.height);
    return view.imageData;
  }

  result(name) {
    return this.state.calls[name];
  }

  get done() { return this.state.getters.done; }
  get width() { return this.state.getters.width; }
  get height() { return this.state.getters.height; }
  getter(name) { return this.state.getters[name]; }

  renderInto(target) { this.view('renderInto', target); }
  quality(options) { return this.remote.quality(options); }
  free() { return this.remote.free(); }
}

const imageOf = ({ image, width, height }) => ({ data: new Uint8ClampedArray(image), width, height });

/**
 * A small pool: `size` workers (default: the core count, at most 4), jobs queued in order.
 * `pool.run(kind, args, runOptions)` creates the session on a free worker, runs it to the end
 * and resolves with `{ event, image }` (the final image); `pool.close()` ends the workers.
 */
export class WorkerPool {
  constructor(spawn, size, options) {
    this.workers = Array.from({ length: Math.max(1, size) }, () => new TexsynthWorker(spawn, options));
    this.idle = [...this.workers];
    this.queue = [];
  }

  async acquire() {
    if (this.idle.length) return this.idle.pop();
    return new Promise((resolve) => this.queue.push(resolve));
  }

  release(worker) {
    const next = this.queue.shift();
    if (next) next(worker);
    else this.idle.push(worker);
  }

  async run(kind, args, { signal, onEvent, every = Infinity } = {}) {
    const worker = await this.acquire();
    try {
      const session = await worker.createSession(kind, ...args);
      let image = null;
      try {
        const result = await session.run({ signal, every, onEvent: (event, img) => {
          if (img) image = img;
          onEvent?.(event, img);
        } });
        return { event: result.event, image };
      } finally {
        await session.free();
      }
    } finally {
      this.release(worker);
    }
  }

  close() {
    for (const worker of this.workers) worker.terminate();
  }
}
