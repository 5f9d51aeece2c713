// overlap.wgsl: narrow phase, sensor contacts (BIN_SENSOR: either fixture is a sensor):
// b2TestOverlap(shapeA, indexA, shapeB, indexB, xfA, xfB) in float32, i.e. b2Distance (GJK with
// an empty simplex cache, radii applied) and distance < 10 * b2_epsilon.
//
// In:  the contacts of the bin (manifold.wgsl: binned list, contactRef, shapes, bodies); any
//      shape pair with a contact type (circles, polygons, edges, chain children as
//      b2DistanceProxy::Set builds them: a chain child is (v[i], v[i + 1])). The GJK itself is
//      distance.wgsl's, shared with continuous collision.
// Out: each contact's manifold record: no points (sensors get no manifold, as b2Contact::Update),
//      header MF_TOUCHING when the shapes overlap.
// Invariants: one invocation per contact of the bin (indirect dispatch sized by contacts.wgsl,
//      zero workgroups for an empty bin); at most 20 GJK iterations (b2Distance's k_maxIters).
// Float32: the threshold is the engine's constant, 10 * FLT_EPSILON (1.19e-6 m). The GJK distance
// of two shapes carries float32 rounding of a few ulps of their coordinates (about 1e-6 m for
// shapes a few metres from body A's cell origin), so the touching state is the engine's except for
// shapes within about that distance of touching; overlapping shapes (cores within the radii)
// give distance 0 exactly, as in the engine.

// b2Distance(...).distance with useRadii, from an empty cache (distance.wgsl's GJK).
fn gjk_distance(pA: ptr<function, Proxy>, xfA: Xf, pB: ptr<function, Proxy>, xfB: Xf) -> f32 {
  var cache = empty_cache();
  var distance = gjk_distance_cached(pA, xfA, pB, xfB, &cache);
  let rA = (*pA).radius;
  let rB = (*pB).radius;
  if (distance > rA + rB && distance > EPSILON) {
    distance = distance - (rA + rB);
  } else {
    distance = 0.0;
  }
  return distance;
}

@compute @workgroup_size(256)
fn sensors(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
           @builtin(local_invocation_index) lid: u32) {
  let c = binned_contact(BIN_SENSOR, wid, nwg, lid);
  if (c == NO_CONTACT) {
    return;
  }
  let refA = contactRef[2u * c];
  let refB = contactRef[2u * c + 1u];
  let origin = bodyCell[refA.z];
  var pA = load_proxy(refA.x, refA.y);
  var pB = load_proxy(refB.x, refB.y);
  let distance = gjk_distance(&pA, body_transform(refA.z, origin), &pB, body_transform(refB.z, origin));
  let touching = distance < 10.0 * EPSILON;
  manifolds[4u * c] = vec4<u32>(select(0u, MF_TOUCHING, touching), 0u, 0u, 0u);
  manifolds[4u * c + 1u] = vec4<u32>(0u);
  manifolds[4u * c + 2u] = vec4<u32>(0u);
}
