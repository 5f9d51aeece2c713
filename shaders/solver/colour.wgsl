// colour.wgsl: GpuStage.Colour, the graph colouring of the solver's items, joints and contacts
// together (hashed-priority Jones-Plassmann), and the colour lists; the last colouring is reused
// while every item has the same dynamic bodies.
//
// Items: joint slots 0 .. SV_JOINTS - 1 (jointBodies, solveJoints.wgsl: up to four bodies, a
// gear's four), then solver contacts k as items SV_JOINTS + k (contactBodies, prepareContacts.wgsl).
// In:  params (joint slots), the broad phase's state (overflow), npState (NP_SOLVER, NP_OVERFLOW),
//      contactBodies and jointBodies (bodies, which are dynamic), signatures (the last colouring's
//      items).
// Out: `begin` (one invocation): solverState SV_SKIP, SV_COUNT, SV_JOINTS, SV_ITEMS, the
//      position-iteration words, SV_COLOUR_CHANGED = 0, SV_PENETRATION = 0 (penetration.wgsl's
//      maximum starts from no depth), SV_AWAKE = 0 (islands.wgsl counts into it), the indirect
//      sizes of per-contact and per-item passes.
//      `invalidate` (one invocation, recorded when the host replaced a buffer that holds the last
//      colouring): SV_COLOUR_CHANGED = 1.
//      `compare` (per item): SV_COLOUR_CHANGED = 1 when the item's signature (its dynamic bodies,
//      NO_BODY for the others) differs from signatures[item]. `decide` (one invocation): a
//      different item or joint count is a change too; without a change the rounds and the sort
//      get zero-sized dispatches and the last colouring's colours and sorted keys stand.
//      `mark` / `pick` (per item, round r = round.colour, rounds 0 .. COLOUR_CAP - 1): each
//      uncoloured item posts its priority (a bijective hash of the item: unique, the same every
//      run) to its dynamic bodies with atomicMax; an item whose priority is the maximum on all its
//      dynamic bodies takes colour r. The items of one colour share no dynamic body; static
//      and kinematic bodies (never written by the solver) block nothing. The last `pick`
//      (round COLOUR_CAP) puts what is left in the overflow set (colour COLOUR_CAP), writes
//      colourKeys[i] = (colour, i) for the sort (radixSort.wgsl, stable: items ascending per
//      colour, so each colour lists its joints, then its contacts) and the item's signature.
//      `rounds` (one workgroup): every round of `mark` and `pick` with barriers, for a small world.
//      `offsets` (one workgroup, every step: the early exit zeroes the position passes' sizes):
//      SV_COLOUR_START (first entry of each colour in the sorted keys, then the overflow set's
//      end, where the idle items begin), the indirect size of each colour's warm-start, velocity
//      and position passes, and one workgroup for the tail passes
//      (the colours the host records no pass of their own for, then the overflow set, which is
//      solved in order), SV_COLOURS_USED (the colours up to the last non-empty one).
// Invariants: bodyMark holds two words per body (round parity); round r posts to parity r & 1
//      and clears parity (r - 1) & 1 for the items that posted there in round r - 1, so both
//      are zero again after the last round, and colours depend on nothing but the items' dynamic
//      bodies and their order: the same bits on every run, and reusing a colouring gives the bits
//      colouring again would. Priorities are compared with atomicMax, whose result does not
//      depend on the order of the atomics. A joint that is not solved this step (dead slot,
//      inactive body) or a sleeping island's contact has no dynamic body: it takes COLOUR_IDLE in
//      round 0, sorted after the overflow set, and no pass visits it.

@group(0) @binding(0) var<uniform> round: ColourParams;
@group(0) @binding(1) var<storage, read> broadState: array<u32>;
@group(0) @binding(2) var<storage, read> npState: array<u32>;
@group(0) @binding(3) var<storage, read_write> solverState: array<atomic<u32>>;
@group(0) @binding(4) var<storage, read_write> solverIndirect: array<u32>;
@group(0) @binding(5) var<storage, read> contactBodies: array<vec4<u32>>;
@group(0) @binding(6) var<storage, read_write> colours: array<u32>;
@group(0) @binding(7) var<storage, read_write> bodyMark: array<atomic<u32>>;
@group(0) @binding(8) var<storage, read_write> colourKeys: array<vec2<u32>>;
@group(0) @binding(9) var<uniform> params: SolverParams;
@group(0) @binding(10) var<storage, read> jointBodies: array<vec4<u32>>;
@group(0) @binding(11) var<storage, read_write> signatures: array<vec4<u32>>;

const NO_BODY: u32 = 0xffffffffu;

fn write_args(offset: u32, size: vec3<u32>) {
  solverIndirect[offset] = size.x;
  solverIndirect[offset + 1u] = size.y;
  solverIndirect[offset + 2u] = size.z;
}

@compute @workgroup_size(1)
fn begin() {
  let skip = broadState[STATE_OVERFLOW] != 0u || npState[NP_OVERFLOW] != 0u;
  let count = select(npState[NP_SOLVER], 0u, skip);
  let items = select(params.jointSlots + count, 0u, skip);
  atomicStore(&solverState[SV_SKIP], select(0u, 1u, skip));
  atomicStore(&solverState[SV_COUNT], count);
  atomicStore(&solverState[SV_JOINTS], params.jointSlots);
  atomicStore(&solverState[SV_ITEMS], items);
  atomicStore(&solverState[SV_POSITION_ITERATIONS], 0u);
  atomicStore(&solverState[SV_POSITION_DONE], 0u);
  atomicStore(&solverState[SV_JOINT_ERROR], 0u);
  atomicStore(&solverState[SV_MIN_SEPARATION], sortable_key(0.0));
  atomicStore(&solverState[SV_COLOUR_CHANGED], 0u);
  atomicStore(&solverState[SV_COLOURS_USED], 0u);
  atomicStore(&solverState[SV_PENETRATION], 0u);
  atomicStore(&solverState[SV_AWAKE], 0u);
  write_args(SV_ARGS_CONTACTS, dispatch_size(count, WORKGROUP_SIZE));
  write_args(SV_ARGS_ITEMS, dispatch_size(items, WORKGROUP_SIZE));
}

@compute @workgroup_size(1)
fn invalidate() {
  atomicStore(&solverState[SV_COLOUR_CHANGED], 1u);
}

@compute @workgroup_size(1)
fn decide() {
  let items = atomicLoad(&solverState[SV_ITEMS]);
  let joints = atomicLoad(&solverState[SV_JOINTS]);
  let changed = atomicLoad(&solverState[SV_COLOUR_CHANGED]) != 0u || items != atomicLoad(&solverState[SV_COLOURED_ITEMS]) ||
    joints != atomicLoad(&solverState[SV_COLOURED_JOINTS]);
  let colouring = select(0u, items, changed);
  atomicStore(&solverState[SV_COLOUR_CHANGED], select(0u, 1u, changed));
  atomicStore(&solverState[SV_COLOURED_ITEMS], items);
  atomicStore(&solverState[SV_COLOURED_JOINTS], joints);
  atomicStore(&solverState[SV_COLOUR_SORT_COUNT], colouring);
  write_args(SV_ARGS_ROUNDS, dispatch_size(colouring, WORKGROUP_SIZE));
  write_args(SV_ARGS_TILES, dispatch_size(colouring, 1024u));
}

// lowbias32 (C. Wellons): every step is a bijection of u32, so distinct items get distinct
// priorities.
fn priority(k: u32) -> u32 {
  var x = k;
  x = x ^ (x >> 16u);
  x = x * 0x7feb352du;
  x = x ^ (x >> 15u);
  x = x * 0x846ca68bu;
  x = x ^ (x >> 16u);
  return x;
}

fn item_index(wid: vec3<u32>, nwg: vec3<u32>, lid: u32) -> u32 {
  let i = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  if (i >= atomicLoad(&solverState[SV_ITEMS])) {
    return NO_CONTACT;
  }
  return i;
}

// The item's bodies (up to four) and a mask of those that are dynamic (bit n: body n).
struct ItemBodies {
  list: vec4<u32>,
  dynamic: u32,
}

fn item_bodies(i: u32) -> ItemBodies {
  let joints = atomicLoad(&solverState[SV_JOINTS]);
  if (i < joints) {
    return ItemBodies(jointBodies[2u * i], jointBodies[2u * i + 1u].y);
  }
  let cb = contactBodies[i - joints];
  var dynamic = 0u;
  if ((cb.z & CB_DYNAMIC_A) != 0u) {
    dynamic = 1u;
  }
  if ((cb.z & CB_DYNAMIC_B) != 0u) {
    dynamic = dynamic | 2u;
  }
  return ItemBodies(vec4<u32>(cb.x, cb.y, 0u, 0u), dynamic);
}

// What the colouring reads of an item: its dynamic bodies, NO_BODY in place of the others.
fn signature(bodies: ItemBodies) -> vec4<u32> {
  var s = vec4<u32>(NO_BODY);
  for (var n = 0u; n < 4u; n = n + 1u) {
    if ((bodies.dynamic & (1u << n)) != 0u) {
      s[n] = bodies.list[n];
    }
  }
  return s;
}

@compute @workgroup_size(256)
fn compare(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
           @builtin(local_invocation_index) lid: u32) {
  let i = item_index(wid, nwg, lid);
  if (i == NO_CONTACT) {
    return;
  }
  if (any(signature(item_bodies(i)) != signatures[i])) {
    atomicStore(&solverState[SV_COLOUR_CHANGED], 1u);
  }
}

// Round r of item i: post its priority to its dynamic bodies (uncoloured items; round 0 uncolours all).
fn mark_item(i: u32, r: u32) {
  if (r == 0u) {
    colours[i] = UNCOLOURED;
  } else if (colours[i] != UNCOLOURED) {
    return;
  }
  let bodies = item_bodies(i);
  let parity = r & 1u;
  let p = priority(i);
  for (var n = 0u; n < 4u; n = n + 1u) {
    if ((bodies.dynamic & (1u << n)) != 0u) {
      atomicMax(&bodyMark[2u * bodies.list[n] + parity], p);
    }
  }
}

// Round r of item i: clear what it posted in round r - 1, take colour r where its priority won.
fn pick_item(i: u32, r: u32) {
  let bodies = item_bodies(i);
  if (r == COLOUR_CAP) {
    signatures[i] = signature(bodies);
  }
  var colour = colours[i];
  // Clear what this item posted in the previous round (the other parity).
  if (r > 0u && (colour == UNCOLOURED || colour == r - 1u)) {
    let previous = (r - 1u) & 1u;
    for (var n = 0u; n < 4u; n = n + 1u) {
      if ((bodies.dynamic & (1u << n)) != 0u) {
        atomicStore(&bodyMark[2u * bodies.list[n] + previous], 0u);
      }
    }
  }
  if (colour != UNCOLOURED) {
    if (r == COLOUR_CAP) {
      colourKeys[i] = vec2<u32>(colour, i);
    }
    return;
  }
  if (bodies.dynamic == 0u) {
    colours[i] = COLOUR_IDLE;
    return;
  }
  if (r == COLOUR_CAP) {
    colours[i] = COLOUR_CAP;
    colourKeys[i] = vec2<u32>(COLOUR_CAP, i);
    return;
  }
  let parity = r & 1u;
  let p = priority(i);
  var wins = true;
  for (var n = 0u; n < 4u; n = n + 1u) {
    if ((bodies.dynamic & (1u << n)) != 0u && atomicLoad(&bodyMark[2u * bodies.list[n] + parity]) != p) {
      wins = false;
    }
  }
  if (wins) {
    colours[i] = r;
  }
}

@compute @workgroup_size(256)
fn mark(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
        @builtin(local_invocation_index) lid: u32) {
  let i = item_index(wid, nwg, lid);
  if (i != NO_CONTACT) {
    mark_item(i, round.colour);
  }
}

@compute @workgroup_size(256)
fn pick(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
        @builtin(local_invocation_index) lid: u32) {
  let i = item_index(wid, nwg, lid);
  if (i != NO_CONTACT) {
    pick_item(i, round.colour);
  }
}

// Every round of a small world in one dispatch of one workgroup: a round's marks, a storage
// barrier, its picks, a barrier; the items of `mark` and `pick` (none when the last colouring
// stands), so the same colours.
@compute @workgroup_size(256)
fn rounds(@builtin(local_invocation_index) lid: u32) {
  let count = atomicLoad(&solverState[SV_COLOUR_SORT_COUNT]);
  for (var r = 0u; r <= COLOUR_CAP; r = r + 1u) {
    if (r < COLOUR_CAP) {
      for (var i = lid; i < count; i = i + WORKGROUP_SIZE) {
        mark_item(i, r);
      }
    }
    storageBarrier();
    for (var i = lid; i < count; i = i + WORKGROUP_SIZE) {
      pick_item(i, r);
    }
    storageBarrier();
  }
}

// Entries of colourKeys[0, count) with a colour below c (lower bound in the sorted keys).
fn colour_start(c: u32, count: u32) -> u32 {
  var lo = 0u;
  var hi = count;
  while (lo < hi) {
    let mid = (lo + hi) / 2u;
    if (colourKeys[mid].x < c) {
      lo = mid + 1u;
    } else {
      hi = mid;
    }
  }
  return lo;
}

@compute @workgroup_size(32)
fn offsets(@builtin(local_invocation_index) lid: u32) {
  if (lid > COLOUR_CAP + 1u) {
    return;
  }
  let count = atomicLoad(&solverState[SV_ITEMS]);
  let start = colour_start(lid, count);
  atomicStore(&solverState[SV_COLOUR_START + lid], start);
  if (lid > COLOUR_CAP) {
    return;
  }
  let end = colour_start(lid + 1u, count);
  var size = dispatch_size(end - start, WORKGROUP_SIZE);
  if (lid == COLOUR_CAP) {
    // The tail pass: whether it has work depends on where the host's per-colour passes stop.
    size = vec3<u32>(1u, 1u, 1u);
  } else if (end > start) {
    atomicMax(&solverState[SV_COLOURS_USED], lid + 1u);
  }
  write_args(SV_ARGS_COLOURS + 3u * lid, size);
  write_args(SV_ARGS_POSITION + 3u * lid, size);
}
