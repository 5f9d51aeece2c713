// bounds.wgsl: stage 1 of the broad phase, the fattened AABB of every proxy slot.
//
// In:  proxyRef[p]     = (fixture slot, child index, body slot, flag word); PROXY_LIVE marks a live slot
//      fixtureShape[f] = (type | flags << 4 | vertexCount << 8, pool offset, body slot, radius as f32 bits)
//      shapePool[]     = vec2 shape data at each fixture's pool offset (layout in src-gpu/layout.ts)
//      bodyXf[b]       = (p.x, p.y, q.c, q.s): the body origin relative to its cell, and its rotation
//      bodyCell[b]     = the body's cell: world position = cell * cellSize + local
// Out: proxyAABB[p]    = (lower.x, lower.y, upper.x, upper.y) relative to the world origin cell,
//                        the child's b2Shape::ComputeAABB at the body transform, extended by
//                        `extension` (b2_aabbExtension) on every side; EMPTY_AABB for dead slots.
// Invariants: one invocation per slot in [0, count); reads nothing another invocation writes.
// Precision: local coordinates (a few cells at most) round at float32 ulp(local) ~ 1e-6 m; the
// one addition of the cell offset rounds at 0.5 ulp(|world coordinate|), 2.4e-4 m at 5 km.

struct BoundsParams {
  count: u32,
  extension: f32,
  cellSize: f32,
  pad0: u32,
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

// b2Mul(xf, v) with the rotation (c, s) and the local origin p, as the JS engine writes it.
fn transform_point(xf: vec4<f32>, v: vec2<f32>) -> vec2<f32> {
  return vec2<f32>(xf.z * v.x - xf.w * v.y + xf.x, xf.w * v.x + xf.z * v.y + xf.y);
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
  let child = proxy.y;
  let body = proxy.z;
  let xf = bodyXf[body];
  let shapeType = shape.x & 0xfu;
  let count = shape.x >> 8u;
  let offset = shape.y;
  let radius = bitcast<f32>(shape.w);

  var lower: vec2<f32>;
  var upper: vec2<f32>;
  var r = radius;
  if (shapeType == 0u) {
    // b2CircleShape: p = xf.p + R * m_p
    let c = shapePool[offset];
    let q = vec2<f32>(xf.z * c.x - xf.w * c.y, xf.w * c.x + xf.z * c.y);
    let centre = xf.xy + q;
    lower = centre;
    upper = centre;
  } else if (shapeType == 2u) {
    // b2PolygonShape: the transformed vertices' bounds
    let v0 = transform_point(xf, shapePool[offset]);
    lower = v0;
    upper = v0;
    for (var i = 1u; i < count; i = i + 1u) {
      let v = transform_point(xf, shapePool[offset + i]);
      lower = min(lower, v);
      upper = max(upper, v);
    }
  } else {
    // b2EdgeShape (vertex1, vertex2 first in its pool entry) or one edge of a b2ChainShape.
    var i1 = offset;
    var i2 = offset + 1u;
    if (shapeType == 3u) {
      // b2ChainShape::ComputeAABB (2.2.1) wraps i2 to 0 and adds no radius.
      i1 = offset + child;
      var j = child + 1u;
      if (j == count) {
        j = 0u;
      }
      i2 = offset + j;
      r = 0.0;
    }
    let v1 = transform_point(xf, shapePool[i1]);
    let v2 = transform_point(xf, shapePool[i2]);
    lower = min(v1, v2);
    upper = max(v1, v2);
  }

  let margin = r + params.extension;
  let base = vec2<f32>(bodyCell[body] - params.originCell) * params.cellSize;
  proxyAABB[p] = vec4<f32>(base + (lower - vec2<f32>(margin)), base + (upper + vec2<f32>(margin)));
}
