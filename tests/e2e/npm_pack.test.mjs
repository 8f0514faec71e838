// The npm package as a user gets it: `npm pack ./pkg`, installed into a fresh Node project, imported.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

const ROOT = new URL('../../', import.meta.url).pathname;
const npm = (args, cwd) => execFileSync('npm', args, { cwd, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });

test('npm pack ./pkg installs into a scratch project that imports and uses it', () => {
  const scratch = mkdtempSync(join(tmpdir(), 'texsynth-pack-'));
  try {
    const packed = JSON.parse(npm(['pack', join(ROOT, 'pkg'), '--pack-destination', scratch, '--json'], ROOT));
    const files = packed[0].files.map((f) => f.path).sort();
    assert.deepEqual(files, ['README.md', 'package.json', 'texsynth.d.ts', 'texsynth.js', 'texsynth_bg.wasm', 'texsynth_bg.wasm.d.ts']);

    const app = join(scratch, 'app');
    execFileSync('mkdir', ['-p', app]);
    writeFileSync(join(app, 'package.json'), JSON.stringify({ name: 'scratch', private: true, type: 'module' }));
    npm(['install', '--no-audit', '--no-fund', join(scratch, packed[0].filename)], app);
    writeFileSync(join(app, 'use.mjs'), `
      import { readFileSync } from 'node:fs';
      import init, { Exemplar, version } from 'texsynth-wasm';
      await init({ module_or_path: readFileSync(new URL(import.meta.resolve('texsynth-wasm/texsynth_bg.wasm'))) });
      const ex = Exemplar.fromBytes(readFileSync(process.argv[2]));
      const rgba = new Uint8ClampedArray(ex.width * ex.height * 4);
      ex.renderInto(rgba);
      let error = '';
      try { Exemplar.fromBytes(new Uint8Array(0)); } catch (e) { error = e instanceof Error ? e.message : 'not an Error'; }
      console.log(JSON.stringify({ version: version(), width: ex.width, height: ex.height, alpha: rgba[3], error }));
    `);
    const out = JSON.parse(execFileSync('node', ['use.mjs', join(ROOT, 'www/samples/sand_64.png')], { cwd: app, encoding: 'utf8' }));
    const manifest = JSON.parse(readFileSync(join(ROOT, 'pkg.json'), 'utf8'));
    assert.deepEqual(out, { version: manifest.version, width: 64, height: 64, alpha: 255, error: 'empty input: no image bytes were given' });
  } finally {
    rmSync(scratch, { recursive: true, force: true });
  }
});
