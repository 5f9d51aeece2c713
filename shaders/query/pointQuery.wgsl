// pointQuery.wgsl: the dynamic body whose shape holds a world point (GpuPointQuery), as the
// Testbed's MouseDown finds one with b2World::QueryAABB and b2Fixture::TestPoint: `main` tests
// every live proxy's circle or polygon (edges and chains hold no point, as TestPoint says) and
// keeps the lowest body slot; `resolve` writes the point in that body's frame beside it.
//
// In:  query (the point as a cell and an offset, the cell size, the proxy slot count), proxyRef,
//      fixtureShape, shapePool, bodyXf, bodyCell, bodyFlags.
// Out: hit[0]: the lowest slot of a live dynamic body with a shape holding the point, or NO_HIT
//      (the host clears it first); after `resolve`, hit[1..2]: the point in that body's frame
//      (f32 bits).
// Invariants: reads the world and never writes it; `main` runs one invocation per proxy slot,
//      `resolve` a single one after it.

struct Query {
  cell: vec2<i32>,
  offset: vec2<f32>,
  cellSize: f32,
  proxySlots: u32,
}

const NO_HIT: u32 = 0xffffffffu;

@group(0) @binding(0) var<uniform> query: Query;
@group(0) @binding(1) var<storage, read> proxyRef: array<vec4<u32>>;
@group(0) @binding(2) var<storage, read> fixtureShape: array<vec4<u32>>;
@group(0) @binding(3) var<storage, read> shapePool: array<vec2<f32>>;
@group(0) @binding(4) var<storage, read> bodyXf: array<vec4<f32>>;
@group(0) @binding(5) var<storage, read> bodyCell: array<vec2<i32>>;
@group(0) @binding(6) var<storage, read> bodyFlags: array<u32>;
@group(0) @binding(7) var<storage, read_write> hit: array<atomic<u32>>;

// The query point in body `b`'s frame (b2MulT(xf, p)), from offsets relative to the body's cell.
fn local_point(b: u32) -> vec2<f32> {
  let xf = bodyXf[b];
  let d = vec2<f32>(query.cell - bodyCell[b]) * query.cellSize + query.offset - xf.xy;
  return vec2<f32>(xf.z * d.x + xf.w * d.y, -xf.w * d.x + xf.z * d.y);
}

@compute @workgroup_size(256)
fn main(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let proxy = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  if (proxy >= query.proxySlots) {
    return;
  }
  let proxyInfo = proxyRef[proxy];
  let body = proxyInfo.z;
  let flags = bodyFlags[body];
  if ((proxyInfo.w & PROXY_LIVE) == 0u || (flags & BODY_LIVE) == 0u || body_type(flags) != DYNAMIC_BODY) {
    return;
  }
  let shape = fixtureShape[proxyInfo.x];
  let shapeType = shape.x & 0xfu;
  let p = local_point(body);
  var inside = false;
  if (shapeType == SHAPE_CIRCLE) {
    let d = p - shapePool[shape.y];
    let radius = bitcast<f32>(shape.w);
    inside = dot(d, d) <= radius * radius;
  } else if (shapeType == SHAPE_POLYGON) {
    // b2PolygonShape::TestPoint: behind every side's normal.
    let count = shape.x >> 8u;
    inside = true;
    for (var i = 0u; i < count; i = i + 1u) {
      if (dot(shapePool[shape.y + count + i], p - shapePool[shape.y + i]) > 0.0) {
        inside = false;
      }
    }
  }
  if (inside) {
    atomicMin(&hit[0], body);
  }
}

@compute @workgroup_size(1)
fn resolve() {
  let body = atomicLoad(&hit[0]);
  if (body == NO_HIT) {
    return;
  }
  let p = local_point(body);
  atomicStore(&hit[1], bitcast<u32>(p.x));
  atomicStore(&hit[2], bitcast<u32>(p.y));
}
