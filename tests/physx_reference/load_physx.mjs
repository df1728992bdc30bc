// Loads the npm build of PhysX (physx-js-webidl, PhysX compiled to WASM) into Node.
//
// The package is built for browsers only: its loader refuses to start when it sees Node's
// `process` global and otherwise fetches the .wasm over HTTP. Both are sidestepped here
// without touching the package: the .wasm bytes are read from disk and handed over as
// `wasmBinary`, and for the synchronous start of the factory call `process` is hidden and
// `window` is defined, so the loader takes its browser path.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';

export async function loadPhysX(packageDir) {
  const { default: factory } = await import(pathToFileURL(join(packageDir, 'physx-js-webidl.mjs')).href);
  const wasmBinary = readFileSync(join(packageDir, 'physx-js-webidl.wasm'));
  const processDescriptor = Object.getOwnPropertyDescriptor(globalThis, 'process');
  const hadWindow = 'window' in globalThis;
  let pending;
  try {
    Object.defineProperty(globalThis, 'process', { value: undefined, configurable: true, writable: true });
    if (!hadWindow) globalThis.window = globalThis;
    pending = factory({ wasmBinary, print: () => {}, printErr: (text) => console.error(text) });
  } finally {
    Object.defineProperty(globalThis, 'process', processDescriptor);
    if (!hadWindow) delete globalThis.window;
  }
  return pending;
}

// PhysX encodes its version as 0xMMmmpp00.
export function versionString(PhysX) {
  const v = PhysX.PHYSICS_VERSION;
  return `${(v >>> 24) & 0xff}.${(v >>> 16) & 0xff}.${(v >>> 8) & 0xff}`;
}
