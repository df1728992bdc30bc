// The script each pthread worker of the OpenUSD build evaluates (the package's worker.js
// loads it as the "main script"). The build expects a browser: it reads `location` to place
// its data package and fetches the package unless Module.getPreloadedPackage hands it over.
// The package directory comes from the environment, which Node's workers share.
globalThis.location = { pathname: '/' };
{
  const fs = require('fs');
  const dir = process.env.ASSET_LINT_USD_WASM_DIR;
  Module.getPreloadedPackage = () => {
    const bytes = fs.readFileSync(dir + '/emHdBindings.data');
    return bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
  };
  eval.call(null, fs.readFileSync(dir + '/emHdBindings.js', 'utf8'));
}
