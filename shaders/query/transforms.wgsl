// transforms.wgsl: every body slot's transform in world coordinates as float32 and its awake flag
// as a byte, laid out as WebGPUBackend.readTransforms hands them to the application, so that the
// host copies them with one memcpy each instead of converting a body at a time.
//
// In:  params (body slot count, cell size), bodyXf, bodyCell, bodyFlags, bodyAwake.
// Out: transforms[slot]: the bits of (x, y, cos, sin), x and y the float32 nearest
//      cell * cellSize + offset (the product is exact: cells are integers below 2^24 and the cell
//      size a power of two, so one rounding); quiet NaN bits in all four for a slot without a
//      live body. awakeBytes: byte `slot` (little-endian words) 1 for a live awake body, else 0.
// Invariants: reads the world and never writes it; one invocation per awake word (four slots).

struct Params {
  slots: u32,
  cellSize: f32,
}

const QUIET_NAN: u32 = 0x7fc00000u;

@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var<storage, read> bodyXf: array<vec4<f32>>;
@group(0) @binding(2) var<storage, read> bodyCell: array<vec2<i32>>;
@group(0) @binding(3) var<storage, read> bodyFlags: array<u32>;
@group(0) @binding(4) var<storage, read> bodyAwake: array<u32>;
@group(0) @binding(5) var<storage, read_write> transforms: array<vec4<u32>>;
@group(0) @binding(6) var<storage, read_write> awakeBytes: array<u32>;

@compute @workgroup_size(256)
fn main(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let word = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  let first = 4u * word;
  if (first >= params.slots) {
    return;
  }
  var bytes = 0u;
  for (var k = 0u; k < 4u; k = k + 1u) {
    let slot = first + k;
    if (slot >= params.slots) {
      break;
    }
    if ((bodyFlags[slot] & BODY_LIVE) == 0u) {
      transforms[slot] = vec4<u32>(QUIET_NAN);
      continue;
    }
    let xf = bodyXf[slot];
    let origin = vec2<f32>(bodyCell[slot]) * params.cellSize;
    transforms[slot] = bitcast<vec4<u32>>(vec4<f32>(origin + xf.xy, xf.zw));
    if (bodyAwake[slot] != 0u) {
      bytes = bytes | (1u << (8u * k));
    }
  }
  awakeBytes[word] = bytes;
}
