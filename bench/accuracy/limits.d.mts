// Types for bench/accuracy/limits.mjs.

export interface LimitOptions {
  /** Integer values (the limit is exact). */
  integer?: boolean;
  /** Find the smallest passing value instead of the largest. */
  smallest?: boolean;
  /** Width of the final bracket (default 1e-3 of the range; 1 for integers). */
  tolerance?: number;
}

export interface LimitResult {
  limit: number | null;
  tests: number;
  /** The last passing and the first failing value tested; null when the limit is outside the range. */
  bracket: [number, number] | null;
  outside: 'below' | 'above' | null;
}

export function bisectLimit(passes: (x: number) => boolean | Promise<boolean>, lo: number, hi: number, options?: LimitOptions): Promise<LimitResult>;
