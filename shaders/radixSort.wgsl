// radixSort.wgsl: one pass of a stable least-significant-digit radix sort of vec2<u32> elements
// by a digit of 4 or 8 bits (reduce-then-scan, as DeviceRadixSort: no chained scan or decoupled
// look-back, which need forward-progress guarantees that WebGPU does not give).
//
// In:  src[0, n), n = state[params.countWord]; the key of an element is element.x
//      (keyComponent 0), element.y (1), or (x, y) as one 64-bit key x << lowBits | y (2, for
//      y < 2^lowBits, 0 < lowBits < 32); the digit is (key >> params.shift) & (2^digitBits - 1).
// Out: dst[0, n): src stably reordered by that digit; digitTotals[d] = elements of digit d.
// Passes: `upsweep` (one workgroup per tile of TILE elements) counts digits per tile into
//      tileHist[digit * numTiles + tile]; `scan` (one workgroup per digit value, or per several
//      when rows are short, or one invocation per digit for at most SERIAL_TILES tiles) turns each
//      digit's row into exclusive prefix sums across tiles and writes the digit's total to
//      digitTotals; `downsweep` (4-bit digits) or `downsweep_wide` (8-bit) ranks its tile
//      locally and scatters it.
// Local ranking (downsweep): each invocation holds ITEMS consecutive elements; a split by 4 bits
//      counts them in 16-bit counters packed two per u32 (8 words per invocation, in workgroup
//      memory) and scans the counters across the workgroup, which gives each element its rank
//      among the tile's elements of the same 4 bits. A 4-bit pass scatters from there:
//      (elements of smaller digits) + (this digit in earlier tiles) + rank. An 8-bit pass orders
//      the tile by the low nibble in workgroup memory, splits that order by the high nibble, and
//      writes the ordered tile with consecutive invocations on consecutive addresses of each
//      digit's run (+ the position in the tile - the digit's first position in the tile).
// Invariants: stable (equal digits keep their order), so running the passes from the least to
// the most significant digit sorts by the whole key; a tile's counts stay below 2^16.

const ITEMS: u32 = 4u;
const TILE: u32 = 1024u;
const MAX_RADIX: u32 = 256u;
const INVALID: u32 = 0xffffffffu;
// Tiles up to which `scan` runs one invocation per digit instead of one workgroup per digit.
const SERIAL_TILES: u32 = 16u;

struct SortParams {
  shift: u32,
  keyComponent: u32,
  countWord: u32,
  digitBits: u32,
  lowBits: u32,
  pad0: u32,
  pad1: u32,
  pad2: u32,
}

@group(0) @binding(0) var<uniform> params: SortParams;
@group(0) @binding(1) var<storage, read> src: array<vec2<u32>>;
@group(0) @binding(2) var<storage, read> state: array<u32>;
@group(0) @binding(3) var<storage, read_write> tileHist: array<u32>;
@group(0) @binding(4) var<storage, read_write> digitTotals: array<u32>;
@group(0) @binding(5) var<storage, read_write> dst: array<vec2<u32>>;

var<workgroup> hist: array<atomic<u32>, MAX_RADIX>;
// scan: the prefix where each of the workgroup's rows starts.
var<workgroup> rowBase: array<u32, MAX_RADIX>;
// Packed split counters: 8 words x 256 invocations, word-major, at counter_at.
var<workgroup> scratch: array<u32, 2176>;
// Per split: each 16-invocation segment's counter sums (exclusive within its word row), and each
// row's total (low half: nibble 2w, high half: nibble 2w + 1).
var<workgroup> segTotals: array<u32, 128>;
var<workgroup> rowTotals: array<u32, 8>;
// An 8-bit pass's tile order: (tile-local index | digit << 16) at each position.
var<workgroup> order: array<u32, TILE>;
// Per digit: its first destination for this tile (minus its first position in the tile, for
// an 8-bit pass).
var<workgroup> digitOffset: array<u32, MAX_RADIX>;

fn digit_of(e: vec2<u32>) -> u32 {
  var lo = e.x;
  var hi = 0u;
  if (params.keyComponent == 1u) {
    lo = e.y;
  } else if (params.keyComponent == 2u) {
    lo = (e.x << params.lowBits) | e.y;
    hi = e.x >> (32u - params.lowBits);
  }
  let s = params.shift;
  var bits: u32;
  if (s >= 32u) {
    bits = hi >> (s - 32u);
  } else {
    bits = (lo >> s) | select(0u, hi << ((32u - s) & 31u), s != 0u);
  }
  return bits & ((1u << params.digitBits) - 1u);
}

// Where counter word f (word-major) lives: one pad word per 16, so that the 16 invocations
// raking one row's segments hit distinct banks.
fn counter_at(f: u32) -> u32 {
  return f + (f >> 4u);
}

// Digit rows each `scan` workgroup takes: as many as fit in one round of TILE counts (a power of
// two, at most the digit count), so that a mid-sized sort does not pay one workgroup per digit.
// The host dispatches radix / rows_per_group(its bound on numTiles) workgroups.
fn rows_per_group(numTiles: u32, radix: u32) -> u32 {
  var rows = 1u;
  while (rows < radix && 2u * rows * numTiles <= TILE) {
    rows = 2u * rows;
  }
  return rows;
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
  atomicStore(&hist[lid], 0u);
  workgroupBarrier();
  let start = tile * TILE;
  for (var k = 0u; k < ITEMS; k = k + 1u) {
    let i = start + k * WORKGROUP_SIZE + lid;
    if (i < n) {
      atomicAdd(&hist[digit_of(src[i])], 1u);
    }
  }
  workgroupBarrier();
  if (lid < (1u << params.digitBits)) {
    tileHist[lid * numTiles + tile] = atomicLoad(&hist[lid]);
  }
}

@compute @workgroup_size(256)
fn scan(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
        @builtin(local_invocation_index) lid: u32) {
  let radix = 1u << params.digitBits;
  let numTiles = tile_count(state[params.countWord]);
  let d = group_index(wid, nwg);
  if (numTiles <= SERIAL_TILES) {
    // Short rows: one invocation of workgroup 0 per digit, no barriers (a CPU implementation
    // such as SwiftShader pays for every workgroup and barrier, and small sorts are most steps;
    // the host then dispatches one workgroup when it knows the count is this small).
    if (d == 0u && lid < radix) {
      var sum = 0u;
      for (var t = 0u; t < numTiles; t = t + 1u) {
        let v = tileHist[lid * numTiles + t];
        tileHist[lid * numTiles + t] = sum;
        sum = sum + v;
      }
      digitTotals[lid] = sum;
    }
    return;
  }
  // Rows d0 .. d0 + rows - 1, contiguous in tileHist: one exclusive scan over them all, less
  // the prefix where each row starts.
  let rows = rows_per_group(numTiles, radix);
  let d0 = d * rows;
  if (d0 >= radix) {
    return;
  }
  let first = d0 * numTiles;
  let length = rows * numTiles;
  var carry = 0u;
  for (var base = 0u; base < length; base = base + TILE) {
    var v: array<u32, 4>;
    var t = 0u;
    for (var k = 0u; k < ITEMS; k = k + 1u) {
      let f = base + lid * ITEMS + k;
      v[k] = 0u;
      if (f < length) {
        v[k] = tileHist[first + f];
      }
      t = t + v[k];
    }
    let before = workgroup_exclusive_scan(lid, t) + carry;
    var running = before;
    for (var k = 0u; k < ITEMS; k = k + 1u) {
      let f = base + lid * ITEMS + k;
      if (f < length && f % numTiles == 0u) {
        rowBase[f / numTiles] = running;
      }
      running = running + v[k];
    }
    workgroupBarrier();
    running = before;
    for (var k = 0u; k < ITEMS; k = k + 1u) {
      let f = base + lid * ITEMS + k;
      if (f < length) {
        tileHist[first + f] = running - rowBase[f / numTiles];
      }
      running = running + v[k];
    }
    carry = carry + wg_scan_total;
  }
  if (lid < rows) {
    var end = carry;
    if (lid + 1u < rows) {
      end = rowBase[lid + 1u];
    }
    digitTotals[d0 + lid] = end - rowBase[lid];
  }
}

// For each of this invocation's elements (ITEMS consecutive ones; INVALID: none), how many
// elements of the tile before it have the same 4-bit value in `nibbles`. Every invocation must call
// it; afterwards rowTotals holds the tile's count of each nibble (nibble_start). Raking, as the
// 4-bit scatter always was: invocation r < 128 scans row r / 16 over the 16 invocations of
// segment r % 16, then 8 invocations scan the segment sums of one row each. Three barriers.
fn split(lid: u32, nibbles: array<u32, 4>) -> array<u32, 4> {
  for (var w = 0u; w < 8u; w = w + 1u) {
    scratch[counter_at(w * WORKGROUP_SIZE + lid)] = 0u;
  }
  var ranks: array<u32, 4>;
  for (var k = 0u; k < ITEMS; k = k + 1u) {
    ranks[k] = 0u;
    let b = nibbles[k];
    if (b != INVALID) {
      let at = counter_at((b >> 1u) * WORKGROUP_SIZE + lid);
      let sh = (b & 1u) * 16u;
      let c = scratch[at];
      ranks[k] = (c >> sh) & 0xffffu;
      scratch[at] = c + (1u << sh);
    }
  }
  workgroupBarrier();
  if (lid < 128u) {
    let at = counter_at((lid / 16u) * WORKGROUP_SIZE + (lid % 16u) * 16u);
    var sum = 0u;
    for (var i = 0u; i < 16u; i = i + 1u) {
      let v = scratch[at + i];
      scratch[at + i] = sum;
      sum = sum + v;
    }
    segTotals[lid] = sum;
  }
  workgroupBarrier();
  if (lid < 8u) {
    var sum = 0u;
    for (var i = 0u; i < 16u; i = i + 1u) {
      let v = segTotals[lid * 16u + i];
      segTotals[lid * 16u + i] = sum;
      sum = sum + v;
    }
    rowTotals[lid] = sum;
  }
  workgroupBarrier();
  for (var k = 0u; k < ITEMS; k = k + 1u) {
    let b = nibbles[k];
    if (b != INVALID) {
      let w = b >> 1u;
      let before = scratch[counter_at(w * WORKGROUP_SIZE + lid)] + segTotals[w * 16u + lid / 16u];
      ranks[k] = ranks[k] + ((before >> ((b & 1u) * 16u)) & 0xffffu);
    }
  }
  return ranks;
}

// The first position of nibble b in the tile ordered by the last split's nibbles.
fn nibble_start(b: u32) -> u32 {
  var start = 0u;
  for (var w = 0u; w < (b >> 1u); w = w + 1u) {
    let t = rowTotals[w];
    start = start + (t & 0xffffu) + (t >> 16u);
  }
  if ((b & 1u) == 1u) {
    start = start + (rowTotals[b >> 1u] & 0xffffu);
  }
  return start;
}

// Where each digit's elements of this tile begin in dst: `smaller` (elements of smaller digits,
// for invocation lid = digit) plus this digit's elements in earlier tiles.
fn tile_offsets(lid: u32, tile: u32, numTiles: u32, smaller: u32) {
  if (lid < (1u << params.digitBits)) {
    digitOffset[lid] = smaller + tileHist[lid * numTiles + tile];
  }
}

// A 4-bit pass: one split, scattered from the invocations' registers.
@compute @workgroup_size(256)
fn downsweep(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
             @builtin(local_invocation_index) lid: u32) {
  let n = state[params.countWord];
  let numTiles = tile_count(n);
  let tile = group_index(wid, nwg);
  if (tile >= numTiles) {
    return;
  }
  let start = tile * TILE;
  // 16 digits: a short serial sum, no barrier.
  var smaller = 0u;
  if (lid < 16u) {
    for (var d = 0u; d < lid; d = d + 1u) {
      smaller = smaller + digitTotals[d];
    }
  }
  tile_offsets(lid, tile, numTiles, smaller);

  var elems: array<vec2<u32>, 4>;
  var digits: array<u32, 4>;
  for (var k = 0u; k < ITEMS; k = k + 1u) {
    let i = start + lid * ITEMS + k;
    digits[k] = INVALID;
    if (i < n) {
      elems[k] = src[i];
      digits[k] = digit_of(elems[k]);
    }
  }
  let ranks = split(lid, digits);
  for (var k = 0u; k < ITEMS; k = k + 1u) {
    if (digits[k] != INVALID) {
      dst[digitOffset[digits[k]] + ranks[k]] = elems[k];
    }
  }
}

// An 8-bit pass: the tile ordered by the low nibble in workgroup memory, that order split stably
// by the high nibble, then written out position by position.
@compute @workgroup_size(256)
fn downsweep_wide(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
                  @builtin(local_invocation_index) lid: u32) {
  let n = state[params.countWord];
  let numTiles = tile_count(n);
  let tile = group_index(wid, nwg);
  if (tile >= numTiles) {
    return;
  }
  let start = tile * TILE;
  let valid = min(TILE, n - start);
  tile_offsets(lid, tile, numTiles, workgroup_exclusive_scan(lid, digitTotals[lid]));

  var digits: array<u32, 4>;
  var idx: array<u32, 4>;
  var nibbles: array<u32, 4>;
  for (var k = 0u; k < ITEMS; k = k + 1u) {
    let i = lid * ITEMS + k;
    nibbles[k] = INVALID;
    idx[k] = i;
    if (i < valid) {
      digits[k] = digit_of(src[start + i]);
      nibbles[k] = digits[k] & 15u;
    }
  }
  var ranks = split(lid, nibbles);
  for (var k = 0u; k < ITEMS; k = k + 1u) {
    if (nibbles[k] != INVALID) {
      order[nibble_start(nibbles[k]) + ranks[k]] = idx[k] | (digits[k] << 16u);
    }
  }
  workgroupBarrier();
  for (var k = 0u; k < ITEMS; k = k + 1u) {
    let p = lid * ITEMS + k;
    nibbles[k] = INVALID;
    if (p < valid) {
      let v = order[p];
      idx[k] = v & 0xffffu;
      digits[k] = v >> 16u;
      nibbles[k] = digits[k] >> 4u;
    }
  }
  ranks = split(lid, nibbles);
  for (var k = 0u; k < ITEMS; k = k + 1u) {
    if (nibbles[k] != INVALID) {
      order[nibble_start(nibbles[k]) + ranks[k]] = idx[k] | (digits[k] << 16u);
    }
  }
  workgroupBarrier();
  // Each digit's first position in the tile turns digitOffset into (destination - position).
  for (var k = 0u; k < ITEMS; k = k + 1u) {
    let p = k * WORKGROUP_SIZE + lid;
    if (p < valid) {
      let d = order[p] >> 16u;
      if (p == 0u || (order[p - 1u] >> 16u) != d) {
        digitOffset[d] = digitOffset[d] - p;
      }
    }
  }
  workgroupBarrier();
  for (var k = 0u; k < ITEMS; k = k + 1u) {
    let p = k * WORKGROUP_SIZE + lid;
    if (p < valid) {
      let v = order[p];
      dst[digitOffset[v >> 16u] + p] = src[start + (v & 0xffffu)];
    }
  }
}
