// collideCircle.wgsl: narrow phase, circle against circle (BIN_CIRCLES) and polygon against
// circle (BIN_POLYGON_CIRCLE): b2CollideCircles and b2CollidePolygonAndCircle in float32.
//
// In:  the contacts of the two bins (manifold.wgsl: binned list, contactRef, shapes, bodies).
// Out: each contact's manifold (manifold.wgsl's record): e_circles with localPoint = circle A's
//      centre and one point at circle B's centre, or e_faceA with the polygon's face normal or
//      the normal towards the circle; the point's id key is 0.
// Invariants: one invocation per contact of the bin (indirect dispatch sized by contacts.wgsl,
//      zero workgroups for an empty bin); an invocation writes its own contact's record only.

fn collide_circles(a: Circle, xfA: Xf, b: Circle, xfB: Xf) -> Manifold {
  var m = empty_manifold();
  let pA = mul_xv(xfA, a.p);
  let pB = mul_xv(xfB, b.p);
  let dx = pB.x - pA.x;
  let dy = pB.y - pA.y;
  let distSqr = dx * dx + dy * dy;
  let radius = a.radius + b.radius;
  if (distSqr > radius * radius) {
    return m;
  }
  m.kind = E_CIRCLES;
  m.point = a.p;
  m.count = 1u;
  m.p0 = b.p;
  return m;
}

fn collide_polygon_circle(poly: ptr<function, Polygon>, xfA: Xf, circle: Circle, xfB: Xf) -> Manifold {
  var m = empty_manifold();
  let c = mul_xv(xfB, circle.p);
  let cLocal = mul_txv(xfA, c);

  // Find the min separating edge.
  var normalIndex = 0u;
  var separation = -MAX_FLOAT;
  let radius = (*poly).radius + circle.radius;
  let count = (*poly).count;
  for (var i = 0u; i < count; i = i + 1u) {
    let n = (*poly).n[i];
    let v = (*poly).v[i];
    let s = n.x * (cLocal.x - v.x) + n.y * (cLocal.y - v.y);
    if (s > radius) {
      return m;
    }
    if (s > separation) {
      separation = s;
      normalIndex = i;
    }
  }

  // Vertices that subtend the incident face.
  let vertIndex1 = normalIndex;
  let vertIndex2 = select(0u, vertIndex1 + 1u, vertIndex1 + 1u < count);
  let v1 = (*poly).v[vertIndex1];
  let v2 = (*poly).v[vertIndex2];

  m.kind = E_FACE_A;
  m.count = 1u;
  m.p0 = circle.p;

  // The centre is inside the polygon.
  if (separation < EPSILON) {
    m.normal = (*poly).n[normalIndex];
    m.point = vec2<f32>(0.5 * (v1.x + v2.x), 0.5 * (v1.y + v2.y));
    return m;
  }

  // Barycentric coordinates.
  let u1 = (cLocal.x - v1.x) * (v2.x - v1.x) + (cLocal.y - v1.y) * (v2.y - v1.y);
  let u2 = (cLocal.x - v2.x) * (v1.x - v2.x) + (cLocal.y - v2.y) * (v1.y - v2.y);
  if (u1 <= 0.0) {
    let dx = cLocal.x - v1.x;
    let dy = cLocal.y - v1.y;
    if (dx * dx + dy * dy > radius * radius) {
      return empty_manifold();
    }
    m.normal = normalize2(vec2<f32>(cLocal.x - v1.x, cLocal.y - v1.y));
    m.point = v1;
  } else if (u2 <= 0.0) {
    let dx = cLocal.x - v2.x;
    let dy = cLocal.y - v2.y;
    if (dx * dx + dy * dy > radius * radius) {
      return empty_manifold();
    }
    m.normal = normalize2(vec2<f32>(cLocal.x - v2.x, cLocal.y - v2.y));
    m.point = v2;
  } else {
    let faceCenter = vec2<f32>(0.5 * (v1.x + v2.x), 0.5 * (v1.y + v2.y));
    let n1 = (*poly).n[vertIndex1];
    let faceSeparation = (cLocal.x - faceCenter.x) * n1.x + (cLocal.y - faceCenter.y) * n1.y;
    if (faceSeparation > radius) {
      return empty_manifold();
    }
    m.normal = n1;
    m.point = faceCenter;
  }
  return m;
}

@compute @workgroup_size(256)
fn circles(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
           @builtin(local_invocation_index) lid: u32) {
  let c = binned_contact(BIN_CIRCLES, wid, nwg, lid);
  if (c == NO_CONTACT) {
    return;
  }
  let refA = contactRef[2u * c];
  let refB = contactRef[2u * c + 1u];
  let origin = bodyCell[refA.z];
  let m = collide_circles(load_circle(refA.x), body_transform(refA.z, origin), load_circle(refB.x), body_transform(refB.z, origin));
  store_manifold(c, m);
}

@compute @workgroup_size(256)
fn polygon_circle(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
                  @builtin(local_invocation_index) lid: u32) {
  let c = binned_contact(BIN_POLYGON_CIRCLE, wid, nwg, lid);
  if (c == NO_CONTACT) {
    return;
  }
  let refA = contactRef[2u * c];
  let refB = contactRef[2u * c + 1u];
  let origin = bodyCell[refA.z];
  var poly = load_polygon(refA.x);
  let m = collide_polygon_circle(&poly, body_transform(refA.z, origin), load_circle(refB.x), body_transform(refB.z, origin));
  store_manifold(c, m);
}
