// integrateVelocities.wgsl: GpuStage.IntegrateVelocities, the first loop of b2Island::Solve: the sweep's start
// of step (c0 = c, a0 = a) and, for dynamic bodies, gravity (times the gravity scale), forces and
// damping (v *= b2Clamp(1 - h * damping, 0, 1)).
//
// In:  params (h, gravity, body slot count), solverState[SV_SKIP], bodyFlags, bodyAwake (after the
//      island search), bodyForce, bodyMass, bodyParams, bodySweep, bodyVel (src-gpu/device/layout.ts).
// Out: bodySweep (c0, a0) of every live active awake non-static body, bodyVel of the dynamic ones.
// Invariants: one invocation per body slot, each writing only its own body; dead, inactive, static
//      and sleeping bodies are left as they are (2.2.1 solves only the islands of awake bodies);
//      nothing runs when the collision passes overflowed.

@group(0) @binding(0) var<uniform> params: SolverParams;
@group(0) @binding(1) var<storage, read> solverState: array<u32>;
@group(0) @binding(2) var<storage, read> bodyFlags: array<u32>;
@group(0) @binding(3) var<storage, read> bodyForce: array<vec4<f32>>;
@group(0) @binding(4) var<storage, read> bodyMass: array<vec4<f32>>;
@group(0) @binding(5) var<storage, read> bodyParams: array<vec4<f32>>;
@group(0) @binding(6) var<storage, read_write> bodySweep: array<vec4<f32>>;
@group(0) @binding(7) var<storage, read_write> bodyVel: array<vec4<f32>>;
@group(0) @binding(8) var<storage, read> bodyAwake: array<u32>;

@compute @workgroup_size(256)
fn main(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
        @builtin(local_invocation_index) lid: u32) {
  let i = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  if (i >= params.bodySlots || solverState[SV_SKIP] != 0u) {
    return;
  }
  let flags = bodyFlags[i];
  if ((flags & BODY_LIVE) == 0u || (flags & BODY_ACTIVE) == 0u || body_type(flags) == STATIC_BODY || bodyAwake[i] == 0u) {
    return;
  }
  let s0 = bodySweep[2u * i];
  let s1 = bodySweep[2u * i + 1u];
  bodySweep[2u * i] = vec4<f32>(s1.xy, s1.z, s0.w);
  if (body_type(flags) != DYNAMIC_BODY) {
    return;
  }
  let h = params.h;
  let vel = bodyVel[i];
  let mass = bodyMass[i];
  let force = bodyForce[i];
  let damping = bodyParams[i];
  var v = vel.xy + h * (damping.z * params.gravity + mass.x * force.xy);
  var w = vel.z + h * mass.y * force.z;
  v = v * clamp(1.0 - h * damping.x, 0.0, 1.0);
  w = w * clamp(1.0 - h * damping.y, 0.0, 1.0);
  bodyVel[i] = vec4<f32>(v, w, 0.0);
}
