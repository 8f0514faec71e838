// Writes docs/benchmarks.md whole from a comparison run (compare.sh's results.json) and, when
// given, the scaling tables (bench-scaling.mjs's output), and the headline rows of the README
// between its `<!-- headline -->` markers. Run by `./scripts/bench.sh --write-docs`. With
// --threads, a second comparison run at N threads (compare.sh --threads N) gets its own section;
// with --inpaint, the hole-filling comparison (compare.sh --task inpaint's inpaint.json) too.
//   node scripts/write-benchmarks.mjs RESULTS.json [SCALING.md] [--threads RESULTS.json] [--inpaint INPAINT.json] --command "..."
import { readFileSync, writeFileSync } from 'node:fs';
import { basename } from 'node:path';

const ROOT = new URL('../', import.meta.url).pathname;
const args = process.argv.slice(2);
const commandAt = args.indexOf('--command');
const command = commandAt >= 0 ? args.splice(commandAt, 2)[1] : './scripts/bench.sh --write-docs';
const threadsAt = args.indexOf('--threads');
const threadsPath = threadsAt >= 0 ? args.splice(threadsAt, 2)[1] : null;
const inpaintAt = args.indexOf('--inpaint');
const inpaintPath = inpaintAt >= 0 ? args.splice(inpaintAt, 2)[1] : null;
const [resultsPath, scalingPath] = args;
if (!resultsPath) throw new Error('usage: write-benchmarks.mjs RESULTS.json [SCALING.md] [--command TEXT]');
const report = JSON.parse(readFileSync(resultsPath, 'utf8'));

const NAMES = {
  optimization: 'texture optimisation',
  'graphcut-random': 'graph cut, random placement',
  'graphcut-entire': 'graph cut, entire-patch matching',
  'graphcut-sub': 'graph cut, sub-patch matching',
  features: 'feature-guided',
  peer: 'peer (texture-synthesis 0.8.2)',
};
const fmt = (v, digits = 2) => (v == null ? '—' : v >= 100 ? v.toFixed(0) : v.toPrecision(digits));
const ms = (v) => (v == null ? '—' : `${Math.round(v)}`);
const [w, h] = report.output_size;
const summaries = report.summary.filter((s) => s.method !== 'peer');
const peer = report.summary.find((s) => s.method === 'peer');
const date = new Date().toISOString().slice(0, 10);
const machine = `${report.machine.cores} cores (${report.machine.cpu}), ${report.machine.os}, Node ${report.node ?? '—'}`;

const lines = [];
lines.push(`Measured on ${date}, ${machine}, by \`${command}\`.`, '');
lines.push('# Benchmarks', '');
lines.push(
  'Speed and quality of each method beside the [`texture-synthesis`](https://crates.io/crates/texture-synthesis)',
  'crate 0.8.2 (the peer), both on one thread with their default settings, on the same exemplar',
  `pixels, output size (${w}x${h}) and seeds (${report.seeds.join(', ')}), over ${report.exemplars.length} exemplars`,
  `from \`${basename(report.dir)}\`. Every figure on this page comes from the one run named above;`,
  'the command rewrites the page whole.',
  '',
  'How to read the figures: time is session construction plus every step, the median over seeds',
  '(native: release build; wasm: the npm package in Node). Quality is measured on the output',
  'against its exemplar, lower is better: coherence (every output patch near some exemplar',
  'patch), completeness (every exemplar patch near some output patch), the colour histogram',
  'distance, and the flat fraction (the share of output pixels with less detail than the',
  "exemplar's flattest tenth; the exemplar itself scores about 0.10).",
  '',
  '## Against the peer',
  '',
  'Geometric means over the exemplars of method / peer on the same exemplar (below 1 is better),',
  'and how many exemplars meet the goal (at least 3x faster, coherence and completeness no worse):',
  '',
  '| method | time native | time wasm | coherence | completeness | histogram | flat | goal met (native / wasm) |',
  '|---|---|---|---|---|---|---|---|',
);
for (const s of summaries) {
  const r = s.ratios ?? {};
  lines.push(`| ${NAMES[s.method] ?? s.method} | ${fmt(r.native_time)} | ${fmt(r.wasm_time)} | ${fmt(r.coherence)} | ${fmt(r.completeness)} | ${fmt(r.histogram)} | ${fmt(r.flat)} | ${s.goal_native_met} / ${s.goal_wasm_met} of ${s.exemplars} |`);
}
lines.push('', 'Mean figures per method (times in ms):', '',
  '| method | native ms | wasm ms | steps | ms per step | longest step | coherence | completeness | histogram | flat | wasm output identical |',
  '|---|---|---|---|---|---|---|---|---|---|---|');
for (const s of [...summaries, ...(peer ? [peer] : [])]) {
  const f = s.figures;
  lines.push(`| ${NAMES[s.method] ?? s.method} | ${ms(f.native_ms)} | ${ms(f.wasm_ms)} | ${fmt(f.steps, 3)} | ${fmt(f.ms_per_step)} | ${ms(f.max_step_ms)} | ${fmt(f.coherence, 3)} | ${fmt(f.completeness, 3)} | ${fmt(f.histogram, 3)} | ${fmt(f.flat, 3)} | ${f.wasm_identical == null ? '—' : f.wasm_identical ? 'yes' : 'no'} |`);
}

const methods = [...summaries.map((s) => s.method), ...(peer ? ['peer'] : [])];
lines.push('', '## The flat fraction per exemplar', '',
  'Where a method loses detail shows here first; the contact sheets (`results/compare/contact-sheets/`,',
  'one per exemplar, the exemplar then each method\'s output) show what the figure means.', '',
  `| exemplar | ${methods.map((m) => NAMES[m] ?? m).join(' | ')} |`,
  `|---|${methods.map(() => '---').join('|')}|`);
for (const e of report.exemplars) {
  const cells = methods.map((m) => fmt(report.results.find((r) => r.exemplar === e.name && r.method === m)?.figures.flat, 2));
  lines.push(`| ${e.name} | ${cells.join(' | ')} |`);
}

if (threadsPath) {
  const threaded = JSON.parse(readFileSync(threadsPath, 'utf8'));
  const n = threaded.threads;
  const [tw, th] = threaded.output_size;
  const one = (method) => report.summary.find((s) => s.method === method)?.figures;
  lines.push('', `## On ${n} threads`, '',
    `The same comparison with ${n} threads on each side: texsynth natively on a rayon pool of ${n}, as`,
    `wasm the threaded module on a pool of ${n} in Node, and the peer with \`max_thread_count(${n})\``,
    `(${tw}x${th}, seeds ${threaded.seeds.join(', ')}, ${threaded.exemplars.length} exemplars). Time ratios are method / peer on the`,
    'same exemplar, geometric means (below 1 is better); "at least 5x" counts the exemplars where the',
    "method takes at most a fifth of the peer's time; the speed-up is the mean time on one thread over",
    `the mean time on ${n}, both from this page's runs.`, '',
    '| method | time native | time wasm | at least 5x (native / wasm) | native ms | wasm ms | speed-up native | speed-up wasm | output as on one thread |',
    '|---|---|---|---|---|---|---|---|---|');
  for (const s of threaded.summary) {
    const r = s.ratios ?? {};
    const f = s.figures;
    const o = one(s.method);
    const peerRow = s.method === 'peer';
    const within = (key) => threaded.results.filter((e) => e.method === s.method && e.ratios?.[key] != null && e.ratios[key] <= 0.2).length;
    const rated = threaded.results.filter((e) => e.method === s.method && e.ratios).length;
    const speedup = (a, b) => (a == null || b == null ? '—' : `${(a / b).toFixed(2)}x`);
    // The peer is deterministic on one thread only; texsynth makes the same bytes at any count.
    const same = threaded.results.filter((e) => e.method === s.method).every((e) => {
      const base = report.results.find((b) => b.exemplar === e.exemplar && b.method === e.method);
      return base && e.runs.every((run) => base.runs.find((b) => b.seed === run.seed)?.output_hash === run.output_hash);
    });
    const counts = peerRow ? '—' : `${within('native_time')} / ${within('wasm_time')} of ${rated}`;
    lines.push(`| ${NAMES[s.method] ?? s.method} | ${peerRow ? '—' : fmt(r.native_time)} | ${peerRow ? '—' : fmt(r.wasm_time)} | ${counts} | ${ms(f.native_ms)} | ${ms(f.wasm_ms)} | ${speedup(o?.native_ms, f.native_ms)} | ${speedup(o?.wasm_ms, f.wasm_ms)} | ${same ? 'yes' : 'no'} |`);
  }
}

if (inpaintPath) {
  const inpaint = JSON.parse(readFileSync(inpaintPath, 'utf8'));
  const n = inpaint.threads;
  const pct = (share) => `${Math.round(share * 100)}%`;
  lines.push('', '## Hole filling', '',
    'Each texture (the largest of its sizes) gets a centred square hole of 25% and of 40% of its pixels,',
    "erased to grey, and is filled by `Inpainting` (defaults, one thread) and by the peer's inpaint",
    '(`inpaint_example`, sampling from the known pixels only, on one thread and on all threads). The',
    'figures of the filled square: coherence against the known part (7x7 patches to the nearest',
    'patch wholly inside one of the four known rectangles around the hole) and the flat fraction,',
    "lower is better; the seam score, the mean colour step across the hole's boundary over the",
    "image's mean step between neighbours, nearer 1 is better (above 1 a seam shows, below 1 the",
    "boundary is smoothed over; a ratio of 2 and of 1/2 count as equally far). The peer's",
    "quality figures are its one-thread run's; the contact sheets (image, mask, texsynth, peer) are",
    'in `contact-sheets/` beside `inpaint.json`.', '',
    `| texture | hole | texsynth ms | peer ms, 1 thread | peer ms, ${n} threads | coherence texsynth / peer | flat texsynth / peer | seam texsynth / peer |`,
    '|---|---|---|---|---|---|---|---|');
  for (const r of inpaint.rows) {
    const [o, p] = [r.ours, r.peer_one_thread];
    lines.push(`| ${r.texture} | ${pct(r.share)} | ${ms(o.ms)} | ${ms(p.ms)} | ${ms(r.peer_threads.ms)} | ${o.coherence.toFixed(4)} / ${p.coherence.toFixed(4)} | ${o.flat.toFixed(2)} / ${p.flat.toFixed(2)} | ${o.seam.toFixed(2)} / ${p.seam.toFixed(2)} |`);
  }
  lines.push('');
  for (const share of [...new Set(inpaint.rows.map((r) => r.share))]) {
    const of = inpaint.rows.filter((r) => r.share === share);
    const good = (peerOf) => of.filter((r) => {
      const p = peerOf(r);
      const seamOk = Math.abs(Math.log(r.ours.seam)) <= Math.abs(Math.log(p.seam)) + Math.log(inpaint.tolerance);
      return r.ours.ms < p.ms && r.ours.coherence <= p.coherence * inpaint.tolerance && seamOk;
    }).length;
    lines.push(`- ${pct(share)} hole: texsynth faster and no worse on coherence and seam score (within ${Math.round((inpaint.tolerance - 1) * 100)}%; the seam score no farther from 1) on ${good((r) => r.peer_one_thread)} of ${of.length} textures against the peer on one thread, ${good((r) => r.peer_threads)} of ${of.length} against it on ${n} threads.`);
  }
}

if (scalingPath) {
  lines.push('', '## How time and memory grow', '',
    'Every method as wasm in Node, one fresh process per case, from the 128x128 tiles sample to',
    'square outputs of each size (flow animation: frames per second after the first frame):', '',
    readFileSync(scalingPath, 'utf8').trim());
}

lines.push('', '## The tools', '',
  '- `./scripts/compare.sh [--dir DIR] [--size WxH] [--seeds 1,2,3] [--methods ...] [--threads N]`: the comparison above, on any folder of PNG and JPEG files; `--help` lists the options. `--task inpaint` runs the hole-filling comparison instead.',
  "- `node scripts/bench-threads.mjs [--rounds 3] [--cases ...] [--environments node,chromium]`: the threaded module on one thread against every thread of the machine, in Node and in the page's worker in headless Chromium, with the serial phases and the speed-up Amdahl's law projects for 8 threads.",
  '- `node scripts/bench-scaling.mjs [--outputs ...] [--exemplars ...] [--repeat N]`: time, longest step and peak memory against output and exemplar size; writes `www/scaling.svg`.',
  '- `node scripts/bench-ab.mjs A/pkg B/pkg --method M --size N --runs R`: two builds of the package timed interleaved in one process, for judging a speed change on a noisy machine.',
  '- `./scripts/bench.sh`: every method natively and as wasm at 256x256, and the max-flow solver against the reference.',
  '- `node scripts/bench-quality.mjs A/pkg B/pkg`, `bench-memory.mjs`, `bench-design.mjs`, `bench-features.mjs`, `bench-video.mjs`: the quality metrics\' speed, peak memory against the estimate, and the design, feature-guided and video timings.',
  '- `cargo run --release -p texsynth-bench --bin NAME` with NAME one of `bench`, `bench_graphcut`, `design_bench`, `features_bench`, `flow_bench`, `video_bench`, `large_exemplar`: the native timings of each method, and every method on a camera-sized exemplar.',
  '');
writeFileSync(`${ROOT}docs/benchmarks.md`, lines.join('\n'));

// The README's headline: three methods, their time and quality ratios.
const headline = ['optimization', 'graphcut-sub', 'features'].map((m) => summaries.find((s) => s.method === m)).filter(Boolean);
const table = ['| method | time (native) | time (wasm) | coherence | completeness |', '|---|---|---|---|---|',
  ...headline.map((s) => `| ${NAMES[s.method]} | ${fmt(s.ratios?.native_time)} | ${fmt(s.ratios?.wasm_time)} | ${fmt(s.ratios?.coherence)} | ${fmt(s.ratios?.completeness)} |`)];
const readmePath = `${ROOT}README.md`;
const readme = readFileSync(readmePath, 'utf8');
const updated = readme.replace(/<!-- headline -->\n[\s\S]*?<!-- \/headline -->/, `<!-- headline -->\n${table.join('\n')}\n<!-- /headline -->`);
if (updated === readme && !readme.includes('<!-- headline -->')) throw new Error('README.md has no <!-- headline --> markers');
writeFileSync(readmePath, updated);
console.log('write-benchmarks: docs/benchmarks.md and the README headline');
