// The declared options and events (the bindings' tables, `__schema()`) against the package's
// TypeScript declarations (schema.d.ts), against the test table of sessions.mjs, and against real
// sessions: every declared option key is accepted, every declared default gives the same bytes
// as leaving the key out, every choice is accepted, and every step's event has exactly the
// declared fields with values of the declared types.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createHash } from 'node:crypto';
import { readFileSync } from 'node:fs';

import { api, render, tinyClip } from './fixtures.mjs';
import { BEGIN, END, apiReference } from '../../scripts/lib/api-reference.mjs';
import { SESSIONS } from './sessions.mjs';

const schemas = api.__schema();
const byClass = Object.fromEntries(schemas.map((s) => [s.class, s]));
const dts = readFileSync(new URL('../../pkg/schema.d.ts', import.meta.url), 'utf8');

/** The member names of `interface name` in schema.d.ts, in order. */
function members(name) {
  const m = dts.match(new RegExp(`export interface ${name} \\{\\n([\\s\\S]*?)\\n\\}`));
  assert.ok(m, `schema.d.ts declares ${name}`);
  return [...m[1].matchAll(/^ {2}(\w+)\??:/gm)].map((x) => x[1]);
}

/** Values for options whose default depends on other options or on the input. */
const SAMPLES = {
  TextureOptimization: { mStepMu: 1 },
  FlowAnimation: { flow: { type: 'vortex', strength: 2, centreX: 0.5, centreY: 0.5, angle: 0, period: 0, turn: 0 } },
  FeatureSynthesis: { patchSize: 16, overlap: 4, featureCandidates: 8, featureMask: new Uint8Array(32 * 32) },
  TileableTexture: { overlapX: 4, overlapY: 4 },
  LayerDesign: { overlap: 2 },
  VideoTextures: { mode: 'extend', outputWidth: 12, outputHeight: 12, outputFrames: 8, fixedFrames: 2 },
};

/** A JS literal of the tables ('256', "'patchmatch'", '[32, 16, 8]') as a value. */
const literal = (text) => JSON.parse(text.replaceAll("'", '"'));

/** Whether `value` is of TypeScript type `ts` (unions of literals, number, boolean, objects, null). */
function ofType(value, ts) {
  return ts.split(/ \| (?![^{]*\})/).some((t) => {
    t = t.trim();
    if (t === 'null') return value === null;
    if (t === 'number') return typeof value === 'number';
    if (t === 'boolean') return typeof value === 'boolean';
    if (t === 'string') return typeof value === 'string';
    if (/^'.*'$/.test(t)) return value === t.slice(1, -1);
    return value !== null && typeof value === 'object';
  });
}

/** Options the test table sets to tiny values (so a session runs in milliseconds). */
const TINY = ['outputWidth', 'outputHeight', 'frames', 'neighbourhoodSizes', 'frameSizes', 'patchSize', 'refinementPatches', 'transitionWindow', 'fixedFrames', 'iterations', 'frameIterations', 'margin'];

const sessionClasses = schemas.filter((s) => s.eventName && s.event[0]?.key === 'kind').map((s) => s.class);

test('schema.d.ts declares exactly the tables', () => {
  for (const s of schemas) {
    if (s.optionsName) assert.deepEqual(members(s.optionsName), s.options.map((o) => o.key), s.optionsName);
    if (s.eventName) assert.deepEqual(members(s.eventName), s.event.map((f) => f.key), s.eventName);
  }
});

test('every session class has a table, and the test table lists its options', () => {
  const stepping = Object.keys(api).filter((k) => typeof api[k]?.prototype?.step === 'function');
  assert.deepEqual([...stepping].sort(), [...sessionClasses].sort());
  for (const name of [...sessionClasses, 'TextureBrush']) {
    assert.deepEqual(Object.keys(SESSIONS[name].options).sort(), byClass[name].options.map((o) => o.key).sort(), name);
  }
});

for (const name of sessionClasses) {
  const s = byClass[name];
  const spec = SESSIONS[name];

  test(`${name}: every declared key is accepted, and events carry the declared fields`, () => {
    const all = { ...Object.fromEntries(s.options.filter((o) => o.default !== null).map((o) => [o.key, literal(o.default)])), ...SAMPLES[name] };
    // The tiny sizes of the test table stand in for the large defaults.
    for (const key of TINY) if (key in all && !(SAMPLES[name] && key in SAMPLES[name])) delete all[key];
    const session = spec.make(all, name === 'VideoTextures' ? tinyClip() : undefined);
    let steps = 0;
    while (!session.done && steps < 40) {
      const event = session.step();
      steps++;
      assert.deepEqual(Object.keys(event), s.event.map((f) => f.key), `${name} event fields`);
      for (const f of s.event) assert.ok(ofType(event[f.key], f.ts), `${name}.${f.key} = ${JSON.stringify(event[f.key])} is ${f.ts}`);
    }
    assert.ok(steps > 0);
    session.free();
  });

  test(`${name}: every choice is accepted and every declared default is the default`, () => {
    for (const o of s.options) {
      for (const choice of o.choices ?? []) {
        if (name === 'VideoTextures' && o.key === 'mode' && choice !== 'loop') continue; // needs outputFrames or the clip's size
        spec.make({ [o.key]: choice }).free();
      }
    }
    const steps = (session) => {
      for (let i = 0; i < 6 && !session.done; i++) session.step();
      const bytes = createHash('sha256').update(render(session)).digest('hex');
      session.free();
      return bytes;
    };
    const plain = steps(spec.make({}));
    for (const o of s.options) {
      if (o.default === null || TINY.includes(o.key)) continue;
      const given = spec.make({ [o.key]: literal(o.default) });
      assert.equal(steps(given), plain, `${name}: { ${o.key}: ${o.default} } differs from leaving it out`);
    }
  });
}

test('docs/api.md gives every option and event field as declared', () => {
  const doc = readFileSync(new URL('../../docs/api.md', import.meta.url), 'utf8');
  const shown = doc.slice(doc.indexOf(BEGIN), doc.indexOf(END) + END.length);
  assert.ok(shown.startsWith(BEGIN), 'docs/api.md has its generated part');
  assert.equal(shown, apiReference(schemas), 'docs/api.md is out of date: node scripts/make-typings.mjs pkg --docs');
});
