// keys.wgsl: broad phase, the sweep entries and their sort keys.
//
// A proxy gets one entry in each strip its AABB spans on the other axis (axis.wgsl chose the
// strips). An entry is (key, proxy slot), key = sweep_key(strip, quantised lower bound on the
// sweep axis) (common.wgsl: KEY_BITS bits), so that one sort orders the entries by strip, then
// along the sweep axis.
// In:  proxyAABB[p] for p in [0, count) (dead slots: lower > upper); the layout in the state
//      buffer (STATE_AXIS, STATE_STRIPS, STATE_OTHER_*, STATE_AXIS_*); STATE_ENTRY_CAPACITY.
//      proxyRef[p], proxyFilter[p] (body, flag word; category, mask, group).
// Out: items[0, E) = (key, slot), E = state[STATE_ENTRIES]; replicaOffset[p]; indirect sizes;
//      proxyRecords[2p, 2p + 1] for live proxies: what the sweep's gather reads of a proxy, in one
//      32-byte sector (sweep.wgsl: reading three tables at the sorted entries' random slots cost
//      twice as much at 10^6 proxies).
// Passes:
//   `replicas`  replicaOffset[p] = strips spanned by live proxy p (0 for a dead slot);
//   (scan.wgsl makes them exclusive offsets; the total goes to state[STATE_ENTRY_TOTAL])
//   `size_args` state[STATE_ENTRIES] = the total, or 0 and OVERFLOW_ENTRIES when it passes the
//               host-given capacity (the host grows the entry buffers and redoes the update);
//               the indirect sizes of the passes over the entries (ARGS_ENTRY_*);
//   `entries`   items[replicaOffset[p] + i] = (key of strip lo + i, p); proxyRecords[2p] = the
//               sortable keys of the AABB with the sweep axis first (min axis, min other, max
//               axis, max other), proxyRecords[2p + 1] = (body, category | mask << 16, group
//               (int16 bits) | flag word << 16, lo << QUANT_BITS | the quantised upper bound on
//               the sweep axis).
// Invariants: entries of a proxy are consecutive and in strip order; the quantisation and the
// strip of a coordinate are monotone, so a <= b on floats gives key(a) <= key(b) in a strip.

struct KeysParams {
  count: u32,
  pad0: u32,
  pad1: u32,
  pad2: u32,
}

@group(0) @binding(0) var<uniform> params: KeysParams;
@group(0) @binding(1) var<storage, read> proxyAABB: array<vec4<f32>>;
@group(0) @binding(2) var<storage, read_write> state: array<u32>;
@group(0) @binding(3) var<storage, read_write> replicaOffset: array<u32>;
@group(0) @binding(4) var<storage, read_write> items: array<vec2<u32>>;
@group(0) @binding(5) var<storage, read_write> indirect: array<u32>;
@group(0) @binding(6) var<storage, read> proxyRef: array<vec4<u32>>;
@group(0) @binding(7) var<storage, read> proxyFilter: array<vec2<u32>>;
@group(0) @binding(8) var<storage, read_write> proxyRecords: array<vec4<u32>>;

struct SweepLayout {
  axis: u32,
  strips: u32,
  otherLo: f32,
  invH: f32,
  axisLo: f32,
  scale: f32,
}

fn read_layout() -> SweepLayout {
  return SweepLayout(state[STATE_AXIS], state[STATE_STRIPS], bitcast<f32>(state[STATE_OTHER_LO]),
                bitcast<f32>(state[STATE_OTHER_INV_H]), bitcast<f32>(state[STATE_AXIS_LO]),
                bitcast<f32>(state[STATE_AXIS_SCALE]));
}

@compute @workgroup_size(256)
fn replicas(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
            @builtin(local_invocation_index) lid: u32) {
  let p = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  if (p >= params.count) {
    return;
  }
  let box = proxyAABB[p];
  var n = 0u;
  if (box.x <= box.z) {
    let l = read_layout();
    let other = 1u - l.axis;
    let lo = strip_of(box[other], l.otherLo, l.invH, l.strips);
    let hi = strip_of(box[2u + other], l.otherLo, l.invH, l.strips);
    n = hi - lo + 1u;
  }
  replicaOffset[p] = n;
}

@compute @workgroup_size(1)
fn size_args() {
  let total = state[STATE_ENTRY_TOTAL];
  var entries = total;
  if (total > state[STATE_ENTRY_CAPACITY]) {
    state[STATE_OVERFLOW] = state[STATE_OVERFLOW] | OVERFLOW_ENTRIES;
    entries = 0u;
  }
  state[STATE_ENTRIES] = entries;
  let a = dispatch_size(entries, WORKGROUP_SIZE);
  let b = dispatch_size(entries, 1024u);
  let c = dispatch_size(entries, 4096u);
  for (var i = 0u; i < 3u; i = i + 1u) {
    indirect[ARGS_ENTRY_GROUPS + i] = a[i];
    indirect[ARGS_ENTRY_TILES + i] = b[i];
    indirect[ARGS_ENTRY_BLOCKS + i] = c[i];
  }
}

@compute @workgroup_size(256)
fn entries(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
           @builtin(local_invocation_index) lid: u32) {
  let p = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  if (p >= params.count) {
    return;
  }
  let box = proxyAABB[p];
  if (box.x > box.z) {
    return;
  }
  let l = read_layout();
  let other = 1u - l.axis;
  let lo = strip_of(box[other], l.otherLo, l.invH, l.strips);
  let hi = strip_of(box[2u + other], l.otherLo, l.invH, l.strips);
  let q = quantise(box[l.axis], l.axisLo, l.scale);
  let quantBits = key_quant_bits(l.strips);
  let keys = vec4<u32>(sortable_key(box.x), sortable_key(box.y), sortable_key(box.z), sortable_key(box.w));
  let proxy = proxyRef[p];
  let filterBits = proxyFilter[p];
  // lo < MAX_STRIPS = 2^STRIP_BITS and the bound <= QUANT_MAX: they share one word.
  let upper = quantise(box[2u + l.axis], l.axisLo, l.scale);
  proxyRecords[2u * p] = select(keys, keys.yxwz, l.axis == 1u);
  proxyRecords[2u * p + 1u] = vec4<u32>(proxy.z, filterBits.x, (filterBits.y & 0xffffu) | (proxy.w << 16u), (lo << QUANT_BITS) | upper);
  let capacity = state[STATE_ENTRY_CAPACITY];
  let first = replicaOffset[p];
  for (var k = lo; k <= hi; k = k + 1u) {
    let index = first + (k - lo);
    if (index < capacity) {
      items[index] = vec2<u32>(sweep_key(k, q, quantBits), p);
    }
  }
}
