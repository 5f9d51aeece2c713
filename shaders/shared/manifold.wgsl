// manifold.wgsl: what the narrow-phase kernels (collideCircle, collidePolygon, collideEdge,
// overlap) share; the host prepends it to each of them after common.wgsl.
//
// In:  the binned contact list (binned[k].y = contact index; bin b holds entries
//      [npState[NP_BINS + b], npState[NP_BINS + b + 1]); the kept contacts of sleeping or static
//      bodies come after every bin and no kernel reads them), contactRef (the oriented fixtures,
//      children and bodies of each contact, contacts.wgsl), and the world mirror's fixtureShape,
//      shapePool, bodyXf and bodyCell (src-gpu/device/layout.ts).
// Out: manifolds[4c .. 4c + 3) of each contact c of the bin, b2Manifold as the contact's
//      Evaluate leaves it: [header = type | pointCount << 2 | MF_TOUCHING, id key of point 0,
//      id key of point 1, -], [localNormal, localPoint], [points[0].localPoint,
//      points[1].localPoint]; word 3 (the impulses) and the other flags are persist.wgsl's. A
//      manifold without points is all zeros (the engine leaves type and normal stale there).
// Invariants: float32 throughout, the operations in the order of the engine's float64 code
// (b2CollideCircle.ts, b2CollidePolygon.ts, b2CollideEdge.ts, b2Collision.ts), so the results
// differ from the engine's by float32 rounding only. Transforms are relative to body A's cell:
// A's position is its cell offset, B's is (cell B - cell A) * cellSize + its offset, exact for
// bodies within 2^24 cells of each other, and every output is in a body's own frame.

struct CollideParams {
  cellSize: f32,
  pad0: u32,
  pad1: u32,
  pad2: u32,
}

@group(0) @binding(0) var<uniform> params: CollideParams;
@group(0) @binding(1) var<storage, read> npState: array<u32>;
@group(0) @binding(2) var<storage, read> binned: array<vec2<u32>>;
@group(0) @binding(3) var<storage, read> contactRef: array<vec4<u32>>;
@group(0) @binding(4) var<storage, read> fixtureShape: array<vec4<u32>>;
@group(0) @binding(5) var<storage, read> shapePool: array<vec2<f32>>;
@group(0) @binding(6) var<storage, read> bodyXf: array<vec4<f32>>;
@group(0) @binding(7) var<storage, read> bodyCell: array<vec2<i32>>;
@group(0) @binding(8) var<storage, read_write> manifolds: array<vec4<u32>>;

// b2Settings.h, as float32.
const MAX_FLOAT: f32 = 0x1.fffffep+127f;     // b2_maxFloat (FLT_MAX)
const EPSILON: f32 = 0x1p-23f;              // b2_epsilon (FLT_EPSILON)
// b2Manifold::Type (E_*), b2ContactFeature::Type (F_*), b2_angularSlop and b2_polygonRadius: the
// engine's constants (src-gpu/device/engineWgsl.ts).

// A b2Transform: p, and the rotation (c, s).
struct Xf {
  p: vec2<f32>,
  c: f32,
  s: f32,
}

// A b2Manifold without the impulses.
struct Manifold {
  kind: u32,
  count: u32,
  normal: vec2<f32>,
  point: vec2<f32>,
  p0: vec2<f32>,
  p1: vec2<f32>,
  id0: u32,
  id1: u32,
}

struct Circle {
  p: vec2<f32>,
  radius: f32,
}

struct Polygon {
  v: array<vec2<f32>, 8>,
  n: array<vec2<f32>, 8>,
  count: u32,
  centroid: vec2<f32>,
  radius: f32,
}

// A b2EdgeShape (or a chain child, as b2ChainShape::GetChildEdge builds it).
struct Edge {
  v0: vec2<f32>,
  v1: vec2<f32>,
  v2: vec2<f32>,
  v3: vec2<f32>,
  has0: bool,
  has3: bool,
  radius: f32,
}

// A b2ClipVertex pair and how many of it are valid.
struct Clip {
  v0: vec2<f32>,
  v1: vec2<f32>,
  id0: u32,
  id1: u32,
  count: u32,
}

// b2ContactID::key of b2ContactFeature {indexA, indexB, typeA, typeB}.
fn feature(indexA: u32, indexB: u32, typeA: u32, typeB: u32) -> u32 {
  return (indexA & 0xffu) | ((indexB & 0xffu) << 8u) | ((typeA & 0xffu) << 16u) | ((typeB & 0xffu) << 24u);
}

// The feature with A and B swapped (b2CollidePolygons' flip, b2EPCollider's e_faceB points).
fn swap_feature(key: u32) -> u32 {
  return ((key & 0xffu) << 8u) | ((key >> 8u) & 0xffu) | ((key & 0xff0000u) << 8u) | ((key >> 8u) & 0xff0000u);
}

fn mul_xv(xf: Xf, v: vec2<f32>) -> vec2<f32> {
  return vec2<f32>(xf.c * v.x - xf.s * v.y + xf.p.x, xf.s * v.x + xf.c * v.y + xf.p.y);
}

fn mul_txv(xf: Xf, v: vec2<f32>) -> vec2<f32> {
  let px = v.x - xf.p.x;
  let py = v.y - xf.p.y;
  return vec2<f32>(xf.c * px + xf.s * py, -xf.s * px + xf.c * py);
}

fn mul_rv(xf: Xf, v: vec2<f32>) -> vec2<f32> {
  return vec2<f32>(xf.c * v.x - xf.s * v.y, xf.s * v.x + xf.c * v.y);
}

fn mul_trv(xf: Xf, v: vec2<f32>) -> vec2<f32> {
  return vec2<f32>(xf.c * v.x + xf.s * v.y, -xf.s * v.x + xf.c * v.y);
}

// b2MulT(A, B) for transforms.
fn mul_txx(a: Xf, b: Xf) -> Xf {
  let dx = b.p.x - a.p.x;
  let dy = b.p.y - a.p.y;
  let s = a.c * b.s - a.s * b.c;
  let c = a.c * b.c + a.s * b.s;
  return Xf(vec2<f32>(a.c * dx + a.s * dy, -a.s * dx + a.c * dy), c, s);
}

fn dot2(a: vec2<f32>, b: vec2<f32>) -> f32 {
  return a.x * b.x + a.y * b.y;
}

// b2Vec2::Normalize: unchanged when shorter than b2_epsilon.
fn normalize2(v: vec2<f32>) -> vec2<f32> {
  let length = sqrt(v.x * v.x + v.y * v.y);
  if (length < EPSILON) {
    return v;
  }
  let inv = 1.0 / length;
  return vec2<f32>(v.x * inv, v.y * inv);
}

// b2ClipSegmentToLine.
fn clip_segment(inV0: vec2<f32>, inId0: u32, inV1: vec2<f32>, inId1: u32, normal: vec2<f32>, offset: f32, vertexIndexA: u32) -> Clip {
  var out = Clip(vec2<f32>(0.0), vec2<f32>(0.0), 0u, 0u, 0u);
  let distance0 = dot2(normal, inV0) - offset;
  let distance1 = dot2(normal, inV1) - offset;
  if (distance0 <= 0.0) {
    out.v0 = inV0;
    out.id0 = inId0;
    out.count = 1u;
  }
  if (distance1 <= 0.0) {
    if (out.count == 0u) {
      out.v0 = inV1;
      out.id0 = inId1;
    } else {
      out.v1 = inV1;
      out.id1 = inId1;
    }
    out.count = out.count + 1u;
  }
  if (distance0 * distance1 < 0.0) {
    let interp = distance0 / (distance0 - distance1);
    let v = vec2<f32>(inV0.x + interp * (inV1.x - inV0.x), inV0.y + interp * (inV1.y - inV0.y));
    let id = feature(vertexIndexA, (inId0 >> 8u) & 0xffu, F_VERTEX, F_FACE);
    if (out.count == 0u) {
      out.v0 = v;
      out.id0 = id;
    } else {
      out.v1 = v;
      out.id1 = id;
    }
    out.count = out.count + 1u;
  }
  return out;
}

fn empty_manifold() -> Manifold {
  return Manifold(0u, 0u, vec2<f32>(0.0), vec2<f32>(0.0), vec2<f32>(0.0), vec2<f32>(0.0), 0u, 0u);
}

fn store_manifold(c: u32, m: Manifold) {
  var header = 0u;
  if (m.count > 0u) {
    header = m.kind | (m.count << 2u) | MF_TOUCHING;
  }
  manifolds[4u * c] = vec4<u32>(header, m.id0, m.id1, 0u);
  manifolds[4u * c + 1u] = bitcast<vec4<u32>>(vec4<f32>(m.normal, m.point));
  manifolds[4u * c + 2u] = bitcast<vec4<u32>>(vec4<f32>(m.p0, m.p1));
}

// The contact index of entry k of bin `bin`, or NO_CONTACT past the bin's end.
fn binned_contact(bin: u32, wid: vec3<u32>, nwg: vec3<u32>, lid: u32) -> u32 {
  let k = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  let start = npState[NP_BINS + bin];
  if (start + k >= npState[NP_BINS + bin + 1u]) {
    return NO_CONTACT;
  }
  return binned[start + k].y;
}

// A body's transform relative to the cell `origin`.
fn body_transform(body: u32, origin: vec2<i32>) -> Xf {
  let x = bodyXf[body];
  let d = bodyCell[body] - origin;
  return Xf(vec2<f32>(d) * params.cellSize + x.xy, x.z, x.w);
}

fn shape_radius(fixture: u32) -> f32 {
  return bitcast<f32>(fixtureShape[fixture].w);
}

fn load_circle(fixture: u32) -> Circle {
  let shape = fixtureShape[fixture];
  return Circle(shapePool[shape.y], bitcast<f32>(shape.w));
}

fn load_polygon(fixture: u32) -> Polygon {
  let shape = fixtureShape[fixture];
  let count = (shape.x >> 8u) & 0xffu;
  var poly: Polygon;
  for (var i = 0u; i < 8u; i = i + 1u) {
    poly.v[i] = vec2<f32>(0.0);
    poly.n[i] = vec2<f32>(0.0);
  }
  for (var i = 0u; i < count; i = i + 1u) {
    poly.v[i] = shapePool[shape.y + i];
    poly.n[i] = shapePool[shape.y + count + i];
  }
  poly.count = count;
  poly.centroid = shapePool[shape.y + 2u * count];
  poly.radius = bitcast<f32>(shape.w);
  return poly;
}

// An edge fixture, or child `child` of a chain fixture (b2ChainShape::GetChildEdge).
fn load_edge(fixture: u32, child: u32) -> Edge {
  let shape = fixtureShape[fixture];
  let flags = (shape.x >> 4u) & 0xfu;
  let base = shape.y;
  var e: Edge;
  e.radius = bitcast<f32>(shape.w);
  if ((shape.x & 0xfu) == SHAPE_EDGE) {
    e.v1 = shapePool[base];
    e.v2 = shapePool[base + 1u];
    e.v0 = shapePool[base + 2u];
    e.v3 = shapePool[base + 3u];
    e.has0 = (flags & 1u) != 0u;
    e.has3 = (flags & 2u) != 0u;
    return e;
  }
  let count = (shape.x >> 8u) & 0xffffffu;
  e.v1 = shapePool[base + child];
  e.v2 = shapePool[base + child + 1u];
  if (child > 0u) {
    e.v0 = shapePool[base + child - 1u];
    e.has0 = true;
  } else {
    e.v0 = shapePool[base + count];
    e.has0 = (flags & 1u) != 0u;
  }
  if (child + 2u < count) {
    e.v3 = shapePool[base + child + 2u];
    e.has3 = true;
  } else {
    e.v3 = shapePool[base + count + 1u];
    e.has3 = (flags & 2u) != 0u;
  }
  return e;
}
