// The README's Vite example: import and use, no init, no plugin; the .wasm is a bundled asset.
import { Exemplar, TextureOptimization, version } from 'texsynth-wasm';
import { createWorker } from 'texsynth-wasm/worker';
import sampleUrl from './sand_64.png';

const bytes = new Uint8Array(await (await fetch(sampleUrl)).arrayBuffer());
const exemplar = Exemplar.fromBytes(bytes);
const session = new TextureOptimization(exemplar, { outputWidth: 64, outputHeight: 64, neighbourhoodSizes: [16, 8] });
const image = new ImageData(session.width, session.height);
await session.run({ onEvent: () => session.renderInto(image.data) });
document.getElementById('out').getContext('2d').putImageData(image, 0, 0);

// The same in a Web Worker, from the production build.
const worker = createWorker();
const remote = await worker.createSession('GraphcutTextures', { bytes }, { outputWidth: 64, outputHeight: 64 });
const { event } = await remote.run({ every: 1000 });
worker.terminate();

document.body.dataset.result = JSON.stringify({ version: version(), done: session.done, alpha: image.data[3], workerDone: event.done });
