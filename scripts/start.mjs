// npm start: build the demo pages (demos/: the testbed and the comparison page) with esbuild and
// serve them on localhost.
//
//   npm start                      # http://localhost:8080/ (the next free port if 8080 is taken)
//   npm start -- --port 3000       # or PORT=3000 npm start; a port given explicitly must be free
//   npm start -- --host 0.0.0.0    # listen on every interface (default: 127.0.0.1 only)
//   npm start -- --watch           # rebuild when demos/ or src/ change (reload the page)
import path from 'node:path';
import { buildDemos, defaultOutDir, repoRoot } from './build-demos.mjs';
import { startServer } from './serve.mjs';

function usage(message) {
  if (message) console.error(`npm start: ${message}`);
  console.error('usage: npm start -- [--port N] [--host H] [--watch]   (PORT=N also sets the port)');
  process.exit(2);
}

const args = process.argv.slice(2);
let port = process.env.PORT;
let host = '127.0.0.1';
let watch = false;
for (let i = 0; i < args.length; ++i) {
  const [flag, inline] = args[i].split(/=(.*)/s, 2);
  const value = () => inline ?? args[++i] ?? usage(`${flag} needs a value`);
  if (flag === '--port' || flag === '-p') port = value();
  else if (flag === '--host') host = value();
  else if (flag === '--watch') watch = true;
  else if (flag === '--help' || flag === '-h') usage();
  else usage(`unknown option ${args[i]}`);
}
const explicitPort = port !== undefined && port !== '';
const firstPort = explicitPort ? Number(port) : 8080;
if (!Number.isInteger(firstPort) || firstPort < 0 || firstPort > 65535) usage(`bad port ${port}`);

// Stop on Ctrl+C, SIGTERM or SIGHUP, and when the process that started this one is gone: npm runs
// this script through `sh -c`, and a SIGTERM or SIGINT sent to npm alone stops that shell, not
// this process. Stopping ends the server and its connections, the esbuild watcher (a child
// process) and this process, with status 0.
let served = null;
let watcher = null;
let stopping = false;
async function stop(why) {
  if (stopping) return;
  stopping = true;
  console.log(`npm start: stopping (${why})`);
  await Promise.all([served?.close(), watcher?.dispose()]);
  process.exit(0);
}
for (const signal of ['SIGINT', 'SIGTERM', 'SIGHUP']) process.on(signal, () => stop(signal));
const parent = process.ppid;
setInterval(() => {
  if (process.ppid !== parent) stop('its parent process exited');
}, 250).unref();

const started = Date.now();
try {
  watcher = await buildDemos(defaultOutDir, { watch });
} catch (error) {
  console.error(`npm start: the demo pages did not build: ${error.message}`);
  process.exit(1);
}
console.log(`Built the demo pages into ${path.relative(repoRoot, defaultOutDir)} in ${Date.now() - started} ms${watch ? ' (watching for changes)' : ''}`);

for (let candidate = firstPort; served === null; ++candidate) {
  try {
    served = await startServer({ root: defaultOutDir, port: candidate, host });
  } catch (error) {
    if (error.code === 'EADDRINUSE' && !explicitPort && candidate < firstPort + 20) continue;
    console.error(
      error.code === 'EADDRINUSE'
        ? `npm start: port ${candidate} is in use; choose another with --port N or PORT=N`
        : `npm start: cannot listen on ${host}:${candidate}: ${error.message}`,
    );
    process.exit(1);
  }
}
console.log(`WebPhysics testbed: ${served.url}   side by side: ${served.url}compare.html   large worlds: ${served.url}large.html   (Ctrl+C to stop)`);
