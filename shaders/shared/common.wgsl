// common.wgsl: definitions every stage shares. The host prepends this file to each stage's WGSL
// (WGSL has no #include), so a stage may use these names without declaring them.
//
// Conventions (see src-gpu/device/layout.ts, which holds the same numbers for the host):
// - Every kernel runs 256 invocations per workgroup (the WebGPU default limit).
// - Large grids are dispatched in 2D (x <= 65535 workgroups, maxComputeWorkgroupsPerDimension);
//   a kernel linearises its workgroup id with `group_index` and bounds-checks the element index.
// - AABB coordinates are float32 relative to the world origin; sort keys are their bit patterns
//   mapped to order-preserving u32 (`sortable_key`), and every AABB comparison in the sweep is
//   made on those keys, so the GPU and a CPU reference that compares the same float32 values
//   agree exactly (no dependence on denormal flushing or fused operations).
// - The state buffer (`STATE_*` word indices) carries counts and parameters between stages
//   without any read-back; sizes known only on the GPU drive indirect dispatches (`ARGS_*`).

const WORKGROUP_SIZE: u32 = 256u;

// maxComputeWorkgroupsPerDimension, as the host dispatches (a pipeline constant, so tests can force
// 2D dispatches with a small value).
override MAX_GROUPS_PER_DIMENSION: u32 = 65535u;

// Word indices of the state buffer (array<u32>, 16 words).
const STATE_AXIS: u32 = 0u;            // 0: sweep along x, 1: along y (axis.wgsl)
const STATE_PAIR_COUNT: u32 = 1u;      // pairs found (atomic; may exceed the capacity)
const STATE_WORK_TOTAL: u32 = 2u;      // sweep work items (scan total of the chunk counts)
const STATE_PAIR_SORT_COUNT: u32 = 3u; // pairs to sort: the pair count, or 0 after an overflow
const STATE_OVERFLOW: u32 = 4u;        // OVERFLOW_PAIRS | OVERFLOW_ENTRIES
const STATE_PAIR_CAPACITY: u32 = 5u;   // pairs the pair buffer holds (host)
const STATE_ENTRY_TOTAL: u32 = 6u;     // sweep entries wanted: sum over proxies of their strips
const STATE_LIVE_COUNT: u32 = 7u;      // live proxies (host)
const STATE_STRIPS: u32 = 8u;          // strips across the other axis (axis.wgsl)
const STATE_AXIS_LO: u32 = 9u;         // f32: lowest lower bound on the sweep axis
const STATE_AXIS_SCALE: u32 = 10u;     // f32: quantisation scale on the sweep axis
const STATE_OTHER_LO: u32 = 11u;       // f32: lowest lower bound on the other axis
const STATE_OTHER_INV_H: u32 = 12u;    // f32: 1 / strip height
const STATE_ENTRY_CAPACITY: u32 = 13u; // entries the entry buffers hold (host)
const STATE_SLOT_COUNT: u32 = 14u;     // proxy slots (host)
const STATE_ENTRIES: u32 = 15u;        // entries to sort and sweep: the total, or 0 after an overflow

const OVERFLOW_PAIRS: u32 = 1u;
const OVERFLOW_ENTRIES: u32 = 2u;

// Sweep entries: key = strip << q | the quantised lower bound on the sweep axis (QUANT_BITS, from
// axis.wgsl) cut to its top q bits, q = min(QUANT_BITS, KEY_BITS - bits of the strip index), so
// that a key fits in KEY_BITS (three 8-bit sort passes). A coarser key only ties more keys: the
// sweep then tests more candidates, which the exact AABB test rejects (sweep.wgsl).
const STRIP_BITS: u32 = 12u;
const MAX_STRIPS: u32 = 4096u;
const QUANT_BITS: u32 = 20u;
const QUANT_MAX: u32 = 1048575u;
const KEY_BITS: u32 = 24u;

// q above, for `strips` strips (MAX_STRIPS at most, so q >= KEY_BITS - STRIP_BITS).
fn key_quant_bits(strips: u32) -> u32 {
  return min(QUANT_BITS, KEY_BITS - (32u - countLeadingZeros(strips - 1u)));
}

// The sweep key of quantised coordinate `q` in strip `strip`; monotone in q.
fn sweep_key(strip: u32, q: u32, quantBits: u32) -> u32 {
  return (strip << quantBits) | (q >> (QUANT_BITS - quantBits));
}

// Indirect-dispatch argument triples (u32 word offsets in the indirect buffer).
const ARGS_EMIT: u32 = 0u;             // sweep emit, one invocation per work item
const ARGS_PAIR_TILES: u32 = 3u;       // pair sort, one workgroup per 1024 pairs
const ARGS_ENTRY_GROUPS: u32 = 6u;     // one invocation per entry
const ARGS_ENTRY_TILES: u32 = 9u;      // entry sort, one workgroup per 1024 entries
const ARGS_ENTRY_BLOCKS: u32 = 12u;    // scans over the entries, one workgroup per 4096

// Proxy flag word (proxyRef.w): shape type in bits 0-1 (b2Shape::e_circle 0, e_edge 1,
// e_polygon 2, e_chain 3), body type in bits 2-3 (b2_staticBody 0, b2_kinematicBody 1,
// b2_dynamicBody 2), then the flags below.
const PROXY_LIVE: u32 = 0x10u;
const PROXY_SENSOR: u32 = 0x20u;
const PROXY_JOINTED: u32 = 0x40u;      // the body has a joint with collideConnected == false

// The live bit of a body slot's bodyFlags word (b2Body::m_flags | type << 16 | BODY_LIVE) and of
// a joint slot's type word; a dead slot's word is 0.
const BODY_LIVE: u32 = 0x80000000u;
const JOINT_LIVE: u32 = 0x80000000u;

// An AABB that overlaps nothing, for dead proxy slots. 3e38 rather than infinity: WGSL
// implementations may assume finite floats.
const EMPTY_AABB: vec4<f32> = vec4<f32>(3e38, 3e38, -3e38, -3e38);

// The b2BodyType in a bodyFlags word (bits 16-17).
fn body_type(flags: u32) -> u32 {
  return (flags >> 16u) & 3u;
}

fn group_index(wid: vec3<u32>, nwg: vec3<u32>) -> u32 {
  return wid.x + wid.y * nwg.x;
}

// Workgroups for `count` items of `per` each, split in 2D (x <= MAX_GROUPS_PER_DIMENSION).
fn dispatch_size(count: u32, per: u32) -> vec3<u32> {
  let groups = (count + per - 1u) / per;
  let x = min(groups, MAX_GROUPS_PER_DIMENSION);
  return vec3<u32>(x, select(1u, (groups + x - 1u) / x, x > 0u), 1u);
}

// The strip of a coordinate on the other axis (floor((v - lo) / h) clamped to [0, strips)).
// Monotone in v: a <= b gives strip(a) <= strip(b).
fn strip_of(v: f32, lo: f32, invH: f32, strips: u32) -> u32 {
  let t = (v - lo) * invH;
  if (t <= 0.0) {
    return 0u;
  }
  return min(u32(t), strips - 1u);
}

// The quantised coordinate on the sweep axis, monotone in v.
fn quantise(v: f32, lo: f32, scale: f32) -> u32 {
  let t = (v - lo) * scale;
  if (t <= 0.0) {
    return 0u;
  }
  return min(u32(t), QUANT_MAX);
}

// Maps a float32 to a u32 whose unsigned order is the float order (negative floats reversed),
// with -0 mapped like +0. Finite inputs only.
fn sortable_key(f: f32) -> u32 {
  var u = bitcast<u32>(f);
  if (u == 0x80000000u) {
    u = 0u;
  }
  if ((u & 0x80000000u) != 0u) {
    return ~u;
  }
  return u | 0x80000000u;
}

// Workgroup-wide exclusive prefix sum (a raking scan: 16 invocations each scan 16 values, one
// scans the 16 segment totals; three barriers, where a Hillis-Steele scan needs sixteen, which
// matters on CPU implementations such as SwiftShader). Every invocation of the workgroup must
// call it (uniform control flow); `wg_scan_total` holds the sum until the next call.
var<workgroup> wg_scan: array<u32, 256>;
var<workgroup> wg_scan_segment: array<u32, 16>;
var<workgroup> wg_scan_total: u32;

fn workgroup_exclusive_scan(lid: u32, value: u32) -> u32 {
  wg_scan[lid] = value;
  workgroupBarrier();
  if (lid < 16u) {
    var sum = 0u;
    for (var i = 0u; i < 16u; i = i + 1u) {
      let v = wg_scan[lid * 16u + i];
      wg_scan[lid * 16u + i] = sum;
      sum = sum + v;
    }
    wg_scan_segment[lid] = sum;
  }
  workgroupBarrier();
  if (lid == 0u) {
    var sum = 0u;
    for (var i = 0u; i < 16u; i = i + 1u) {
      let v = wg_scan_segment[i];
      wg_scan_segment[i] = sum;
      sum = sum + v;
    }
    wg_scan_total = sum;
  }
  workgroupBarrier();
  return wg_scan[lid] + wg_scan_segment[lid / 16u];
}

// ---- The narrow phase (src-gpu/device/layout.ts NP, BIN, NP_ARGS, MF) ----

// Word indices of the narrow phase's state buffer (array<u32>, 32 words).
const NP_COUNT_0: u32 = 0u;            // contacts held by contact set 0 (the sets alternate per step)
const NP_COUNT_1: u32 = 1u;            // contacts held by contact set 1
const NP_CONTACTS: u32 = 2u;           // contacts this step: min(pairs, capacity)
const NP_PREV: u32 = 3u;               // contacts of the previous step (the other set)
const NP_CAPACITY: u32 = 4u;           // contacts the buffers hold (host)
const NP_OVERFLOW: u32 = 5u;           // OVERFLOW_CONTACTS when the pairs did not fit
const NP_PAIRS: u32 = 6u;              // pairs the broad phase handed over (the capacity needed)
const NP_SOLVER: u32 = 7u;             // touching non-sensor contacts (the solver list's length)
const NP_EVENTS: u32 = 8u;             // begin/end events
const NP_EVENT_SLOTS: u32 = 9u;        // NP_CONTACTS + NP_PREV (the event scan's length)
const NP_KEPT: u32 = 10u;              // contacts kept from the previous step, not collided (BIN_KEPT)
const NP_BINS: u32 = 16u;              // 9 words: first contact of bin b in the binned list, then the end

const OVERFLOW_CONTACTS: u32 = 1u;

// Pair-type bins (contact A/B as b2Contact::Create orders them).
const BIN_CIRCLES: u32 = 0u;           // circle A, circle B
const BIN_POLYGON_CIRCLE: u32 = 1u;    // polygon A, circle B
const BIN_POLYGONS: u32 = 2u;          // polygon A, polygon B
const BIN_EDGE_CIRCLE: u32 = 3u;       // edge A, circle B
const BIN_EDGE_POLYGON: u32 = 4u;      // edge A, polygon B
const BIN_CHAIN_CIRCLE: u32 = 5u;      // chain child A, circle B
const BIN_CHAIN_POLYGON: u32 = 6u;     // chain child A, polygon B
const BIN_SENSOR: u32 = 7u;            // either fixture is a sensor: b2TestOverlap only
const BIN_NONE: u32 = 8u;              // no contact type (not produced by the broad phase)
const BIN_KEPT: u32 = 9u;              // sort digit only: neither body awake and non-static, no kernel runs
const BIN_COUNT: u32 = 8u;

// Bit of contactRef's flag word (bin << 4 | CONTACT_KEPT | sensor << 1 | swapped): the contact
// keeps the previous step's manifold (contacts.wgsl `keep`, persist.wgsl).
const CONTACT_KEPT: u32 = 0x4u;

// Indirect-dispatch triples of the narrow phase (u32 word offsets in its indirect buffer).
const NP_ARGS_CONTACTS: u32 = 0u;      // one invocation per contact
const NP_ARGS_TILES: u32 = 3u;         // bin sort, one workgroup per 1024 contacts
const NP_ARGS_BLOCKS: u32 = 6u;        // scans over the contacts, one workgroup per 4096
const NP_ARGS_PREV: u32 = 9u;          // one invocation per contact of the previous step
const NP_ARGS_EVENT_SLOTS: u32 = 12u;  // one invocation per event slot (contacts, then previous contacts)
const NP_ARGS_EVENT_BLOCKS: u32 = 15u; // the event scan, one workgroup per 4096 slots
const NP_ARGS_SOLVER: u32 = 18u;       // one invocation per solver contact
const NP_ARGS_BINS: u32 = 21u;         // + 3 * bin: one invocation per contact of the bin

// Contact flags in the manifold header word (bits 0-1 b2Manifold::Type, bits 2-3 pointCount).
const MF_TOUCHING: u32 = 0x10u;        // b2Contact::e_touchingFlag after this step's update
const MF_SENSOR: u32 = 0x20u;          // either fixture is a sensor (no manifold, no solver contact)
const MF_BEGAN: u32 = 0x40u;           // BeginContact: touching now, not before
const MF_ENDED: u32 = 0x80u;           // EndContact: touching before, not now
const MF_WARM: u32 = 0x100u;           // matched a contact of the previous step
const MF_SWAPPED: u32 = 0x200u;        // fixture A is the pair's second proxy (b2Contact::Create swapped)
const MF_SOLVED: u32 = 0x400u;         // solved this step (an awake island's): b2Island::Report gives it PostSolve

const NO_CONTACT: u32 = 0xffffffffu;
const EVENT_BEGIN: u32 = 1u;
const EVENT_END: u32 = 2u;

// ---- The solver (src-gpu/device/layout.ts SV, SV_ARGS, COLOUR_CAP, CONSTRAINT_VEC4) ----

// Word indices of the solver's state buffer (array<u32>, SV_STATE_WORDS words).
const SV_SKIP: u32 = 0u;               // 1 when the collision passes overflowed: this submission solves nothing
const SV_COUNT: u32 = 1u;              // solver contacts this step (npState[NP_SOLVER], or 0 when skipping)
const SV_MIN_SEPARATION: u32 = 2u;     // sortable_key of this position iteration's minimum separation
const SV_POSITION_ITERATIONS: u32 = 3u; // position iterations that ran (2.2.1's early exit stops the rest)
const SV_POSITION_DONE: u32 = 4u;      // 1 once an iteration ended with every separation >= -3 b2_linearSlop and the joints within slop
const SV_JOINT_ERROR: u32 = 5u;        // 1 when a joint of this position iteration is not within b2_linearSlop / b2_angularSlop
const SV_JOINTS: u32 = 6u;             // joint slots: the colouring's items are joint slots, then solver contacts (k + SV_JOINTS)
const SV_ITEMS: u32 = 7u;              // items to colour and solve: SV_JOINTS + SV_COUNT, or 0 when skipping
const SV_COLOUR_START: u32 = 8u;       // COLOUR_CAP + 2 words: first entry of colour c in colourKeys, then the overflow set's end (the idle items follow)
const SV_COLOUR_CHANGED: u32 = 34u;    // 1 when an item's dynamic bodies differ from the last colouring's: colour again
const SV_COLOURED_ITEMS: u32 = 35u;    // SV_ITEMS of the last colouring
const SV_COLOURED_JOINTS: u32 = 36u;   // SV_JOINTS of the last colouring
const SV_COLOUR_SORT_COUNT: u32 = 37u; // items the colour sort sorts: SV_ITEMS when colouring again, else 0
const SV_COLOURS_USED: u32 = 38u;      // colours below COLOUR_CAP up to the last non-empty one (the fused and tail passes stop there; read back)
const SV_PENETRATION: u32 = 39u;       // bits of the step's deepest penetration after its last motion (f32 >= 0, so atomicMax orders it: penetration.wgsl; read back)
const SV_AWAKE: u32 = 40u;             // non-static bodies awake at the end of the step (islands.wgsl `sleep`; read back)

// Colours of the graph colouring; colour COLOUR_CAP is the overflow set (solved in order by one invocation).
const COLOUR_CAP: u32 = 24u;
// An item with no dynamic body (a sleeping island's contact, a joint not solved): after the overflow set, solved by no pass.
const COLOUR_IDLE: u32 = 25u;
const UNCOLOURED: u32 = 0xffffffffu;

// Indirect-dispatch triples of the solver (u32 word offsets in its indirect buffer).
const SV_ARGS_CONTACTS: u32 = 0u;      // one invocation per solver contact
const SV_ARGS_TILES: u32 = 3u;         // the colour sort, one workgroup per 1024 items
const SV_ARGS_COLOURS: u32 = 6u;       // + 3 * colour: the warm-start and velocity passes over one colour; + 3 * COLOUR_CAP: the tail pass
const SV_ARGS_POSITION: u32 = 81u;     // + 3 * colour: the position passes, then the tail's (all zeroed by the early exit)
const SV_ARGS_ITEMS: u32 = 156u;       // one invocation per item (the comparison with the last colouring)
const SV_ARGS_ROUNDS: u32 = 159u;      // one invocation per item when colouring again, else none (the rounds)

// vec4s per solver contact in the constraint buffer (solverCommon.wgsl lists them).
const CONSTRAINT_VEC4: u32 = 13u;
