// sweep.wgsl: broad phase, sweep-and-prune over the sorted entries, strip by strip, with the work
// split evenly however the intervals are distributed.
//
// In:  items[e] = (key, proxy slot) sorted by key (keys.wgsl, radixSort.wgsl), e in [0, E),
//      E = state[STATE_ENTRIES]; proxyRecords (per slot, keys.wgsl); jointRange[body] =
//      (start, count) into jointList: the bodies joined to `body` by a joint with
//      collideConnected == false, ascending.
// Out: pairs[0, min(found, capacity)) = (proxy a, proxy b), a < b, in no particular order;
//      state[STATE_PAIR_COUNT] = found, counted past the capacity so the host can grow and redo.
// Passes:
//   `gather`    sortedKeys[2e] = sortable keys of the entry's AABB with the sweep axis first
//               (min axis, min other, max axis, max other), sortedKeys[2e + 1] = (key, key of
//               the upper bound in the same strip, the proxy's first strip, the entry's strip):
//               what each candidate test reads, side by side; sortedInfo[e] = (slot, body,
//               category | mask << 16, group (int16 bits) | flag word << 16). Then the entry's
//               candidates: the entries after it up to the first whose key passes its upper key
//               (all of it from the proxy's 32-byte record: one sector read per entry)
//               (a galloping, then binary search on the sorted keys); workOffset[e] = their number
//               in chunks of CHUNK.
//   (scan.wgsl turns workOffset into exclusive offsets and their total, state[STATE_WORK_TOTAL])
//   `emit_args` the indirect size of `emit`.
//   `emit`      one invocation per work item: its entry e (binary search of the offsets) and up
//               to CHUNK candidates t. (e, t) is a pair when the AABBs overlap (exact comparisons of
//               sortable keys), e's strip is the first strip both proxies are in (so a pair found
//               in several strips is kept once), and Box2D would create a contact. A workgroup
//               reserves room for its pairs with one atomicAdd and writes them in invocation order.
// Invariants: the keys order entries by strip, then by quantised lower bound: quantisation is
// monotone (however coarse: sweep_key keeps KEY_BITS - strip bits of it), so an entry whose key
// passes e's upper key cannot overlap e, and a candidate with the same quantised lower bound as e
// still comes after e or finds e itself; each pair is found once. Ties only add candidates.
// One invocation does at most CHUNK overlap tests, so a huge AABB does not serialise the sweep.

const CHUNK: u32 = 32u;

struct SweepParams {
  pairCapacity: u32,
  pad0: u32,
  pad1: u32,
  pad2: u32,
}

@group(0) @binding(0) var<uniform> params: SweepParams;
@group(0) @binding(1) var<storage, read> items: array<vec2<u32>>;
@group(0) @binding(2) var<storage, read> proxyRecords: array<vec4<u32>>;
@group(0) @binding(5) var<storage, read> state: array<u32>;
@group(0) @binding(6) var<storage, read_write> sortedKeys: array<vec4<u32>>;
@group(0) @binding(7) var<storage, read_write> sortedInfo: array<vec4<u32>>;
@group(0) @binding(9) var<storage, read_write> workOffset: array<u32>;
@group(0) @binding(10) var<storage, read> jointRange: array<vec2<u32>>;
@group(0) @binding(11) var<storage, read> jointList: array<u32>;
@group(0) @binding(12) var<storage, read_write> pairs: array<vec2<u32>>;
@group(0) @binding(13) var<storage, read_write> stateAtomic: array<atomic<u32>>;
@group(0) @binding(14) var<storage, read_write> indirect: array<u32>;

var<workgroup> groupBase: u32;

@compute @workgroup_size(256)
fn gather(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
          @builtin(local_invocation_index) lid: u32) {
  let e = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  let n = state[STATE_ENTRIES];
  if (e >= n) {
    return;
  }
  let item = items[e];
  let slot = item.y;
  let info = proxyRecords[2u * slot + 1u];
  sortedInfo[e] = vec4<u32>(slot, info.x, info.y, info.z);
  let quantBits = key_quant_bits(state[STATE_STRIPS]);
  let strip = item.x >> quantBits;
  let upper = sweep_key(strip, info.w & QUANT_MAX, quantBits);
  sortedKeys[2u * e] = proxyRecords[2u * slot];
  sortedKeys[2u * e + 1u] = vec4<u32>(item.x, upper, info.w >> QUANT_BITS, strip);

  // Gallop: find hi with items[hi].x > upper (or hi = n), lo just past the last known <= upper.
  var lo = e + 1u;
  var hi = e + 1u;
  var step = 1u;
  loop {
    if (hi >= n) {
      hi = n;
      break;
    }
    if (items[hi].x > upper) {
      break;
    }
    lo = hi + 1u;
    hi = hi + step;
    step = step * 2u;
  }
  while (lo < hi) {
    let mid = lo + (hi - lo) / 2u;
    if (items[mid].x <= upper) {
      lo = mid + 1u;
    } else {
      hi = mid;
    }
  }
  workOffset[e] = (lo - e - 1u + CHUNK - 1u) / CHUNK;
}

@compute @workgroup_size(1)
fn emit_args() {
  let size = dispatch_size(state[STATE_WORK_TOTAL], WORKGROUP_SIZE);
  indirect[ARGS_EMIT] = size.x;
  indirect[ARGS_EMIT + 1u] = size.y;
  indirect[ARGS_EMIT + 2u] = size.z;
}

// Is `other` joined to `body` by a joint that turns collision off? (jointList is ascending.)
fn joined(body: u32, other: u32) -> bool {
  let range = jointRange[body];
  var lo = range.x;
  var hi = range.x + range.y;
  while (lo < hi) {
    let mid = lo + (hi - lo) / 2u;
    if (jointList[mid] < other) {
      lo = mid + 1u;
    } else {
      hi = mid;
    }
  }
  return lo < range.x + range.y && jointList[lo] == other;
}

// b2ContactManager::AddPair's tests for two proxies of sortedInfo: different bodies,
// b2Body::ShouldCollide (one body dynamic; no joint with collideConnected == false),
// a contact type exists for the shape pair (2.2.1 registers none for edge or chain against edge
// or chain), and b2ContactFilter::ShouldCollide (group, then category and mask).
fn should_collide(a: vec4<u32>, b: vec4<u32>) -> bool {
  if (a.y == b.y) {
    return false;
  }
  let wa = a.w >> 16u;
  let wb = b.w >> 16u;
  if (((wa >> 2u) & 3u) != 2u && ((wb >> 2u) & 3u) != 2u) {
    return false;
  }
  if ((wa & 1u) == 1u && (wb & 1u) == 1u) {
    return false;
  }
  let ga = bitcast<i32>(a.w << 16u) >> 16u;
  let gb = bitcast<i32>(b.w << 16u) >> 16u;
  if (ga == gb && ga != 0) {
    if (ga < 0) {
      return false;
    }
  } else if ((((a.z >> 16u) & b.z) & 0xffffu) == 0u || ((a.z & (b.z >> 16u)) & 0xffffu) == 0u) {
    return false;
  }
  if ((wa & PROXY_JOINTED) != 0u && (wb & PROXY_JOINTED) != 0u) {
    if (joined(a.y, b.y)) {
      return false;
    }
  }
  return true;
}


@compute @workgroup_size(256)
fn emit(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
        @builtin(local_invocation_index) lid: u32) {
  let w = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  let total = atomicLoad(&stateAtomic[STATE_WORK_TOTAL]);
  let n = atomicLoad(&stateAtomic[STATE_ENTRIES]);
  var mask = 0u;
  var e = 0u;
  var first = 0u;
  if (w < total) {
    // The entry whose work items cover w: the last e with workOffset[e] <= w.
    var lo = 0u;
    var hi = n;
    while (lo < hi) {
      let mid = lo + (hi - lo) / 2u;
      if (workOffset[mid] <= w) {
        lo = mid + 1u;
      } else {
        hi = mid;
      }
    }
    e = lo - 1u;
    first = e + 1u + (w - workOffset[e]) * CHUNK;
    let end = min(n, first + CHUNK);
    let boxE = sortedKeys[2u * e];
    let auxE = sortedKeys[2u * e + 1u];
    let infoE = sortedInfo[e];
    let strip = auxE.w;
    for (var t = first; t < end; t = t + 1u) {
      let auxT = sortedKeys[2u * t + 1u];
      if (auxT.x > auxE.y) {
        break;
      }
      let boxT = sortedKeys[2u * t];
      // Exact overlap (the quantised order does not give boxE.x <= boxT.x), in the strip where
      // the pair belongs.
      if (boxT.x <= boxE.z && boxE.x <= boxT.z && boxT.y <= boxE.w && boxE.y <= boxT.w &&
          strip == max(auxE.z, auxT.z)) {
        if (should_collide(infoE, sortedInfo[t])) {
          mask = mask | (1u << (t - first));
        }
      }
    }
  }
  let found = countOneBits(mask);
  let before = workgroup_exclusive_scan(lid, found);
  if (lid == 0u && wg_scan_total > 0u) {
    groupBase = atomicAdd(&stateAtomic[STATE_PAIR_COUNT], wg_scan_total);
  }
  workgroupBarrier();
  if (mask != 0u) {
    var index = groupBase + before;
    let a = sortedInfo[e].x;
    var m = mask;
    while (m != 0u) {
      let bit = firstTrailingBit(m);
      m = m & (m - 1u);
      let b = sortedInfo[first + bit].x;
      if (index < params.pairCapacity) {
        pairs[index] = vec2<u32>(min(a, b), max(a, b));
      }
      index = index + 1u;
    }
  }
}
