// solverCommon.wgsl: what the solver stages share (b2Island::Solve and b2ContactSolver in
// float32); the host prepends it to each solver stage after common.wgsl.
//
// In:  nothing itself: definitions only.
// Out: the solver's parameters (uniform), the constants of b2Settings.h it uses, the layout of a
//      solver contact (below), the small vector helpers of b2Math.h and b2PositionSolverManifold
//      (the position iterations and the penetration measure evaluate separations alike).
// Solver contacts (index k: position in this step's solverList) live in two buffers:
//   contactBodies  vec4<u32>  body A, body B, CB_* flags (point counts, manifold type, which bodies
//                             are dynamic), the contact index
//   constraints    CONSTRAINT_VEC4 x vec4<f32>:
//     0 normal, friction, restitution      1 invMassA, invIA, invMassB, invIB
//     2 rA, rB of point 0                  3 rA, rB of point 1
//     4 normalImpulse 0, tangentImpulse 0, normalImpulse 1, tangentImpulse 1
//     5 normalMass 0, tangentMass 0, normalMass 1, tangentMass 1
//     6 velocityBias 0, velocityBias 1, radiusA, radiusB
//     7 K (ex.x, ex.y, ey.x, ey.y)         8 normalMass of the block solver (ex.x, ex.y, ey.x, ey.y)
//     9 localNormal, localPoint            10 localPoints[0], localPoints[1]
//     11 localCenterA, localCenterB        12 B's cell relative to A's ((cellB - cellA) * cellSize), 0, 0
// Positions: a body's sweep centre is relative to its own cell; a contact works in body A's cell
// (B's centre + row 12), so its arithmetic does not depend on the distance from the origin.
// Only dynamic bodies are written: static and kinematic ones have zero inverse mass, so the
// solver never changes them, and several contacts of one colour may share them.

struct SolverParams {
  h: f32,                 // b2TimeStep::dt
  dtRatio: f32,           // b2TimeStep::dtRatio (warm-start scale)
  gravity: vec2<f32>,
  cellSize: f32,
  warmStarting: u32,
  bodySlots: u32,
  jointSlots: u32,
  velocityIterations: u32, // the fused passes (one workgroup for a small world) loop over these
  positionIterations: u32,
  pad0: u32,
  pad1: u32,
}

// A colour: the one a per-colour pass (`main`) solves, the first one a tail pass (`tail`) walks,
// or a round of the colouring (colour.wgsl).
struct ColourParams {
  colour: u32,
  pad0: u32,
  pad1: u32,
  pad2: u32,
}

// b2Settings.h, as float32.
const S_EPSILON: f32 = 0x1p-23f;               // b2_epsilon
const MAX_CONDITION_NUMBER: f32 = 1000.0;      // k_maxConditionNumber (b2ContactSolver.cpp)

// contactBodies[k].z
const CB_POINTS: u32 = 0x3u;                   // points the velocity solver uses (1 when the block solver is ill-conditioned)
const CB_MANIFOLD_POINTS_SHIFT: u32 = 2u;      // bits 2-3: the manifold's point count
const CB_TYPE_SHIFT: u32 = 4u;                 // bits 4-5: b2Manifold::Type
const CB_DYNAMIC_A: u32 = 0x100u;
const CB_DYNAMIC_B: u32 = 0x200u;

// b2Cross(a, b) for vectors, b2Cross(v, s) and b2Cross(s, v).
fn cross2(a: vec2<f32>, b: vec2<f32>) -> f32 {
  return a.x * b.y - a.y * b.x;
}
fn cross_vs(v: vec2<f32>, s: f32) -> vec2<f32> {
  return vec2<f32>(s * v.y, -s * v.x);
}
fn cross_sv(s: f32, v: vec2<f32>) -> vec2<f32> {
  return vec2<f32>(-s * v.y, s * v.x);
}

// b2Rot(angle) as (c, s), and b2Mul(q, v).
fn rot(angle: f32) -> vec2<f32> {
  return vec2<f32>(cos(angle), sin(angle));
}
fn rotate(q: vec2<f32>, v: vec2<f32>) -> vec2<f32> {
  return vec2<f32>(q.x * v.x - q.y * v.y, q.y * v.x + q.x * v.y);
}

// b2Vec2::Normalize: unchanged when shorter than b2_epsilon.
fn normalize2(v: vec2<f32>) -> vec2<f32> {
  let length = sqrt(v.x * v.x + v.y * v.y);
  if (length < S_EPSILON) {
    return v;
  }
  let inv = 1.0 / length;
  return v * inv;
}

// b2PositionSolverManifold::Initialize for point j of a manifold of type `kind` (lm: localNormal,
// localPoint; localPoints: points[0], points[1]) between bodies at (pA, qA) and (pB, qB), both
// relative to one origin: the normal (from A to B), the point and its separation.
struct PositionManifold {
  normal: vec2<f32>,
  point: vec2<f32>,
  separation: f32,
}

fn position_manifold(kind: u32, j: u32, pA: vec2<f32>, qA: vec2<f32>, pB: vec2<f32>, qB: vec2<f32>,
                     lm: vec4<f32>, localPoints: vec4<f32>, radii: vec2<f32>) -> PositionManifold {
  var m: PositionManifold;
  if (kind == E_CIRCLES) {
    let pointA = pA + rotate(qA, lm.zw);
    let pointB = pB + rotate(qB, localPoints.xy);
    m.normal = normalize2(pointB - pointA);
    m.point = 0.5 * (pointA + pointB);
    m.separation = dot(pointB - pointA, m.normal) - radii.x - radii.y;
  } else if (kind == E_FACE_A) {
    m.normal = rotate(qA, lm.xy);
    let planePoint = pA + rotate(qA, lm.zw);
    let clipPoint = pB + rotate(qB, select(localPoints.zw, localPoints.xy, j == 0u));
    m.separation = dot(clipPoint - planePoint, m.normal) - radii.x - radii.y;
    m.point = clipPoint;
  } else {
    let normal = rotate(qB, lm.xy);
    let planePoint = pB + rotate(qB, lm.zw);
    let clipPoint = pA + rotate(qA, select(localPoints.zw, localPoints.xy, j == 0u));
    m.separation = dot(clipPoint - planePoint, normal) - radii.x - radii.y;
    m.point = clipPoint;
    m.normal = -normal;
  }
  return m;
}
