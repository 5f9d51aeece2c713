// warmStart.wgsl: solver stage 4, b2ContactSolver::WarmStart over one colour: each contact
// applies its carried impulses (already scaled by dtRatio, prepareContacts.wgsl) to its bodies.
//
// In:  colour (the pass's colour, serial for the overflow set), solverState[SV_COLOUR_START],
//      colourKeys (sorted (colour, k)), contactBodies, constraints (normal, rA, rB, impulses,
//      masses), bodyVel.
// Out: bodyVel of the dynamic bodies of the colour's contacts.
// Invariants: the contacts of a colour share no dynamic body, so each body has one writer per
//      pass; the overflow set runs in one invocation, in contact order.

@group(0) @binding(0) var<uniform> colour: ColourParams;
@group(0) @binding(1) var<storage, read> solverState: array<u32>;
@group(0) @binding(2) var<storage, read> colourKeys: array<vec2<u32>>;
@group(0) @binding(3) var<storage, read> contactBodies: array<vec4<u32>>;
@group(0) @binding(4) var<storage, read> constraints: array<vec4<f32>>;
@group(0) @binding(5) var<storage, read_write> bodyVel: array<vec4<f32>>;

fn warm_start(k: u32) {
  let cb = contactBodies[k];
  let base = CONSTRAINT_VEC4 * k;
  let normal = constraints[base].xy;
  let masses = constraints[base + 1u];
  let impulses = constraints[base + 4u];
  let tangent = cross_vs(normal, 1.0);
  var velA = bodyVel[cb.x];
  var velB = bodyVel[cb.y];
  var vA = velA.xy;
  var wA = velA.z;
  var vB = velB.xy;
  var wB = velB.z;
  let count = cb.z & CB_POINTS;
  for (var j = 0u; j < count; j = j + 1u) {
    let r = constraints[base + 2u + j];
    let P = select(impulses.z, impulses.x, j == 0u) * normal + select(impulses.w, impulses.y, j == 0u) * tangent;
    wA = wA - masses.y * cross2(r.xy, P);
    vA = vA - masses.x * P;
    wB = wB + masses.w * cross2(r.zw, P);
    vB = vB + masses.z * P;
  }
  if ((cb.z & CB_DYNAMIC_A) != 0u) {
    bodyVel[cb.x] = vec4<f32>(vA, wA, 0.0);
  }
  if ((cb.z & CB_DYNAMIC_B) != 0u) {
    bodyVel[cb.y] = vec4<f32>(vB, wB, 0.0);
  }
}

@compute @workgroup_size(256)
fn main(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
        @builtin(local_invocation_index) lid: u32) {
  let start = solverState[SV_COLOUR_START + colour.colour];
  let end = solverState[SV_COLOUR_START + colour.colour + 1u];
  let t = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  if (colour.serial != 0u) {
    if (t == 0u) {
      for (var e = start; e < end; e = e + 1u) {
        warm_start(colourKeys[e].y);
      }
    }
    return;
  }
  if (start + t < end) {
    warm_start(colourKeys[start + t].y);
  }
}
