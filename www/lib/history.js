// The step history of a session on the page: the images drawn after each step, kept within a
// memory budget. Past the budget the history is thinned evenly (every other kept step goes, and
// from then on only every 2nd, 4th, ... step is kept), so a long run stays covered from its first
// step to its last instead of losing its beginning. The last image of each level is always kept:
// those are the pictures of Fig. 3 of Kwatra et al. 2005. Plain data, no DOM: the scrubber and
// the thumbnails are in history-view.js.

/** The budget, stated on the page and in the README: 64 MiB of RGBA pixels. */
export const HISTORY_BUDGET = 64 * 1024 * 1024;

/** Bytes of one kept image: an ImageData, or a snapshot { width, height } (see history-view.js). */
const bytesOf = (image) => image.data?.length ?? image.width * image.height * 4;

export class StepHistory {
  /** `onDrop(entry)` is called for every entry the store lets go (to free what it holds). */
  constructor(budget = HISTORY_BUDGET, onDrop = () => {}) {
    this.budget = budget;
    this.onDrop = onDrop;
    this.entries = [];
    this.clear();
  }

  clear() {
    for (const entry of this.entries) this.onDrop(entry);
    /** Oldest first; each `{ step, levelKey, levelEnd, label, images, bytes, ... }`. */
    this.entries = [];
    this.bytes = 0;
    /** Steps kept: those with (step - 1) % stride === 0, the level ends and the newest. */
    this.stride = 1;
  }

  /**
   * Adds the images of step `entry.step` (1 for the first step of a run). `entry.images` is a
   * list of ImageData (one per canvas the panel shows); `entry.levelKey` names the level the step
   * belongs to (null for methods without levels), so that the step before a level change is
   * kept as that level's last image.
   */
  add(entry) {
    const stored = { levelEnd: false, ...entry, bytes: entry.images.reduce((n, image) => n + bytesOf(image), 0) };
    const last = this.entries.at(-1);
    if (last && stored.levelKey !== last.levelKey && last.levelKey != null) last.levelEnd = true;
    // The newest image is always kept; the one it replaces stays only where the stride says.
    if (last && !this.#wanted(last)) this.#removeAt(this.entries.length - 1);
    this.entries.push(stored);
    this.bytes += stored.bytes;
    while (this.bytes > this.budget && this.entries.length > 1) this.#thin();
    return stored;
  }

  #wanted(entry) {
    return entry.levelEnd || (entry.step - 1) % this.stride === 0;
  }

  #removeAt(index) {
    const [gone] = this.entries.splice(index, 1);
    this.bytes -= gone.bytes;
    this.onDrop(gone);
  }

  /** Doubles the stride and drops what it no longer keeps. Each call removes at least one image:
   * when the stride spares them all (only level ends, the first step and the newest are left,
   * which happens with huge images), the oldest goes. */
  #thin() {
    this.stride *= 2;
    const newest = this.entries.at(-1);
    const kept = this.entries.filter((e) => e === newest || this.#wanted(e));
    if (kept.length === this.entries.length) {
      this.#removeAt(0);
      return;
    }
    const keep = new Set(kept);
    for (const entry of this.entries) if (!keep.has(entry)) this.onDrop(entry);
    this.entries = kept;
    this.bytes = kept.reduce((n, e) => n + e.bytes, 0);
  }

  /**
   * The entries the thumbnail strip shows: for a method with levels, the last image of each
   * finished level and the newest; otherwise up to `count` steps spread evenly over the run.
   */
  strip(count = 8) {
    const { entries } = this;
    if (entries.length === 0) return [];
    if (entries.some((e) => e.levelKey != null)) return entries.filter((e, i) => e.levelEnd || i === entries.length - 1);
    if (entries.length <= count) return [...entries];
    const picked = new Set();
    for (let k = 0; k < count; k++) picked.add(entries[Math.round((k * (entries.length - 1)) / (count - 1))]);
    return [...picked];
  }
}
