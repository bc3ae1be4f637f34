// One simplification by meshoptimizer's WebAssembly build (the npm package `meshoptimizer`,
// pinned in package.json and package-lock.json), for Tools/MeshOptimizerJS.cxx.
//
//   node simplify.mjs --version    (prints {"meshoptimizer": VERSION, "node": VERSION})
//   node simplify.mjs MODE INPUT OUTPUT --target-index-count N [--target-error E]
//                     [--weights W,W,W]
//
// MODE: attributes (simplifyWithAttributes), update (simplifyWithUpdate: the kept vertices'
// positions and attributes are moved), prune (simplifyWithAttributes with the Prune flag:
// small disconnected pieces may be removed whole). The per-vertex colour (RGB in [0,1]) is
// the 3 attributes, each with its weight (1 by default); no vertex is locked and LockBorder
// is off (meshoptimizer's default behaviour).
//
// INPUT (little-endian): "CDMJ", uint32 vertex count n, uint32 index count m; float32
// positions [3n], float32 colours [3n], uint32 indices [m].
// OUTPUT: "CDMJ", uint32 n' (n in update mode, else 0), uint32 index count k; uint32 indices
// [k]; in update mode float32 positions [3n] and colours [3n] of every input vertex.
// Prints one JSON line: the times (seconds: wall clock around the simplify call alone,
// performance.now(); cpu_seconds: process.cpuUsage() over the same span), result_error,
// the index count and the memory figures.
//
// MeshOptimizerJS.cxx runs it as `node --no-liftoff --no-wasm-lazy-compilation simplify.mjs
// ...`, so that V8 compiles the whole WebAssembly module with its optimising compiler when it
// is loaded, before the call. By default V8 compiles each function at its first call with its
// baseline compiler, and one long call runs that slower code to its end (the same result;
// docs/BENCHMARK.md, "The set-up against the loop").
//
// Exit status: 0 done, 2 bad command line or input, 3 the package is missing or not the
// pinned version.
import { readFileSync, writeFileSync } from 'node:fs';
import { performance } from 'node:perf_hooks';

const PINNED = '1.3.0';
const MAGIC = 0x4a4d4443; // "CDMJ" read as a little-endian uint32
const FUNCTIONS = {
  attributes: 'simplifyWithAttributes',
  update: 'simplifyWithUpdate',
  prune: 'simplifyWithAttributes',
};
const FLAGS = { attributes: [], update: [], prune: ['Prune'] };
const INSTALL = 'npm ci --prefix Tools/MeshOptimizerJS';

function fail(status, message) {
  process.stderr.write(`simplify.mjs: ${message}\n`);
  process.exit(status);
}

/// The installed package's version; exits with status 3 when it is missing or not pinned.
function packageVersion() {
  let version;
  try {
    // The package's exports leave its package.json out: read it from node_modules.
    const file = new URL('node_modules/meshoptimizer/package.json', import.meta.url);
    version = JSON.parse(readFileSync(file)).version;
  } catch {
    fail(3, `the npm package meshoptimizer is not installed (${INSTALL})`);
  }
  if (version !== PINNED) {
    fail(3, `meshoptimizer ${version} is installed, not the pinned ${PINNED} (${INSTALL})`);
  }
  return version;
}

function parseArguments(argv) {
  const [mode, input, output, ...rest] = argv;
  if (!(mode in FUNCTIONS) || !input || !output) {
    fail(2, 'usage: simplify.mjs attributes|update|prune INPUT OUTPUT --target-index-count N ' +
      '[--target-error E] [--weights W,W,W]');
  }
  const args = { mode, input, output, targetIndexCount: -1, targetError: 1, weights: [1, 1, 1] };
  for (let i = 0; i < rest.length; i += 2) {
    const value = rest[i + 1];
    if (rest[i] === '--target-index-count') args.targetIndexCount = Number(value);
    else if (rest[i] === '--target-error') args.targetError = Number(value);
    else if (rest[i] === '--weights') args.weights = String(value).split(',').map(Number);
    else fail(2, `unknown option '${rest[i]}'`);
  }
  const count = args.targetIndexCount;
  const weights = args.weights.length === 3 && args.weights.every((w) => w >= 0);
  if (!Number.isInteger(count) || count < 0 || count % 3 || !(args.targetError >= 0) || !weights) {
    fail(2, 'bad --target-index-count (a multiple of 3), --target-error or --weights ' +
      '(3 numbers >= 0)');
  }
  return args;
}

/// The mesh of INPUT as typed arrays (copied, so that they are aligned and writable).
function readMesh(path) {
  const file = readFileSync(path);
  const header = new Uint32Array(file.buffer.slice(file.byteOffset, file.byteOffset + 12));
  const [magic, n, m] = header;
  if (magic !== MAGIC || file.length !== 12 + 24 * n + 4 * m || m % 3) {
    fail(2, `${path} is not a mesh file of this tool`);
  }
  const data = file.buffer.slice(file.byteOffset + 12, file.byteOffset + file.length);
  return {
    positions: new Float32Array(data, 0, 3 * n),
    colors: new Float32Array(data, 12 * n, 3 * n),
    indices: new Uint32Array(data, 24 * n, m),
  };
}

function writeResult(path, indices, updated) {
  const n = updated ? updated.positions.length / 3 : 0;
  const parts = [new Uint32Array([MAGIC, n, indices.length]), indices];
  if (updated) parts.push(updated.positions, updated.colors);
  const bytes = parts.map((a) => Buffer.from(a.buffer, a.byteOffset, a.byteLength));
  writeFileSync(path, Buffer.concat(bytes));
}

/// The simplify call of `args.mode`: its indices (the kept triangles) and result_error.
function simplify(MeshoptSimplifier, args, mesh) {
  const { positions, colors, indices } = mesh;
  const rest = [args.weights, null, args.targetIndexCount, args.targetError, FLAGS[args.mode]];
  if (args.mode === 'update') {
    const [count, error] = MeshoptSimplifier.simplifyWithUpdate(
      indices, positions, 3, colors, 3, ...rest);
    return [indices.subarray(0, count), error];
  }
  return MeshoptSimplifier.simplifyWithAttributes(indices, positions, 3, colors, 3, ...rest);
}

async function main() {
  const version = packageVersion();
  if (process.argv[2] === '--version') {
    const versions = { meshoptimizer: version, node: process.version };
    process.stdout.write(JSON.stringify(versions) + '\n');
    return;
  }
  const args = parseArguments(process.argv.slice(2));
  const mesh = readMesh(args.input);
  if (args.targetIndexCount > mesh.indices.length) {
    fail(2, '--target-index-count above the index count');
  }
  const { MeshoptSimplifier } = await import('meshoptimizer/simplifier');
  await MeshoptSimplifier.ready;
  const rssBefore = process.memoryUsage().rss;
  const cpu = process.cpuUsage();
  const start = performance.now();
  const [kept, error] = simplify(MeshoptSimplifier, args, mesh);
  const seconds = (performance.now() - start) / 1000;
  const used = process.cpuUsage(cpu);
  const maxRss = process.resourceUsage().maxRSS * 1024;
  writeResult(args.output, kept, args.mode === 'update' ? mesh : null);
  const figures = {
    meshoptimizer: version,
    function: FUNCTIONS[args.mode],
    flags: FLAGS[args.mode],
    node: process.version,
    node_flags: process.execArgv,
    seconds,
    cpu_seconds: (used.user + used.system) / 1e6,
    result_error: error,
    index_count: kept.length,
    target_index_count: args.targetIndexCount,
    target_error: args.targetError,
    weights: args.weights,
    rss_before_bytes: rssBefore,
    max_rss_bytes: maxRss,
  };
  process.stdout.write(JSON.stringify(figures) + '\n');
}

await main();
