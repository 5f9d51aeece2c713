// node bench/accuracy/merge.mjs BASE.json EXTRA.json... [--out DIR]: the study in BASE with the
// stability limits of the runs EXTRA put in place of BASE's for the same methods, then written
// as run.mjs writes a study (accuracy.json, accuracy.md, the charts; DIR defaults to BASE's
// folder). For limits searched elsewhere, e.g. every GPU method's on a real GPU, one process a
// method (run.mjs --scenes '' --methods '' --gpu --gpu-methods M): a GPU limit keeps the device
// it was found on.
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { parseArgs } from 'node:util';
import { pathToFileURL } from 'node:url';
import { writeAccuracy } from './run.mjs';

/** `base` with the limits of each of `extras` replacing base's of the same methods. */
export function mergeLimits(base, extras) {
  const limits = [...base.limits];
  for (const extra of extras) {
    const owners = new Set(extra.limits.map((l) => l.method));
    const device = extra.machine.gpu?.device ?? null;
    for (let i = limits.length - 1; i >= 0; --i) if (owners.has(limits[i].method)) limits.splice(i, 1);
    for (const l of extra.limits) limits.push(l.method.startsWith('webgpu ') && device !== null ? { ...l, device } : l);
  }
  return { ...base, limits };
}

async function main() {
  const { values, positionals } = parseArgs({ options: { out: { type: 'string' } }, allowPositionals: true });
  if (positionals.length < 2) throw new Error('usage: node bench/accuracy/merge.mjs BASE.json EXTRA.json... [--out DIR]');
  const [base, ...extras] = positionals.map((file) => JSON.parse(readFileSync(file, 'utf8')));
  const dir = values.out ?? path.dirname(positionals[0]);
  for (const f of writeAccuracy(mergeLimits(base, extras), dir)) process.stderr.write(`wrote ${path.relative(process.cwd(), f)}\n`);
}

if (import.meta.url === pathToFileURL(process.argv[1] ?? '').href) {
  main().catch((e) => {
    process.stderr.write(`${e instanceof Error ? e.message : e}\n`);
    process.exit(1);
  });
}
