#!/usr/bin/env node
// The `webphysics` command (see src/cli/main.ts, or `webphysics --help`).
//
// In a checkout (src/ present, devDependencies installed by `npm ci`) it bundles src/cli/main.ts in
// memory with esbuild, so it always runs the working tree's code, with no build step. In the
// published package (no src/) it runs the prebuilt dist/cli.mjs.
import { existsSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const packageRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');

async function loadFromSource(entry) {
  let esbuild;
  try {
    esbuild = await import('esbuild');
  } catch {
    return null;
  }
  const result = await esbuild.build({
    entryPoints: [entry],
    bundle: true,
    platform: 'node',
    format: 'esm',
    target: 'node20',
    write: false,
    sourcemap: 'inline',
    logLevel: 'silent',
  });
  const code = Buffer.from(result.outputFiles[0].contents).toString('base64');
  return import(`data:text/javascript;base64,${code}`);
}

async function loadCli() {
  const source = path.join(packageRoot, 'src/cli/main.ts');
  if (existsSync(source)) {
    const cli = await loadFromSource(source);
    if (cli !== null) return cli;
  }
  const built = path.join(packageRoot, 'dist/cli.mjs');
  if (existsSync(built)) return import(pathToFileURL(built).href);
  throw new Error(
    existsSync(source) ? 'cannot run from source without esbuild: run `npm ci` first (or `npm run build`)' : 'dist/cli.mjs is missing: reinstall the package',
  );
}

let cli;
try {
  cli = await loadCli();
} catch (e) {
  process.stderr.write(`webphysics: ${String(e instanceof Error ? e.message : e).replace(/\s*\n\s*/g, ' ')}\n`);
  process.exit(1);
}

process.exitCode = await cli.main(process.argv.slice(2), {
  stdout: process.stdout,
  stderr: process.stderr,
  cwd: process.cwd(),
  packageRoot,
});
