/*
 * Summary statistics for step timings.
 */

/**
 * The p-quantile (p in [0, 1]) of ascending `sorted` values by the nearest-rank method: the
 * smallest value with at least p of the values at or below it. NaN when there are none.
 */
export function percentile(sorted: ArrayLike<number>, p: number): number {
  const n = sorted.length;
  if (n === 0) return NaN;
  const rank = Math.ceil(p * n);
  return sorted[rank < 1 ? 0 : rank - 1];
}
