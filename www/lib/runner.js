// Drives a session from the page: Run steps once per animation frame (so each step is drawn),
// Pause stops, Step runs exactly one. The caller owns the session; this only paces it.
export class Runner {
  constructor({ step, onStep, onDone, onError }) {
    Object.assign(this, { stepFn: step, onStep, onDone, onError });
    this.running = false;
  }

  run() {
    if (this.running) return;
    this.running = true;
    const tick = () => {
      if (!this.running) return;
      if (!this.stepOnce()) {
        this.running = false;
        return;
      }
      requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
  }

  pause() {
    this.running = false;
  }

  /** Runs one step; returns false when the session is finished or failed. */
  stepOnce() {
    try {
      const event = this.stepFn();
      if (!event) return false;
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
