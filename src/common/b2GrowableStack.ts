/**
 * A growable LIFO stack (b2GrowableStack.h). The tree queries use it so that traversal order is
 * the C++ one; the backing array is kept and reused, so steady-state queries do not allocate.
 */
export class b2GrowableStack<T> {
  private m_stack: T[];
  private m_count = 0;

  constructor(capacity: number) {
    this.m_stack = new Array<T>(capacity);
  }

  Reset(): this {
    this.m_count = 0;
    return this;
  }

  Push(element: T): void {
    this.m_stack[this.m_count] = element;
    ++this.m_count;
  }

  Pop(): T {
    --this.m_count;
    return this.m_stack[this.m_count];
  }

  GetCount(): number {
    return this.m_count;
  }
}
