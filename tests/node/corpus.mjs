// The bad-input corpus as one list of rows [what, call, expectation], generated from the table of
// sessions.mjs (every option of every session type times the wrong values of bad_values.mjs, the
// options object itself, the life cycle: freed, finished) plus the positional arguments of
// bad_calls.mjs. An expectation is 'ok' (must return), a string or RegExp (must throw a JS Error
// whose message contains or matches it), { either } (that error, or a normal return), or
// 'no-trap' (a normal return or any JS Error: for methods called blindly by reflection).
import { api } from './fixtures.mjs';
import { BAD_CALLS } from './bad_calls.mjs';
import { BAD_OPTIONS, BAD_VALUES, EITHER, EITHER_SIZE, NAMED, badEnum } from './bad_values.mjs';
import { SESSIONS, exercise, inputFor } from './sessions.mjs';

/** A budget refusal is a documented answer to any size: it names the budget option. */
const BUDGET = 'memoryBudgetMiB';

const describe = (v) => {
  if (typeof v === 'string') return JSON.stringify(v);
  if (ArrayBuffer.isView(v)) return `${v.constructor.name}(${v.length})`;
  if (Array.isArray(v)) return v.length > 4 ? `Array(${v.length})` : `[${v.map(describe).join(', ')}]`;
  if (v && typeof v === 'object') return JSON.stringify(v);
  return String(v);
};

/** Makes the session (or calls the function) and, when it is a session, drives it a little. */
function makeAndDrive(spec, options) {
  const made = spec.make(options);
  if (made && typeof made.step === 'function') (spec.exercise ?? exercise)(made);
  return made;
}

function optionRows(kind, spec) {
  const rows = [];
  for (const [key, type] of Object.entries(spec.options)) {
    const values = type.special ?? (type.enum ? badEnum() : BAD_VALUES[type]);
    if (!values) throw new Error(`sessions.mjs: ${kind}.${key} has an unknown kind ${JSON.stringify(type)}`);
    for (const [value, expect] of values) {
      const expectation = {
        [NAMED]: key,
        [EITHER]: { either: key },
        [EITHER_SIZE]: { either: new RegExp(`${key}|output size|the output|the frame|patch size`) },
      }[expect] ?? expect;
      rows.push([`${kind} { ${key}: ${describe(value)} }`, () => makeAndDrive(spec, { [key]: value }), expectation]);
    }
  }
  if (spec.noOptions) return rows;
  for (const [value, what, message] of BAD_OPTIONS) {
    rows.push([`${kind} with ${what} for options`, () => makeAndDrive(spec, value), message]);
  }
  return rows;
}

/** A finished session steps again, a freed one is used: documented results, never a trap. */
function lifeCycleRows(kind, spec) {
  const probe = spec.make({});
  const isSession = probe && typeof probe.step === 'function';
  probe?.free?.();
  if (!isSession) return [];
  return [
    [`${kind}: step after done`, () => {
      const s = spec.make({});
      for (let i = 0; i < 5000 && !s.done; i++) s.step();
      if (!s.done) throw new Error('did not finish in 5000 steps');
      const again = s.step();
      if (again.done !== true) throw new Error(`a step after done returned done = ${again.done}`);
    }, 'ok'],
    [`${kind}: step on a freed session`, () => {
      const s = spec.make({});
      s.free();
      s.step();
    }, 'null pointer passed to rust'],
    [`${kind}: render of a freed session`, () => {
      const s = spec.make({});
      const { width, height } = s;
      s.free();
      s.renderInto(new Uint8ClampedArray(width * height * 4));
    }, 'null pointer passed to rust'],
    // wasm-bindgen's own check: the second free() is an Error, not a double free.
    [`${kind}: free twice`, () => {
      const s = spec.make({});
      s.free();
      s.free();
    }, 'null pointer passed to rust'],
    [`${kind}: renderInto(null) leaves the session usable`, () => {
      const s = spec.make({});
      try {
        s.renderInto(null);
      } catch (error) {
        if (!(error instanceof Error)) throw error;
      }
      exercise(s); // a JS exception thrown through Rust must not leave the session borrowed
    }, 'ok'],
  ];
}

/** Every method of a session type's prototype, found by reflection, so that a method added later
 * is covered without a line here: called with no arguments it must not trap; a view that renders
 * into a buffer refuses a short one and `null`, by name. */
function methodRows(kind, spec) {
  const probe = spec.make({});
  if (!probe || typeof probe.free !== 'function') return [];
  const proto = Object.getPrototypeOf(probe);
  probe.free();
  const skip = new Set(['constructor', 'free', 'run', '__destroy_into_raw']);
  const names = Object.getOwnPropertyNames(proto).filter((name) =>
    !skip.has(name) && typeof Object.getOwnPropertyDescriptor(proto, name).value === 'function');
  const rows = [];
  for (const name of names) {
    rows.push([`${kind}.${name}() with no arguments`, () => spec.make({})[name](), 'no-trap']);
    if (!/^render|Into$/.test(name)) continue;
    // renderFrameInto, renderSeamsInto and renderSliceXtInto take a frame or row first, and
    // transferInto the image to transfer (one of the session's exemplar size).
    const first = (s) => (name === 'transferInto' ? inputFor(kind) : kind === 'VideoTextures' && /^render(Frame|Seams|SliceXt)Into$/.test(name) ? 0 : undefined);
    const call = (s, buffer) => {
      const lead = first(s);
      return lead === undefined ? s[name](buffer) : s[name](lead, buffer);
    };
    rows.push([`${kind}.${name} into a short buffer`, () => call(spec.make({}), new Uint8ClampedArray(3)), /target pixel array|length/]);
    rows.push([`${kind}.${name} into null`, () => call(spec.make({}), null), 'target']);
  }
  return rows;
}

const freedExemplarRows = [
  ['a freed Exemplar passed to a session', () => {
    const e = api.Exemplar.fromBytes(new Uint8Array(readPng()));
    e.free();
    return new api.TextureOptimization(e, {});
  }, 'null pointer passed to rust'],
];
function readPng() {
  return api.Exemplar.fromRgba(new Uint8Array(64).fill(90), 4, 4).toPng();
}

export function corpusRows() {
  const rows = [];
  for (const [kind, spec] of Object.entries(SESSIONS)) {
    rows.push(...optionRows(kind, spec), ...lifeCycleRows(kind, spec), ...methodRows(kind, spec));
  }
  rows.push(...freedExemplarRows, ...BAD_CALLS);
  return rows;
}

/**
 * Runs one row: { outcome: 'ok' | 'error' | 'trap' | 'non-error', message, ms, pass, why }. A
 * trap is a `WebAssembly.RuntimeError` (a Rust panic or an out-of-bounds access): always a failure.
 */
export function runRow([, call, expectation]) {
  const start = performance.now();
  let outcome = 'ok';
  let message = '';
  try {
    call();
  } catch (error) {
    message = String(error?.message ?? error);
    outcome = error instanceof WebAssembly.RuntimeError ? 'trap' : error instanceof Error ? 'error' : 'non-error';
  }
  const ms = performance.now() - start;
  const matches = (want) => (want instanceof RegExp ? want.test(message) : message.includes(want));
  let pass;
  if (expectation === 'ok') pass = outcome === 'ok';
  else if (expectation === 'no-trap') pass = outcome === 'ok' || outcome === 'error';
  else if (expectation?.either !== undefined) {
    pass = outcome === 'ok' || (outcome === 'error' && (matches(expectation.either) || message.includes(BUDGET)));
  } else pass = outcome === 'error' && matches(expectation);
  const want = expectation === 'ok' ? 'no error' : expectation === 'no-trap' ? 'no trap' : expectation?.either !== undefined
    ? `no error, or an Error naming ${expectation.either}` : `an Error naming ${expectation}`;
  return { outcome, message, ms, pass, why: pass ? '' : `wanted ${want}; got ${outcome}${message ? `: ${message}` : ''}` };
}
