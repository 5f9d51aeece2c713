// keys.wgsl: stage 3, the sweep entries and their sort keys.
//
// A proxy gets one entry in each strip its AABB spans on the other axis (axis.wgsl chose the
// strips). An entry is (key, proxy slot), key = sweep_key(strip, quantised lower bound on the
// sweep axis) (common.wgsl: KEY_BITS bits), so that one sort orders the entries by strip, then
// along the sweep axis.
// In:  proxyAABB[p] for p in [0, count) (dead slots: lower > upper); the layout in the state
//      buffer (STATE_AXIS, STATE_STRIPS, STATE_OTHER_*, STATE_AXIS_*); STATE_ENTRY_CAPACITY.
// Out: items[0, E) = (key, slot), E = state[STATE_ENTRIES]; replicaOffset[p]; indirect sizes.
// Passes:
//   `replicas`  replicaOffset[p] = strips spanned by live proxy p (0 for a dead slot);
//   (scan.wgsl makes them exclusive offsets; the total goes to state[STATE_ENTRY_TOTAL])
//   `size_args` state[STATE_ENTRIES] = the total, or 0 and OVERFLOW_ENTRIES when it passes the
//               host-given capacity (the host grows the entry buffers and redoes the update);
//               the indirect sizes of the passes over the entries (ARGS_ENTRY_*);
//   `entries`   items[replicaOffset[p] + i] = (key of strip lo + i, p).
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
  let capacity = state[STATE_ENTRY_CAPACITY];
  let first = replicaOffset[p];
  for (var k = lo; k <= hi; k = k + 1u) {
    let index = first + (k - lo);
    if (index < capacity) {
      items[index] = vec2<u32>(sweep_key(k, q, quantBits), p);
    }
  }
}
