// Reads layers with OpenUSD 22.11 (WASM, see load_usd.mjs) and prints, as JSON, each one as
// OpenUSD writes it in USDA (the root layer of a stage, not composed): the reference
// tests/usd_crate_test.cpp holds asset-lint's crate reader to.
//
//   node export_layers.mjs <three-usdz-loader package dir> <file>...
//   node export_layers.mjs <three-usdz-loader package dir> --to-crate <in.usda> <out.usd>
//
// Output of the first form: {"openusd": "22.11", "layers": [{"path", "usda" | null, "errors"}]}.
// The second form writes <in.usda> as a crate layer (OpenUSD's stage export, flattened), to
// make crate fixtures from small USDA ones.
import { readFileSync, writeFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { loadUsd } from './load_usd.mjs';

const startupNoise = /Failed to find plugin for schema type 'UsdVol/;

const [packageDir, ...args] = process.argv.slice(2);
let errors = [];
const usd = await loadUsd(packageDir, (text) => {
  if (!startupNoise.test(text) && text.trim() !== '') errors.push(text.trim());
});

function place(path) {
  usd.FS.mkdirTree(path.substring(0, path.lastIndexOf('/')));
  usd.FS.writeFile(path, readFileSync(path));
}

if (args[0] === '--to-crate') {
  const input = resolve(args[1]);
  const output = resolve(args[2]);
  place(input);
  const stage = usd.UsdStage.Open(input);
  usd.FS.mkdirTree(output.substring(0, output.lastIndexOf('/')));
  if (stage) stage.Export(output, false);
  if (!stage || !usd.FS.analyzePath(output).exists) {
    process.stderr.write(`cannot export ${input}: ${errors.join('\n')}\n`);
    process.exit(1);
  }
  writeFileSync(output, usd.FS.readFile(output));
  process.exit(0);
}

const files = args.map((a) => resolve(a));
for (const path of files) place(path);
const layers = [];
for (const path of files) {
  errors = [];
  let usda = null;
  try {
    const stage = usd.UsdStage.Open(path);
    if (stage) usda = stage.GetRootLayer().ExportToString();
  } catch (e) {
    errors.push(String(e));
  }
  layers.push({ path, usda, errors });
}
process.stdout.write(JSON.stringify({ openusd: '22.11', layers }));
process.exit(0);
