// The command line of bench/split.mjs and bench/processes.mjs: their options parsed with
// node:util's parseArgs (with --json and -h/--help added), checked, run, and the result's table
// printed, or with --json the result as JSON on stdout and the table on stderr. And the child
// processes of bench/heap.mjs and bench/processes.mjs (and its native runners), which answer with
// one line of JSON.
import { spawnSync } from 'node:child_process';
import { parseArgs } from 'node:util';

/**
 * Runs `node ...nodeArgs` and returns the JSON value on the last line of its output; throws,
 * beginning with `what` and ending with the last lines of its error output, if it fails.
 */
export function runJsonChild(nodeArgs, what) {
  return runJsonProgram(process.execPath, nodeArgs, what);
}

/** runJsonChild for any program: `file` run with `args`. */
export function runJsonProgram(file, args, what) {
  const child = spawnSync(file, args, { encoding: 'utf8', maxBuffer: 1 << 20 });
  if (child.status !== 0) {
    const why = child.error ? child.error.message : (child.stderr || child.stdout).trim().split('\n').slice(-3).join(' | ');
    throw new Error(`${what} failed: ${why}`);
  }
  const lines = child.stdout.trim().split('\n');
  return JSON.parse(lines[lines.length - 1]);
}

/**
 * Runs one bench command on `argv` (without node and the script): `options` are parseArgs specs,
 * `check(values)` throws on values the run would reject, `run(values)` resolves to the result and
 * `format(result)` is its table. Resolves to the exit code: 0, 1 when the run fails, 2 for a bad
 * command line (the message and `usage` on stderr).
 */
export async function runCommand(argv, { options, usage, check, run, format }) {
  let values;
  try {
    ({ values } = parseArgs({ args: argv, options: { ...options, json: { type: 'boolean' }, help: { type: 'boolean', short: 'h' } } }));
    if (!values.help) check(values);
  } catch (err) {
    process.stderr.write(`${err.message}\n\n${usage}\n`);
    return 2;
  }
  if (values.help) {
    process.stdout.write(`${usage}\n`);
    return 0;
  }
  let result;
  try {
    result = await run(values);
  } catch (err) {
    process.stderr.write(`${err.message}\n`);
    return 1;
  }
  const table = format(result);
  if (values.json) {
    process.stderr.write(`${table}\n`);
    process.stdout.write(`${JSON.stringify(result, null, 1)}\n`);
  } else {
    process.stdout.write(`${table}\n`);
  }
  return 0;
}
