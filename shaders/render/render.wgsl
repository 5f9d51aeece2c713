// render.wgsl: draws the world straight from the solver's buffers (GpuRenderer): the proxies that
// cull.wgsl listed, each list with its own pipeline (LIST) and indirect draw: shapes filled
// (`fill_vertex`: circles and polygons), outlined (`outline_vertex`: circles with their radius
// line, polygons, edges and chain children) or, too small to see, drawn as one pixel at their
// centre (`point_vertex`); and every live joint as b2World::DrawJoint draws it (`joint_vertex`),
// in the colour cull.wgsl gave each body.
//
// In:  view (camera cell and offset, clip units per metre, cell size, list stride), visible (the
//      draw lists), proxyRef, fixtureShape, shapePool, bodyXf, bodyCell, bodyRgba (each body
//      slot's colour, rgba8); joints, jointParams, and the body transforms for the joints' lines.
// Out: the colour attachment only.
// Invariants: reads the world and never writes it, so a frame can be drawn between any two steps;
//      every listed proxy is live; a vertex beyond what its shape needs, and a dead joint slot's,
//      is a degenerate primitive outside the clip volume.

// The draw list this pipeline draws (LIST_* in renderView.wgsl): set per pipeline by the host.
override LIST: u32;
// Sides of a circle's outline (its radius line is one more): RENDER_CIRCLE_SEGMENTS in layout.ts.
const CIRCLE_SEGMENTS: u32 = 16u;
const JOINT_PARAMS_VEC4: u32 = 5u;

@group(0) @binding(0) var<uniform> view: View;
@group(0) @binding(1) var<storage, read> bodyXf: array<vec4<f32>>;
@group(0) @binding(2) var<storage, read> bodyCell: array<vec2<i32>>;
@group(0) @binding(3) var<storage, read> bodyRgba: array<u32>;
@group(1) @binding(0) var<storage, read> proxyRef: array<vec4<u32>>;
@group(1) @binding(1) var<storage, read> fixtureShape: array<vec4<u32>>;
@group(1) @binding(2) var<storage, read> shapePool: array<vec2<f32>>;
@group(1) @binding(3) var<storage, read> visible: array<u32>;
@group(2) @binding(0) var<storage, read> joints: array<vec4<u32>>;
@group(2) @binding(1) var<storage, read> jointParams: array<vec4<f32>>;

struct Varyings {
  @builtin(position) position: vec4<f32>,
  @location(0) colour: vec4<f32>,
  // A circle's fill: the position in the circle's square, radius 1 (|local| > 1 is outside).
  @location(1) local: vec2<f32>,
  @location(2) @interpolate(flat) circle: u32,
}

fn hidden() -> Varyings {
  var out: Varyings;
  out.position = vec4<f32>(2.0, 2.0, 2.0, 1.0);
  out.colour = vec4<f32>(0.0);
  out.local = vec2<f32>(0.0);
  out.circle = 0u;
  return out;
}

// A world point given as a cell and an offset in it, in clip coordinates.
fn to_clip(cell: vec2<i32>, offset: vec2<f32>) -> vec4<f32> {
  return vec4<f32>(view_clip(view, cell, offset), 0.0, 1.0);
}

// A point in body `b`'s frame, in clip coordinates.
fn body_point_clip(b: u32, p: vec2<f32>) -> vec4<f32> {
  let xf = bodyXf[b];
  let offset = vec2<f32>(xf.x + xf.z * p.x - xf.w * p.y, xf.y + xf.w * p.x + xf.z * p.y);
  return to_clip(bodyCell[b], offset);
}

// Body `b`'s colour (cull.wgsl `colours`).
fn body_rgb(b: u32) -> vec3<f32> {
  return unpack4x8unorm(bodyRgba[b]).rgb;
}

// The shape of the proxy at `instance` of this pipeline's list.
fn listed_shape(instance: u32) -> ProxyShape {
  let proxy = visible[LIST * view.listStride + instance];
  let info = proxyRef[proxy];
  return decode_proxy(info, fixtureShape[info.x]);
}

// The corners of a quad as two triangles, in [-1, 1]^2.
fn quad_corner(i: u32) -> vec2<f32> {
  let x = select(-1.0, 1.0, i == 1u || i == 2u || i == 4u);
  let y = select(-1.0, 1.0, i == 2u || i == 4u || i == 5u);
  return vec2<f32>(x, y);
}

// Circles as a quad (6 vertices, the fragment cuts the disc), polygons as a triangle fan
// (3 (n - 2) vertices, at most 18): filled at half the colour, half transparent, as
// b2Draw::DrawSolidPolygon and DrawSolidCircle fill.
@vertex
fn fill_vertex(@builtin(vertex_index) v: u32, @builtin(instance_index) instance: u32) -> Varyings {
  let s = listed_shape(instance);
  var out: Varyings;
  if (s.shapeType == SHAPE_CIRCLE) {
    if (v >= 6u) {
      return hidden();
    }
    let corner = quad_corner(v);
    out.position = body_point_clip(s.body, shapePool[s.base] + corner * s.radius);
    out.local = corner;
    out.circle = 1u;
  } else if (s.shapeType == SHAPE_POLYGON) {
    let triangle = v / 3u;
    let k = v % 3u;
    if (triangle + 2u >= s.count) {
      return hidden();
    }
    out.position = body_point_clip(s.body, shapePool[s.base + select(triangle + k, 0u, k == 0u)]);
    out.local = vec2<f32>(0.0);
    out.circle = 0u;
  } else {
    return hidden();
  }
  out.colour = vec4<f32>(0.5 * body_rgb(s.body), 0.5);
  return out;
}

// Line-list outlines: a polygon's n sides, a circle's CIRCLE_SEGMENTS sides and its radius line
// along the body's x axis (b2Draw::DrawSolidCircle's axis), an edge or chain child's segment.
@vertex
fn outline_vertex(@builtin(vertex_index) v: u32, @builtin(instance_index) instance: u32) -> Varyings {
  let s = listed_shape(instance);
  let side = v / 2u;
  let end = v % 2u;
  var p: vec2<f32>;
  if (s.shapeType == SHAPE_CIRCLE) {
    let centre = shapePool[s.base];
    if (side < CIRCLE_SEGMENTS) {
      let angle = 2.0 * PI * f32(side + end) / f32(CIRCLE_SEGMENTS);
      p = centre + s.radius * vec2<f32>(cos(angle), sin(angle));
    } else if (side == CIRCLE_SEGMENTS) {
      p = centre + f32(end) * vec2<f32>(s.radius, 0.0);
    } else {
      return hidden();
    }
  } else if (s.shapeType == SHAPE_POLYGON) {
    if (side >= s.count) {
      return hidden();
    }
    p = shapePool[s.base + (side + end) % s.count];
  } else {
    if (side > 0u) {
      return hidden();
    }
    p = shapePool[segment_start(s) + end];
  }
  var out: Varyings;
  out.position = body_point_clip(s.body, p);
  out.colour = vec4<f32>(body_rgb(s.body), 1.0);
  out.local = vec2<f32>(0.0);
  out.circle = 0u;
  return out;
}

// A point-list vertex at the shape's centre in its outline colour: a circle's centre, a
// polygon's centroid (after its vertices and normals in the pool), an edge's vertex 1, a chain
// child's first vertex.
@vertex
fn point_vertex(@builtin(instance_index) instance: u32) -> Varyings {
  let s = listed_shape(instance);
  // segment_start is also a circle's centre and an edge's vertex 1: the base of their records.
  var centre = segment_start(s);
  if (s.shapeType == SHAPE_POLYGON) {
    centre = s.base + 2u * s.count;
  }
  var out: Varyings;
  out.position = body_point_clip(s.body, shapePool[centre]);
  out.colour = vec4<f32>(body_rgb(s.body), 1.0);
  out.local = vec2<f32>(0.0);
  out.circle = 0u;
  return out;
}

// b2World::DrawJoint: body A's origin to anchor A, anchor A to anchor B, body B's origin to
// anchor B (two line-list vertices each); a distance joint its anchors only; a pulley its
// anchors to their ground anchors and the ground anchors to each other; a mouse joint nothing.
@vertex
fn joint_vertex(@builtin(vertex_index) v: u32, @builtin(instance_index) j: u32) -> Varyings {
  let joint = joints[j];
  if ((joint.w & JOINT_LIVE) == 0u || joint.z == MOUSE_JOINT) {
    return hidden();
  }
  let line = v / 2u;
  let end = v % 2u;
  let params = JOINT_PARAMS_VEC4 * j;
  let anchors = jointParams[params];
  let a = body_point_clip(joint.x, anchors.xy);
  let b = body_point_clip(joint.y, anchors.zw);
  var out: Varyings;
  if (joint.z == DISTANCE_JOINT) {
    if (line > 0u) {
      return hidden();
    }
    out.position = select(a, b, end == 1u);
  } else if (joint.z == PULLEY_JOINT) {
    let offsets = jointParams[params + 2u];
    let cells = bitcast<vec4<i32>>(jointParams[params + 3u]);
    let groundA = to_clip(cells.xy, offsets.xy);
    let groundB = to_clip(cells.zw, offsets.zw);
    let lineStart = array<vec4<f32>, 3>(groundA, groundB, groundA);
    let lineEnd = array<vec4<f32>, 3>(a, b, groundB);
    out.position = select(lineStart[line], lineEnd[line], end == 1u);
  } else {
    let originA = to_clip(bodyCell[joint.x], bodyXf[joint.x].xy);
    let originB = to_clip(bodyCell[joint.y], bodyXf[joint.y].xy);
    let lineStart = array<vec4<f32>, 3>(originA, a, originB);
    let lineEnd = array<vec4<f32>, 3>(a, b, b);
    out.position = select(lineStart[line], lineEnd[line], end == 1u);
  }
  out.colour = vec4<f32>(0.5, 0.8, 0.8, 1.0);
  out.local = vec2<f32>(0.0);
  out.circle = 0u;
  return out;
}

@fragment
fn shade(in: Varyings) -> @location(0) vec4<f32> {
  if (in.circle != 0u && dot(in.local, in.local) > 1.0) {
    discard;
  }
  return in.colour;
}
