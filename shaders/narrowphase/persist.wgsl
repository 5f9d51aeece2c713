// persist.wgsl: GpuStage.Persist, contact persistence: the touching state, the warm-start
// impulses carried over from the previous step, and the begin/end flags.
//
// In:  this step's manifolds (headers and ids from the collide kernels), contactRef (bin, kept,
//      sensor and swapped flags; the previous step's index of each contact, contacts.wgsl), the
//      previous step's manifolds and keys, this step's keys.
// Out: `main` (per contact i): a kept contact (CONTACT_KEPT: no kernel collided it) first takes
//      the previous step's manifold, its type, points, ids, touching flag and impulses, unchanged
//      (b2ContactManager::Collide leaves a contact of sleeping bodies as it was); then for every
//      contact the header completed with MF_SENSOR, MF_SWAPPED, MF_WARM, MF_BEGAN, MF_ENDED (never
//      for a kept one: its touching state is the previous one) and word 3 = the previous step's
//      index; manifolds[4i + 3] = (normalImpulse, tangentImpulse) of points 0 and 1, copied from
//      the previous manifold's point with the same b2ContactID key and 0 otherwise
//      (b2Contact::Update; sensors carry nothing), or as they were for a kept contact;
//      solverFlags[i] = touching and not a sensor; eventFlags[i] = began or ended.
//      `vanished` (per previous contact j): eventFlags[NP_CONTACTS + j] = 1 when the contact is gone
//      this step (no contact with its proxies and generations) and was touching: b2ContactManager
//      destroys it and calls EndContact.
// Invariants: a contact of BIN_NONE (no kernel ran) is written as a contact without points. The
// flags feed the two scans of the compaction (src-gpu/narrowphase/compact.ts).

@group(0) @binding(0) var<storage, read> npState: array<u32>;
@group(0) @binding(1) var<storage, read> contactRef: array<vec4<u32>>;
@group(0) @binding(2) var<storage, read_write> manifolds: array<vec4<u32>>;
@group(0) @binding(3) var<storage, read> prevManifolds: array<vec4<u32>>;
@group(0) @binding(4) var<storage, read_write> solverFlags: array<u32>;
@group(0) @binding(5) var<storage, read_write> eventFlags: array<u32>;
@group(0) @binding(6) var<storage, read> curKey: array<vec4<u32>>;
@group(0) @binding(7) var<storage, read> prevKey: array<vec4<u32>>;

@compute @workgroup_size(256)
fn main(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
        @builtin(local_invocation_index) lid: u32) {
  let i = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  if (i >= npState[NP_CONTACTS]) {
    return;
  }
  let refA = contactRef[2u * i];
  let previous = contactRef[2u * i + 1u].w;
  let bin = (refA.w >> 4u) & 0xfu;
  let sensor = (refA.w & 2u) != 0u;
  let kept = (refA.w & CONTACT_KEPT) != 0u;
  var h = manifolds[4u * i];
  if (kept) {
    h = prevManifolds[4u * previous];
    manifolds[4u * i + 1u] = prevManifolds[4u * previous + 1u];
    manifolds[4u * i + 2u] = prevManifolds[4u * previous + 2u];
  } else if (bin == BIN_NONE) {
    h = vec4<u32>(0u);
    manifolds[4u * i + 1u] = vec4<u32>(0u);
    manifolds[4u * i + 2u] = vec4<u32>(0u);
  }
  var flags = h.x & 0x1fu;
  let touching = (flags & MF_TOUCHING) != 0u;
  if (sensor) {
    flags = flags | MF_SENSOR;
  }
  if ((refA.w & 1u) != 0u) {
    flags = flags | MF_SWAPPED;
  }
  var impulses = vec4<f32>(0.0);
  var wasTouching = false;
  if (previous != NO_CONTACT) {
    flags = flags | MF_WARM;
    let ph = prevManifolds[4u * previous];
    wasTouching = (ph.x & MF_TOUCHING) != 0u;
    if (kept) {
      impulses = bitcast<vec4<f32>>(prevManifolds[4u * previous + 3u]);
    } else if (!sensor) {
      let count = (flags >> 2u) & 3u;
      let prevCount = (ph.x >> 2u) & 3u;
      let prevImpulses = bitcast<vec4<f32>>(prevManifolds[4u * previous + 3u]);
      for (var k = 0u; k < count; k = k + 1u) {
        let id = select(h.y, h.z, k == 1u);
        for (var j = 0u; j < prevCount; j = j + 1u) {
          if (select(ph.y, ph.z, j == 1u) == id) {
            impulses[2u * k] = prevImpulses[2u * j];
            impulses[2u * k + 1u] = prevImpulses[2u * j + 1u];
            break;
          }
        }
      }
    }
  }
  let began = touching && !wasTouching;
  let ended = !touching && wasTouching;
  if (began) {
    flags = flags | MF_BEGAN;
  }
  if (ended) {
    flags = flags | MF_ENDED;
  }
  manifolds[4u * i] = vec4<u32>(flags, h.y, h.z, previous);
  manifolds[4u * i + 3u] = bitcast<vec4<u32>>(impulses);
  solverFlags[i] = select(0u, 1u, touching && !sensor);
  eventFlags[i] = select(0u, 1u, began || ended);
}

// Is the previous step's contact `key` in this step's list (same proxies and generations)?
fn still_there(key: vec4<u32>) -> bool {
  var lo = 0u;
  let n = npState[NP_CONTACTS];
  var hi = n;
  while (lo < hi) {
    let mid = lo + (hi - lo) / 2u;
    let k = curKey[mid];
    if (k.x < key.x || (k.x == key.x && k.y < key.y)) {
      lo = mid + 1u;
    } else {
      hi = mid;
    }
  }
  return lo < n && all(curKey[lo] == key);
}

@compute @workgroup_size(256)
fn vanished(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
            @builtin(local_invocation_index) lid: u32) {
  let j = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  if (j >= npState[NP_PREV]) {
    return;
  }
  let wasTouching = (prevManifolds[4u * j].x & MF_TOUCHING) != 0u;
  eventFlags[npState[NP_CONTACTS] + j] = select(0u, 1u, wasTouching && !still_there(prevKey[j]));
}
