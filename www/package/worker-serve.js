// The inside of a texsynth worker (Web Worker or worker_threads): owns sessions, runs them, and
// answers the client of worker-client.js. Messages in: { id, type, ... }; every reply carries
// the id of the request it answers. Images travel as transferred ArrayBuffers.
//   create { kind, args }       args: exemplars as { bytes } or { rgba, width, height }, objects
//                               made here before as { ref: id }; kind 'Class' (new Class(...args))
//                               or 'Class.factory' (Class.factory(...args), a static constructor)
//   step   { render }           one step -> { event, image? }
//   run    { render, every }    steps until done or paused; streams { type: 'event', event, image? }
//   pause                       stops a run after the current step
//   call   { method, args }     any session method or getter (teaching views: schedule, field, ...);
//                               args as create's: exemplars, and objects made here as { ref: id }
//   render { method, width?, height? } -> { image, width, height } (renderInto, renderOffsetMapInto, renderSeamsInto, ...)
//   snapshot { views, calls, getters }   rendered views, method results and getters in one reply
//     (step takes the same keys, plus finalViews / finalCalls wanted when that step finishes)
//   quality { maxSide? }        measureQuality of the current output against the session's exemplar
//                               (of its central maxSide x maxSide window when it is larger; the
//                               reply then names the window)
//   free
// Any class the package exports can be made here (a session added in Rust needs nothing in this
// file); constructor arguments of the form { bytes } or { rgba, width, height } become Exemplars,
// { clip: { width, height, frames, rgba } } a VideoClip, and { ref: id } the object created here
// by request id (a FeatureMap detected and edited here, handed to FeatureSynthesis.withFeatureMap
// without copying a photo-sized map through the page and detecting it again).
const isExemplarWire = (a) =>
  a !== null && typeof a === 'object' && !ArrayBuffer.isView(a) && !Array.isArray(a) &&
  (('bytes' in a && Object.keys(a).length === 1) || ('rgba' in a && 'width' in a && 'height' in a && Object.keys(a).length === 3));

// A video clip travels as { clip: { width, height, frames, rgba } } (the frames' RGBA one after the
// other) and becomes a VideoClip.
const isClipWire = (a) => a !== null && typeof a === 'object' && Object.keys(a).length === 1 && a.clip?.rgba !== undefined;
const isRefWire = (a) => a !== null && typeof a === 'object' && Object.keys(a).length === 1 && Number.isInteger(a.ref);

/**
 * The central `maxSide` x `maxSide` (at most) window of a `width` x `height` output, or null when
 * the output fits (or no `maxSide` is given). Scoring a whole 4096x4096 output takes minutes and
 * more memory than the default budget allows; its centre is a sample of it.
 */
function centralWindow(width, height, maxSide) {
  if (maxSide == null) return null;
  if (!Number.isInteger(maxSide) || maxSide < 7) throw new Error(`quality: maxSide must be an integer of at least 7, got ${maxSide}`);
  if (width <= maxSide && height <= maxSide) return null;
  const w = Math.min(width, maxSide);
  const h = Math.min(height, maxSide);
  return { x: Math.floor((width - w) / 2), y: Math.floor((height - h) / 2), width: w, height: h };
}

/** The RGBA pixels of `win` out of a `width`-wide RGBA image. */
function cropRgba(rgba, width, win) {
  const out = new Uint8ClampedArray(win.width * win.height * 4);
  for (let row = 0; row < win.height; row++) {
    const from = ((win.y + row) * width + win.x) * 4;
    out.set(rgba.subarray(from, from + win.width * 4), row * win.width * 4);
  }
  return out;
}

export function serve(lib, { post, listen }) {
  const toClip = ({ clip }) => {
    if (!lib.VideoClip) throw new Error('this build has no video textures (VideoClip)');
    const rgba = clip.rgba instanceof Uint8Array ? clip.rgba : new Uint8Array(clip.rgba.buffer ?? clip.rgba);
    return lib.VideoClip.fromFrames(clip.width, clip.height, clip.frames, rgba);
  };
  const sessions = new Map();
  const exemplars = new Map();
  const running = new Map();

  const toExemplar = (value) => {
    if (value instanceof lib.Exemplar) return value;
    if (value?.bytes) return lib.Exemplar.fromBytes(new Uint8Array(value.bytes));
    if (value?.rgba) return lib.Exemplar.fromRgba(new Uint8Array(value.rgba.buffer ?? value.rgba), value.width, value.height);
    return value;
  };
  // Exemplar arguments of methods (addSource, addLayer) are marked { exemplar: ... }.
  const toObject = ({ ref }) => {
    if (!sessions.has(ref)) throw new Error(`no object ${ref} in this worker (freed, or made by another)`);
    return sessions.get(ref);
  };
  const convertArgs = (args) => args.map((a) => (isRefWire(a) ? toObject(a)
    : a && typeof a === 'object' && 'exemplar' in a ? toExemplar(a.exemplar) : a));
  // Exemplars (also inside plain objects and arrays, e.g. TileableTexture.result()) travel as
  // { width, height, png }: PNG keeps the channels; Exemplar.fromBytes(png) on the other side.
  const cloneable = (value) => {
    if (value instanceof lib.Exemplar) {
      const out = { width: value.width, height: value.height, png: value.toPng() };
      value.free();
      return out;
    }
    if (Array.isArray(value)) return value.map(cloneable);
    if (value && typeof value === 'object' && Object.getPrototypeOf(value) === Object.prototype) {
      return Object.fromEntries(Object.entries(value).map(([k, v]) => [k, cloneable(v)]));
    }
    return value;
  };
  const image = (session, method = 'renderInto', width = session.width, height = session.height) => {
    const data = new Uint8ClampedArray(width * height * 4);
    session[method](data);
    return { image: data.buffer, width, height };
  };
  /** The views (rendered RGBA, transferred), method results and getters a mirror asked for. */
  const snapshot = (session, { views = [], calls = [], getters = [] }) => {
    const value = { views: {}, calls: {}, getters: { done: session.done, width: session.width, height: session.height } };
    const transfer = [];
    for (const view of views) {
      const img = image(session, view);
      value.views[view] = img;
      transfer.push(img.image);
    }
    for (const call of calls) value.calls[call] = cloneable(session[call]());
    for (const getter of getters) value.getters[getter] = session[getter];
    return { value, transfer };
  };
  const reply = (id, body, transfer = []) => post({ id, ...body }, transfer);
  const fail = (id, error) => reply(id, { type: 'error', message: error?.message ?? String(error), name: error?.name ?? 'Error' });
  // Between two steps the worker lets waiting messages (a pause) in. In Node, setImmediate
  // does that without delay. A browser clamps nested setTimeout calls to 4 ms, which a run of
  // short steps would spend much of its time waiting on, so there the worker mostly posts a
  // message to itself, which queues behind the messages already waiting, and takes a timer at
  // least every TIMER_MS so that no scheduler can starve the incoming messages.
  const TIMER_MS = 200;
  const channel = typeof setImmediate === 'function' ? null : new MessageChannel();
  const waiting = [];
  if (channel) channel.port1.onmessage = () => waiting.shift()?.();
  let lastTimer = 0;
  const yieldNow = () => new Promise((r) => {
    if (!channel) {
      setImmediate(r);
    } else if (performance.now() - lastTimer >= TIMER_MS) {
      lastTimer = performance.now();
      setTimeout(r, 0);
    } else {
      waiting.push(r);
      channel.port2.postMessage(0);
    }
  });

  async function run(id, sid, session, { render = 'renderInto', every = 1 } = {}) {
    running.set(id, { session: sid, on: true });
    let count = 0;
    let last = null;
    while (running.get(id)?.on && !session.done) {
      last = session.step();
      count++;
      const body = { type: 'event', event: last };
      const transfer = [];
      if (render && (last?.done || count % every === 0)) {
        Object.assign(body, image(session, render));
        transfer.push(body.image);
      }
      reply(id, body, transfer);
      if (last?.done) break;
      await yieldNow(); // lets a pause message in
    }
    const paused = !session.done && !last?.done;
    running.delete(id);
    reply(id, { type: 'result', value: { paused, event: last } });
  }

  listen(async (message) => {
    const { id, type, session: sid } = message;
    try {
      if (type === 'create') {
        const [name, factory, ...rest] = String(message.kind).split('.');
        const Cls = lib[name];
        if (typeof Cls !== 'function' || !/^[A-Z]/.test(name) || name === 'Exemplar' || !Cls.prototype?.free || rest.length) {
          throw new Error(`unknown session kind '${message.kind}'`);
        }
        if (factory !== undefined && (!/^[a-z]\w*$/.test(factory) || typeof Cls[factory] !== 'function')) {
          throw new Error(`${name} has no static constructor '${factory}'`);
        }
        const args = message.args.map((a) => (isExemplarWire(a) ? toExemplar(a) : isClipWire(a) ? toClip(a) : isRefWire(a) ? toObject(a) : a));
        const session = factory === undefined ? new Cls(...args) : Cls[factory](...args);
        // A clip has been copied into the session.
        for (const a of args) if (lib.VideoClip && a instanceof lib.VideoClip) a.free();
        // The exemplar stays for `quality`; the others are freed.
        const [exemplar, ...others] = args.filter((a) => a instanceof lib.Exemplar);
        for (const a of others) a.free();
        if (exemplar) exemplars.set(id, exemplar);
        sessions.set(id, session);
        reply(id, { type: 'result', value: { session: id, width: session.width, height: session.height } });
        return;
      }
      const session = sessions.get(sid);
      if (!session) throw new Error(`no session ${sid} in this worker`);
      if (type === 'step' && message.snapshot) {
        const event = session.step();
        const spec = message.snapshot;
        const final = event?.done || session.done;
        const snap = snapshot(session, {
          views: final ? spec.finalViews ?? spec.views : spec.views,
          calls: final ? spec.finalCalls ?? spec.calls : spec.calls,
          getters: spec.getters,
        });
        reply(id, { type: 'result', value: { event, ...snap.value } }, snap.transfer);
      } else if (type === 'snapshot') {
        const snap = snapshot(session, message);
        reply(id, { type: 'result', value: snap.value }, snap.transfer);
      } else if (type === 'quality') {
        const exemplar = exemplars.get(sid);
        if (!exemplar) throw new Error('this session has no exemplar to measure against');
        const rgba = new Uint8ClampedArray(session.width * session.height * 4);
        session.renderInto(rgba);
        const win = centralWindow(session.width, session.height, message.maxSide);
        const pixels = win ? cropRgba(rgba, session.width, win) : rgba;
        const q = lib.measureQuality(exemplar, pixels, win?.width ?? session.width, win?.height ?? session.height);
        const value = { coherence: q.coherence, completeness: q.completeness, histogram: q.histogram, flat: q.flat };
        reply(id, { type: 'result', value: win ? { ...value, window: win } : value });
      } else if (type === 'step') {
        const event = session.step();
        const body = { type: 'result', value: { event } };
        if (message.render) {
          const img = image(session, message.render);
          Object.assign(body.value, img);
          reply(id, body, [img.image]);
        } else reply(id, body);
      } else if (type === 'run') {
        await run(id, sid, session, message);
      } else if (type === 'pause') {
        for (const run of running.values()) if (run.session === sid) run.on = false;
        reply(id, { type: 'result', value: null });
      } else if (type === 'call') {
        const member = session[message.method];
        const value = typeof member === 'function' ? member.apply(session, convertArgs(message.args ?? [])) : member;
        reply(id, { type: 'result', value: cloneable(value) });
      } else if (type === 'render') {
        const img = image(session, message.method, message.width, message.height);
        reply(id, { type: 'result', value: img }, [img.image]);
      } else if (type === 'free') {
        session.free();
        sessions.delete(sid);
        exemplars.get(sid)?.free();
        exemplars.delete(sid);
        reply(id, { type: 'result', value: null });
      } else throw new Error(`unknown message type '${type}'`);
    } catch (error) {
      running.delete(id);
      fail(id, error);
    }
  });
}
