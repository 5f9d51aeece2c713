// contacts.wgsl: GpuStage.Contacts, from the broad phase's pairs to oriented, binned contacts
// matched with the previous step's.
//
// In:  pairs[0, n) = (proxy a, proxy b), a < b, sorted by (a, b) (the broad phase's list; n =
//      broadState[STATE_PAIR_SORT_COUNT], 0 when the pairs overflowed); proxyRef (fixture, child,
//      body, flag word: shape type bits 0-1, PROXY_SENSOR); proxyKey (the engine's proxy id, the
//      slot's generation); the previous step's keys prevKey[0, npState[NP_PREV]), sorted;
//      params.curSet (the contact set written this step; the other holds the previous step);
//      bodyFlags (the body type) and bodyAwake (the awake flags as the step starts: last step's
//      islands, and what the host uploaded since).
// Out: `begin` (one invocation): npState[NP_CONTACTS] = min(n, capacity) (OVERFLOW_CONTACTS when
//      n does not fit: the host grows the buffers and runs the narrow phase again),
//      npState[NP_PREV], npState[NP_COUNT_0 + curSet], npState[NP_EVENT_SLOTS] and the indirect
//      sizes of the passes over contacts, previous contacts and event slots.
//      `classify` (per contact i): curKey[i] = (a, b, generation of a, generation of b);
//      contactRef[2i] = (fixture A, child A, body A, bin << 4 | sensor << 1 | swapped),
//      contactRef[2i + 1] = (fixture B, child B, body B, index of the same contact in the previous
//      step or NO_CONTACT); items[i] = (bin, i) for the bin sort (BIN_NONE, which no kernel
//      collides and persist.wgsl zeroes, cannot come from the broad phase's pair rules).
//      `keep` (per contact i, after classify): a contact of the previous step whose bodies are
//      both asleep or static gets CONTACT_KEPT in contactRef[2i].w and items[i] = (BIN_KEPT, i):
//      no collide kernel sees it, persist.wgsl carries its previous manifold over.
//      `bin_args` (one invocation, after the one-digit radix sort of items): npState[NP_BINS + b] =
//      first entry of bin b in the sorted items, and the indirect size of each bin's kernel
//      (zero workgroups for an empty bin: nothing runs); npState[NP_KEPT] = the kept contacts.
// Invariants: A/B follow b2Contact::Create: the registry puts the polygon before a circle and the
// edge or chain before a circle or polygon; two shapes of one type keep the broad-phase order of
// b2BroadPhase::QueryCallback, lower engine proxy id first. A contact matches the previous step's
// only with the same proxies and generations (a reused slot is a new contact, as in Box2D). The bin
// sort is stable, so each bin lists its contacts in key order: the same order on every run.
// Kept contacts follow b2ContactManager::Collide, which updates a contact only when one of its
// bodies is awake and not static (activeA || activeB), with two differences that come from the
// GPU's contacts being the pairs of this step: a contact new this step is always collided (in
// 2.2.1 b2ContactManager::AddPair woke both bodies before the Collide that first sees it; the GPU
// wakes them in the islands stage, after the collide), and a contact whose pair left the list is
// gone, even between sleeping bodies (2.2.1 keeps it until a body wakes). The awake flags are
// those of the start of the step: a body that 2.2.1's Collide wakes on the way (a touch change in
// an earlier contact of its list) is collided from the next step. A body moved by SetTransform
// while asleep stays asleep, as in 2.2.1: its contacts with sleeping or static bodies keep their
// manifolds, and the new pairs its move makes are collided and wake it.
// `keep` is a pass of its own because classify binds 8 storage buffers already, the most a stage
// may (the device asks for the default limits), and the collide kernels too.

struct ContactParams {
  curSet: u32,
  pad0: u32,
  pad1: u32,
  pad2: u32,
}

@group(0) @binding(0) var<uniform> params: ContactParams;
@group(0) @binding(1) var<storage, read> broadState: array<u32>;
@group(0) @binding(2) var<storage, read_write> npState: array<u32>;
@group(0) @binding(3) var<storage, read_write> npIndirect: array<u32>;
@group(0) @binding(4) var<storage, read> pairs: array<vec2<u32>>;
@group(0) @binding(5) var<storage, read> proxyRef: array<vec4<u32>>;
@group(0) @binding(6) var<storage, read> proxyKey: array<vec2<u32>>;
@group(0) @binding(7) var<storage, read_write> curKey: array<vec4<u32>>;
@group(0) @binding(8) var<storage, read> prevKey: array<vec4<u32>>;
@group(0) @binding(9) var<storage, read_write> contactRef: array<vec4<u32>>;
@group(0) @binding(10) var<storage, read_write> items: array<vec2<u32>>;
@group(0) @binding(11) var<storage, read> digitTotals: array<u32>;
@group(0) @binding(12) var<storage, read> bodyFlags: array<u32>;
@group(0) @binding(13) var<storage, read> bodyAwake: array<u32>;

const SORT_TILE: u32 = 1024u;
const SCAN_BLOCK: u32 = 4096u;

fn write_args(word: u32, size: vec3<u32>) {
  npIndirect[word] = size.x;
  npIndirect[word + 1u] = size.y;
  npIndirect[word + 2u] = size.z;
}

@compute @workgroup_size(1)
fn begin() {
  let n = broadState[STATE_PAIR_SORT_COUNT];
  let capacity = npState[NP_CAPACITY];
  var count = n;
  if (n > capacity) {
    npState[NP_OVERFLOW] = npState[NP_OVERFLOW] | OVERFLOW_CONTACTS;
    count = capacity;
  }
  let prev = npState[NP_COUNT_0 + (1u - params.curSet)];
  npState[NP_PAIRS] = n;
  npState[NP_CONTACTS] = count;
  npState[NP_PREV] = prev;
  npState[NP_COUNT_0 + params.curSet] = count;
  npState[NP_EVENT_SLOTS] = count + prev;
  npState[NP_SOLVER] = 0u;
  npState[NP_EVENTS] = 0u;
  write_args(NP_ARGS_CONTACTS, dispatch_size(count, WORKGROUP_SIZE));
  write_args(NP_ARGS_TILES, dispatch_size(count, SORT_TILE));
  write_args(NP_ARGS_BLOCKS, dispatch_size(count, SCAN_BLOCK));
  write_args(NP_ARGS_PREV, dispatch_size(prev, WORKGROUP_SIZE));
  write_args(NP_ARGS_EVENT_SLOTS, dispatch_size(count + prev, WORKGROUP_SIZE));
  write_args(NP_ARGS_EVENT_BLOCKS, dispatch_size(count + prev, SCAN_BLOCK));
}

// The contact rank of a shape type in b2Contact::Create's registry: the higher rank is fixture A.
fn type_rank(shapeType: u32) -> u32 {
  // circle -> 0, polygon -> 1, edge and chain -> 2
  return select(select(2u, 1u, shapeType == SHAPE_POLYGON), 0u, shapeType == SHAPE_CIRCLE);
}

fn bin_of(typeA: u32, typeB: u32) -> u32 {
  if (typeA == SHAPE_CIRCLE && typeB == SHAPE_CIRCLE) {
    return BIN_CIRCLES;
  }
  let circleB = typeB == SHAPE_CIRCLE;
  let convexB = circleB || typeB == SHAPE_POLYGON;
  if (typeA == SHAPE_POLYGON) {
    return select(BIN_NONE, select(BIN_POLYGONS, BIN_POLYGON_CIRCLE, circleB), convexB);
  }
  if (typeA == SHAPE_EDGE) {
    return select(BIN_NONE, select(BIN_EDGE_POLYGON, BIN_EDGE_CIRCLE, circleB), convexB);
  }
  if (typeA == SHAPE_CHAIN) {
    return select(BIN_NONE, select(BIN_CHAIN_POLYGON, BIN_CHAIN_CIRCLE, circleB), convexB);
  }
  return BIN_NONE;
}

// The previous step's index of the contact with key (a, b) and these generations, or NO_CONTACT.
fn find_previous(a: u32, b: u32, genA: u32, genB: u32) -> u32 {
  var lo = 0u;
  var hi = npState[NP_PREV];
  while (lo < hi) {
    let mid = lo + (hi - lo) / 2u;
    let k = prevKey[mid];
    if (k.x < a || (k.x == a && k.y < b)) {
      lo = mid + 1u;
    } else {
      hi = mid;
    }
  }
  if (lo < npState[NP_PREV]) {
    let k = prevKey[lo];
    if (k.x == a && k.y == b && k.z == genA && k.w == genB) {
      return lo;
    }
  }
  return NO_CONTACT;
}

@compute @workgroup_size(256)
fn classify(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
            @builtin(local_invocation_index) lid: u32) {
  let i = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  if (i >= npState[NP_CONTACTS]) {
    return;
  }
  let pair = pairs[i];
  let refA0 = proxyRef[pair.x];
  let refB0 = proxyRef[pair.y];
  let keyA0 = proxyKey[pair.x];
  let keyB0 = proxyKey[pair.y];
  let typeA0 = refA0.w & 3u;
  let typeB0 = refB0.w & 3u;
  let rankA = type_rank(typeA0);
  let rankB = type_rank(typeB0);
  let swapped = rankB > rankA || (rankB == rankA && keyB0.x < keyA0.x);
  var refA = refA0;
  var refB = refB0;
  if (swapped) {
    refA = refB0;
    refB = refA0;
  }
  let sensor = ((refA0.w | refB0.w) & PROXY_SENSOR) != 0u;
  var bin = bin_of(refA.w & 3u, refB.w & 3u);
  if (sensor && bin != BIN_NONE) {
    bin = BIN_SENSOR;
  }
  curKey[i] = vec4<u32>(pair.x, pair.y, keyA0.y, keyB0.y);
  let previous = find_previous(pair.x, pair.y, keyA0.y, keyB0.y);
  let flags = (bin << 4u) | select(0u, 2u, sensor) | select(0u, 1u, swapped);
  contactRef[2u * i] = vec4<u32>(refA.x, refA.y, refA.z, flags);
  contactRef[2u * i + 1u] = vec4<u32>(refB.x, refB.y, refB.z, previous);
  items[i] = vec2<u32>(bin, i);
}

// b2ContactManager::Collide's activeA / activeB: awake and not static.
fn is_active(body: u32) -> bool {
  return bodyAwake[body] != 0u && body_type(bodyFlags[body]) != STATIC_BODY;
}

@compute @workgroup_size(256)
fn keep(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
        @builtin(local_invocation_index) lid: u32) {
  let i = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  if (i >= npState[NP_CONTACTS]) {
    return;
  }
  let refA = contactRef[2u * i];
  let refB = contactRef[2u * i + 1u];
  if (refB.w == NO_CONTACT || is_active(refA.z) || is_active(refB.z)) {
    return;
  }
  contactRef[2u * i] = vec4<u32>(refA.xyz, refA.w | CONTACT_KEPT);
  items[i] = vec2<u32>(BIN_KEPT, i);
}

@compute @workgroup_size(1)
fn bin_args() {
  var start = 0u;
  for (var b = 0u; b < BIN_COUNT; b = b + 1u) {
    npState[NP_BINS + b] = start;
    let count = digitTotals[b];
    write_args(NP_ARGS_BINS + 3u * b, dispatch_size(count, WORKGROUP_SIZE));
    start = start + count;
  }
  npState[NP_BINS + BIN_COUNT] = start;
  npState[NP_KEPT] = digitTotals[BIN_KEPT];
}
