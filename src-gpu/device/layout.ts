/*
 * The GPU backend's data layout: every buffer the stages share, word by word. The WGSL side
 * holds the same numbers in shaders/shared/common.wgsl and in each stage's declarations; a test checks
 * that the two agree.
 *
 * Indices. Bodies, fixtures, proxies and joints each live in a slot: a dense index into their
 * structure-of-arrays buffers, handed out by GpuWorld (src-gpu/world/world.ts) lowest free slot first
 * and reused after a destroy. A proxy is one child of a fixture (a chain fixture has one proxy per
 * edge; every other shape has one), as in b2Fixture::m_proxies. A slot whose object is gone is
 * "dead": its flags say so and every stage skips it.
 *
 * Positions. A body's position is an integer cell and a float32 offset inside it:
 * world = cell * cellSize + local (cellSize 32 m by default). The offset stays within half a cell,
 * so it keeps about 1e-6 m of resolution anywhere in a world of any size, where a float32
 * absolute coordinate would keep 2.4e-4 m at 5 km. Stages that need a world coordinate (the
 * broad phase's AABBs) compute it relative to the world origin cell, in float32.
 *
 * Body buffers (index: body slot)
 *   bodyXf     vec4<f32>  p.x, p.y (body origin, relative to the cell), q.c, q.s (m_xf)
 *   bodyCell   vec2<i32>  the cell
 *   bodySweep  2 x vec4<f32>  c0.x, c0.y, a0, alpha0 | c.x, c.y, a, sleepTime  (m_sweep; c0 and c
 *                         relative to the same cell)
 *   bodyVel    vec4<f32>  v.x, v.y, w, 0
 *   bodyForce  vec4<f32>  force.x, force.y, torque, 0
 *   bodyMass   vec4<f32>  invMass, invI, localCenter.x, localCenter.y
 *   bodyParams vec4<f32>  linearDamping, angularDamping, gravityScale, 0
 *   bodyFlags  u32        b2Body::m_flags (bits 0-15) | type << 16 (bits 16-17) | BODY_LIVE
 *   bodyAwake  u32        1 awake, 0 asleep (b2Body::e_awakeFlag): GPU-owned once it
 *                         steps, like the motion (the islands stage wakes and puts to sleep;
 *                         bodyFlags' copy of e_awakeFlag is the JavaScript value, unused on the GPU)
 *   jointRange vec2<u32>  (start, count) into jointList: the bodies joined to this one by a joint
 *                         with collideConnected == false, ascending
 * Joint buffers
 *   jointList  u32        body slots (see jointRange)
 *   joints     vec4<u32>  (index: joint slot) body A slot, body B slot, b2JointType,
 *                         collideConnected | JOINT_LIVE
 *   jointParams 5 x vec4<f32>  (index: joint slot) row 0: localAnchorA, localAnchorB
 *                         (mouse: 0, localAnchorB), rows 1-4 by b2JointType (unused words 0; a
 *                         world point is a cell (i32 bits) and the offset in it, as bodies are):
 *       revolute   referenceAngle, lowerAngle, upperAngle, maxMotorTorque | motorSpeed,
 *                  enableLimit, enableMotor
 *       prismatic  referenceAngle, lowerTranslation, upperTranslation, maxMotorForce |
 *                  motorSpeed, enableLimit, enableMotor | localXAxisA, localYAxisA
 *       distance   length, frequencyHz, dampingRatio
 *       pulley     lengthA, lengthB, ratio, constant | groundAnchorA offset, groundAnchorB
 *                  offset | groundAnchorA cell, groundAnchorB cell
 *       mouse      frequencyHz, dampingRatio, maxForce, body B's mass | target offset | target cell
 *       gear       referenceAngleA, referenceAngleB, ratio, constant | localAnchorC,
 *                  localAnchorD | localAxisC, localAxisD | body C slot, body D slot (u32 bits),
 *                  joint types A, B (u32 bits)
 *       wheel      frequencyHz, dampingRatio, 0, maxMotorTorque | motorSpeed, 0, enableMotor |
 *                  localXAxisA, localYAxisA
 *       weld       referenceAngle, frequencyHz, dampingRatio
 *       friction   maxForce, maxTorque
 *       rope       maxLength
 *   jointState 2 x vec4<f32>  impulses: revolute, prismatic x, y, z, motorImpulse; weld x, y, z;
 *                         distance, pulley, gear, rope impulse; mouse x, y; wheel impulse,
 *                         springImpulse, motorImpulse; friction linear x, y, angular |
 *                         b2LimitState as a float (revolute, prismatic, rope): the warm-start
 *                         state, GPU-owned once it steps
 * Fixture buffers (index: fixture slot)
 *   fixtureShape    vec4<u32>  type | shape flags << 4 | vertexCount << 8, pool offset,
 *                              body slot, radius (f32 bits)
 *   fixtureMaterial vec4<f32>  friction, restitution, density, 0
 *   shapePool       vec2<f32>  shape data, at the fixture's pool offset:
 *       circle   [m_p]
 *       edge     [m_vertex1, m_vertex2, m_vertex0, m_vertex3]   (ghosts valid per the flags)
 *       polygon  [vertices 0..n-1, normals 0..n-1, m_centroid]  (n = vertexCount <= 8)
 *       chain    [vertices 0..n-1, m_prevVertex, m_nextVertex]  (n = vertexCount = m_count;
 *                 child i is the edge (v[i], v[i+1]) with ghosts v[i-1] or m_prevVertex and
 *                 v[i+2] or m_nextVertex, as b2ChainShape::GetChildEdge)
 *     shape flags: SHAPE_HAS_VERTEX0 (edge m_hasVertex0, chain m_hasPrevVertex),
 *     SHAPE_HAS_VERTEX3 (edge m_hasVertex3, chain m_hasNextVertex), SHAPE_SENSOR.
 * Proxy buffers (index: proxy slot)
 *   proxyRef    vec4<u32>  fixture slot, child index, body slot, flag word: shape type (bits 0-1),
 *                          body type (bits 2-3), PROXY_LIVE, PROXY_SENSOR, PROXY_JOINTED
 *   proxyFilter vec2<u32>  categoryBits | maskBits << 16, groupIndex & 0xffff (int16 bits)
 *   proxyKey    vec2<u32>  the engine's broad-phase proxy id (b2FixtureProxy.proxyId; the slot
 *                          when there is none), the slot's generation (changes whenever the slot
 *                          is given to another proxy)
 *   proxyAABB   vec4<f32>  lower.x, lower.y, upper.x, upper.y relative to the world origin cell,
 *                          written by the bounds stage; EMPTY for a dead slot
 * Broad-phase output
 *   pairs       vec2<u32>  (proxy a, proxy b), a < b, sorted by (a, b), no duplicates
 *   state       u32 x STATE_WORDS  counts and parameters passed between stages (STATE below)
 *   indirect    u32 x INDIRECT_WORDS  dispatch sizes computed on the GPU (ARGS below)
 *
 * Narrow-phase output (src-gpu/narrowphase/narrowPhase.ts; index: contact = position in this step's
 * pair list, sorted by (proxy a, proxy b)). Two contact sets alternate: this step's and the
 * previous step's (keys and manifolds), the rest is per step.
 *   contactKey  vec4<u32>  proxy a, proxy b (a < b, the pair), generation of a, generation of b:
 *                          the persistent key, sorted
 *   contactRef  2 x vec4<u32>  (fixture A, child A, body A, bin << 4 | CONTACT_KEPT | sensor << 1 | swapped),
 *                          (fixture B, child B, body B, previous step's index or NO_CONTACT):
 *                          A and B ordered as b2Contact::Create orders the fixtures
 *   manifold    4 x vec4   [header (u32): type | pointCount << 2 | MF flags, id key 0, id key 1,
 *                          previous index], [localNormal, localPoint] (f32), [points[0].localPoint,
 *                          points[1].localPoint] (f32), [normalImpulse 0, tangentImpulse 0,
 *                          normalImpulse 1, tangentImpulse 1] (f32): b2Manifold, id keys packed
 *                          as b2ContactID::key (indexA | indexB << 8 | typeA << 16 | typeB << 24)
 *   solverList  u32        indices of the touching non-sensor contacts, ascending (NP.SOLVER)
 *   events      vec4<u32>  (proxy A, proxy B, EVENT_BEGIN | EVENT_END, contact index, or previous
 *                          index | 0x80000000 for a contact gone with its pair), in contact order
 *   npState     u32 x NP_STATE_WORDS  (NP below), npIndirect u32 x NP_INDIRECT_WORDS (NP_ARGS)
 *
 * Solver (src-gpu/solver/solver.ts; index k: position in this step's solverList). It writes the
 * body motion tables in place (bodySweep, bodyVel, bodyXf, bodyCell) and word 3 of the manifolds.
 *   contactBodies  vec4<u32>  body A, body B, flags (points used, manifold points and type, which
 *                          bodies are dynamic: shaders/shared/solverCommon.wgsl CB_*), contact index
 *   constraints    CONSTRAINT_VEC4 x vec4<f32>  b2ContactVelocityConstraint and
 *                          b2ContactPositionConstraint together (rows in solverCommon.wgsl)
 *   colours        u32        colour of each item (joint slots, then solver contacts k as items
 *                         joints + k), COLOUR_CAP for the overflow set
 *   colourKeys     vec2<u32>  (colour, item) sorted by colour, items ascending within a colour
 *   jointBodies    2 x vec4<u32>  (index: joint slot) bodies A, B, C, D (NO_BODY but for a gear) |
 *                          b2JointType, dynamic mask, solved this step, b2LimitState
 *   jointConstraints JOINT_VEC4 x vec4<f32>  (index: joint slot) the joint's solver data (rows in
 *                          shaders/shared/solveJointsCommon.wgsl)
 *   bodyMark       2 x u32    per body slot: Jones-Plassmann priorities of the round's parity
 *   solverState    u32 x SV_STATE_WORDS (SV below), solverIndirect u32 x SV_INDIRECT_WORDS
 *   islands        ISLAND_WORDS x u32 per body slot: union-find parent (after the island search
 *                          the island's label, its smallest body slot; NO_ISLAND for static,
 *                          inactive and dead bodies), then per root: any body awake, the smallest
 *                          sleep time (f32 bits) (shaders/solver/islands.wgsl)
 *   toiBody        u32        continuous collision (src-gpu/solver/timeOfImpact.ts): word 0 the contacts to
 *                          test, word 1 those tested, word 2 + body slot 0x3f800000 - bits of the
 *                          body's earliest time of impact (0: none; zero again after each step),
 *                          toiIndirect 3 x u32
 */

/** GPUBufferUsage, without relying on the WebGPU globals being installed. */
export const USAGE = {
  MAP_READ: 0x0001,
  MAP_WRITE: 0x0002,
  COPY_SRC: 0x0004,
  COPY_DST: 0x0008,
  UNIFORM: 0x0040,
  STORAGE: 0x0080,
  INDIRECT: 0x0100,
  QUERY_RESOLVE: 0x0200,
} as const;

/** Sides of a circle's outline drawn by the renderer (shaders/render/render.wgsl CIRCLE_SEGMENTS). */
export const RENDER_CIRCLE_SEGMENTS = 16;

/**
 * The renderer's draw lists, in drawing order (shaders/shared/renderView.wgsl LIST_*): each is a
 * region of the list buffer and a drawIndirect record of RENDER_DRAW_ARGS_WORDS words.
 */
export const RENDER_LIST = { FILL_SMALL: 0, FILL: 1, OUTLINE_SMALL: 2, OUTLINE: 3, POINT: 4 } as const;
export const RENDER_LIST_COUNT = 5;
/** vertexCount, instanceCount, firstVertex, firstInstance (renderView.wgsl DRAW_ARGS_WORDS). */
export const RENDER_DRAW_ARGS_WORDS = 4;
/** Polygons of at most this many vertices take the small lists (shaders/render/cull.wgsl SMALL_POLYGON_VERTICES). */
export const RENDER_SMALL_POLYGON_VERTICES = 4;
/** A shape narrower than this many pixels on screen is drawn as one point (cull.wgsl POINT_PIXELS). */
export const RENDER_POINT_PIXELS = 2;
/** view.colourMode: colours by body state or the application's per body (cull.wgsl COLOUR_*). */
export const RENDER_COLOUR_MODE = { STATE: 0, BODY: 1 } as const;

/** GPUShaderStage, without relying on the WebGPU globals being installed. */
export const SHADER_STAGE = { VERTEX: 0x1, FRAGMENT: 0x2, COMPUTE: 0x4 } as const;

/** GPUTextureUsage, likewise. */
export const TEXTURE_USAGE = { COPY_SRC: 0x01, COPY_DST: 0x02, TEXTURE_BINDING: 0x04, STORAGE_BINDING: 0x08, RENDER_ATTACHMENT: 0x10 } as const;

/** GPUMapMode.READ. */
export const MAP_READ = 0x0001;

export const WORKGROUP_SIZE = 256;

/** Word indices of the state buffer (shaders/shared/common.wgsl STATE_*). */
export const STATE = {
  AXIS: 0,
  PAIR_COUNT: 1,
  WORK_TOTAL: 2,
  PAIR_SORT_COUNT: 3,
  OVERFLOW: 4,
  PAIR_CAPACITY: 5,
  ENTRY_TOTAL: 6,
  LIVE_COUNT: 7,
  STRIPS: 8,
  AXIS_LO: 9,
  AXIS_SCALE: 10,
  OTHER_LO: 11,
  OTHER_INV_H: 12,
  ENTRY_CAPACITY: 13,
  SLOT_COUNT: 14,
  ENTRIES: 15,
} as const;
export const STATE_WORDS = 16;

/** Bits of state[STATE.OVERFLOW]. */
export const OVERFLOW_PAIRS = 1;
export const OVERFLOW_ENTRIES = 2;

/**
 * Sweep entry keys: strip << q | the quantised lower bound cut to q bits, KEY_BITS in all
 * (shaders/shared/common.wgsl sweep_key).
 */
export const QUANT_BITS = 20;
export const MAX_STRIPS = 4096;
export const KEY_BITS = 24;

/** Word offsets of the indirect-dispatch triples (shaders/shared/common.wgsl ARGS_*). */
export const ARGS = {
  EMIT: 0,
  PAIR_TILES: 3,
  ENTRY_GROUPS: 6,
  ENTRY_TILES: 9,
  ENTRY_BLOCKS: 12,
} as const;
export const INDIRECT_WORDS = 16;

export const PROXY_LIVE = 0x10;
export const PROXY_SENSOR = 0x20;
export const PROXY_JOINTED = 0x40;

export const SHAPE_HAS_VERTEX0 = 0x1;
export const SHAPE_HAS_VERTEX3 = 0x2;
export const SHAPE_SENSOR = 0x4;

export const BODY_LIVE = 0x80000000;
export const JOINT_LIVE = 0x80000000;

/** Word indices of the narrow phase's state buffer (shaders/shared/common.wgsl NP_*). */
export const NP = {
  COUNT_0: 0,
  COUNT_1: 1,
  CONTACTS: 2,
  PREV: 3,
  CAPACITY: 4,
  OVERFLOW: 5,
  PAIRS: 6,
  SOLVER: 7,
  EVENTS: 8,
  EVENT_SLOTS: 9,
  KEPT: 10,
  BINS: 16,
} as const;
export const NP_STATE_WORDS = 32;

/** Bit of npState[NP.OVERFLOW]. */
export const OVERFLOW_CONTACTS = 1;

/** Pair-type bins (shaders/shared/common.wgsl BIN_*): contact A/B as b2Contact::Create orders them. */
export const BIN = {
  CIRCLES: 0,
  POLYGON_CIRCLE: 1,
  POLYGONS: 2,
  EDGE_CIRCLE: 3,
  EDGE_POLYGON: 4,
  CHAIN_CIRCLE: 5,
  CHAIN_POLYGON: 6,
  SENSOR: 7,
  NONE: 8,
  KEPT: 9,
} as const;
export const BIN_COUNT = 8;
/**
 * Bit of contactRef's flag word (word 3 of a contact's first record): the contact is not collided
 * this step and keeps the previous step's manifold (b2ContactManager::Collide: neither body awake
 * and non-static; shaders/narrowphase/contacts.wgsl `keep`).
 */
export const CONTACT_KEPT = 0x4;
export const BIN_NAMES = ['circles', 'polygon-circle', 'polygons', 'edge-circle', 'edge-polygon', 'chain-circle', 'chain-polygon', 'sensor'] as const;

/** Word offsets of the narrow phase's indirect triples (shaders/shared/common.wgsl NP_ARGS_*). */
export const NP_ARGS = {
  CONTACTS: 0,
  TILES: 3,
  BLOCKS: 6,
  PREV: 9,
  EVENT_SLOTS: 12,
  EVENT_BLOCKS: 15,
  SOLVER: 18,
  BINS: 21,
} as const;
export const NP_INDIRECT_WORDS = 48;

/** Flags of a manifold's header word (shaders/shared/common.wgsl MF_*); bits 0-1 type, 2-3 point count. */
export const MF = {
  TOUCHING: 0x10,
  SENSOR: 0x20,
  BEGAN: 0x40,
  ENDED: 0x80,
  WARM: 0x100,
  SWAPPED: 0x200,
  SOLVED: 0x400,
} as const;
/** u32 words per contact in the manifold buffer. */
export const MANIFOLD_WORDS = 16;
export const NO_CONTACT = 0xffffffff;
export const EVENT_BEGIN = 1;
export const EVENT_END = 2;

/** Word indices of the solver's state buffer (shaders/shared/common.wgsl SV_*). */
export const SV = {
  SKIP: 0,
  COUNT: 1,
  MIN_SEPARATION: 2,
  POSITION_ITERATIONS: 3,
  POSITION_DONE: 4,
  JOINT_ERROR: 5,
  JOINTS: 6,
  ITEMS: 7,
  COLOUR_START: 8,
  COLOUR_CHANGED: 34,
  COLOURED_ITEMS: 35,
  COLOURED_JOINTS: 36,
  COLOUR_SORT_COUNT: 37,
  COLOURS_USED: 38,
  PENETRATION: 39,
  AWAKE: 40,
} as const;
export const SV_STATE_WORDS = 41;
/**
 * Solver state words each step's read-back carries (pipeline.ts, one copy): SV.COLOUR_START ..
 * SV.AWAKE, the colour starts (the sizes GpuSolver.passColours follows), the colours used, the
 * step's penetration and the bodies awake after it (a world at rest skips its steps: GpuPipeline.skipResting).
 */
export const SV_READBACK_WORDS = SV.AWAKE + 1 - SV.COLOUR_START;

/**
 * Solver items (contacts and joints) up to which one workgroup runs the colouring rounds, the warm
 * start and the velocity and position iterations of a step, each in one dispatch (the solver's
 * fused passes): for a small world, hundreds of nearly empty per-colour dispatches cost more than
 * the parallelism they buy. Set where the two cost the same device time on an H100
 * (bench/results/gpu-small-world.md).
 */
export const FUSED_SOLVER_ITEMS = 6144;

/** Colours of the graph colouring; colour COLOUR_CAP is the overflow set. */
export const COLOUR_CAP = 24;
/**
 * The colour of an item with no dynamic body, which nothing solves: a sleeping island's contact
 * (prepareContacts leaves it none) or a joint not solved this step. Sorted after the overflow set,
 * where no pass reaches, so a world at rest dispatches its iterations over nothing.
 */
export const COLOUR_IDLE = COLOUR_CAP + 1;
export const UNCOLOURED = 0xffffffff;

/**
 * Items below which a colour gets no pass of its own in the warm start and each velocity and
 * position iteration: the tail pass (one workgroup) solves it after the colours that do
 * (GpuSolver.passColours: the leading colours of at least this many items in the latest read-back
 * step). A colour of fewer items than a workgroup's invocations is one workgroup in a dispatch of
 * its own as well; in the tail the same work costs a storage barrier instead of a dispatch (about
 * 2 µs on an H100). A colour of more costs the tail another round of WORKGROUP_SIZE items, which
 * the fused passes' H100 timings price at 2-7 µs (bench/results/gpu-small-world.md: 0.1-0.33 µs a
 * contact a step over 12 passes), no less than the dispatch it would save.
 */
export const TAIL_COLOUR_ITEMS = WORKGROUP_SIZE;

/**
 * Word offsets of the solver's indirect triples (shaders/shared/common.wgsl SV_ARGS_*). COLOURS
 * and POSITION hold one triple per colour, then at COLOUR_CAP the tail pass's (one workgroup).
 */
export const SV_ARGS = {
  CONTACTS: 0,
  TILES: 3,
  COLOURS: 6,
  POSITION: 81,
  ITEMS: 156,
  ROUNDS: 159,
} as const;
export const SV_INDIRECT_WORDS = 164;

/** u32 words per body slot in the islands buffer, and the label of a body in no island (shaders/solver/islands.wgsl). */
export const ISLAND_WORDS = 4;
export const NO_ISLAND = 0xffffffff;

/** vec4s per solver contact in the constraint buffer (shaders/shared/solverCommon.wgsl). */
export const CONSTRAINT_VEC4 = 13;

/** The default cell size in metres (a power of two, so cell * cellSize is exact in float32). */
export const DEFAULT_CELL_SIZE = 32;

/** Elements each radix-sort workgroup handles (shaders/primitives/radixSort.wgsl TILE). */
export const SORT_TILE = 1024;
/** Elements each scan block covers (shaders/primitives/scan.wgsl BLOCK). */
export const SCAN_BLOCK = 4096;
/** AABBs each axis-reduction workgroup covers (shaders/broadphase/axis.wgsl ITEMS_PER_GROUP). */
export const AXIS_ITEMS_PER_GROUP = 4096;
/** Candidates one sweep invocation tests (shaders/broadphase/sweep.wgsl CHUNK). */
export const SWEEP_CHUNK = 32;

/** Workgroups in x and y for `groups` workgroups under the per-dimension limit. */
export function split2D(groups: number, maxPerDimension = 65535): [number, number] {
  if (groups <= 0) return [0, 1];
  const x = Math.min(groups, maxPerDimension);
  return [x, Math.ceil(groups / x)];
}

/** The sortable u32 of a float32 (shaders/shared/common.wgsl sortable_key), for CPU references. */
export function sortableKey(f32bits: number): number {
  let u = f32bits >>> 0;
  if (u === 0x80000000) u = 0;
  return (u & 0x80000000) !== 0 ? ~u >>> 0 : (u | 0x80000000) >>> 0;
}
