// radixSort.wgsl: one pass of a stable least-significant-digit radix sort of vec2<u32> elements
// by 4 bits of one component (reduce-then-scan, as DeviceRadixSort: no chained scan or
// decoupled look-back, which need forward-progress guarantees that WebGPU does not give).
//
// In:  src[0, n), n = state[params.countWord]; the digit of an element is
//      (element[params.keyComponent] >> params.shift) & 15.
// Out: dst[0, n): src stably reordered by that digit.
// Passes: `upsweep` (one workgroup per tile of TILE elements) counts digits per tile into
//      tileHist[digit * numTiles + tile]; `scan` (16 workgroups, one per digit) turns each digit's
//      row into exclusive prefix sums across tiles and writes the digit's total to digitTotals;
//      `downsweep` ranks each tile's elements (each invocation holds ITEMS consecutive elements,
//      16-bit digit counters packed two per u32, prefix-summed across the workgroup) and scatters
//      them to (elements of smaller digits) + (this digit in earlier tiles) + (rank in tile).
// Invariants: stable (equal digits keep their order), so running the passes from the least to
// the most significant digit sorts by the whole key; counts per tile stay below 2^16.

const RADIX: u32 = 16u;
const ITEMS: u32 = 4u;
const TILE: u32 = 1024u;

struct SortParams {
  shift: u32,
  keyComponent: u32,
  countWord: u32,
  pad: u32,
}

@group(0) @binding(0) var<uniform> params: SortParams;
@group(0) @binding(1) var<storage, read> src: array<vec2<u32>>;
@group(0) @binding(2) var<storage, read> state: array<u32>;
@group(0) @binding(3) var<storage, read_write> tileHist: array<u32>;
@group(0) @binding(4) var<storage, read_write> digitTotals: array<u32>;
@group(0) @binding(5) var<storage, read_write> dst: array<vec2<u32>>;

var<workgroup> hist: array<atomic<u32>, 16>;
var<workgroup> packedScan: array<u32, 2048>;
var<workgroup> segmentScan: array<u32, 128>;
var<workgroup> tileBase: array<u32, 16>;

fn digit_of(e: vec2<u32>) -> u32 {
  let key = select(e.x, e.y, params.keyComponent == 1u);
  return (key >> params.shift) & 15u;
}

fn tile_count(n: u32) -> u32 {
  return (n + TILE - 1u) / TILE;
}

@compute @workgroup_size(256)
fn upsweep(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
           @builtin(local_invocation_index) lid: u32) {
  let n = state[params.countWord];
  let numTiles = tile_count(n);
  let tile = group_index(wid, nwg);
  if (tile >= numTiles) {
    return;
  }
  if (lid < RADIX) {
    atomicStore(&hist[lid], 0u);
  }
  workgroupBarrier();
  let start = tile * TILE;
  for (var k = 0u; k < ITEMS; k = k + 1u) {
    let i = start + k * WORKGROUP_SIZE + lid;
    if (i < n) {
      atomicAdd(&hist[digit_of(src[i])], 1u);
    }
  }
  workgroupBarrier();
  if (lid < RADIX) {
    tileHist[lid * numTiles + tile] = atomicLoad(&hist[lid]);
  }
}


@compute @workgroup_size(256)
fn scan(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
        @builtin(local_invocation_index) lid: u32) {
  let d = group_index(wid, nwg);
  if (d >= RADIX) {
    return;
  }
  let numTiles = tile_count(state[params.countWord]);
  let row = d * numTiles;
  var carry = 0u;
  for (var base = 0u; base < numTiles; base = base + TILE) {
    var v: array<u32, 4>;
    var t = 0u;
    for (var k = 0u; k < ITEMS; k = k + 1u) {
      let idx = base + lid * ITEMS + k;
      v[k] = 0u;
      if (idx < numTiles) {
        v[k] = tileHist[row + idx];
      }
      t = t + v[k];
    }
    var running = workgroup_exclusive_scan(lid, t) + carry;
    for (var k = 0u; k < ITEMS; k = k + 1u) {
      let idx = base + lid * ITEMS + k;
      if (idx < numTiles) {
        tileHist[row + idx] = running;
      }
      running = running + v[k];
    }
    carry = carry + wg_scan_total;
  }
  if (lid == 0u) {
    digitTotals[d] = carry;
  }
}

@compute @workgroup_size(256)
fn downsweep(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
             @builtin(local_invocation_index) lid: u32) {
  let n = state[params.countWord];
  let numTiles = tile_count(n);
  let tile = group_index(wid, nwg);
  if (tile >= numTiles) {
    return;
  }
  if (lid < RADIX) {
    var base = 0u;
    for (var d = 0u; d < lid; d = d + 1u) {
      base = base + digitTotals[d];
    }
    tileBase[lid] = base + tileHist[lid * numTiles + tile];
  }

  // This invocation's ITEMS consecutive elements, their digits and their rank among the
  // invocation's own elements of the same digit.
  let first = tile * TILE + lid * ITEMS;
  var elems: array<vec2<u32>, 4>;
  var digits: array<u32, 4>;
  var ranks: array<u32, 4>;
  var packed: array<u32, 8>;
  for (var w = 0u; w < 8u; w = w + 1u) {
    packed[w] = 0u;
  }
  for (var k = 0u; k < ITEMS; k = k + 1u) {
    let i = first + k;
    digits[k] = RADIX;
    if (i < n) {
      let e = src[i];
      let d = digit_of(e);
      let w = d >> 1u;
      let sh = (d & 1u) * 16u;
      elems[k] = e;
      digits[k] = d;
      ranks[k] = (packed[w] >> sh) & 0xffffu;
      packed[w] = packed[w] + (1u << sh);
    }
  }

  // Exclusive prefix sums of the packed counters across the workgroup, raking: invocation
  // r < 128 scans word r / 16 over the 16 invocations of segment r % 16, then 8 invocations scan
  // the segment totals of one word each.
  for (var w = 0u; w < 8u; w = w + 1u) {
    packedScan[w * WORKGROUP_SIZE + lid] = packed[w];
  }
  workgroupBarrier();
  if (lid < 128u) {
    let w = lid / 16u;
    let seg = lid % 16u;
    var sum = 0u;
    for (var i = 0u; i < 16u; i = i + 1u) {
      let at = w * WORKGROUP_SIZE + seg * 16u + i;
      let v = packedScan[at];
      packedScan[at] = sum;
      sum = sum + v;
    }
    segmentScan[w * 16u + seg] = sum;
  }
  workgroupBarrier();
  if (lid < 8u) {
    var sum = 0u;
    for (var i = 0u; i < 16u; i = i + 1u) {
      let v = segmentScan[lid * 16u + i];
      segmentScan[lid * 16u + i] = sum;
      sum = sum + v;
    }
  }
  workgroupBarrier();

  for (var k = 0u; k < ITEMS; k = k + 1u) {
    let d = digits[k];
    if (d < RADIX) {
      let w = d >> 1u;
      let sh = (d & 1u) * 16u;
      let before = ((packedScan[w * WORKGROUP_SIZE + lid] + segmentScan[w * 16u + lid / 16u]) >> sh) & 0xffffu;
      dst[tileBase[d] + before + ranks[k]] = elems[k];
    }
  }
}
