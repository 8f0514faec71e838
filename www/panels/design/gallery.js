// The designed textures of the texture-design panel: the sample, its deformations, brushed
// textures and large syntheses, each with a thumbnail, buttons to make it the base (B) or the
// reference (R) of the next stage, and a PNG download. The gallery owns its Exemplars.
import { Exemplar } from '../../pkg/texsynth.js';
import { drawInto } from '../../lib/canvas.js';

export class Gallery {
  constructor(element, onSelection) {
    this.element = element;
    this.onSelection = onSelection;
    this.items = [];
    this.base = 0;
    this.reference = 0;
    this.sampleOf = null;
  }

  /** A copy the gallery can keep after the page frees the original. */
  copy(exemplar) {
    return Exemplar.fromRgba(exemplar.toRgba(), exemplar.width, exemplar.height);
  }

  clear() {
    for (const item of this.items) item.exemplar.free();
    this.items = [];
    this.base = this.reference = 0;
    this.element.replaceChildren();
  }

  /** Adds a texture (the gallery takes ownership); returns its index. */
  add(label, exemplar) {
    if (this.items.length >= 40) {
      const [old] = this.items.splice(1, 1); // keep the sample, drop the oldest design
      old.exemplar.free();
      this.base = Math.max(0, this.base - 1);
      this.reference = Math.max(0, this.reference - 1);
    }
    this.items.push({ label, exemplar });
    this.render();
    return this.items.length - 1;
  }

  get baseItem() { return this.items[this.base]; }

  get referenceItem() { return this.items[this.reference]; }

  select(role, index) {
    this[role] = index;
    this.render();
    this.onSelection?.();
  }

  render() {
    this.element.replaceChildren(...this.items.map((item, i) => {
      const figure = document.createElement('figure');
      figure.className = 'gallery-item';
      figure.setAttribute('role', 'listitem');
      figure.dataset.index = String(i);
      const canvas = document.createElement('canvas');
      drawInto(canvas, item.exemplar);
      const caption = document.createElement('figcaption');
      caption.textContent = `${item.label} · ${item.exemplar.width}×${item.exemplar.height}`;
      const buttons = document.createElement('div');
      for (const [role, text] of [['base', 'B'], ['reference', 'R']]) {
        const b = document.createElement('button');
        b.type = 'button';
        b.textContent = text;
        b.title = `use as the ${role}`;
        b.dataset.role = role;
        b.setAttribute('aria-pressed', String(this[role] === i));
        b.addEventListener('click', () => this.select(role, i));
        buttons.append(b);
      }
      const download = document.createElement('button');
      download.type = 'button';
      download.textContent = 'PNG';
      download.title = 'download as PNG';
      download.addEventListener('click', () => {
        const blob = new Blob([item.exemplar.toPng()], { type: 'image/png' });
        const a = document.createElement('a');
        a.href = URL.createObjectURL(blob);
        a.download = `${item.label.replace(/[^a-z0-9]+/gi, '-')}.png`;
        a.click();
        setTimeout(() => URL.revokeObjectURL(a.href), 1000);
      });
      buttons.append(download);
      figure.append(canvas, caption, buttons);
      return figure;
    }));
    document.body.dataset.galleryCount = String(this.items.length);
  }
}
