/*
 * `npm start` (scripts/start.mjs) stops when asked: its server, its esbuild watcher and itself,
 * whether the signal reaches it directly (Ctrl+C) or only npm, which runs it through `sh -c`, so
 * that a SIGTERM to npm stops the shell and not the script. A process of the tree still alive
 * keeps the output pipes open, so the pipes' end is the proof that every process has exited.
 */

import { spawn } from 'node:child_process';
import type { ChildProcess } from 'node:child_process';
import { get } from 'node:http';
import { afterEach, describe, expect, it } from 'vitest';
import { repoRoot } from '../../scripts/build-demos.mjs';

const groups: number[] = [];

afterEach(() => {
  for (const group of groups.splice(0)) {
    try {
      process.kill(-group, 'SIGKILL');
    } catch (error) {
      if ((error as NodeJS.ErrnoException).code !== 'ESRCH') throw error;
    }
  }
});

interface Started {
  child: ChildProcess;
  url: string;
  /** stdout and stderr so far, together. */
  output(): string;
  /** Resolves when both pipes have ended, with the output and the child's exit status or signal. */
  ended: Promise<{ output: string; code: number | null; signal: NodeJS.Signals | null }>;
}

/** Spawns `command args` in the checkout and waits for the server's address. */
function start(command: string, args: string[]): Promise<Started> {
  // Its own process group, which afterEach kills whole should a process outlive a failed test.
  const child = spawn(command, args, { cwd: repoRoot, stdio: ['ignore', 'pipe', 'pipe'], detached: true });
  groups.push(child.pid!);
  let output = '';
  const pipeEnded = (stream: NodeJS.ReadableStream) => new Promise<void>((resolve) => stream.on('end', resolve));
  const exited = new Promise<[number | null, NodeJS.Signals | null]>((resolve) => child.on('exit', (code, signal) => resolve([code, signal])));
  const ended = Promise.all([pipeEnded(child.stdout!), pipeEnded(child.stderr!), exited]).then(([, , [code, signal]]) => ({ output, code, signal }));
  return new Promise((resolve, reject) => {
    const onData = (data: Buffer) => {
      output += data.toString();
      const url = /WebPhysics testbed: (http:\/\/\S+)/.exec(output)?.[1];
      if (url !== undefined) resolve({ child, url, output: () => output, ended });
    };
    child.stdout!.on('data', onData);
    child.stderr!.on('data', onData);
    ended.then(() => reject(new Error(`it exited before serving:\n${output}`)));
  });
}

/** The status of GET url, or the error's code (ECONNREFUSED once the server is gone). */
function status(url: string): Promise<number | string> {
  return new Promise((resolve) => {
    get(url, (res) => {
      res.resume();
      resolve(res.statusCode ?? 0);
    }).on('error', (error: NodeJS.ErrnoException) => resolve(error.code ?? error.message));
  });
}

describe('npm start', () => {
  it('stops its server and exits when npm alone gets SIGTERM', async () => {
    const started = await start('npm', ['start', '--', '--port', '0']);
    expect(await status(started.url)).toBe(200);
    started.child.kill('SIGTERM');
    const { output } = await started.ended;
    expect(output).toContain('npm start: stopping (its parent process exited)');
    expect(await status(started.url)).toBe('ECONNREFUSED');
  });

  it('on Ctrl+C (SIGINT) closes the server and the watcher and exits with status 0', async () => {
    const started = await start(process.execPath, ['scripts/start.mjs', '--port', '0', '--watch']);
    expect(await status(started.url)).toBe(200);
    started.child.kill('SIGINT');
    const { output, code, signal } = await started.ended;
    expect(output).toContain('npm start: stopping (SIGINT)');
    expect([code, signal]).toEqual([0, null]);
    expect(await status(started.url)).toBe('ECONNREFUSED');
  });
});
