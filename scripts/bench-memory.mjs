// Peak wasm memory per method against the constructor's estimate:
//   node scripts/bench-memory.mjs [--sizes 1024,2048] [--methods optimization,graphcut,...]
//                                 [--big optimization,graphcut] [--skip flow:2048,...] [--budget 3584]
// Each case runs in a fresh Node process (wasm memory never shrinks, so the peak of a run is
// the memory's byteLength after it): the 128x128 www/samples/tiles_128.png is loaded, the
// session constructed (its `memoryEstimate` read), and run to the end (flow: 3 frames). The
// table gives the estimate, the memory's growth from before the constructor to after the run,
// and estimate / growth. `--big` lists the methods also run at 4096x4096 (default: none; their
// estimate is printed either way); `--skip method:size` prints only the estimate of a case. Needs the wasm package: ./scripts/build.sh.
import { spawnSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { performance } from 'node:perf_hooks';
import { fileURLToPath } from 'node:url';

const MiB = 1 << 20;
const args = Object.fromEntries(
  process.argv.slice(2).reduce((pairs, arg, i, all) => (arg.startsWith('--') ? [...pairs, [arg.slice(2), all[i + 1]]] : pairs), []),
);
const METHODS = {
  optimization: 'texture optimisation',
  graphcut: 'graph cut (entire patch)',
  flow: 'flow animation (3 frames)',
  features: 'feature-guided (graph-cut placement)',
  layers: 'texture design (layers)',
  tileable: 'texture design (tileable)',
};

async function runCase(method, size, budget) {
  const lib = await import('../pkg/texsynth.js');
  const wasm = await lib.default({ module_or_path: readFileSync(new URL('../pkg/texsynth_bg.wasm', import.meta.url)) });
  const texture = lib.Exemplar.fromBytes(readFileSync(new URL('../www/samples/tiles_128.png', import.meta.url)));
  const output = { outputWidth: size, outputHeight: size, memoryBudgetMiB: budget };
  let input = texture;
  if (method === 'tileable') {
    // Scaled up to the size (deformTexture scales by at most 4 at a time).
    const steps = [];
    for (let f = size / 128; f > 1; f /= Math.min(4, f)) steps.push({ scale: Math.min(4, f) });
    input = lib.deformTexture(texture, steps);
  }
  const base = wasm.memory.buffer.byteLength;
  const make = {
    optimization: () => new lib.TextureOptimization(texture, output),
    graphcut: () => new lib.GraphcutTextures(texture, { ...output, placement: 'entire-patch' }),
    flow: () => new lib.FlowAnimation(texture, { ...output, frames: 3 }),
    features: () => new lib.FeatureSynthesis(texture, output),
    layers: () => {
      const d = new lib.LayerDesign(output);
      d.addLayer(texture, undefined);
      return d;
    },
    tileable: () => new lib.TileableTexture(input, { memoryBudgetMiB: budget }),
  }[method];
  const start = performance.now();
  const session = make();
  const estimate = session.memoryEstimate;
  const run = process.env.BENCH_MEMORY_ESTIMATE_ONLY !== '1';
  let steps = 0;
  if (run) {
    while (!session.done) {
      session.step();
      steps++;
    }
  }
  const peak = wasm.memory.buffer.byteLength;
  return { estimate, base, peak, steps, run, ms: performance.now() - start };
}

if (args.case) {
  const [method, size, budget] = args.case.split(':');
  const result = await runCase(method, Number(size), Number(budget));
  console.log(JSON.stringify(result));
} else {
  const sizes = (args.sizes ?? '1024,2048').split(',').map(Number);
  const methods = (args.methods ?? Object.keys(METHODS).join(',')).split(',');
  const big = new Set((args.big ?? '').split(',').filter(Boolean));
  const skip = new Set((args.skip ?? '').split(',').filter(Boolean));
  const budget = Number(args.budget ?? 3584);
  const script = fileURLToPath(import.meta.url);
  console.log(`wasm (Node ${process.version}), tiles_128.png, memoryBudgetMiB ${budget}; growth = memory after the run - before the constructor`);
  console.log();
  console.log('| method | output | estimate (MiB) | measured growth (MiB) | peak memory (MiB) | estimate / growth | run time |');
  console.log('|---|---|---:|---:|---:|---:|---:|');
  for (const method of methods) {
    for (const size of [...sizes, 4096]) {
      if (size === 4096 && sizes.includes(4096)) continue;
      const estimateOnly = (size === 4096 && !big.has(method) && !sizes.includes(4096)) || skip.has(`${method}:${size}`);
      const child = spawnSync(process.execPath, [script, '--case', `${method}:${size}:${budget}`], {
        encoding: 'utf8',
        env: { ...process.env, BENCH_MEMORY_ESTIMATE_ONLY: estimateOnly ? '1' : '0' },
        maxBuffer: 1 << 20,
      });
      const label = `${size}x${size}`;
      if (child.status !== 0) {
        const msg = (child.stderr.match(/Error: (.*)/) ?? [, child.stderr.trim().split('\n').pop()])[1];
        console.log(`| ${METHODS[method]} | ${label} | | | | | failed: ${msg} |`);
        continue;
      }
      const r = JSON.parse(child.stdout.trim().split('\n').pop());
      const growth = r.peak - r.base;
      if (!r.run) {
        console.log(`| ${METHODS[method]} | ${label} | ${(r.estimate / MiB).toFixed(0)} | not run (estimate only) | | | |`);
      } else {
        console.log(
          `| ${METHODS[method]} | ${label} | ${(r.estimate / MiB).toFixed(0)} | ${(growth / MiB).toFixed(0)} | ${(r.peak / MiB).toFixed(0)} | ${(r.estimate / growth).toFixed(2)} | ${(r.ms / 1000).toFixed(1)} s |`,
        );
      }
    }
  }
}
