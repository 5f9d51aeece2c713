// pairs.wgsl: broad phase, the pair list's bookkeeping between the sweep and the pair sort.
//
// In:  state[STATE_PAIR_COUNT] (pairs the sweep found, possibly more than it could store) and
//      state[STATE_PAIR_CAPACITY] (host-written).
// Out: OVERFLOW_PAIRS set in state[STATE_OVERFLOW] when the pairs did not fit (the host then grows
//      the pair buffer and redoes the sweep: a pair is never lost silently);
//      state[STATE_PAIR_SORT_COUNT] = the pair count, or 0 after an overflow (the sort of a
//      truncated list would be wasted work);
//      indirect[3..6) = the dispatch size of the pair sort's upsweep and downsweep (one
//      workgroup per 1024 pairs, split in 2D under 65535).
// The pair sort that follows (radixSort.wgsl: the passes on the second proxy's bits, then on the
// first's) leaves the pairs ordered by (proxy a, proxy b), the same list on every run.

const SORT_TILE: u32 = 1024u;

@group(0) @binding(0) var<storage, read_write> state: array<u32>;
@group(0) @binding(1) var<storage, read_write> indirect: array<u32>;

@compute @workgroup_size(1)
fn finish() {
  let found = state[STATE_PAIR_COUNT];
  let overflow = found > state[STATE_PAIR_CAPACITY];
  let n = select(found, 0u, overflow);
  if (overflow) {
    state[STATE_OVERFLOW] = state[STATE_OVERFLOW] | OVERFLOW_PAIRS;
  }
  state[STATE_PAIR_SORT_COUNT] = n;
  let size = dispatch_size(n, SORT_TILE);
  indirect[ARGS_PAIR_TILES] = size.x;
  indirect[ARGS_PAIR_TILES + 1u] = size.y;
  indirect[ARGS_PAIR_TILES + 2u] = size.z;
}
