// bounds.wgsl: broad phase, the fattened AABB of every proxy slot, swept over the
// body's last motion and the motion predicted for the coming step.
//
// In:  proxyRef[p]     = (fixture slot, child index, body slot, flag word); PROXY_LIVE marks a live slot
//      fixtureShape[f] = (type | flags << 4 | vertexCount << 8, pool offset, body slot, radius as f32 bits)
//      shapePool[]     = vec2 shape data at each fixture's pool offset (layout in src-gpu/device/layout.ts)
//      bodyXf[b]       = (p.x, p.y, q.c, q.s): the body origin relative to its cell, and its rotation
//      bodyCell[b]     = the body's cell: world position = cell * cellSize + local
//      bodySweep[b]    = (c0, a0, alpha0 | c, a, sleepTime): the last step's motion (b2Sweep)
//      bodyVel[b]      = (v, w, 0)
// Out: proxyAABB[p]    = (lower.x, lower.y, upper.x, upper.y) relative to the world origin cell:
//                        the union of the child's b2Shape::ComputeAABB at the sweep's start
//                        (q = R(a0), p = c0 - q localCenter) and at the body transform, as
//                        b2Fixture::Synchronize sweeps it, extended by `extension`
//                        (b2_aabbExtension) on every side, then in the direction of
//                        b2_aabbMultiplier x the last displacement (p - p0, as b2DynamicTree::
//                        MoveProxy predicts) and of b2_aabbMultiplier x predictTime x v (the coming
//                        step's motion: continuous collision, timeOfImpact.wgsl, tests this step's
//                        contacts after the solve); EMPTY_AABB for dead slots.
// Invariants: one invocation per slot in [0, count); reads nothing another invocation writes.
//      A body that did not move in its last step (c0 == c, a0 == a) and has no velocity gets
//      exactly the AABB at its transform.
// Precision: local coordinates (a few cells at most) round at float32 ulp(local) ~ 1e-6 m; the
// one addition of the cell offset rounds at 0.5 ulp(|world coordinate|), 2.4e-4 m at 5 km.

struct BoundsParams {
  count: u32,
  extension: f32,
  cellSize: f32,
  predictTime: f32,       // the coming step's dt as far as known (the last step's), 0 when unknown
  originCell: vec2<i32>,
  pad1: vec2<u32>,
}

@group(0) @binding(0) var<uniform> params: BoundsParams;
@group(0) @binding(1) var<storage, read> proxyRef: array<vec4<u32>>;
@group(0) @binding(2) var<storage, read> fixtureShape: array<vec4<u32>>;
@group(0) @binding(3) var<storage, read> shapePool: array<vec2<f32>>;
@group(0) @binding(4) var<storage, read> bodyXf: array<vec4<f32>>;
@group(0) @binding(5) var<storage, read> bodyCell: array<vec2<i32>>;
@group(0) @binding(6) var<storage, read_write> proxyAABB: array<vec4<f32>>;
@group(0) @binding(7) var<storage, read> bodySweep: array<vec4<f32>>;
@group(0) @binding(8) var<storage, read> bodyVel: array<vec4<f32>>;

// b2_aabbMultiplier (b2Settings.h).
const AABB_MULTIPLIER: f32 = 2.0;

// b2Mul(xf, v) with the rotation (c, s) and the local origin p, as the JS engine writes it.
fn transform_point(xf: vec4<f32>, v: vec2<f32>) -> vec2<f32> {
  return vec2<f32>(xf.z * v.x - xf.w * v.y + xf.x, xf.w * v.x + xf.z * v.y + xf.y);
}

// b2Shape::ComputeAABB of a proxy's child at the transform xf, without the radius (lower, upper).
fn child_bounds(shapeType: u32, count: u32, offset: u32, child: u32, xf: vec4<f32>) -> vec4<f32> {
  if (shapeType == SHAPE_CIRCLE) {
    // b2CircleShape: p = xf.p + R * m_p
    let c = shapePool[offset];
    let q = vec2<f32>(xf.z * c.x - xf.w * c.y, xf.w * c.x + xf.z * c.y);
    let centre = xf.xy + q;
    return vec4<f32>(centre, centre);
  }
  if (shapeType == SHAPE_POLYGON) {
    // b2PolygonShape: the transformed vertices' bounds
    let v0 = transform_point(xf, shapePool[offset]);
    var lower = v0;
    var upper = v0;
    for (var i = 1u; i < count; i = i + 1u) {
      let v = transform_point(xf, shapePool[offset + i]);
      lower = min(lower, v);
      upper = max(upper, v);
    }
    return vec4<f32>(lower, upper);
  }
  // b2EdgeShape (vertex1, vertex2 first in its pool entry) or one edge of a b2ChainShape.
  var i1 = offset;
  var i2 = offset + 1u;
  if (shapeType == SHAPE_CHAIN) {
    // b2ChainShape::ComputeAABB (2.2.1) wraps i2 to 0.
    i1 = offset + child;
    var j = child + 1u;
    if (j == count) {
      j = 0u;
    }
    i2 = offset + j;
  }
  let v1 = transform_point(xf, shapePool[i1]);
  let v2 = transform_point(xf, shapePool[i2]);
  return vec4<f32>(min(v1, v2), max(v1, v2));
}

// (1 - cos x, sin x) to float32 accuracy, relative, for |x| <= b2_maxRotation (a step turns a body
// at most that far): Taylor series to x^14 and x^13, whose remainders there are below 1e-9. Not
// WGSL's cos and sin: they are only as accurate as the platform makes them (SwiftShader: about
// 1e-5 absolute, 1e-4 m at 10 m from a body's centre), and 1 - cos x from them cancels.
fn turn(x: f32) -> vec2<f32> {
  if (abs(x) > 1.5707963) {
    return vec2<f32>(1.0 - cos(x), sin(x));
  }
  let x2 = x * x;
  let versine = x2 / 2.0 * (1.0 - x2 / 12.0 * (1.0 - x2 / 30.0 * (1.0 - x2 / 56.0 * (1.0 - x2 / 90.0 * (1.0 - x2 / 132.0 * (1.0 - x2 / 182.0))))));
  let sine = x * (1.0 - x2 / 6.0 * (1.0 - x2 / 20.0 * (1.0 - x2 / 42.0 * (1.0 - x2 / 72.0 * (1.0 - x2 / 110.0 * (1.0 - x2 / 156.0))))));
  return vec2<f32>(versine, sine);
}

@compute @workgroup_size(256)
fn main(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
        @builtin(local_invocation_index) lid: u32) {
  let p = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  if (p >= params.count) {
    return;
  }
  let proxy = proxyRef[p];
  if ((proxy.w & PROXY_LIVE) == 0u) {
    proxyAABB[p] = EMPTY_AABB;
    return;
  }
  let shape = fixtureShape[proxy.x];
  let body = proxy.z;
  let xf = bodyXf[body];
  let shapeType = shape.x & 0xfu;
  let count = shape.x >> 8u;
  // b2ChainShape::ComputeAABB (2.2.1) adds no radius.
  let r = select(bitcast<f32>(shape.w), 0.0, shapeType == SHAPE_CHAIN);

  var box = child_bounds(shapeType, count, shape.y, proxy.y, xf);
  var displacement = vec2<f32>(0.0);
  let s0 = bodySweep[2u * body];
  let s1 = bodySweep[2u * body + 1u];
  if (any(s0.xyz != s1.xyz)) {
    // The sweep's start (q0 = R(a0), p0 = c0 - q0 localCenter) from the transform: R(a0) =
    // R(a) R(a0 - a), localCenter = R(a)^T (c - p), and p - p0 = (c - c0) - (q - q0) localCenter
    // with q - q0 = R(a) (1 - cos(a0 - a), -sin(a0 - a)) (no cancellation: a lever of metres
    // would magnify it), which is c - c0 exactly when the body did not turn.
    let lc = vec2<f32>(xf.z * (s1.x - xf.x) + xf.w * (s1.y - xf.y), -xf.w * (s1.x - xf.x) + xf.z * (s1.y - xf.y));
    let w = turn(s0.z - s1.z);
    let q0 = vec2<f32>(xf.z * (1.0 - w.x) - xf.w * w.y, xf.w * (1.0 - w.x) + xf.z * w.y);
    let dq = vec2<f32>(xf.z * w.x + xf.w * w.y, xf.w * w.x - xf.z * w.y);
    displacement = (s1.xy - s0.xy) - vec2<f32>(dq.x * lc.x - dq.y * lc.y, dq.y * lc.x + dq.x * lc.y);
    let start = child_bounds(shapeType, count, shape.y, proxy.y, vec4<f32>(xf.xy - displacement, q0));
    box = vec4<f32>(min(box.xy, start.xy), max(box.zw, start.zw));
  }
  let d = AABB_MULTIPLIER * displacement;
  let e = AABB_MULTIPLIER * params.predictTime * bodyVel[body].xy;

  // Where the world coordinate is larger than the local one, the margins go on in local
  // coordinates and the cell offset last (one rounding at the world's magnitude); where the cell
  // offset cancels the local coordinate (a body near the origin in a cell beside it), the offset
  // goes first, exactly, and the margins after (roundings at the small result's magnitude).
  let margin = vec2<f32>(r + params.extension);
  let below = margin - min(min(d, e), vec2<f32>(0.0));
  let above = margin + max(max(d, e), vec2<f32>(0.0));
  let base = vec2<f32>(bodyCell[body] - params.originCell) * params.cellSize;
  let worldLower = base + box.xy;
  let worldUpper = base + box.zw;
  let lower = select(worldLower - below, base + (box.xy - below), abs(box.xy) < abs(worldLower));
  let upper = select(worldUpper + above, base + (box.zw + above), abs(box.zw) < abs(worldUpper));
  proxyAABB[p] = vec4<f32>(lower, upper);
}
