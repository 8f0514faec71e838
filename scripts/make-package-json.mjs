// Writes pkg/package.json from pkg.json (the package manifest kept at the repository root), after
// checking that its version matches Cargo.toml so the npm and crate versions never drift apart.
import { readFileSync, writeFileSync } from 'node:fs';

const manifest = JSON.parse(readFileSync('pkg.json', 'utf8'));
const cargo = readFileSync('Cargo.toml', 'utf8');
const crateVersion = /^version = "([^"]+)"/m.exec(cargo)[1];
if (manifest.version !== crateVersion) {
  console.error(`pkg.json version ${manifest.version} differs from Cargo.toml version ${crateVersion}`);
  process.exit(1);
}
writeFileSync('pkg/package.json', JSON.stringify(manifest, null, 2) + '\n');
