// Writes pkg/README.md, the npm page, from the repository's README.md: what the package is, its
// install and quick starts for the JS environments, the methods, and links to the documentation
// (absolute, since docs/ does not ship in the package). Run by scripts/build.sh.
//   node scripts/make-package-readme.mjs [pkg]
import { readFileSync, writeFileSync } from 'node:fs';
import { join, resolve } from 'node:path';

const ROOT = new URL('../', import.meta.url).pathname;
const REPO = 'https://github.com/texsynth/texsynth/blob/main/';
const pkg = resolve(process.argv[2] ?? join(ROOT, 'pkg'));
const readme = readFileSync(join(ROOT, 'README.md'), 'utf8');

/** The README's section from the heading `from` up to the heading `to`. */
function section(from, to) {
  const start = readme.indexOf(from);
  const end = readme.indexOf(to, start);
  if (start < 0 || end < 0) throw new Error(`README.md has no section "${from}" up to "${to}"`);
  return readme.slice(start, end);
}
const absolute = (text) => text.replace(/\]\((?!https?:|#)([^)]+)\)/g, (_, path) => `](${REPO}${path})`);

const quickStart = section('## Install and quick start', '### Rust')
  .replace(/<!-- quickstart: \S+ -->\n/g, '')
  .replace(/^cargo add texsynth.*\n/m, '')
  .replace(/^Every example below is run by the test command, as it is written here\.\n\n/m, '');
const out = [
  '# texsynth-wasm',
  '',
  'Texture synthesis in the browser, in Node and in Workers: large, seamless textures from a small',
  'example image, made step by step so that you can watch them form. Four papers (texture',
  'optimisation, graph-cut textures and video textures, texture design, feature-guided synthesis),',
  'written in Rust and compiled to WebAssembly; the same code is the Rust crate `texsynth`.',
  '',
  'Every method is a *session*: `new Class(inputs..., options)`, then `step()` until `done`; each',
  'step returns an event with its numbers, and `renderInto(imageData.data)` draws the output as it',
  'is. Sessions are iterable and have an async `run({ signal, onEvent })`. The TypeScript',
  'declarations cover every option, with its default, and every event.',
  '',
  quickStart.trimEnd(),
  '',
  absolute(section('## Methods', '## How it compares')).trimEnd(),
  '',
  absolute(section('## Documentation', '## Layout')).trimEnd(),
  '',
  '## Licence',
  '',
  'MIT or Apache-2.0, at your choice (`LICENSE-MIT` and `LICENSE-APACHE` in the package).',
  '',
].join('\n');
writeFileSync(join(pkg, 'README.md'), out);
console.log(`make-package-readme: ${join(pkg, 'README.md')} (${out.split('\n').length} lines)`);
