// renderView.wgsl: what the renderer's two stages share (GpuRenderer): the camera as the shaders
// see it, the numbers of the draw lists that cull.wgsl fills and render.wgsl draws, and the
// decoding of a proxy's shape record. The host prepends it to both after common.wgsl.
//
// In:  nothing itself: definitions only; each stage binds `view` (View) and the world's tables.
// Out: pure helpers over values the stages read.

struct View {
  cameraCell: vec2<i32>,
  cameraOffset: vec2<f32>,
  clipScale: vec2<f32>,     // clip units per metre, x and y
  cellSize: f32,
  colourMode: u32,          // COLOUR_STATE or COLOUR_BODY (cull.wgsl)
  pixelsPerMetre: f32,
  listStride: u32,          // entries per draw list in `visible`: the proxy capacity
  proxies: u32,             // proxy slots
  bodies: u32,              // body slots
}

// The draw lists (RENDER_LIST in layout.ts), numbered in drawing order so that outlines cover
// fills. List L holds proxy slots at visible[L * listStride ..], and its drawIndirect record is
// the DRAW_ARGS_WORDS words at DRAW_ARGS_WORDS * L of the argument buffer.
const LIST_FILL_SMALL: u32 = 0u;     // circles' quads and fans of polygons of few vertices
const LIST_FILL: u32 = 1u;           // fans of the other polygons
const LIST_OUTLINE_SMALL: u32 = 2u;  // sides of polygons of few vertices, edges, chain children
const LIST_OUTLINE: u32 = 3u;        // circles' sides and radius lines, the other polygons' sides
const LIST_POINT: u32 = 4u;          // one point a shape, for shapes too small to see
const LIST_COUNT: u32 = 5u;
const DRAW_ARGS_WORDS: u32 = 4u;

// A world point given as a cell and an offset in it, in clip coordinates of view `v`.
fn view_clip(v: View, cell: vec2<i32>, offset: vec2<f32>) -> vec2<f32> {
  let rel = vec2<f32>(cell - v.cameraCell) * v.cellSize + (offset - v.cameraOffset);
  return rel * v.clipScale;
}

// A proxy slot's shape record: its body, its child index, and the fixture's shape type, vertex
// count, pool offset and radius.
struct ProxyShape {
  body: u32,
  child: u32,
  shapeType: u32,
  count: u32,
  base: u32,
  radius: f32,
}

// The shape record of a proxy from its proxyRef word and its fixture's fixtureShape word.
fn decode_proxy(info: vec4<u32>, shape: vec4<u32>) -> ProxyShape {
  return ProxyShape(info.z, info.y, shape.x & 0xfu, shape.x >> 8u, shape.y, bitcast<f32>(shape.w));
}

// The pool index of an edge's or chain child's first vertex: an edge's vertices 1 and 2 lead its
// record, and a chain's child i is (v[i], v[i + 1]).
fn segment_start(s: ProxyShape) -> u32 {
  return s.base + select(0u, s.child, s.shapeType == SHAPE_CHAIN);
}
