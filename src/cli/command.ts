/*
 * What a `webphysics` subcommand is, and how it reports errors. A command is registered in
 * ./main.ts (the `commands` list); main prints its help, dispatches to it and turns a thrown
 * CliError into one line on stderr and the error's exit code.
 */

/** Where a command writes, and where it runs. */
export interface CliContext {
  /** Standard output; `isTTY` says whether it is a terminal (for progress bars). */
  readonly stdout: { write(text: string): unknown; readonly isTTY?: boolean; readonly columns?: number };
  readonly stderr: { write(text: string): unknown };
  /** The folder relative paths are resolved against. */
  readonly cwd: string;
  /** The package's root folder (where package.json and scenes/ are). */
  readonly packageRoot: string;
}

export interface CliCommand {
  /** The subcommand word (`run`). */
  readonly name: string;
  /** One line for the command list of `webphysics --help`. */
  readonly summary: string;
  /** The full text of `webphysics <name> --help`. */
  readonly help: string;
  /** Run with the arguments after the subcommand word; resolves to the exit code. */
  run(args: string[], context: CliContext): Promise<number> | number;
}

/** Exit code for a wrong command line (unknown option, bad value). */
export const EXIT_USAGE = 2;
/** Exit code for a failure running a valid command line (missing file, bad scene). */
export const EXIT_FAILURE = 1;

/** An error to report as one line (`webphysics run: <message>`), exiting with `exitCode`. */
export class CliError extends Error {
  readonly exitCode: number;

  constructor(message: string, exitCode: number = EXIT_FAILURE) {
    super(message);
    this.name = 'CliError';
    this.exitCode = exitCode;
  }
}
