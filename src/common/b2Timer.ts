// The host's monotonic clock where it has one (browsers, Node, Deno), else the wall clock.
const now: () => number = typeof performance !== 'undefined' && typeof performance.now === 'function' ? () => performance.now() : () => Date.now();

/** Timer for profiling (b2Timer.h), in milliseconds. */
export class b2Timer {
  private m_start = 0;

  constructor() {
    this.Reset();
  }

  /** Reset the timer. */
  Reset(): void {
    this.m_start = now();
  }

  /** Get the time since construction or the last reset. */
  GetMilliseconds(): number {
    return now() - this.m_start;
  }
}
