// scan.wgsl: exclusive prefix sum of a u32 array, in place (reduce-then-scan: three dispatches,
// no inter-workgroup waiting, so it is correct without forward-progress guarantees).
//
// In:  data[0, count), count = state[params.countWord] (host- or GPU-written).
// Out: data[i] = data[0] + ... + data[i - 1]; state[params.totalWord] = the sum of all elements.
// Dispatch: `reduce` and `downsweep` with at least ceil(count / BLOCK) workgroups (direct, or
//      indirect from a size computed on the GPU); extra workgroups return at once.
// Passes: `reduce` sums each block of BLOCK elements into blockSums[block]; `scan_blocks` (one
//      workgroup) turns blockSums into exclusive prefix sums, in rounds of BLOCK, and writes the
//      total; `downsweep` scans each block and adds its blockSums entry.
// Invariants: sums are exact as long as the total stays below 2^32.

const PER_INVOCATION: u32 = 16u;
const BLOCK: u32 = 4096u;

struct ScanParams {
  countWord: u32,
  totalWord: u32,
  pad0: u32,
  pad1: u32,
}

@group(0) @binding(0) var<uniform> params: ScanParams;
@group(0) @binding(1) var<storage, read_write> data: array<u32>;
@group(0) @binding(2) var<storage, read_write> blockSums: array<u32>;
@group(0) @binding(3) var<storage, read_write> state: array<u32>;



var<workgroup> wg_count: u32;

// The element count, uniform across the workgroup (state is read_write here, so a plain load
// would not be uniform for the barriers that follow).
fn element_count(lid: u32) -> u32 {
  if (lid == 0u) {
    wg_count = state[params.countWord];
  }
  return workgroupUniformLoad(&wg_count);
}

@compute @workgroup_size(256)
fn reduce(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
          @builtin(local_invocation_index) lid: u32) {
  let count = element_count(lid);
  let b = group_index(wid, nwg);
  if (b >= (count + BLOCK - 1u) / BLOCK) {
    return;
  }
  var t = 0u;
  for (var k = 0u; k < PER_INVOCATION; k = k + 1u) {
    let i = b * BLOCK + k * WORKGROUP_SIZE + lid;
    if (i < count) {
      t = t + data[i];
    }
  }
  workgroup_exclusive_scan(lid, t);
  if (lid == 0u) {
    blockSums[b] = wg_scan_total;
  }
}

@compute @workgroup_size(256)
fn scan_blocks(@builtin(local_invocation_index) lid: u32) {
  let numBlocks = (element_count(lid) + BLOCK - 1u) / BLOCK;
  var carry = 0u;
  for (var base = 0u; base < numBlocks; base = base + BLOCK) {
    var v: array<u32, 16>;
    var t = 0u;
    for (var k = 0u; k < PER_INVOCATION; k = k + 1u) {
      let idx = base + lid * PER_INVOCATION + k;
      v[k] = 0u;
      if (idx < numBlocks) {
        v[k] = blockSums[idx];
      }
      t = t + v[k];
    }
    var running = workgroup_exclusive_scan(lid, t) + carry;
    for (var k = 0u; k < PER_INVOCATION; k = k + 1u) {
      let idx = base + lid * PER_INVOCATION + k;
      if (idx < numBlocks) {
        blockSums[idx] = running;
      }
      running = running + v[k];
    }
    carry = carry + wg_scan_total;
  }
  if (lid == 0u) {
    state[params.totalWord] = carry;
  }
}

@compute @workgroup_size(256)
fn downsweep(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
             @builtin(local_invocation_index) lid: u32) {
  let count = element_count(lid);
  let b = group_index(wid, nwg);
  if (b >= (count + BLOCK - 1u) / BLOCK) {
    return;
  }
  let first = b * BLOCK + lid * PER_INVOCATION;
  var v: array<u32, 16>;
  var t = 0u;
  for (var k = 0u; k < PER_INVOCATION; k = k + 1u) {
    let i = first + k;
    v[k] = 0u;
    if (i < count) {
      v[k] = data[i];
    }
    t = t + v[k];
  }
  var running = workgroup_exclusive_scan(lid, t) + blockSums[b];
  for (var k = 0u; k < PER_INVOCATION; k = k + 1u) {
    let i = first + k;
    if (i < count) {
      data[i] = running;
    }
    running = running + v[k];
  }
}
