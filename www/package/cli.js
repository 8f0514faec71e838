#!/usr/bin/env node
// The package's command line (`npx texsynth-wasm ...`). Run with --help for the commands.
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { basename, extname, join } from 'node:path';
import { parseArgs } from 'node:util';
import {
  Exemplar, FeatureSynthesis, FlowAnimation, GraphcutTextures, Inpainting, TextureOptimization, extendBorder, measureQuality, version,
} from './node.js';

const HELP = `texsynth-wasm ${version()}: texture synthesis from the command line

Usage:
  texsynth-wasm synth IN.png [IN2.png ...] -o OUT.png [options]
      --method optimization|graphcut|features   (default optimization: Kwatra et al. 2005; graphcut: 2003; features: Wu & Yu 2004)
      --size WxH                       output size (default 256x256)
      --seed N[,N...]                  seed or seeds (default 1)
      --tileable                       make the output tile seamlessly
      --set key=value                  any session option, repeatable (e.g. --set search=exact,
                                       --set placement=sub-patch); values are JSON or strings
      --transfer MAP.png:OUT-MAP.png   a map of the input's size (normal, height, roughness)
                                       carried along with the output (repeatable; optimization
                                       and graphcut)
      With several inputs or seeds, OUT may contain {name} and {seed}; otherwise
      "-NAME-sSEED" is added before the extension.
  texsynth-wasm animate IN.png -o DIR [--flow vortex|sink|source|shear|translation]
      [--strength S] [--frames N] [--size WxH] [--seed N] [--set key=value]
      writes DIR/frame-0001.png ... (flow-guided animation, Kwatra et al. 2005 section 4.1)
  texsynth-wasm inpaint IN.png --mask MASK.png -o OUT.png [--exemplar EX.png] [--seed N] [--set key=value]
      fills the hole (mask pixels that are not black) from the rest of the image, or from EX
  texsynth-wasm uncrop IN.png --border N|TOP,RIGHT,BOTTOM,LEFT -o OUT.png [--seed N] [--set key=value]
      extends the image by a border of that many pixels, filled like a hole
  texsynth-wasm measure EXEMPLAR.png OUTPUT.png
      prints coherence, completeness, histogram and flat (lower is better)

Common options:
  --jobs N     run several inputs or seeds in parallel on N worker threads (default 1)
  --json       one JSON event per line on stdout instead of the progress bar
  -h, --help   this text
  -v, --version
`;

class UsageError extends Error {}

function fail(message, code = 1) {
  process.stderr.write(`texsynth-wasm: ${message}\n`);
  process.exit(code);
}

function readExemplar(path) {
  let bytes;
  try {
    bytes = readFileSync(path);
  } catch (error) {
    throw new Error(error.code === 'ENOENT' ? `${path}: no such file` : `${path}: cannot read (${error.code ?? error.message})`);
  }
  try {
    return Exemplar.fromBytes(bytes);
  } catch (error) {
    throw new Error(`${path}: ${error.message}`);
  }
}

function parseSize(text) {
  const m = /^(\d+)x(\d+)$/.exec(text ?? '');
  if (!m) throw new UsageError(`--size must be WIDTHxHEIGHT, e.g. 512x512 (got '${text}')`);
  return { outputWidth: Number(m[1]), outputHeight: Number(m[2]) };
}

function parseSets(list = []) {
  const options = {};
  for (const item of list) {
    const eq = item.indexOf('=');
    if (eq <= 0) throw new UsageError(`--set wants key=value (got '${item}')`);
    const key = item.slice(0, eq);
    const raw = item.slice(eq + 1);
    let value;
    try {
      value = JSON.parse(raw);
    } catch {
      value = raw;
    }
    options[key] = value;
  }
  return options;
}

function parseInt10(text, name) {
  const n = Number(text);
  if (!Number.isInteger(n) || n < 0) throw new UsageError(`${name} must be a whole number (got '${text}')`);
  return n;
}

function writePng(path, rgba, width, height) {
  const image = Exemplar.fromRgba(new Uint8Array(rgba.buffer, rgba.byteOffset, rgba.byteLength), width, height);
  writeFileSync(path, image.toPng());
  image.free();
}

/** Progress on stderr: a bar when stderr is a terminal, nothing otherwise. */
function progress(label) {
  const tty = process.stderr.isTTY;
  let last = 0;
  return {
    update(fraction, text) {
      if (!tty) return;
      const now = Date.now();
      if (now - last < 50 && fraction < 1) return;
      last = now;
      const width = 30;
      const filled = Math.round(Math.max(0, Math.min(1, fraction)) * width);
      process.stderr.write(`\r${label} [${'#'.repeat(filled)}${'.'.repeat(width - filled)}] ${String(Math.round(fraction * 100)).padStart(3)}% ${text}\x1b[K`);
    },
    end() {
      if (tty) process.stderr.write('\n');
    },
  };
}

/** How far along a session is, from its events (0..1). */
function progressOf(kind, session, options) {
  let area = 0;
  let placedWhenCovered = null;
  return (event) => {
    if (event.done) return 1;
    if (kind === 'GraphcutTextures') {
      // Covering the output (by patch area, overlaps counted twice), then the refinement patches.
      if (!event.covered) {
        area += event.rect ? event.rect.width * event.rect.height : 0;
        return Math.min(0.8, (0.8 * area) / (session.width * session.height));
      }
      placedWhenCovered ??= event.patchesPlaced;
      return 0.8 + (0.2 * (event.patchesPlaced - placedWhenCovered)) / (options.refinementPatches ?? 24);
    }
    if (kind === 'FlowAnimation') return (event.frame ?? 0) / (session.frames || 1);
    if (kind === 'FeatureSynthesis') return event.patchesPlaced / (event.patchesPlanned || 1);
    if (kind === 'TextureOptimization') return Math.min(0.99, ((event.level ?? 0) + (event.iteration ?? 0) / 6) / (event.levelCount || 1));
    return 0;
  };
}

const SESSION_OF = { optimization: 'TextureOptimization', graphcut: 'GraphcutTextures', features: 'FeatureSynthesis' };
const CLASSES = { TextureOptimization, GraphcutTextures, FeatureSynthesis };

function outputPath(pattern, name, seed, many) {
  if (pattern.includes('{name}') || pattern.includes('{seed}')) return pattern.replaceAll('{name}', name).replaceAll('{seed}', String(seed));
  if (!many) return pattern;
  const ext = extname(pattern) || '.png';
  return `${pattern.slice(0, pattern.length - extname(pattern).length)}-${name}-s${seed}${ext}`;
}

async function synth(positionals, values) {
  if (positionals.length === 0) throw new UsageError('synth needs at least one input image');
  if (!values.output) throw new UsageError('synth needs -o OUT.png');
  const method = values.method ?? 'optimization';
  const kind = SESSION_OF[method];
  if (!kind) throw new UsageError(`--method must be optimization, graphcut or features (got '${method}')`);
  const seeds = (values.seed ?? '1').split(',').map((s) => parseInt10(s, '--seed'));
  const options = { ...parseSize(values.size ?? '256x256'), ...parseSets(values.set) };
  if (values.tileable) options.tileable = true;
  const jobs = parseInt10(values.jobs ?? '1', '--jobs') || 1;
  const transfers = (values.transfer ?? []).map((pair) => {
    const colon = pair.lastIndexOf(':');
    if (colon <= 0 || colon === pair.length - 1) throw new UsageError(`--transfer wants MAP.png:OUT.png (got '${pair}')`);
    return { from: pair.slice(0, colon), to: pair.slice(colon + 1) };
  });
  if (transfers.length && method === 'features') throw new UsageError('--transfer works with --method optimization or graphcut');
  if (transfers.length && jobs > 1) throw new UsageError('--transfer runs with --jobs 1');
  const maps = new Map(transfers.map((t) => [t.from, readExemplar(t.from)]));
  const tasks = [];
  for (const input of positionals) for (const seed of seeds) tasks.push({ input, seed });
  const many = tasks.length > 1;
  // Read every input first, so a missing or broken file fails before any work starts.
  const exemplars = new Map(positionals.map((p) => [p, readExemplar(p)]));
  const emit = (task, event) => values.json && process.stdout.write(JSON.stringify({ input: task.input, seed: task.seed, ...event }) + '\n');

  if (jobs <= 1) {
    for (const task of tasks) {
      const bar = progress(many ? `${basename(task.input)} s${task.seed}` : method);
      const session = new CLASSES[kind](exemplars.get(task.input), { ...options, seed: task.seed });
      const fraction = progressOf(kind, session, options);
      for (const event of session) {
        emit(task, event);
        bar.update(fraction(event), event.kind);
      }
      bar.end();
      const rgba = new Uint8ClampedArray(session.width * session.height * 4);
      session.renderInto(rgba);
      const out = outputPath(values.output, basename(task.input, extname(task.input)), task.seed, many);
      writePng(out, rgba, session.width, session.height);
      const written = [out];
      for (const t of transfers) {
        session.transferInto(maps.get(t.from), rgba);
        const to = outputPath(t.to, basename(task.input, extname(task.input)), task.seed, many);
        writePng(to, rgba, session.width, session.height);
        written.push(to);
      }
      session.free();
      for (const path of written) {
        if (!values.json) process.stderr.write(`wrote ${path}\n`);
        else process.stdout.write(JSON.stringify({ kind: 'written', path }) + '\n');
      }
    }
    return;
  }

  const { createPool } = await import('./worker-node.js');
  const pool = createPool(Math.min(jobs, tasks.length));
  let finished = 0;
  const bar = progress(`${tasks.length} jobs`);
  try {
    await Promise.all(tasks.map(async (task) => {
      const ex = exemplars.get(task.input);
      const { image } = await pool.run(kind, [ex, { ...options, seed: task.seed }], {
        onEvent: (event) => emit(task, event),
      });
      const out = outputPath(values.output, basename(task.input, extname(task.input)), task.seed, many);
      writePng(out, image.data, image.width, image.height);
      finished++;
      bar.update(finished / tasks.length, `${finished}/${tasks.length}`);
      if (values.json) process.stdout.write(JSON.stringify({ kind: 'written', path: out }) + '\n');
      else if (!process.stderr.isTTY) process.stderr.write(`wrote ${out}\n`);
    }));
  } finally {
    bar.end();
    pool.close();
  }
}

async function animate(positionals, values) {
  if (positionals.length !== 1) throw new UsageError('animate needs exactly one input image');
  if (!values.output) throw new UsageError('animate needs -o DIR');
  const exemplar = readExemplar(positionals[0]);
  const flow = { type: values.flow ?? 'vortex' };
  if (values.strength !== undefined) {
    flow.strength = Number(values.strength);
    if (!Number.isFinite(flow.strength)) throw new UsageError(`--strength must be a number (got '${values.strength}')`);
  }
  const options = {
    ...parseSize(values.size ?? '128x128'),
    frames: parseInt10(values.frames ?? '60', '--frames'),
    seed: parseInt10(values.seed ?? '1', '--seed'),
    flow,
    ...parseSets(values.set),
  };
  const anim = new FlowAnimation(exemplar, options);
  mkdirSync(values.output, { recursive: true });
  const rgba = new Uint8ClampedArray(anim.width * anim.height * 4);
  const bar = progress('animate');
  let written = 0;
  for (const event of anim) {
    if (values.json) process.stdout.write(JSON.stringify(event) + '\n');
    if (event.frameFinished) {
      anim.renderInto(rgba);
      written++;
      writePng(join(values.output, `frame-${String(written).padStart(4, '0')}.png`), rgba, anim.width, anim.height);
    }
    bar.update(written / anim.frames, `frame ${written}/${anim.frames}`);
  }
  bar.end();
  if (!values.json) process.stderr.write(`wrote ${written} frames to ${values.output}\n`);
}

/** Runs an inpainting of `image` over `mask` to the end and writes it to `-o`. */
function fill(image, mask, values, label) {
  const options = { seed: parseInt10(values.seed ?? '1', '--seed'), ...parseSets(values.set) };
  const exemplar = values.exemplar ? readExemplar(values.exemplar) : null;
  const session = exemplar ? Inpainting.withExemplar(image, mask, exemplar, options) : new Inpainting(image, mask, options);
  const bar = progress(label);
  for (const event of session) {
    if (values.json) process.stdout.write(JSON.stringify(event) + '\n');
    const fraction = event.stage === 'fill' ? (0.5 * event.pixelsFilled) / event.holePixels : 0.5 + (0.5 * ((event.level ?? 0) + 1)) / (event.levelCount || 1);
    bar.update(event.done ? 1 : fraction, event.kind);
  }
  bar.end();
  const rgba = new Uint8ClampedArray(session.width * session.height * 4);
  session.renderInto(rgba);
  writePng(values.output, rgba, session.width, session.height);
  session.free();
  if (!values.json) process.stderr.write(`wrote ${values.output}\n`);
}

function inpaint(positionals, values) {
  if (positionals.length !== 1) throw new UsageError('inpaint needs exactly one input image');
  if (!values.mask) throw new UsageError('inpaint needs --mask MASK.png');
  if (!values.output) throw new UsageError('inpaint needs -o OUT.png');
  const image = readExemplar(positionals[0]);
  const maskImage = readExemplar(values.mask);
  if (maskImage.width !== image.width || maskImage.height !== image.height) {
    throw new Error(`the mask ${values.mask} is ${maskImage.width}x${maskImage.height}, the image ${image.width}x${image.height}`);
  }
  // A pixel that is not black marks the hole (alpha is ignored).
  const rgba = maskImage.toRgba();
  const mask = new Uint8Array(image.width * image.height);
  for (let i = 0; i < mask.length; i++) mask[i] = rgba[i * 4] || rgba[i * 4 + 1] || rgba[i * 4 + 2] ? 1 : 0;
  fill(image, mask, values, 'inpaint');
}

function uncrop(positionals, values) {
  if (positionals.length !== 1) throw new UsageError('uncrop needs exactly one input image');
  if (!values.border) throw new UsageError('uncrop needs --border N or --border TOP,RIGHT,BOTTOM,LEFT');
  if (!values.output) throw new UsageError('uncrop needs -o OUT.png');
  const widths = values.border.split(',').map((w) => parseInt10(w, '--border'));
  if (widths.length !== 1 && widths.length !== 4) throw new UsageError(`--border takes N or TOP,RIGHT,BOTTOM,LEFT (got '${values.border}')`);
  const [top, right, bottom, left] = widths.length === 1 ? [widths[0], widths[0], widths[0], widths[0]] : widths;
  const { image, mask } = extendBorder(readExemplar(positionals[0]), { top, right, bottom, left });
  fill(image, mask, values, 'uncrop');
}

function measure(positionals, values) {
  if (positionals.length !== 2) throw new UsageError('measure needs EXEMPLAR.png OUTPUT.png');
  const exemplar = readExemplar(positionals[0]);
  const output = readExemplar(positionals[1]);
  const q = measureQuality(exemplar, output.toRgba(), output.width, output.height);
  const figures = { coherence: q.coherence, completeness: q.completeness, histogram: q.histogram, flat: q.flat };
  if (values.json) process.stdout.write(JSON.stringify(figures) + '\n');
  else for (const [k, v] of Object.entries(figures)) process.stdout.write(`${k.padEnd(13)} ${v.toPrecision(4)}\n`);
}

async function main(argv) {
  let parsed;
  try {
    parsed = parseArgs({
      args: argv,
      allowPositionals: true,
      options: {
        output: { type: 'string', short: 'o' },
        method: { type: 'string' },
        size: { type: 'string' },
        seed: { type: 'string' },
        tileable: { type: 'boolean' },
        set: { type: 'string', multiple: true },
        flow: { type: 'string' },
        strength: { type: 'string' },
        mask: { type: 'string' },
        exemplar: { type: 'string' },
        border: { type: 'string' },
        transfer: { type: 'string', multiple: true },
        frames: { type: 'string' },
        jobs: { type: 'string', short: 'j' },
        json: { type: 'boolean' },
        help: { type: 'boolean', short: 'h' },
        version: { type: 'boolean', short: 'v' },
      },
    });
  } catch (error) {
    fail(`${error.message}\n(see --help)`, 2);
  }
  const { values, positionals } = parsed;
  if (values.help) return process.stdout.write(HELP);
  if (values.version) return process.stdout.write(`${version()}\n`);
  const [command, ...rest] = positionals;
  const commands = { synth, animate, inpaint, uncrop, measure };
  const names = 'synth, animate, inpaint, uncrop or measure';
  if (!command) fail(`no command given: ${names} (see --help)`, 2);
  if (!commands[command]) fail(`unknown command '${command}': ${names} (see --help)`, 2);
  try {
    await commands[command](rest, values);
  } catch (error) {
    fail(error instanceof UsageError ? `${error.message} (see --help)` : error.message, error instanceof UsageError ? 2 : 1);
  }
}

await main(process.argv.slice(2));
