// The page's sessions run in one Web Worker (the package's worker wrapper, pkg/worker.js), so the
// main thread only draws: a 1024x1024 step that takes 1.5 s does not freeze the page. A panel
// creates its session with `remoteSession(kind, args, spec)` and gets a MirrorSession: `await
// session.step()`, then the views named in `spec` (rendered in the worker, sent with the step)
// are read synchronously by the usual drawing code: session.renderInto(buffer),
// session.view('renderSeamsInto', buffer), session.result('field'), session.getter('constraintEnergy').
import { createWorker } from '../pkg/worker.js';

let worker = null;

/** The page's worker, started on first use. */
export function pageWorker() {
  worker ??= createWorker();
  return worker;
}

/** A session of `kind` built in the worker from `args` (Exemplars are copied over as PNG). */
export async function remoteSession(kind, args, spec) {
  const remote = await pageWorker().createSession(kind, ...args);
  return remote.mirror(spec);
}
