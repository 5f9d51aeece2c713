// integratePositions.wgsl: integrate positions (in GpuStage.Velocity) and synchronize (GpuStage.Position), from b2Island::Solve: positions from velocities
// with b2_maxTranslation / b2_maxRotation clamps (`main`), and, after the position iterations,
// the transforms (`synchronize`: b2Body::SynchronizeTransform, and a new cell for a body that
// left its own).
//
// In:  params (h, cellSize, body slot count), solverState[SV_SKIP], bodyFlags, bodyAwake, bodyMass
//      (local centre), bodySweep, bodyVel, bodyXf, bodyCell.
// Out: `main`: bodySweep c, a and bodyVel (clamped) of live active awake non-static bodies.
//      `synchronize`: bodyXf (p = c - R(a) localCenter, q = R(a)); when p leaves
//      [-cellSize/2, cellSize/2] on an axis, bodyCell moves by round(p / cellSize) there and p, c0,
//      c move the other way (exact: multiples of a power of two), keeping offsets within a cell.
// Invariants: one invocation per body slot writing only its own body; static and sleeping bodies
//      never move (a body put to sleep this step is synchronized first: islands.wgsl runs after).

@group(0) @binding(0) var<uniform> params: SolverParams;
@group(0) @binding(1) var<storage, read> solverState: array<u32>;
@group(0) @binding(2) var<storage, read> bodyFlags: array<u32>;
@group(0) @binding(3) var<storage, read> bodyMass: array<vec4<f32>>;
@group(0) @binding(4) var<storage, read_write> bodySweep: array<vec4<f32>>;
@group(0) @binding(5) var<storage, read_write> bodyVel: array<vec4<f32>>;
@group(0) @binding(6) var<storage, read_write> bodyXf: array<vec4<f32>>;
@group(0) @binding(7) var<storage, read_write> bodyCell: array<vec2<i32>>;
@group(0) @binding(8) var<storage, read> bodyAwake: array<u32>;

fn moving_body(i: u32) -> bool {
  if (i >= params.bodySlots || solverState[SV_SKIP] != 0u) {
    return false;
  }
  let flags = bodyFlags[i];
  return (flags & BODY_LIVE) != 0u && (flags & BODY_ACTIVE) != 0u && body_type(flags) != STATIC_BODY && bodyAwake[i] != 0u;
}

@compute @workgroup_size(256)
fn main(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
        @builtin(local_invocation_index) lid: u32) {
  let i = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  if (!moving_body(i)) {
    return;
  }
  let h = params.h;
  let vel = bodyVel[i];
  var v = vel.xy;
  var w = vel.z;
  let translation = h * v;
  if (dot(translation, translation) > MAX_TRANSLATION * MAX_TRANSLATION) {
    let ratio = MAX_TRANSLATION / length(translation);
    v = v * ratio;
  }
  let rotation = h * w;
  if (rotation * rotation > MAX_ROTATION * MAX_ROTATION) {
    let ratio = MAX_ROTATION / abs(rotation);
    w = w * ratio;
  }
  let s1 = bodySweep[2u * i + 1u];
  bodySweep[2u * i + 1u] = vec4<f32>(s1.xy + h * v, s1.z + h * w, s1.w);
  bodyVel[i] = vec4<f32>(v, w, 0.0);
}

@compute @workgroup_size(256)
fn synchronize(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
               @builtin(local_invocation_index) lid: u32) {
  let i = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  if (!moving_body(i)) {
    return;
  }
  var s0 = bodySweep[2u * i];
  var s1 = bodySweep[2u * i + 1u];
  let q = rot(s1.z);
  var p = s1.xy - rotate(q, bodyMass[i].zw);
  let half = 0.5 * params.cellSize;
  if (abs(p.x) > half || abs(p.y) > half) {
    let shift = vec2<f32>(select(0.0, round(p.x / params.cellSize), abs(p.x) > half),
                          select(0.0, round(p.y / params.cellSize), abs(p.y) > half));
    let delta = shift * params.cellSize;
    p = p - delta;
    s0 = vec4<f32>(s0.xy - delta, s0.zw);
    s1 = vec4<f32>(s1.xy - delta, s1.zw);
    bodySweep[2u * i] = s0;
    bodySweep[2u * i + 1u] = s1;
    bodyCell[i] = bodyCell[i] + vec2<i32>(shift);
  }
  bodyXf[i] = vec4<f32>(p, q);
}
