/*
 * Command-line options as the `webphysics` subcommands take them: `--name value`, `--name=value`,
 * flags (`--help`, `-h`), positionals, and `--` to end the options. Errors are CliErrors with
 * the usage exit code and a one-line message.
 */

import { CliError, EXIT_USAGE } from './command';

export interface OptionSpec {
  /** The long name, without the dashes (`steps` for --steps). */
  readonly name: string;
  /** Does the option take a value (`--steps 10`), or is it a flag (`--help`)? */
  readonly takesValue: boolean;
  /** A one-letter alias (`h` for -h). */
  readonly short?: string;
}

export interface ParsedOptions {
  /** The value of each option given (the last one when repeated), true for flags. */
  readonly values: Map<string, string | true>;
  readonly positionals: string[];
}

function usageError(message: string, seeHelp: string): never {
  throw new CliError(`${message} (${seeHelp})`, EXIT_USAGE);
}

/** Parse `args` against `specs`; `seeHelp` ends each error message (`see webphysics run --help`). */
export function parseOptions(args: readonly string[], specs: readonly OptionSpec[], seeHelp: string): ParsedOptions {
  const values = new Map<string, string | true>();
  const positionals: string[] = [];
  for (let i = 0; i < args.length; ++i) {
    const arg = args[i];
    if (arg === '--') {
      positionals.push(...args.slice(i + 1));
      break;
    }
    if (!arg.startsWith('-') || arg === '-') {
      positionals.push(arg);
      continue;
    }
    const long = arg.startsWith('--');
    const equals = arg.indexOf('=');
    const key = long ? arg.slice(2, equals < 0 ? undefined : equals) : arg.slice(1);
    const spec = specs.find((s) => (long ? s.name === key : s.short === key));
    if (spec === undefined || (!long && equals >= 0)) {
      usageError(`unknown option ${long ? `--${key}` : arg}`, seeHelp);
    }
    if (!spec.takesValue) {
      if (long && equals >= 0) usageError(`--${spec.name} takes no value`, seeHelp);
      values.set(spec.name, true);
    } else if (long && equals >= 0) {
      values.set(spec.name, arg.slice(equals + 1));
    } else if (i + 1 < args.length) {
      values.set(spec.name, args[++i]);
    } else {
      usageError(`--${spec.name} needs a value`, seeHelp);
    }
  }
  return { values, positionals };
}
