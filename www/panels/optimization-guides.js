// Guide maps for the "Texture optimization" panel (the guide term of Hertzmann et al. 2001's
// image analogies, and of Embark's guided synthesis): the M-step's distance adds
// weight ||g_source − g_target||², so a match must look like the exemplar and have the guide
// value the target guide asks for there. The source guide is the exemplar's luminance; the
// target guide is a picture's luminance at the output size (style transfer: the output draws
// the picture with the exemplar's texture) or a built-in gradient. Both are made here, in JS,
// and sent to the session before its first step; the target guide is shown beside the output.
import { Exemplar } from '../pkg/texsynth.js';
import { SAMPLES } from '../lib/samples.js';
import { blurred, greyRgba, gradientLuminance, luminance, remapLuminance, resizedRgba } from '../lib/guide-images.js';

/** The targets offered for style transfer: the 128-pixel samples (more structure to draw). */
const TARGETS = SAMPLES.filter((s) => s.id.endsWith('_128'));
const DEFAULT_TARGET = 'squares_128';
/**
 * A smooth target guide (the gradients) is compared with the exemplar's local mean luminance:
 * both guides are blurred by this standard deviation in pixels, the node spacing (w/4) of the
 * finest 8x8 neighbourhoods. Against the exemplar's full-detail luminance a smooth target is
 * matched best by the flattest neighbourhoods, and the output washes out (gravel 64 to 96x96 at
 * weight 4: 94% flat against 18% blurred; the exemplar itself is about 10%). A picture has
 * detail of its own and is compared as it is, as in image analogies' texture transfer.
 */
const SMOOTH_GUIDE_BLUR = 2;
/** An uploaded target larger than this on its longer side is shrunk on arrival. */
const UPLOAD_MAX_SIDE = 1024;

export const GUIDE_OPTIONS_HTML = `
  <span class="views" title="guide maps (Hertzmann et al. 2001, image analogies): the M-step prefers exemplar parts whose luminance is what the target guide asks for there">
    <label>guide <select id="to-guide">
      <option value="none">none</option>
      <option value="style">style transfer</option>
      <option value="gradient">gradient (dark → bright)</option>
      <option value="radial">radial (bright centre)</option>
    </select></label>
    <label id="to-guide-target-label" hidden>target <select id="to-guide-target">
      ${TARGETS.map((s) => `<option value="${s.id}"${s.id === DEFAULT_TARGET ? ' selected' : ''}>${s.label.split(' ')[0]}</option>`).join('')}
      <option value="file">an image file…</option>
    </select></label>
    <input id="to-guide-file" class="view" type="file" accept="image/png,image/jpeg" aria-label="Target image file for style transfer" hidden>
    <label id="to-guide-weight-label" title="weight of the guide term; 1: a guide value counts as much as a colour value (useful: about 0.5 to 20)" hidden>guide weight
      <input id="to-guide-weight" type="number" value="4" min="0" max="10000" step="0.5"></label>
  </span>`;

const PREVIEW_HTML = `
  <canvas id="to-guide-canvas" width="1" height="1" aria-label="Target guide"></canvas>
  <figcaption id="to-guide-caption">target guide</figcaption>`;

/**
 * The guide controls of the panel. `showError(message)` is the page's error display. Gives
 * `apply(session)` (sends the guides, before the first step), `preview()` (redraws the target
 * guide beside the output), `describe()` (a few words for the readout) and `active()`.
 */
export function createGuides(ui, showError) {
  // An uploaded target: { rgba, width, height, name }. Decoded targets are kept by sample id.
  let upload = null;
  const decoded = new Map();
  let figure = null;
  let previewRun = 0;

  const mode = () => ui.$('to-guide').value;
  const target = () => ui.$('to-guide-target').value;
  const weight = () => Number(ui.$('to-guide-weight').value);

  /** The style-transfer picture as RGBA: a sample (fetched and decoded by wasm) or the upload. */
  async function picture() {
    if (target() === 'file') {
      if (!upload) throw new Error('style transfer: choose a target image file, or pick a sample as the target');
      return upload;
    }
    const sample = TARGETS.find((s) => s.id === target()) ?? TARGETS.find((s) => s.id === DEFAULT_TARGET);
    if (!decoded.has(sample.id)) {
      const response = await fetch(sample.url);
      if (!response.ok) throw new Error(`style transfer target ${sample.label}: HTTP ${response.status}`);
      decoded.set(sample.id, decode(new Uint8Array(await response.arrayBuffer()), sample.label));
    }
    return decoded.get(sample.id);
  }

  /** The guides of the current mode, as grey RGBA: { source, target } (null for 'none'). */
  async function build() {
    if (mode() === 'none') return null;
    const exemplar = ui.exemplar();
    const [width, height] = [ui.outputWidth(), ui.outputHeight()];
    let source = luminance(exemplar.toRgba());
    let wanted;
    if (mode() === 'style') {
      const p = await picture();
      wanted = luminance(resizedRgba(p.rgba, p.width, p.height, width, height));
    } else {
      source = blurred(source, exemplar.width, exemplar.height, SMOOTH_GUIDE_BLUR);
      wanted = blurred(gradientLuminance(width, height, mode()), width, height, SMOOTH_GUIDE_BLUR);
    }
    return {
      source: { rgba: greyRgba(source), width: exemplar.width, height: exemplar.height },
      // The target's luminance moved to the exemplar's mean and spread (image analogies'
      // luminance remapping): a guide value the exemplar lacks would be matched by nothing.
      target: { rgba: greyRgba(remapLuminance(wanted, source)), width, height },
    };
  }

  /** Sends the guides of the current mode to `session` (a mirror made in the page's worker). */
  async function apply(session) {
    const guides = await build();
    if (!guides) return;
    await session.send('setGuides', { exemplar: guides.source }, { exemplar: guides.target }, weight());
  }

  /** Draws the target guide beside the output (hidden for 'none'); an error goes to the page. */
  async function preview() {
    const run = ++previewRun;
    const guided = mode() !== 'none';
    ui.$('to-guide-target-label').hidden = mode() !== 'style';
    ui.$('to-guide-weight-label').hidden = !guided;
    if (!figure) return;
    figure.hidden = !guided;
    if (!guided || !ui.exemplar()) return;
    try {
      const guides = await build();
      if (run !== previewRun || !figure) return;
      const canvas = ui.$('to-guide-canvas');
      canvas.width = guides.target.width;
      canvas.height = guides.target.height;
      canvas.getContext('2d').putImageData(new ImageData(guides.target.rgba, canvas.width, canvas.height), 0, 0);
      ui.$('to-guide-caption').textContent = `target guide: ${describe()}`;
      document.body.dataset.guidePreview = mode();
    } catch (error) {
      if (run === previewRun) showError(error.message ?? String(error));
    }
  }

  function describe() {
    if (mode() === 'style') {
      const name = target() === 'file' ? upload?.name ?? 'no file yet' : target().split('_')[0];
      return `style transfer (${name}), weight ${weight()}`;
    }
    return `${mode() === 'radial' ? 'radial' : 'gradient'}, weight ${weight()}`;
  }

  async function loadFile() {
    const file = ui.$('to-guide-file').files[0];
    if (!file) return;
    try {
      upload = decode(new Uint8Array(await file.arrayBuffer()), file.name);
      ui.$('to-guide-target').value = 'file';
      // A change of a (non-view) option resets the run, so the next one takes the new target.
      ui.$('to-guide-target').dispatchEvent(new Event('change', { bubbles: true }));
    } catch (error) {
      showError(`${file.name}: ${error.message ?? error}`);
    }
  }

  return {
    active: () => mode() !== 'none',
    apply,
    preview,
    describe,
    mount() {
      figure = document.createElement('figure');
      figure.className = 'guide-preview';
      figure.id = 'to-guide-preview';
      figure.hidden = true;
      figure.title = 'The target guide as the session gets it: the luminance moved to the mean and spread of the exemplar\'s';
      figure.innerHTML = PREVIEW_HTML;
      ui.outputCanvas.after(figure);
      // Choosing "an image file…" opens the file chooser (a link restoring it does not).
      ui.$('to-guide-target').addEventListener('change', (event) => {
        if (target() === 'file' && event.isTrusted) ui.$('to-guide-file').click();
      });
      ui.$('to-guide-file').addEventListener('change', loadFile);
      preview();
    },
    unmount() {
      figure?.remove();
      figure = null;
      delete document.body.dataset.guidePreview;
    },
  };
}

/** PNG or JPEG bytes decoded by wasm (its own message for a file it cannot read), as RGBA. */
function decode(bytes, name) {
  const full = Exemplar.fromBytes(bytes);
  const fits = Math.max(full.width, full.height) <= UPLOAD_MAX_SIDE;
  const exemplar = fits ? full : full.resized(UPLOAD_MAX_SIDE);
  const picture = { rgba: exemplar.toRgba(), width: exemplar.width, height: exemplar.height, name };
  if (!fits) exemplar.free();
  full.free();
  return picture;
}
