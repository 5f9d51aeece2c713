// cull.wgsl: the renderer's compute pass before it draws (GpuRenderer): `main` sorts the live
// proxies into the draw lists by what they cover on screen, so that the indirect draws run the
// vertex shader for visible shapes only and with the vertices each needs; `colours` works out
// each body's colour once, so that the vertex shaders read one word where they would read three
// tables (which also keeps them within the default 8 storage buffers).
//
// In:  view (camera, clip units and pixels per metre, list stride, proxy and body slot counts,
//      colour mode); main: proxyRef, fixtureShape, shapePool, bodyXf, bodyCell, and drawArgs as
//      the host reset it (instance counts 0); colours: bodyFlags, bodyAwake, bodyColour (the
//      application's rgba8 per body slot, read when view.colourMode is COLOUR_BODY).
// Out: main: visible[L * view.listStride + i], i < drawArgs[DRAW_ARGS_WORDS * L + 1], the proxy
//      slots of list L. Skipped: dead slots, and shapes whose bounding circle about the body
//      origin (radius: the farthest vertex or circle edge, plus the shape's radius) lies outside
//      the view. A shape narrower than POINT_PIXELS on screen goes to LIST_POINT alone; a larger
//      one to a fill list (none for edges and chain children) and an outline list, the small
//      ones when its geometry fits their vertex counts.
//      colours: bodyRgba[b], body slot b's colour (rgba8, alpha 1): b2World::DrawDebugData's by
//      state, or the application's.
// Invariants: reads the world and never writes it; a proxy enters a list at most once, so no
//      list holds more than the proxy slots (the stride); one global atomic per list per
//      workgroup; the order within a list is unspecified.

// Polygons of at most this many vertices use the small lists (RENDER_SMALL_POLYGON_VERTICES).
const SMALL_POLYGON_VERTICES: u32 = 4u;
// Narrower than this on screen, a shape is a point (RENDER_POINT_PIXELS).
const POINT_PIXELS: f32 = 2.0;
// view.colourMode (RENDER_COLOUR_MODE).
const COLOUR_STATE: u32 = 0u;
const COLOUR_BODY: u32 = 1u;
const NO_LIST: u32 = 0xffffffffu;

@group(0) @binding(0) var<uniform> view: View;
@group(0) @binding(1) var<storage, read> proxyRef: array<vec4<u32>>;
@group(0) @binding(2) var<storage, read> fixtureShape: array<vec4<u32>>;
@group(0) @binding(3) var<storage, read> shapePool: array<vec2<f32>>;
@group(0) @binding(4) var<storage, read> bodyXf: array<vec4<f32>>;
@group(0) @binding(5) var<storage, read> bodyCell: array<vec2<i32>>;
@group(0) @binding(6) var<storage, read_write> visible: array<u32>;
@group(0) @binding(7) var<storage, read_write> drawArgs: array<atomic<u32>>;
@group(0) @binding(8) var<storage, read> bodyFlags: array<u32>;
@group(0) @binding(9) var<storage, read> bodyAwake: array<u32>;
@group(0) @binding(10) var<storage, read> bodyColour: array<u32>;
@group(0) @binding(11) var<storage, read_write> bodyRgba: array<u32>;

var<workgroup> wg_count: array<atomic<u32>, LIST_COUNT>;
var<workgroup> wg_base: array<u32, LIST_COUNT>;

// The distance from the body origin within which the shape lies.
fn shape_reach(s: ProxyShape) -> f32 {
  var far = 0.0;
  if (s.shapeType == SHAPE_CIRCLE) {
    far = length(shapePool[s.base]);
  } else if (s.shapeType == SHAPE_POLYGON) {
    for (var i = 0u; i < s.count; i = i + 1u) {
      far = max(far, length(shapePool[s.base + i]));
    }
  } else {
    let first = segment_start(s);
    far = max(length(shapePool[first]), length(shapePool[first + 1u]));
  }
  return far + s.radius;
}

// The lists proxy slot `proxy` enters: (fill, outline), (LIST_POINT, NO_LIST), or none.
fn lists_of(proxy: u32) -> vec2<u32> {
  let info = proxyRef[proxy];
  if ((info.w & PROXY_LIVE) == 0u) {
    return vec2<u32>(NO_LIST);
  }
  let s = decode_proxy(info, fixtureShape[info.x]);
  let reach = shape_reach(s);
  let origin = view_clip(view, bodyCell[s.body], bodyXf[s.body].xy);
  if (any(abs(origin) > vec2<f32>(1.0) + reach * view.clipScale)) {
    return vec2<u32>(NO_LIST);
  }
  if (2.0 * reach * view.pixelsPerMetre < POINT_PIXELS) {
    return vec2<u32>(LIST_POINT, NO_LIST);
  }
  if (s.shapeType == SHAPE_CIRCLE) {
    return vec2<u32>(LIST_FILL_SMALL, LIST_OUTLINE);
  }
  if (s.shapeType == SHAPE_POLYGON) {
    if (s.count <= SMALL_POLYGON_VERTICES) {
      return vec2<u32>(LIST_FILL_SMALL, LIST_OUTLINE_SMALL);
    }
    return vec2<u32>(LIST_FILL, LIST_OUTLINE);
  }
  return vec2<u32>(NO_LIST, LIST_OUTLINE_SMALL);
}

// One invocation per proxy slot. Appends are counted in workgroup memory first, so that each
// list takes one global atomic per workgroup rather than one per proxy.
@compute @workgroup_size(256)
fn main(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  if (lid < LIST_COUNT) {
    atomicStore(&wg_count[lid], 0u);
  }
  workgroupBarrier();
  let proxy = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  var lists = vec2<u32>(NO_LIST);
  if (proxy < view.proxies) {
    lists = lists_of(proxy);
  }
  var at = vec2<u32>(0u);
  for (var k = 0u; k < 2u; k = k + 1u) {
    if (lists[k] != NO_LIST) {
      at[k] = atomicAdd(&wg_count[lists[k]], 1u);
    }
  }
  workgroupBarrier();
  if (lid < LIST_COUNT) {
    let n = atomicLoad(&wg_count[lid]);
    if (n > 0u) {
      wg_base[lid] = atomicAdd(&drawArgs[DRAW_ARGS_WORDS * lid + 1u], n);
    }
  }
  workgroupBarrier();
  for (var k = 0u; k < 2u; k = k + 1u) {
    if (lists[k] != NO_LIST) {
      visible[lists[k] * view.listStride + wg_base[lists[k]] + at[k]] = proxy;
    }
  }
}

// b2World::DrawDebugData's colour of a body's shapes, or the application's.
fn body_colour(b: u32) -> vec3<f32> {
  // A body the application never coloured (a zero word: its alpha byte is 0) keeps its state's.
  if (view.colourMode == COLOUR_BODY && bodyColour[b] != 0u) {
    return unpack4x8unorm(bodyColour[b]).rgb;
  }
  let flags = bodyFlags[b];
  if ((flags & BODY_ACTIVE) == 0u) {
    return vec3<f32>(0.5, 0.5, 0.3);
  }
  let bodyType = body_type(flags);
  if (bodyType == STATIC_BODY) {
    return vec3<f32>(0.5, 0.9, 0.5);
  }
  if (bodyType != DYNAMIC_BODY) {
    return vec3<f32>(0.5, 0.5, 0.9);
  }
  if (bodyAwake[b] == 0u) {
    return vec3<f32>(0.6, 0.6, 0.6);
  }
  return vec3<f32>(0.9, 0.7, 0.7);
}

// One invocation per body slot.
@compute @workgroup_size(256)
fn colours(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let b = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  if (b >= view.bodies) {
    return;
  }
  bodyRgba[b] = pack4x8unorm(vec4<f32>(body_colour(b), 1.0));
}
