// Loads OpenUSD 22.11 compiled to WASM (the npm package three-usdz-loader, external/emHdBindings.*)
// into Node 20 without touching the package.
//
// The build is meant for browsers and uses pthreads. In Node its loader takes the Node path
// (worker_threads for the threads), but its data package (OpenUSD's plugInfo and schemas)
// is placed relative to `location` and fetched over HTTP unless `getPreloadedPackage`
// returns the bytes; the same holds in every worker, whose main script is therefore
// pthread_main.cjs, which sets both up before evaluating the real script.
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));

function arrayBufferOf(bytes) {
  return bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
}

// Resolves to the module (UsdStage, FS, ...). OpenUSD's diagnostics go to `onError`.
export async function loadUsd(packageDir, onError) {
  const dir = join(resolve(packageDir), 'external');
  process.env.ASSET_LINT_USD_WASM_DIR = dir;
  globalThis.location = { pathname: '/' };
  const factory = createRequire(import.meta.url)(join(dir, 'emHdBindings.js'));
  const data = readFileSync(join(dir, 'emHdBindings.data'));
  return factory({
    wasmBinary: readFileSync(join(dir, 'emHdBindings.wasm')),
    getPreloadedPackage: () => arrayBufferOf(data),
    mainScriptUrlOrBlob: join(here, 'pthread_main.cjs'),
    print: () => {},
    printErr: onError,
  });
}
