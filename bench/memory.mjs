// Memory measurement for the benchmark, with what Node 20 itself provides.
//
// Bytes allocated: V8 keeps no running total of allocated bytes that JavaScript can read, but it does
// report the heap's used size (v8.getHeapStatistics().used_heap_size), and v8.GCProfiler (Node
// >= 18.15) reports the used size before and after every garbage collection that runs while it is
// on. Every byte allocated in a window is either still counted at its end or was freed by one of
// those collections, so
//     allocated = used(end) - used(start) + sum over GCs of (used before GC - used after GC).
// Steady-state allocation per step is that, over a window of steps, divided by the step count. The
// window starts right after a forced full GC, so collections inside it are scavenges of the
// window's own garbage. The count covers the JavaScript heap only: memory inside a WebAssembly
// instance (box2d-wasm, box2d3-wasm, Rapier) is outside it, and is reported as the size of that
// instance's linear memory instead. The method is checked in test/bench against a loop allocating
// a known number of bytes.
//
// World size and heap growth (heap.mjs, in a process of the engine's own): used_heap_size after
// forced full GCs, taken (1) with an empty world of the engine alive, (2) after building the scene's
// world, (3) after the run. World heap is (2) - (1); heap growth is (3) - (2), what the run kept
// (contacts, pools, caches, leaks).
//
// Forced GCs use the `gc` function V8 exposes under --expose-gc; when the process was started
// without it, the flag is set at run time and the function fetched from a fresh context.
import v8 from 'node:v8';
import vm from 'node:vm';

let gcFn = globalThis.gc ?? null;

/** A full, synchronous garbage collection. */
export function fullGC() {
  if (!gcFn) {
    v8.setFlagsFromString('--expose-gc');
    gcFn = vm.runInNewContext('gc');
  }
  gcFn();
}

/** Bytes in use on the JavaScript heap. */
export const usedHeap = () => v8.getHeapStatistics().used_heap_size;

/** Heap in use after a full GC: what is reachable. */
export function retainedHeap() {
  fullGC();
  fullGC();
  return usedHeap();
}

/**
 * Runs fn() (which does `count` steps) and returns the bytes it allocated on the JavaScript heap,
 * with the number and total time of the collections that ran meanwhile.
 */
export function measureAllocation(fn) {
  const profiler = new v8.GCProfiler();
  profiler.start();
  const start = usedHeap();
  fn();
  const end = usedHeap();
  const report = profiler.stop();
  let freed = 0;
  let gcMs = 0;
  let scavenges = 0;
  let majors = 0;
  for (const s of report.statistics) {
    freed += s.beforeGC.heapStatistics.usedHeapSize - s.afterGC.heapStatistics.usedHeapSize;
    gcMs += s.cost / 1000; // microseconds
    if (/Scavenge|MinorMarkSweep|MinorMarkCompact/i.test(s.gcType)) scavenges++;
    else majors++;
  }
  return { bytes: end - start + freed, gcCount: report.statistics.length, scavenges, majors, gcMs };
}
