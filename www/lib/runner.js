// Drives a session from the page: Run steps once per animation frame (so each step is drawn),
// Pause stops, Step runs exactly one. The caller owns the session; this only paces it. `step` may
// return the event or a promise of it (a session in the worker, www/lib/worker.js): one step is
// in flight at a time, and the main thread stays free while the worker computes. A step that
// resolves to { idle: why } runs nothing: the runner stops and hands `why` to onIdle.
export class Runner {
  constructor({ step, onStep, onDone, onError, onIdle }) {
    Object.assign(this, { stepFn: step, onStep, onDone, onError, onIdle });
    this.running = false;
    this.busy = null;
    this.loop = null;
  }

  run() {
    if (this.running) return;
    this.running = true;
    const loop = {};
    this.loop = loop;
    const tick = async () => {
      if (!this.running || this.loop !== loop) return;
      if (!(await this.stepOnce())) {
        if (this.loop === loop) this.running = false;
        return;
      }
      if (this.running && this.loop === loop) requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
  }

  pause() {
    this.running = false;
    this.loop = null;
  }

  /** Runs one step; resolves to false when the session is finished or failed. */
  async stepOnce() {
    if (this.busy) return this.busy; // a step is in flight: this one is the same step
    this.busy = this.#step();
    try {
      return await this.busy;
    } finally {
      this.busy = null;
    }
  }

  async #step() {
    try {
      const event = await this.stepFn();
      if (!event) return false;
      // A panel with nothing to run where it stands (a design stage driven by its own buttons)
      // says so instead of leaving "running…" up.
      if (event.idle) {
        this.running = false;
        this.onIdle?.(event.idle);
        return false;
      }
      this.onStep(event);
      if (event.done) {
        this.running = false;
        this.onDone?.(event);
        return false;
      }
      return true;
    } catch (error) {
      this.running = false;
      this.onError(error.message ?? String(error));
      return false;
    }
  }
}
