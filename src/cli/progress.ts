/*
 * A one-line progress bar for terminals, redrawn in place with a carriage return.
 */

const WIDTH = 30;

export class ProgressBar {
  private readonly out: { write(text: string): unknown };
  private readonly total: number;
  private shown = -1;

  constructor(out: { write(text: string): unknown }, total: number) {
    this.out = out;
    this.total = total;
  }

  /** Show `done` of the total finished; redraws only when the bar's percentage changes. */
  update(done: number): void {
    const percent = this.total === 0 ? 100 : Math.floor((100 * done) / this.total);
    if (percent === this.shown) return;
    this.shown = percent;
    const filled = Math.round((WIDTH * percent) / 100);
    this.out.write(`\r[${'#'.repeat(filled)}${'.'.repeat(WIDTH - filled)}] ${percent}% ${done}/${this.total} steps`);
  }

  /** Erase the bar, leaving the cursor at the start of the line. */
  done(): void {
    if (this.shown >= 0) this.out.write('\r\x1b[K');
  }
}
