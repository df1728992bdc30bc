// Composes USDA layer stacks with OpenUSD 22.11 (WASM, see load_usd.mjs) and prints, as JSON,
// each stack flattened to one USDA text: the reference tests/usd_reference_test.cpp holds
// asset-lint's composition to.
//
//   node flatten.mjs <three-usdz-loader package dir> <dir>...
//
// Every .usda and crate .usd file under each <dir> is written into OpenUSD's in-memory file
// system at its own absolute path (so relative asset paths between them resolve as on disk),
// then each .usda file is opened as the root layer of a stage and flattened. Output: {"openusd": version,
// "stages": [{"path", "flattened" | null, "errors": [OpenUSD's messages]}]}.
import { readdirSync, readFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { loadUsd } from './load_usd.mjs';

function layerFiles(dir, extensions) {
  const found = [];
  for (const entry of readdirSync(dir, { withFileTypes: true })) {
    const path = join(dir, entry.name);
    if (entry.isDirectory()) found.push(...layerFiles(path, extensions));
    else if (entry.isFile() && extensions.some((e) => entry.name.endsWith(e))) found.push(path);
  }
  return found.sort();
}

// Messages about schema plugins this WASM build leaves out (UsdVol): said once at start-up
// for every stage, unrelated to the layers opened.
const startupNoise = /Failed to find plugin for schema type 'UsdVol/;

const [packageDir, ...dirs] = process.argv.slice(2);
let errors = [];
const usd = await loadUsd(packageDir, (text) => {
  if (!startupNoise.test(text) && text.trim() !== '') errors.push(text.trim());
});

const files = dirs.flatMap((dir) => layerFiles(resolve(dir), ['.usda']));
for (const path of dirs.flatMap((dir) => layerFiles(resolve(dir), ['.usda', '.usd']))) {
  usd.FS.mkdirTree(path.substring(0, path.lastIndexOf('/')));
  usd.FS.writeFile(path, readFileSync(path));
}

const stages = [];
for (const path of files) {
  errors = [];
  let flattened = null;
  try {
    const stage = usd.UsdStage.Open(path);
    if (stage) flattened = stage.ExportToString();
  } catch (e) {
    errors.push(String(e));
  }
  stages.push({ path, flattened, errors });
}
process.stdout.write(JSON.stringify({ openusd: '22.11', stages }));
process.exit(0);
