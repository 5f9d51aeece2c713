// axis.wgsl: broad phase, the layout of the sweep: its axis, and strips across the other axis.
//
// In:  proxyAABB[p] for p in [0, count); dead slots hold EMPTY_AABB (lower > upper) and are skipped.
// Out: `partial` writes one statistic per workgroup to partials[g]; `finish` (one workgroup) merges
//      them and writes to the state buffer:
//        STATE_AXIS       the sweep axis: the one along which the AABB centres vary most (0 x, 1 y);
//        STATE_STRIPS     S, strips of height h across the other axis, h = max(2 x the mean extent
//                         on that axis, range / MAX_STRIPS), S <= live / 32 (no strips for tiny sets);
//        STATE_OTHER_LO, STATE_OTHER_INV_H   where strip 0 starts, 1 / h (f32 bits);
//        STATE_AXIS_LO, STATE_AXIS_SCALE     the quantisation of the sweep axis to QUANT_BITS.
// Why strips: a sweep along one axis tests every proxy whose interval overlaps on that axis, about
// sqrt(n) of them per proxy in a uniform 2D world; within strips about as high as the proxies, only
// the near ones (Liu et al. 2010's subdivision, with one sort for all strips). Because h is at
// least twice the mean extent, a proxy spans on average at most 1.5 strips + 1: the sweep entries
// number at most 2.5 x the proxies, whatever the sizes.
// Invariants: no read-back and no float atomics. Each workgroup reduces ITEMS_PER_GROUP AABBs
// (16 per invocation, strided for coalescing) with Welford's update, then a fixed-shape tree
// merges (Chan et al.'s pairwise formula, stable where sums of squares cancel at 5 km), so the
// layout is the same on every run. The layout only steers performance: any layout gives the same
// pair set.

const ITEMS_PER_INVOCATION: u32 = 16u;
const ITEMS_PER_GROUP: u32 = 4096u;
const STRIP_HEIGHT_FACTOR: f32 = 2.0;
const MIN_PROXIES_PER_STRIP: f32 = 32.0;

struct Stat {
  n: f32,
  pad: f32,
  mean: vec2<f32>,   // mean centre
  m2: vec2<f32>,     // sum of squared deviations of the centres
  ext: vec2<f32>,    // mean extent (upper - lower)
  lo: vec2<f32>,     // lowest lower bound
  hi: vec2<f32>,     // highest upper bound
}

struct AxisParams {
  count: u32,
  partialCount: u32,
  pad0: u32,
  pad1: u32,
}

@group(0) @binding(0) var<uniform> params: AxisParams;
@group(0) @binding(1) var<storage, read> proxyAABB: array<vec4<f32>>;
@group(0) @binding(2) var<storage, read_write> partials: array<Stat>;
@group(0) @binding(3) var<storage, read_write> state: array<u32>;

var<workgroup> shared_stats: array<Stat, 256>;

fn empty_stat() -> Stat {
  return Stat(0.0, 0.0, vec2<f32>(0.0), vec2<f32>(0.0), vec2<f32>(0.0), vec2<f32>(3e38), vec2<f32>(-3e38));
}

fn merge(a: Stat, b: Stat) -> Stat {
  if (b.n == 0.0) {
    return a;
  }
  if (a.n == 0.0) {
    return b;
  }
  let n = a.n + b.n;
  let wb = b.n / n;
  let delta = b.mean - a.mean;
  let mean = a.mean + delta * wb;
  let m2 = a.m2 + b.m2 + delta * delta * (a.n * wb);
  let ext = a.ext + (b.ext - a.ext) * wb;
  return Stat(n, 0.0, mean, m2, ext, min(a.lo, b.lo), max(a.hi, b.hi));
}

fn reduce_shared(lid: u32) {
  for (var stride = 128u; stride > 0u; stride = stride >> 1u) {
    if (lid < stride) {
      shared_stats[lid] = merge(shared_stats[lid], shared_stats[lid + stride]);
    }
    workgroupBarrier();
  }
}

@compute @workgroup_size(256)
fn partial(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
           @builtin(local_invocation_index) lid: u32) {
  let g = group_index(wid, nwg);
  if (g >= params.partialCount) {
    return;
  }
  var s = empty_stat();
  let start = g * ITEMS_PER_GROUP;
  for (var k = 0u; k < ITEMS_PER_INVOCATION; k = k + 1u) {
    let i = start + k * WORKGROUP_SIZE + lid;
    if (i < params.count) {
      let box = proxyAABB[i];
      if (box.x <= box.z) {
        let c = 0.5 * (box.xy + box.zw);
        s.n = s.n + 1.0;
        let d = c - s.mean;
        s.mean = s.mean + d / s.n;
        s.m2 = s.m2 + d * (c - s.mean);
        s.ext = s.ext + ((box.zw - box.xy) - s.ext) / s.n;
        s.lo = min(s.lo, box.xy);
        s.hi = max(s.hi, box.zw);
      }
    }
  }
  shared_stats[lid] = s;
  workgroupBarrier();
  reduce_shared(lid);
  if (lid == 0u) {
    partials[g] = shared_stats[0];
  }
}

@compute @workgroup_size(256)
fn finish(@builtin(local_invocation_index) lid: u32) {
  var s = empty_stat();
  for (var i = lid; i < params.partialCount; i = i + WORKGROUP_SIZE) {
    s = merge(s, partials[i]);
  }
  shared_stats[lid] = s;
  workgroupBarrier();
  reduce_shared(lid);
  if (lid == 0u) {
    let t = shared_stats[0];
    let axis = select(0u, 1u, t.m2.y > t.m2.x);
    let other = 1u - axis;
    var strips = 1u;
    var invH = 0.0;
    var otherLo = 0.0;
    var axisLo = 0.0;
    var scale = 0.0;
    if (t.n > 0.0) {
      otherLo = t.lo[other];
      let range = t.hi[other] - otherLo;
      var h = max(STRIP_HEIGHT_FACTOR * t.ext[other], range / f32(MAX_STRIPS));
      let cap = max(1.0, min(f32(MAX_STRIPS), floor(t.n / MIN_PROXIES_PER_STRIP)));
      if (h > 0.0) {
        strips = u32(clamp(ceil(range / h), 1.0, cap));
        h = max(h, range / f32(strips));
        invH = 1.0 / h;
      }
      axisLo = t.lo[axis];
      let axisRange = t.hi[axis] - axisLo;
      if (axisRange > 0.0) {
        scale = f32(QUANT_MAX) / axisRange;
      }
    }
    state[STATE_AXIS] = axis;
    state[STATE_STRIPS] = strips;
    state[STATE_OTHER_LO] = bitcast<u32>(otherLo);
    state[STATE_OTHER_INV_H] = bitcast<u32>(invH);
    state[STATE_AXIS_LO] = bitcast<u32>(axisLo);
    state[STATE_AXIS_SCALE] = bitcast<u32>(scale);
  }
}
