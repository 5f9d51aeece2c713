// Types for scripts/serve.mjs.
import type { Server } from 'node:http';

export interface ServedFolder {
  server: Server;
  port: number;
  url: string;
  /** Stops listening and ends the open connections. */
  close(): Promise<void>;
}

/** Serve a folder's files over HTTP on host:port (port 0: a free one). */
export function startServer(options: { root: string; port?: number; host?: string; log?: ((line: string) => void) | null }): Promise<ServedFolder>;
