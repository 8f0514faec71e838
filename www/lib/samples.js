// The built-in sample textures (copied from the shared CC0 / public-domain set; see samples/SOURCES.md).
export const SAMPLES = [
  'brick', 'grass', 'gravel', 'sand', 'ballast', 'tiles',
  'paving', 'stone', 'dirt', 'planks', 'jungle', 'rock', 'carpet', 'squares', 'potatoes', 'roof',
].flatMap((name) => [
  { id: `${name}_64`, label: `${name} 64×64`, url: `./samples/${name}_64.png` },
  { id: `${name}_128`, label: `${name} 128×128`, url: `./samples/${name}_128.png` },
]);
