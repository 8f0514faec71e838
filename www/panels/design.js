// The "Texture design" panel (Shen et al. 2009): a designer makes a family of textures from one
// sample, stage by stage. Each stage is a module in ./design/; they share a gallery of designed
// textures (the set S of the paper), from which the base and the reference are picked.
import { explain } from '../lib/explain.js';
import { setupTablist } from '../lib/tablist.js';
import { Gallery } from './design/gallery.js';
import * as deformStage from './design/deform.js';
import * as brushStage from './design/brush.js';
import * as synthesisStage from './design/synthesis.js';
import * as layersStage from './design/layers.js';
import * as tileableStage from './design/tileable.js';

export const id = 'design';
export const title = 'Texture design';

const STAGES = [deformStage, brushStage, synthesisStage, layersStage, tileableStage];

export function createPanel(ui) {
  let gallery = null;
  let stage = null;
  let stageTitle = '';
  let syncStages = () => {};
  const context = { ui, get gallery() { return gallery; }, readout: (text) => { ui.$('ds-readout').textContent = text; } };

  function selectStage(module) {
    stage?.unmount?.();
    stage = module.createStage(context);
    stageTitle = module.title;
    ui.$('ds-stage-options').innerHTML = stage.optionsHtml;
    ui.$('ds-stage-side').innerHTML = stage.sideHtml ?? '';
    explain(ui.$('ds-explain'), `ds-${module.id}`);
    for (const button of ui.$('ds-stages').children) {
      button.setAttribute('aria-selected', String(button.dataset.stage === module.id));
    }
    syncStages();
    document.body.dataset.designStage = module.id;
    context.readout(stage.hint);
    stage.mount();
  }

  return {
    id,
    title,
    optionsHtml: `<nav class="stages" id="ds-stages" role="tablist" aria-label="Design stage">
        ${STAGES.map((s, i) => `<button type="button" role="tab" aria-controls="ds-stage-options" data-stage="${s.id}">${i + 1}. ${s.title}</button>`).join('')}
      </nav>
      <div class="method-options" id="ds-stage-options" role="tabpanel" aria-label="Stage options"></div>`,
    sideHtml: `<div class="readout" id="ds-readout"></div>
      <div class="explain" id="ds-explain" data-history-text aria-live="polite"></div>
      <div id="ds-stage-side"></div>
      <h3 class="side-title">Designed textures <small>(B: base, R: reference)</small></h3>
      <div class="gallery" id="ds-gallery" role="list" aria-label="Designed textures"></div>`,
    mount() {
      gallery = new Gallery(ui.$('ds-gallery'), () => stage?.onSelection?.());
      syncStages = setupTablist(ui.$('ds-stages'));
      for (const button of ui.$('ds-stages').children) {
        button.addEventListener('click', () => selectStage(STAGES.find((s) => s.id === button.dataset.stage)));
      }
      selectStage(STAGES[0]);
    },
    unmount() {
      stage?.unmount?.();
      gallery?.clear();
    },
    step() {
      if (!stage) return null;
      // Deform and Brush act on their own buttons and clicks: Run says so rather than spinning.
      if (!stage.step) return { idle: `nothing to run in ${stageTitle}: ${stage.hint}` };
      return stage.step();
    },
    onStep(event) {
      stage?.onStep?.(event);
    },
    reset() {
      // A new exemplar (or new output size / seed) starts the design over from the sample.
      if (!gallery || !ui.exemplar()) return;
      if (gallery.sampleOf !== ui.exemplar()) {
        gallery.clear();
        gallery.add('sample I', gallery.copy(ui.exemplar()));
        gallery.sampleOf = ui.exemplar();
      }
      stage?.reset?.();
    },
  };
}
