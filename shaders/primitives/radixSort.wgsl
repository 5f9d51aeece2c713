// radixSort.wgsl: one pass of a stable least-significant-digit radix sort of vec2<u32> elements
// by a digit of 4 or 8 bits (reduce-then-scan, as DeviceRadixSort: no chained scan or decoupled
// look-back, which need forward-progress guarantees that WebGPU does not give).
//
// In:  src[0, n), n = state[params.countWord]; the key of an element is element.x
//      (keyComponent 0), element.y (1), or (x, y) as one 64-bit key x << lowBits | y (2, for
//      y < 2^lowBits, 0 < lowBits < 32); the digit is (key >> params.shift) & (2^digitBits - 1).
// Out: dst[0, n): src stably reordered by that digit; digitTotals[d] = elements of digit d;
//      unless this is the last pass (params.nextBits 0), nextHist holds the next pass's digit
//      counts per tile of dst, as `upsweep` would count them from dst.
// Passes: `upsweep` (one workgroup per tile of TILE elements; the first pass only) counts digits
//      per tile into tileHist[digit * numTiles + tile]; `scan` (one workgroup per digit value, or
//      per several when rows are short, or one invocation per digit for at most SERIAL_TILES
//      tiles) turns each digit's row into exclusive prefix sums across tiles, writes the digit's
//      total to digitTotals and zeroes nextHist; `downsweep` (4-bit digits) or `downsweep_wide`
//      (8-bit) ranks its tile locally, scatters it, and counts the next pass's digits per
//      destination tile into nextHist (integer atomics: the counts, and so the sort, do not
//      depend on their order). The host alternates two histogram buffers as tileHist and
//      nextHist, so a sort of P passes is 2P + 1 dispatches (3P with an upsweep per pass).
// Local ranking (downsweep): each invocation holds ITEMS consecutive elements; a split by 4 bits
//      counts them in 16-bit counters packed two per u32 (8 words per invocation, in workgroup
//      memory) and scans the counters across the workgroup, which gives each element its rank
//      among the tile's elements of the same 4 bits. A 4-bit pass scatters from there:
//      (elements of smaller digits) + (this digit in earlier tiles) + rank. An 8-bit pass orders
//      the tile by the low nibble in workgroup memory, splits that order by the high nibble, and
//      writes the ordered tile with consecutive invocations on consecutive addresses of each
//      digit's run (+ the position in the tile - the digit's first position in the tile, one
//      exclusive scan over the digits that shares the first split's barriers): 8 barriers per
//      tile (12 with that scan and the first positions found on their own).
// Invariants: stable (equal digits keep their order), so running the passes from the least to
// the most significant digit sorts by the whole key; a tile's counts stay below 2^16.

const ITEMS: u32 = 4u;
const TILE: u32 = 1024u;
const MAX_RADIX: u32 = 256u;
const INVALID: u32 = 0xffffffffu;
// Tiles up to which `scan` runs one invocation per digit instead of one workgroup per digit.
const SERIAL_TILES: u32 = 16u;

// This pass's digit and the next pass's (nextBits 0: this is the last pass).
struct SortParams {
  shift: u32,
  keyComponent: u32,
  countWord: u32,
  digitBits: u32,
  lowBits: u32,
  nextShift: u32,
  nextComponent: u32,
  nextBits: u32,
  nextLowBits: u32,
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
@group(0) @binding(6) var<storage, read_write> nextHist: array<atomic<u32>>;

var<workgroup> hist: array<atomic<u32>, MAX_RADIX>;
// scan: the prefix where each of the workgroup's rows starts.
var<workgroup> rowBase: array<u32, MAX_RADIX>;
// Split counters: 8 packed words and the value to scan (split's `value`) x 256 invocations,
// word-major, at counter_at.
var<workgroup> scratch: array<u32, 2448>;
// Per split: each 16-invocation segment's counter sums (exclusive within its word row), and each
// row's total (low half: nibble 2w, high half: nibble 2w + 1).
var<workgroup> segTotals: array<u32, 144>;
var<workgroup> rowTotals: array<u32, 9>;
// An 8-bit pass's tile order: (tile-local index | next pass's digit << 16 | digit << 24) at each
// position.
var<workgroup> order: array<u32, TILE>;
// Per digit: its first destination for this tile (minus its first position in the tile, for
// an 8-bit pass).
var<workgroup> digitOffset: array<u32, MAX_RADIX>;

// The `width`-bit digit at bit `s` of e's key (`component`, `lowBits`: SortParams.keyComponent).
fn key_digit(e: vec2<u32>, component: u32, lowBits: u32, s: u32, width: u32) -> u32 {
  var lo = e.x;
  var hi = 0u;
  if (component == 1u) {
    lo = e.y;
  } else if (component == 2u) {
    lo = (e.x << lowBits) | e.y;
    hi = e.x >> (32u - lowBits);
  }
  var bits: u32;
  if (s >= 32u) {
    bits = hi >> (s - 32u);
  } else {
    bits = (lo >> s) | select(0u, hi << ((32u - s) & 31u), s != 0u);
  }
  return bits & ((1u << width) - 1u);
}

fn digit_of(e: vec2<u32>) -> u32 {
  return key_digit(e, params.keyComponent, params.lowBits, params.shift, params.digitBits);
}

// The next pass's digit (0 when there is none).
fn next_digit_of(e: vec2<u32>) -> u32 {
  return key_digit(e, params.nextComponent, params.nextLowBits, params.nextShift, params.nextBits);
}

// Counts one element for each entry of `at` (a nextHist index; INVALID: none), one atomicAdd per
// run of equal neighbours. Random keys send a tile's elements to many (digit, tile) counters, so
// an address takes few adds from each workgroup; equal keys send them all to one, and the runs
// cut that from TILE adds per workgroup to TILE / ITEMS.
fn count_next(at: array<u32, 4>) {
  var cur = INVALID;
  var count = 0u;
  for (var k = 0u; k < ITEMS; k = k + 1u) {
    if (at[k] != cur) {
      if (cur != INVALID) {
        atomicAdd(&nextHist[cur], count);
      }
      cur = at[k];
      count = 0u;
    }
    count = count + 1u;
  }
  if (cur != INVALID) {
    atomicAdd(&nextHist[cur], count);
  }
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
  // The next pass's counts start from zero: this pass's downsweep adds to them, and the previous
  // pass's downsweep, which read this buffer's prefix sums, has finished.
  if (params.nextBits != 0u) {
    let words = (1u << params.nextBits) * numTiles;
    let stride = nwg.x * nwg.y * WORKGROUP_SIZE;
    for (var f = d * WORKGROUP_SIZE + lid; f < words; f = f + stride) {
      atomicStore(&nextHist[f], 0u);
    }
  }
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

struct Split {
  // Per element: the tile's elements before it with the same nibble.
  ranks: array<u32, 4>,
  // The sum of `value` over the invocations before this one.
  before: u32,
}

// For each of this invocation's elements (ITEMS consecutive ones; INVALID: none), how many
// elements of the tile before it have the same 4-bit value in `nibbles`, and an exclusive scan of
// `value` across the workgroup riding on the same barriers (a ninth counter row). Every invocation
// must call it; afterwards rowTotals holds the tile's count of each nibble (nibble_start).
// Raking, as the 4-bit scatter always was: invocation r < 144 scans row r / 16 over the 16
// invocations of segment r % 16, then 9 invocations scan the segment sums of one row each. Three
// barriers.
fn split(lid: u32, nibbles: array<u32, 4>, value: u32) -> Split {
  for (var w = 0u; w < 8u; w = w + 1u) {
    scratch[counter_at(w * WORKGROUP_SIZE + lid)] = 0u;
  }
  scratch[counter_at(8u * WORKGROUP_SIZE + lid)] = value;
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
  if (lid < 144u) {
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
  if (lid < 9u) {
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
  let row = 8u * WORKGROUP_SIZE;
  return Split(ranks, scratch[counter_at(row + lid)] + segTotals[8u * 16u + lid / 16u]);
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
  let ranks = split(lid, digits, 0u).ranks;
  var at: array<u32, 4>;
  for (var k = 0u; k < ITEMS; k = k + 1u) {
    at[k] = INVALID;
    if (digits[k] != INVALID) {
      let j = digitOffset[digits[k]] + ranks[k];
      dst[j] = elems[k];
      at[k] = next_digit_of(elems[k]) * numTiles + j / TILE;
    }
  }
  if (params.nextBits != 0u) {
    count_next(at);
  }
}

// Puts each of this invocation's order words at its place in the tile ordered by the last split's
// nibbles (its nibble's first position + its rank).
fn place(nibbles: array<u32, 4>, ranks: array<u32, 4>, words: array<u32, 4>) {
  for (var k = 0u; k < ITEMS; k = k + 1u) {
    if (nibbles[k] != INVALID) {
      order[nibble_start(nibbles[k]) + ranks[k]] = words[k];
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
  // Digit lid's destination less its first position in the ordered tile: its elements in earlier
  // tiles, plus the elements of smaller digits outside this tile (all smaller digits precede it
  // in dst, but those of this tile also precede it in the tile). The scan of the latter rides on
  // the first split.
  let before = tileHist[lid * numTiles + tile];
  var through = digitTotals[lid];
  if (tile + 1u < numTiles) {
    through = tileHist[lid * numTiles + tile + 1u];
  }
  let outside = digitTotals[lid] - (through - before);

  // Each element travels as its order word.
  var words: array<u32, 4>;
  var nibbles: array<u32, 4>;
  for (var k = 0u; k < ITEMS; k = k + 1u) {
    let i = lid * ITEMS + k;
    nibbles[k] = INVALID;
    if (i < valid) {
      let e = src[start + i];
      let d = digit_of(e);
      words[k] = i | (next_digit_of(e) << 16u) | (d << 24u);
      nibbles[k] = d & 15u;
    }
  }
  let low = split(lid, nibbles, outside);
  digitOffset[lid] = before + low.before;
  place(nibbles, low.ranks, words);
  workgroupBarrier();
  for (var k = 0u; k < ITEMS; k = k + 1u) {
    let p = lid * ITEMS + k;
    nibbles[k] = INVALID;
    if (p < valid) {
      words[k] = order[p];
      nibbles[k] = words[k] >> 28u;
    }
  }
  let high = split(lid, nibbles, 0u);
  place(nibbles, high.ranks, words);
  workgroupBarrier();
  for (var k = 0u; k < ITEMS; k = k + 1u) {
    let p = k * WORKGROUP_SIZE + lid;
    if (p < valid) {
      let v = order[p];
      dst[digitOffset[v >> 24u] + p] = src[start + (v & 0xffffu)];
    }
  }
  // The next pass's counts, over each invocation's ITEMS consecutive positions (consecutive
  // destinations within a digit, so runs of one (digit, tile) merge in count_next).
  if (params.nextBits != 0u) {
    var at: array<u32, 4>;
    for (var k = 0u; k < ITEMS; k = k + 1u) {
      let p = lid * ITEMS + k;
      at[k] = INVALID;
      if (p < valid) {
        let v = order[p];
        at[k] = ((v >> 16u) & 0xffu) * numTiles + (digitOffset[v >> 24u] + p) / TILE;
      }
    }
    count_next(at);
  }
}
