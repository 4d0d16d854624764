// Bundles the viewer (src/main.js + three.js) into one minified script: node build.mjs OUTFILE.
// CMake runs it at build time (apps/ssimarch/CMakeLists.txt) and embeds the result in the binary.
import { build } from 'esbuild';

const outfile = process.argv[2] || 'dist/viewer.js';
await build({
  entryPoints: ['src/main.js'],
  bundle: true,
  minify: true,
  format: 'iife',
  target: 'es2020',
  legalComments: 'none',
  logLevel: 'warning',
  outfile,
});
