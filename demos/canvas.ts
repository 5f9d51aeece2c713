/*
 * What the demo pages' canvases share: a backing store that matches the element's CSS size times
 * the device pixel ratio, so that lines and text stay sharp on high-density screens.
 */

/** Matches `canvas`'s backing store to its CSS size (at least 1 x 1) times the device pixel ratio; returns both. */
export function fitCanvas(canvas: HTMLCanvasElement): { width: number; height: number; dpr: number } {
  const dpr = window.devicePixelRatio || 1;
  const rect = canvas.getBoundingClientRect();
  const width = Math.max(1, rect.width);
  const height = Math.max(1, rect.height);
  const bw = Math.round(width * dpr);
  const bh = Math.round(height * dpr);
  if (canvas.width !== bw || canvas.height !== bh) {
    canvas.width = bw;
    canvas.height = bh;
  }
  return { width, height, dpr };
}
