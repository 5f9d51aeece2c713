// prepareContacts.wgsl: GpuStage.Prepare, the solver contacts of the step: b2ContactSolver's
// constructor and InitializeVelocityConstraints, one invocation per solver contact.
//
// In:  solverState[SV_COUNT], solverList (contact indices), contactRef (fixtures and bodies in
//      A/B order), fixtureShape (radius), fixtureMaterial (friction, restitution), manifolds
//      (type, local normal and points, warm-start impulses in word 3), bodyMass, and after GpuStage.IntegrateVelocities
//      bodySweep, bodyVel, bodyCell; params (dtRatio, warmStarting, cellSize); bodyAwake (after
//      the island search).
// Out: contactBodies[k] and constraints[k] (solverCommon.wgsl) of each solver contact k:
//      `bodies`   bodies, which are dynamic, b2MixFriction / b2MixRestitution, masses, radii,
//                 local centres;
//      `manifold` point counts and type, local normal and points, impulses (dtRatio x the
//                 manifold's when warm starting, else 0); a contact of a sleeping island (no
//                 awake dynamic body: 2.2.1 neither updates nor solves it) gets no points and no
//                 dynamic body, so no pass writes a body, and keeps the manifold's impulses,
//                 which storeImpulses writes back unchanged;
//      `velocity` b2WorldManifold::Initialize in A's cell, normal, rA, rB, normal and tangent
//                 masses, the restitution bias (vRel < -b2_velocityThreshold), and for two points
//                 the block solver's K and its inverse, or one point when K's condition number
//                 passes k_maxConditionNumber.
// Invariants: each invocation writes only its own contact's records; float32 in the engine's
//      operation order.

@group(0) @binding(0) var<uniform> params: SolverParams;
@group(0) @binding(1) var<storage, read> solverState: array<u32>;
@group(0) @binding(2) var<storage, read> solverList: array<u32>;
@group(0) @binding(3) var<storage, read> contactRef: array<vec4<u32>>;
@group(0) @binding(4) var<storage, read> fixtureShape: array<vec4<u32>>;
@group(0) @binding(5) var<storage, read> fixtureMaterial: array<vec4<f32>>;
@group(0) @binding(6) var<storage, read> bodyMass: array<vec4<f32>>;
@group(0) @binding(7) var<storage, read_write> contactBodies: array<vec4<u32>>;
@group(0) @binding(8) var<storage, read_write> constraints: array<vec4<f32>>;
@group(0) @binding(9) var<storage, read> manifolds: array<vec4<u32>>;
@group(0) @binding(10) var<storage, read> bodySweep: array<vec4<f32>>;
@group(0) @binding(11) var<storage, read> bodyVel: array<vec4<f32>>;
@group(0) @binding(12) var<storage, read> bodyCell: array<vec2<i32>>;
@group(0) @binding(13) var<storage, read> bodyAwake: array<u32>;

fn contact_of(wid: vec3<u32>, nwg: vec3<u32>, lid: u32) -> u32 {
  let k = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  if (k >= solverState[SV_COUNT]) {
    return NO_CONTACT;
  }
  return k;
}

@compute @workgroup_size(256)
fn bodies(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
          @builtin(local_invocation_index) lid: u32) {
  let k = contact_of(wid, nwg, lid);
  if (k == NO_CONTACT) {
    return;
  }
  let i = solverList[k];
  let refA = contactRef[2u * i];
  let refB = contactRef[2u * i + 1u];
  let massA = bodyMass[refA.z];
  let massB = bodyMass[refB.z];
  // Dynamic bodies, and only they, have a positive inverse mass (b2Body::ResetMassData).
  var dynamic = 0u;
  if (massA.x > 0.0) {
    dynamic = dynamic | CB_DYNAMIC_A;
  }
  if (massB.x > 0.0) {
    dynamic = dynamic | CB_DYNAMIC_B;
  }
  contactBodies[k] = vec4<u32>(refA.z, refB.z, dynamic, i);
  let materialA = fixtureMaterial[refA.x];
  let materialB = fixtureMaterial[refB.x];
  let base = CONSTRAINT_VEC4 * k;
  // b2MixFriction, b2MixRestitution.
  constraints[base] = vec4<f32>(0.0, 0.0, sqrt(materialA.x * materialB.x), max(materialA.y, materialB.y));
  constraints[base + 1u] = vec4<f32>(massA.x, massA.y, massB.x, massB.y);
  constraints[base + 6u] = vec4<f32>(0.0, 0.0, bitcast<f32>(fixtureShape[refA.x].w), bitcast<f32>(fixtureShape[refB.x].w));
  constraints[base + 11u] = vec4<f32>(massA.zw, massB.zw);
}

@compute @workgroup_size(256)
fn manifold(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
            @builtin(local_invocation_index) lid: u32) {
  let k = contact_of(wid, nwg, lid);
  if (k == NO_CONTACT) {
    return;
  }
  let cb = contactBodies[k];
  let i = cb.w;
  let header = manifolds[4u * i].x;
  let kind = header & 3u;
  let base = CONSTRAINT_VEC4 * k;
  // Islands are connected components, so one awake dynamic body means the whole contact is awake.
  let awake = ((cb.z & CB_DYNAMIC_A) != 0u && bodyAwake[cb.x] != 0u) || ((cb.z & CB_DYNAMIC_B) != 0u && bodyAwake[cb.y] != 0u);
  let count = select(0u, (header >> 2u) & 3u, awake);
  contactBodies[k].z = select(0u, cb.z & (CB_DYNAMIC_A | CB_DYNAMIC_B), awake) | count | (count << CB_MANIFOLD_POINTS_SHIFT) | (kind << CB_TYPE_SHIFT);
  var impulses = vec4<f32>(0.0);
  if (!awake) {
    impulses = bitcast<vec4<f32>>(manifolds[4u * i + 3u]);
  } else if (params.warmStarting != 0u) {
    impulses = params.dtRatio * bitcast<vec4<f32>>(manifolds[4u * i + 3u]);
    if (count < 2u) {
      impulses = vec4<f32>(impulses.xy, 0.0, 0.0);
    }
  }
  constraints[base + 4u] = impulses;
  constraints[base + 9u] = bitcast<vec4<f32>>(manifolds[4u * i + 1u]);
  constraints[base + 10u] = bitcast<vec4<f32>>(manifolds[4u * i + 2u]);
}

@compute @workgroup_size(256)
fn velocity(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
            @builtin(local_invocation_index) lid: u32) {
  let k = contact_of(wid, nwg, lid);
  if (k == NO_CONTACT) {
    return;
  }
  let cb = contactBodies[k];
  let base = CONSTRAINT_VEC4 * k;
  let row0 = constraints[base];
  let masses = constraints[base + 1u];
  let mA = masses.x;
  let iA = masses.y;
  let mB = masses.z;
  let iB = masses.w;
  let radii = constraints[base + 6u].zw;
  let lm = constraints[base + 9u];
  let localPoints = constraints[base + 10u];
  let centres = constraints[base + 11u];
  let cellDelta = vec2<f32>(bodyCell[cb.y] - bodyCell[cb.x]) * params.cellSize;
  constraints[base + 12u] = vec4<f32>(cellDelta, 0.0, 0.0);

  let sweepA = bodySweep[2u * cb.x + 1u];
  let sweepB = bodySweep[2u * cb.y + 1u];
  let cA = sweepA.xy;
  let cB = sweepB.xy + cellDelta;
  let velA = bodyVel[cb.x];
  let velB = bodyVel[cb.y];
  let vA = velA.xy;
  let wA = velA.z;
  let vB = velB.xy;
  let wB = velB.z;
  let qA = rot(sweepA.z);
  let qB = rot(sweepB.z);
  let pA = cA - rotate(qA, centres.xy);
  let pB = cB - rotate(qB, centres.zw);

  // b2WorldManifold::Initialize.
  let count = (cb.z >> CB_MANIFOLD_POINTS_SHIFT) & 3u;
  let kind = (cb.z >> CB_TYPE_SHIFT) & 3u;
  var normal = vec2<f32>(1.0, 0.0);
  var points: array<vec2<f32>, 2>;
  points[0] = vec2<f32>(0.0);
  points[1] = vec2<f32>(0.0);
  if (kind == E_CIRCLES) {
    let pointA = pA + rotate(qA, lm.zw);
    let pointB = pB + rotate(qB, localPoints.xy);
    let d = pointB - pointA;
    if (dot(d, d) > S_EPSILON * S_EPSILON) {
      normal = normalize2(d);
    }
    let ca = pointA + radii.x * normal;
    let cc = pointB - radii.y * normal;
    points[0] = 0.5 * (ca + cc);
  } else if (kind == E_FACE_A) {
    normal = rotate(qA, lm.xy);
    let planePoint = pA + rotate(qA, lm.zw);
    for (var j = 0u; j < count; j = j + 1u) {
      let lp = select(localPoints.zw, localPoints.xy, j == 0u);
      let clipPoint = pB + rotate(qB, lp);
      let ca = clipPoint + (radii.x - dot(clipPoint - planePoint, normal)) * normal;
      let cc = clipPoint - radii.y * normal;
      points[j] = 0.5 * (ca + cc);
    }
  } else {
    normal = rotate(qB, lm.xy);
    let planePoint = pB + rotate(qB, lm.zw);
    for (var j = 0u; j < count; j = j + 1u) {
      let lp = select(localPoints.zw, localPoints.xy, j == 0u);
      let clipPoint = pA + rotate(qA, lp);
      let cc = clipPoint + (radii.y - dot(clipPoint - planePoint, normal)) * normal;
      let ca = clipPoint - radii.x * normal;
      points[j] = 0.5 * (ca + cc);
    }
    normal = -normal;
  }

  let tangent = cross_vs(normal, 1.0);
  var r: array<vec4<f32>, 2>;
  r[0] = vec4<f32>(0.0);
  r[1] = vec4<f32>(0.0);
  var pointMasses = vec4<f32>(0.0);
  var bias = vec2<f32>(0.0);
  for (var j = 0u; j < count; j = j + 1u) {
    let rA = points[j] - cA;
    let rB = points[j] - cB;
    r[j] = vec4<f32>(rA, rB);
    let rnA = cross2(rA, normal);
    let rnB = cross2(rB, normal);
    let kNormal = mA + mB + iA * rnA * rnA + iB * rnB * rnB;
    let normalMass = select(0.0, 1.0 / kNormal, kNormal > 0.0);
    let rtA = cross2(rA, tangent);
    let rtB = cross2(rB, tangent);
    let kTangent = mA + mB + iA * rtA * rtA + iB * rtB * rtB;
    let tangentMass = select(0.0, 1.0 / kTangent, kTangent > 0.0);
    let vRel = dot(normal, vB + cross_sv(wB, rB) - vA - cross_sv(wA, rA));
    var b = 0.0;
    if (vRel < -VELOCITY_THRESHOLD) {
      b = -row0.w * vRel;
    }
    if (j == 0u) {
      pointMasses = vec4<f32>(normalMass, tangentMass, pointMasses.zw);
      bias.x = b;
    } else {
      pointMasses = vec4<f32>(pointMasses.xy, normalMass, tangentMass);
      bias.y = b;
    }
  }
  constraints[base] = vec4<f32>(normal, row0.zw);
  constraints[base + 2u] = r[0];
  constraints[base + 3u] = r[1];
  constraints[base + 5u] = pointMasses;
  constraints[base + 6u] = vec4<f32>(bias, radii);

  var points_used = count;
  var kMatrix = vec4<f32>(0.0);
  var inverse = vec4<f32>(0.0);
  if (count == 2u) {
    let rn1A = cross2(r[0].xy, normal);
    let rn1B = cross2(r[0].zw, normal);
    let rn2A = cross2(r[1].xy, normal);
    let rn2B = cross2(r[1].zw, normal);
    let k11 = mA + mB + iA * rn1A * rn1A + iB * rn1B * rn1B;
    let k22 = mA + mB + iA * rn2A * rn2A + iB * rn2B * rn2B;
    let k12 = mA + mB + iA * rn1A * rn2A + iB * rn1B * rn2B;
    if (k11 * k11 < MAX_CONDITION_NUMBER * (k11 * k22 - k12 * k12)) {
      kMatrix = vec4<f32>(k11, k12, k12, k22);
      // b2Mat22::GetInverse.
      var det = k11 * k22 - k12 * k12;
      if (det != 0.0) {
        det = 1.0 / det;
      }
      inverse = vec4<f32>(det * k22, -det * k12, -det * k12, det * k11);
    } else {
      points_used = 1u;
    }
  }
  constraints[base + 7u] = kMatrix;
  constraints[base + 8u] = inverse;
  contactBodies[k].z = (cb.z & ~CB_POINTS) | points_used;
}
