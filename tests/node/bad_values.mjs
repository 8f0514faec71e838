// The wrong (and the edge) values tried for each kind of option of sessions.mjs, with what each
// must give: NAMED, a JS Error whose message names the option; EITHER, that error or a session
// that then steps and renders without fault (a documented result: e.g. a 1x1 output, r = 0).
import { BOOL, BUDGET, COUNT, COUNTS, REAL, REALS, SEED, SIZE } from './sessions.mjs';

export const NAMED = 'named';
export const EITHER = 'either';
/** Like EITHER, for a size: the error may instead name the output size or a size that must fit
 * into it (a 1-pixel output is too small for any neighbourhood; 2^20 is over the 8192 limit). */
export const EITHER_SIZE = 'either-size';

const notNumbers = [[NaN, NAMED], [Infinity, NAMED], [-Infinity, NAMED], ['8', NAMED], [{}, NAMED], [true, NAMED], [[8], NAMED]];

export const BAD_VALUES = {
  [SIZE]: [...notNumbers, [-1, NAMED], [0, NAMED], [2.5, NAMED], [1e12, NAMED], [1, EITHER_SIZE], [1 << 20, EITHER_SIZE], [8192, EITHER_SIZE]],
  [COUNT]: [...notNumbers, [-1, NAMED], [0.5, NAMED], [1e12, NAMED], [0, EITHER], [1, EITHER], [1 << 16, EITHER]],
  [SEED]: [...notNumbers, [-1, NAMED], [0.5, NAMED], [2 ** 53, NAMED], [0, EITHER], [2 ** 32 - 1, EITHER]],
  [REAL]: [...notNumbers, [-1, EITHER], [0, EITHER], [1e-300, EITHER], [1e30, EITHER], [-1e30, EITHER], [Number.MAX_VALUE, EITHER]],
  [BOOL]: [['yes', NAMED], [1, NAMED], [{}, NAMED], [false, EITHER]],
  [BUDGET]: [...notNumbers, [0, NAMED], [15, NAMED], [1e6, NAMED], [16, EITHER], [3584, EITHER]],
  [COUNTS]: [[8, NAMED], ['8,4', NAMED], [[NaN], NAMED], [[-1], NAMED], [[1.5], NAMED], [['8'], NAMED], [[], EITHER], [[0], EITHER], [[1], EITHER], [[1 << 16], EITHER], [new Array(100).fill(4), EITHER]],
  [REALS]: [[1, NAMED], [[NaN], NAMED], [['1'], NAMED], [[Infinity], NAMED], [[], EITHER], [[0], EITHER], [[-1], EITHER], [[1e9], EITHER], [[1e-9], EITHER], [[1, 1, 1, 1, 1], NAMED]],
};

/** Values for an enum option: names that are not one of its names. */
export const badEnum = () => [['nope', NAMED], [3, NAMED], ['', NAMED], [['patchmatch'], NAMED]];

/** The options object itself: not an object, and keys nobody knows. */
export const BAD_OPTIONS = [
  ['a string', 'not an object', 'options'],
  [42, 'a number', 'options'],
  [{ bogus: 1 }, 'an unknown key', "unknown option 'bogus'"],
  [{ OutputWidth: 8 }, 'a key in the wrong case', "unknown option 'OutputWidth'"],
];
