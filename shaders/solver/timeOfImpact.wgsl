// timeOfImpact.wgsl: continuous collision after the solve (2.2.1 b2World::SolveTOI, in one parallel
// pass): b2TimeOfImpact for every contact 2.2.1 would test, each dynamic body stopped at the
// earliest time of impact of its contacts (b2Body::Advance). src-gpu/solver/timeOfImpact.ts lists how
// this differs from 2.2.1's sequential loop.
//
// In:  npState[NP_CONTACTS] and contactRef (this step's contacts, A/B as b2Contact::Create orders
//      them), solverState[SV_SKIP], the mirror's fixtureShape, shapePool, bodyFlags, bodyAwake,
//      bodyMass (local centre), bodyCell, bodySweep (c0, a0 at the start of the step, c, a at
//      its end).
// Out: `begin`: toiBody[0] = contacts to test (0 when the step is skipped), toiBody[1] = 0,
//      toiIndirect.
//      `candidates`: toiBody[2 + b] = atomicMax of 0x3f800000 - bits(alpha) over body b's
//      contacts touching at a time of impact 0 < alpha (non-negative floats order as their bits,
//      reversed here so that 0, the cleared value, means none); only dynamic bodies get one.
//      toiBody[1] = the contacts that ran b2TimeOfImpact (for tests and tools).
//      `advance`: an awake body with alpha <= 1 - 10 b2_epsilon gets b2Body::Advance(alpha): c0 =
//      c = the sweep at alpha, a0 = a, alpha0 = alpha, bodyXf from them; velocities are kept.
//      Every other body's alpha0 returns to 0 (SolveTOI's reset). toiBody[2 + b] is cleared.
//      `evaluate` (tests and tools): b2TimeOfImpact of given records, unfiltered.
// Invariants: one invocation per contact / body slot; the only shared writes are atomicMax on
//      integer keys and the tested count's atomicAdd, so the result is the same bits on every
//      run. Contacts are tested as 2.2.1's SolveTOI selects them: no sensor, a bullet or a
//      non-dynamic body on one side (whether a body is awake is looked at when advancing it),
//      and, before b2TimeOfImpact, fast: the most the two shapes' cores can approach over the
//      step (each body's |c - c0| plus |a - a0| times its shape's farthest core point from its
//      centre of mass) is at least toi.minMotion (b2_linearSlop). A slower pair cannot stop a
//      body unless it already overlaps deeply: cores that do not overlap are at least the radii
//      apart, and b2TimeOfImpact's target plus tolerance is 2.75 b2_linearSlop less than that
//      (radii of 4 b2_linearSlop or more: any pair with a polygon, edge or chain skin); a
//      resting pair overlaps by about b2_linearSlop. So resting and slow bodies skip the
//      distance computations, with the results of testing them, but for pairs overlapping by
//      more than 1.75 b2_linearSlop, which the regular solver takes as it takes every touching
//      contact. Sweeps span the whole step (alpha0 = 0, as SolveTOI starts each step); B's
//      sweep is moved into A's cell. Nothing changes when SV_SKIP is set (the host reruns the
//      step).
// Float32: b2TimeOfImpact's target (max(b2_linearSlop, radii - 3 b2_linearSlop)) and tolerance
// (b2_linearSlop / 4) are millimetres, far above the rounding of cell-relative coordinates
// (about 1e-6 m), so the TOI is the engine's up to float32 rounding in the root finder.

struct ToiParams {
  cellSize: f32,
  bodySlots: u32,
  pairs: u32,                                  // `evaluate`: records in contactRef
  minMotion: f32,                              // `candidates`: the least approach tested
}

@group(0) @binding(9) var<uniform> toi: ToiParams;
@group(0) @binding(10) var<storage, read> solverState: array<u32>;
@group(0) @binding(11) var<storage, read_write> toiIndirect: array<u32>;
@group(0) @binding(12) var<storage, read_write> toiBody: array<atomic<u32>>;
@group(0) @binding(13) var<storage, read> bodyFlags: array<u32>;
@group(0) @binding(14) var<storage, read> bodyMass: array<vec4<f32>>;
@group(0) @binding(15) var<storage, read> bodySweepIn: array<vec4<f32>>;
@group(0) @binding(16) var<storage, read_write> bodySweep: array<vec4<f32>>;
@group(0) @binding(17) var<storage, read_write> bodyXfOut: array<vec4<f32>>;
@group(0) @binding(18) var<storage, read_write> evaluated: array<vec2<u32>>;
@group(0) @binding(19) var<storage, read> bodyAwake: array<u32>;

// b2Settings.h and b2TimeOfImpact.cpp, as float32.
const TOI_MAX_ITERATIONS: u32 = 20u;           // k_maxIterations
const TOI_MAX_ROOT_ITERATIONS: u32 = 50u;      // the root finder's limit
const TWO_PI: f32 = 6.28318530717958647692;

// bodyFlags: b2Body::m_flags | type << 16 | BODY_LIVE (BODY_BULLET, the types: src-gpu/device/engineWgsl.ts).

// contactRef[2c].w: bin << 4 | CONTACT_KEPT | sensor << 1 | swapped.
const REF_SENSOR: u32 = 0x2u;

// b2TOIOutput::State
const TOI_FAILED: u32 = 1u;
const TOI_OVERLAPPED: u32 = 2u;
const TOI_TOUCHING: u32 = 3u;
const TOI_SEPARATED: u32 = 4u;

// b2SeparationFunction::Type
const SEP_POINTS: u32 = 0u;
const SEP_FACE_A: u32 = 1u;
const SEP_FACE_B: u32 = 2u;

const ONE_BITS: u32 = 0x3f800000u;             // bits of 1.0f

// A b2Sweep: c0, c relative to one cell.
struct Sweep {
  localCenter: vec2<f32>,
  c0: vec2<f32>,
  c: vec2<f32>,
  a0: f32,
  a: f32,
}

struct ToiOutput {
  state: u32,
  t: f32,
}

struct SeparationFunction {
  kind: u32,
  localPoint: vec2<f32>,
  axis: vec2<f32>,
}

struct MinSeparation {
  separation: f32,
  indexA: u32,
  indexB: u32,
}

// b2Sweep::GetTransform(xf, beta).
fn sweep_transform(s: Sweep, beta: f32) -> Xf {
  let px = (1.0 - beta) * s.c0.x + beta * s.c.x;
  let py = (1.0 - beta) * s.c0.y + beta * s.c.y;
  let angle = (1.0 - beta) * s.a0 + beta * s.a;
  let c = cos(angle);
  let sn = sin(angle);
  let lc = s.localCenter;
  return Xf(vec2<f32>(px - (c * lc.x - sn * lc.y), py - (sn * lc.x + c * lc.y)), c, sn);
}

// b2Sweep::Normalize.
fn normalize_sweep(s: Sweep) -> Sweep {
  var out = s;
  let d = TWO_PI * floor(s.a0 / TWO_PI);
  out.a0 = s.a0 - d;
  out.a = s.a - d;
  return out;
}

// b2SeparationFunction::Initialize (its value at t1 is not used by b2TimeOfImpact).
fn separation_init(cache: ptr<function, SimplexCache>, pA: ptr<function, Proxy>, sA: Sweep, pB: ptr<function, Proxy>, sB: Sweep, t1: f32) -> SeparationFunction {
  let xfA = sweep_transform(sA, t1);
  let xfB = sweep_transform(sB, t1);
  var f: SeparationFunction;
  if ((*cache).count == 1u) {
    f.kind = SEP_POINTS;
    f.localPoint = vec2<f32>(0.0);
    let pointA = mul_xv(xfA, (*pA).v[(*cache).indexA[0]]);
    let pointB = mul_xv(xfB, (*pB).v[(*cache).indexB[0]]);
    f.axis = normalize2(vec2<f32>(pointB.x - pointA.x, pointB.y - pointA.y));
    return f;
  }
  if ((*cache).indexA[0] == (*cache).indexA[1]) {
    // Two points on B and one on A.
    f.kind = SEP_FACE_B;
    let b1 = (*pB).v[(*cache).indexB[0]];
    let b2 = (*pB).v[(*cache).indexB[1]];
    var axis = normalize2(vec2<f32>(1.0 * (b2.y - b1.y), -1.0 * (b2.x - b1.x)));
    let normal = mul_rv(xfB, axis);
    f.localPoint = vec2<f32>(0.5 * (b1.x + b2.x), 0.5 * (b1.y + b2.y));
    let pointB = mul_xv(xfB, f.localPoint);
    let pointA = mul_xv(xfA, (*pA).v[(*cache).indexA[0]]);
    let s = (pointA.x - pointB.x) * normal.x + (pointA.y - pointB.y) * normal.y;
    if (s < 0.0) {
      axis = -axis;
    }
    f.axis = axis;
    return f;
  }
  // Two points on A and one or two points on B.
  f.kind = SEP_FACE_A;
  let a1 = (*pA).v[(*cache).indexA[0]];
  let a2 = (*pA).v[(*cache).indexA[1]];
  var axis = normalize2(vec2<f32>(1.0 * (a2.y - a1.y), -1.0 * (a2.x - a1.x)));
  let normal = mul_rv(xfA, axis);
  f.localPoint = vec2<f32>(0.5 * (a1.x + a2.x), 0.5 * (a1.y + a2.y));
  let pointA = mul_xv(xfA, f.localPoint);
  let pointB = mul_xv(xfB, (*pB).v[(*cache).indexB[0]]);
  let s = (pointB.x - pointA.x) * normal.x + (pointB.y - pointA.y) * normal.y;
  if (s < 0.0) {
    axis = -axis;
  }
  f.axis = axis;
  return f;
}

// b2SeparationFunction::FindMinSeparation.
fn find_min_separation(f: SeparationFunction, pA: ptr<function, Proxy>, sA: Sweep, pB: ptr<function, Proxy>, sB: Sweep, t: f32) -> MinSeparation {
  let xfA = sweep_transform(sA, t);
  let xfB = sweep_transform(sB, t);
  var out: MinSeparation;
  if (f.kind == SEP_POINTS) {
    out.indexA = support(pA, mul_trv(xfA, f.axis));
    out.indexB = support(pB, mul_trv(xfB, -f.axis));
    let pointA = mul_xv(xfA, (*pA).v[out.indexA]);
    let pointB = mul_xv(xfB, (*pB).v[out.indexB]);
    out.separation = (pointB.x - pointA.x) * f.axis.x + (pointB.y - pointA.y) * f.axis.y;
  } else if (f.kind == SEP_FACE_A) {
    let normal = mul_rv(xfA, f.axis);
    let pointA = mul_xv(xfA, f.localPoint);
    out.indexA = 0u;
    out.indexB = support(pB, mul_trv(xfB, -normal));
    let pointB = mul_xv(xfB, (*pB).v[out.indexB]);
    out.separation = (pointB.x - pointA.x) * normal.x + (pointB.y - pointA.y) * normal.y;
  } else {
    let normal = mul_rv(xfB, f.axis);
    let pointB = mul_xv(xfB, f.localPoint);
    out.indexB = 0u;
    out.indexA = support(pA, mul_trv(xfA, -normal));
    let pointA = mul_xv(xfA, (*pA).v[out.indexA]);
    out.separation = (pointA.x - pointB.x) * normal.x + (pointA.y - pointB.y) * normal.y;
  }
  return out;
}

// b2SeparationFunction::Evaluate.
fn evaluate_separation(f: SeparationFunction, pA: ptr<function, Proxy>, sA: Sweep, pB: ptr<function, Proxy>, sB: Sweep, indexA: u32, indexB: u32, t: f32) -> f32 {
  let xfA = sweep_transform(sA, t);
  let xfB = sweep_transform(sB, t);
  if (f.kind == SEP_POINTS) {
    let pointA = mul_xv(xfA, (*pA).v[indexA]);
    let pointB = mul_xv(xfB, (*pB).v[indexB]);
    return (pointB.x - pointA.x) * f.axis.x + (pointB.y - pointA.y) * f.axis.y;
  }
  if (f.kind == SEP_FACE_A) {
    let normal = mul_rv(xfA, f.axis);
    let pointA = mul_xv(xfA, f.localPoint);
    let pointB = mul_xv(xfB, (*pB).v[indexB]);
    return (pointB.x - pointA.x) * normal.x + (pointB.y - pointA.y) * normal.y;
  }
  let normal = mul_rv(xfB, f.axis);
  let pointB = mul_xv(xfB, f.localPoint);
  let pointA = mul_xv(xfA, (*pA).v[indexA]);
  return (pointA.x - pointB.x) * normal.x + (pointA.y - pointB.y) * normal.y;
}

// b2TimeOfImpact: conservative advancement on separating axes over [0, tMax].
fn time_of_impact(pA: ptr<function, Proxy>, sweepA: Sweep, pB: ptr<function, Proxy>, sweepB: Sweep, tMax: f32) -> ToiOutput {
  var out = ToiOutput(0u, tMax);
  let sA = normalize_sweep(sweepA);
  let sB = normalize_sweep(sweepB);
  let totalRadius = (*pA).radius + (*pB).radius;
  // b2TimeOfImpact's target ('target' is reserved in WGSL).
  let goal = max(LINEAR_SLOP, totalRadius - 3.0 * LINEAR_SLOP);
  let tolerance = 0.25 * LINEAR_SLOP;
  var t1 = 0.0;
  var iter = 0u;
  var cache = empty_cache();
  loop {
    let distance = gjk_distance_cached(pA, sweep_transform(sA, t1), pB, sweep_transform(sB, t1), &cache);
    // Overlapped: continuous collision gives up.
    if (distance <= 0.0) {
      out = ToiOutput(TOI_OVERLAPPED, 0.0);
      break;
    }
    if (distance < goal + tolerance) {
      out = ToiOutput(TOI_TOUCHING, t1);
      break;
    }
    let f = separation_init(&cache, pA, sA, pB, sB, t1);

    // Resolve the deepest point on the axis, at most once per polygon vertex.
    var done = false;
    var t2 = tMax;
    var pushBackIter = 0u;
    loop {
      let m = find_min_separation(f, pA, sA, pB, sB, t2);
      var s2 = m.separation;
      if (s2 > goal + tolerance) {
        out = ToiOutput(TOI_SEPARATED, tMax);
        done = true;
        break;
      }
      if (s2 > goal - tolerance) {
        t1 = t2;
        break;
      }
      var s1 = evaluate_separation(f, pA, sA, pB, sB, m.indexA, m.indexB, t1);
      if (s1 < goal - tolerance) {
        out = ToiOutput(TOI_FAILED, t1);
        done = true;
        break;
      }
      if (s1 <= goal + tolerance) {
        out = ToiOutput(TOI_TOUCHING, t1);
        done = true;
        break;
      }
      // The root of s(t) = target: bisection and the secant rule in turn.
      var rootIterCount = 0u;
      var a1 = t1;
      var a2 = t2;
      loop {
        var t: f32;
        if ((rootIterCount & 1u) != 0u) {
          t = a1 + (goal - s1) * (a2 - a1) / (s2 - s1);
        } else {
          t = 0.5 * (a1 + a2);
        }
        let s = evaluate_separation(f, pA, sA, pB, sB, m.indexA, m.indexB, t);
        if (abs(s - goal) < tolerance) {
          t2 = t;
          break;
        }
        if (s > goal) {
          a1 = t;
          s1 = s;
        } else {
          a2 = t;
          s2 = s;
        }
        rootIterCount = rootIterCount + 1u;
        if (rootIterCount == TOI_MAX_ROOT_ITERATIONS) {
          break;
        }
      }
      pushBackIter = pushBackIter + 1u;
      if (pushBackIter == MAX_POLYGON_VERTICES) {
        break;
      }
    }
    iter = iter + 1u;
    if (done) {
      break;
    }
    if (iter == TOI_MAX_ITERATIONS) {
      out = ToiOutput(TOI_FAILED, t1);
      break;
    }
  }
  return out;
}

// Body b's sweep, moved by `shift` (its cell relative to the frame's).
fn load_sweep(b: u32, shift: vec2<f32>) -> Sweep {
  let s0 = bodySweepIn[2u * b];
  let s1 = bodySweepIn[2u * b + 1u];
  return Sweep(bodyMass[b].zw, s0.xy + shift, s1.xy + shift, s0.z, s1.z);
}

// A contact's shapes and sweeps (refA, refB: contactRef's layout), in A's cell.
struct ContactMotion {
  pA: Proxy,
  sA: Sweep,
  pB: Proxy,
  sB: Sweep,
}

fn contact_motion(refA: vec4<u32>, refB: vec4<u32>) -> ContactMotion {
  let shiftB = vec2<f32>(bodyCell[refB.z] - bodyCell[refA.z]) * toi.cellSize;
  return ContactMotion(load_proxy(refA.x, refA.y), load_sweep(refA.z, vec2<f32>(0.0)),
                       load_proxy(refB.x, refB.y), load_sweep(refB.z, shiftB));
}

// The most a core point of p moves over the sweep s: |c - c0| + |a - a0| |v - localCenter|.
fn motion_bound(p: ptr<function, Proxy>, s: Sweep) -> f32 {
  var extent = 0.0;
  for (var i = 0u; i < (*p).count; i = i + 1u) {
    extent = max(extent, length((*p).v[i] - s.localCenter));
  }
  return length(s.c - s.c0) + abs(s.a - s.a0) * extent;
}

// b2TimeOfImpact of a contact over [0, 1].
fn contact_toi(m: ptr<function, ContactMotion>) -> ToiOutput {
  return time_of_impact(&(*m).pA, (*m).sA, &(*m).pB, (*m).sB, 1.0);
}

@compute @workgroup_size(1)
fn begin() {
  var count = npState[NP_CONTACTS];
  if (solverState[SV_SKIP] != 0u) {
    count = 0u;
  }
  atomicStore(&toiBody[0], count);
  atomicStore(&toiBody[1], 0u);
  let size = dispatch_size(count, WORKGROUP_SIZE);
  toiIndirect[0] = size.x;
  toiIndirect[1] = size.y;
  toiIndirect[2] = size.z;
}

@compute @workgroup_size(256)
fn candidates(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
              @builtin(local_invocation_index) lid: u32) {
  let c = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  if (c >= atomicLoad(&toiBody[0])) {
    return;
  }
  let refA = contactRef[2u * c];
  let refB = contactRef[2u * c + 1u];
  if ((refA.w & REF_SENSOR) != 0u) {
    return;
  }
  let flagsA = bodyFlags[refA.z];
  let flagsB = bodyFlags[refB.z];
  let typeA = body_type(flagsA);
  let typeB = body_type(flagsB);
  if (typeA == STATIC_BODY && typeB == STATIC_BODY) {
    return;
  }
  let collideA = (flagsA & BODY_BULLET) != 0u || typeA != DYNAMIC_BODY;
  let collideB = (flagsB & BODY_BULLET) != 0u || typeB != DYNAMIC_BODY;
  // Two non-bullet dynamic bodies: no continuous collision between them.
  if (!collideA && !collideB) {
    return;
  }
  var m = contact_motion(refA, refB);
  if (motion_bound(&m.pA, m.sA) + motion_bound(&m.pB, m.sB) < toi.minMotion) {
    return;
  }
  // One atomic per fast pair, which the filter keeps rare (a count for tests and tools).
  atomicAdd(&toiBody[1], 1u);
  let out = contact_toi(&m);
  // Touching at the start of the step is left to the regular solver: 2.2.1 would solve a TOI
  // island there and move on; stopping the body at t = 0 would undo this step's position
  // correction, so a body resting 3 b2_linearSlop deep would stay there.
  if (out.state != TOI_TOUCHING || out.t <= 0.0) {
    return;
  }
  let key = ONE_BITS - bitcast<u32>(min(out.t, 1.0));
  if (typeA == DYNAMIC_BODY) {
    atomicMax(&toiBody[2u + refA.z], key);
  }
  if (typeB == DYNAMIC_BODY) {
    atomicMax(&toiBody[2u + refB.z], key);
  }
}

@compute @workgroup_size(256)
fn advance(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
           @builtin(local_invocation_index) lid: u32) {
  let i = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  if (i >= toi.bodySlots || solverState[SV_SKIP] != 0u) {
    return;
  }
  let alpha = bitcast<f32>(ONE_BITS - atomicExchange(&toiBody[2u + i], 0u));
  let s0 = bodySweep[2u * i];
  if (1.0 - 10.0 * EPSILON < alpha || bodyAwake[i] == 0u) {
    if (s0.w != 0.0) {
      bodySweep[2u * i] = vec4<f32>(s0.xyz, 0.0);
    }
    return;
  }
  // b2Body::Advance(alpha) from alpha0 = 0: the sweep's state at alpha becomes both ends.
  let s1 = bodySweep[2u * i + 1u];
  let beta = alpha;
  let c = vec2<f32>((1.0 - beta) * s0.x + beta * s1.x, (1.0 - beta) * s0.y + beta * s1.y);
  let a = (1.0 - beta) * s0.z + beta * s1.z;
  bodySweep[2u * i] = vec4<f32>(c, a, alpha);
  bodySweep[2u * i + 1u] = vec4<f32>(c, a, s1.w);
  let q = vec2<f32>(cos(a), sin(a));
  let lc = bodyMass[i].zw;
  bodyXfOut[i] = vec4<f32>(c.x - (q.x * lc.x - q.y * lc.y), c.y - (q.y * lc.x + q.x * lc.y), q);
}

// For tests and tools: b2TimeOfImpact of `toi.pairs` records in contactRef's layout, unfiltered;
// evaluated[k] = (b2TOIOutput::State, bits of t).
@compute @workgroup_size(256)
fn evaluate(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
            @builtin(local_invocation_index) lid: u32) {
  let k = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  if (k >= toi.pairs) {
    return;
  }
  var m = contact_motion(contactRef[2u * k], contactRef[2u * k + 1u]);
  let out = contact_toi(&m);
  evaluated[k] = vec2<u32>(out.state, bitcast<u32>(out.t));
}
