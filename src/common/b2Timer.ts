/** Timer for profiling (b2Timer.h), in milliseconds from the host's monotonic clock. */
export class b2Timer {
  private m_start = 0;

  constructor() {
    this.Reset();
  }

  /** Reset the timer. */
  Reset(): void {
    this.m_start = performance.now();
  }

  /** Get the time since construction or the last reset. */
  GetMilliseconds(): number {
    return performance.now() - this.m_start;
  }
}
