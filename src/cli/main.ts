/*
 * The `webphysics` command line: `webphysics <command> [arguments]`. bin/webphysics.mjs loads this
 * module (built as dist/cli.mjs, or bundled from source in a checkout) and calls main.
 *
 * To add a subcommand, write a CliCommand (see ./command.ts and ./run.ts) and list it in
 * `commands` below; --help, dispatch and error reporting come with it.
 */

import { readFileSync } from 'node:fs';
import path from 'node:path';
import { CliError, EXIT_FAILURE, EXIT_USAGE } from './command';
import type { CliCommand, CliContext } from './command';
import { benchCommand } from './bench';
import { runCommand } from './run';

export type { CliCommand, CliContext } from './command';
export { CliError, EXIT_FAILURE, EXIT_USAGE } from './command';

/** The subcommands, in the order --help lists them. */
export const commands: CliCommand[] = [runCommand, benchCommand];

function findCommand(name: string): CliCommand | undefined {
  return commands.find((c) => c.name === name);
}

function overview(): string {
  const width = Math.max(...commands.map((c) => c.name.length));
  const list = commands.map((c) => `  ${c.name.padEnd(width)}  ${c.summary}`).join('\n');
  return `usage: webphysics <command> [arguments]

WebPhysics: Box2D 2.2.1 for the web, bit for bit, with the Box2DWeb API.

commands:
${list}

  webphysics <command> --help   help for a command
  webphysics --version          the package version
`;
}

function version(packageRoot: string): string {
  const pkg = JSON.parse(readFileSync(path.join(packageRoot, 'package.json'), 'utf8')) as { version?: string };
  return pkg.version ?? 'unknown';
}

/** Run the command line `argv` (the arguments after `webphysics`); resolves to the exit code. */
export async function main(argv: string[], context: CliContext): Promise<number> {
  const [first, ...rest] = argv;
  let prefix = 'webphysics';
  try {
    if (first === undefined || first === '-h' || first === '--help') {
      context.stdout.write(overview());
      return 0;
    }
    if (first === '--version' || first === '-v') {
      context.stdout.write(`${version(context.packageRoot)}\n`);
      return 0;
    }
    if (first === 'help') {
      const topic = rest[0] === undefined ? undefined : findCommand(rest[0]);
      if (rest[0] !== undefined && topic === undefined) {
        throw new CliError(`unknown command ${JSON.stringify(rest[0])} (see webphysics --help)`, EXIT_USAGE);
      }
      context.stdout.write(topic === undefined ? overview() : topic.help);
      return 0;
    }
    const command = findCommand(first);
    if (command === undefined) {
      throw new CliError(
        first.startsWith('-') ? `unknown option ${first} (see webphysics --help)` : `unknown command ${JSON.stringify(first)} (see webphysics --help)`,
        EXIT_USAGE,
      );
    }
    prefix = `webphysics ${command.name}`;
    return await command.run(rest, context);
  } catch (e) {
    const message = e instanceof Error ? e.message : String(e);
    const exitCode = e instanceof CliError ? e.exitCode : EXIT_FAILURE;
    // One line, whatever the message holds.
    context.stderr.write(`${prefix}: ${message.replace(/\s*\n\s*/g, ' ')}\n`);
    return exitCode;
  }
}
