// node bench/accuracy/merge.mjs BASE.json EXTRA.json... [--out DIR]: the study in BASE with the
// scenes and the stability limits of the runs EXTRA put in place of BASE's (a scene by its id,
// limits by their method), then written as run.mjs writes a study (accuracy.json, accuracy.md,
// the charts; DIR defaults to BASE's folder). For parts run apart: limits searched elsewhere,
// e.g. every GPU method's on a real GPU, one process a method (run.mjs --scenes '' --methods ''
// --gpu --gpu-methods M), where a GPU limit keeps the device it was found on; or new scenes run
// on the machine of BASE (run.mjs --scenes NEW --no-limits).
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { parseArgs } from 'node:util';
import { pathToFileURL } from 'node:url';
import { writeAccuracy } from './run.mjs';

/** `base` with the scenes and limits of each of `extras` replacing base's of the same scene or method. */
export function mergeStudies(base, extras) {
  const limits = [...base.limits];
  const scenes = [...base.scenes];
  const methods = [...base.methods];
  for (const extra of extras) {
    for (const scene of extra.scenes) {
      const at = scenes.findIndex((s) => s.id === scene.id);
      if (at >= 0) scenes[at] = scene;
      else scenes.push(scene);
    }
    for (const m of extra.methods) if (!methods.some((x) => x.id === m.id)) methods.push(m);
    const owners = new Set(extra.limits.map((l) => l.method));
    const device = extra.machine.gpu?.device ?? null;
    for (let i = limits.length - 1; i >= 0; --i) if (owners.has(limits[i].method)) limits.splice(i, 1);
    for (const l of extra.limits) limits.push(l.method.startsWith('webgpu ') && device !== null ? { ...l, device } : l);
  }
  return { ...base, scenes, methods, limits };
}

async function main() {
  const { values, positionals } = parseArgs({ options: { out: { type: 'string' } }, allowPositionals: true });
  if (positionals.length < 2) throw new Error('usage: node bench/accuracy/merge.mjs BASE.json EXTRA.json... [--out DIR]');
  const [base, ...extras] = positionals.map((file) => JSON.parse(readFileSync(file, 'utf8')));
  const dir = values.out ?? path.dirname(positionals[0]);
  for (const f of writeAccuracy(mergeStudies(base, extras), dir)) process.stderr.write(`wrote ${path.relative(process.cwd(), f)}\n`);
}

if (import.meta.url === pathToFileURL(process.argv[1] ?? '').href) {
  main().catch((e) => {
    process.stderr.write(`${e instanceof Error ? e.message : e}\n`);
    process.exit(1);
  });
}
