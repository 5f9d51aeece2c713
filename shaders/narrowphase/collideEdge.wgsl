// collideEdge.wgsl: narrow phase, edges and chain children against circles and polygons
// (BIN_EDGE_CIRCLE, BIN_EDGE_POLYGON, BIN_CHAIN_CIRCLE, BIN_CHAIN_POLYGON): b2CollideEdgeAndCircle
// and b2EPCollider::Collide (b2CollideEdgeAndPolygon) of Box2D 2.2.1 in float32, with the ghost
// vertices of an edge (m_hasVertex0 / m_hasVertex3) or of a chain child (its neighbours, or the
// chain's m_prevVertex / m_nextVertex at its ends).
//
// In:  the contacts of the four bins (manifold.wgsl: binned list, contactRef, shapes, bodies);
//      contactRef's child index of A picks the chain's edge.
// Out: each contact's manifold (manifold.wgsl's record). Edge-circle: e_circles at a vertex
//      (feature: vertex 0 or 1) when the circle is past an end and not in the neighbour edge's
//      region, else e_faceA with the edge normal facing the circle. Edge-polygon: b2EPCollider's
//      front/back classification, normal limits from the adjacent edges, edge and polygon axes
//      (polygon axes outside the limits by b2_angularSlop are skipped, one-sided collision),
//      hysteresis 0.98 / 0.001, and clipping with radius 2 * b2_polygonRadius.
// Invariants: one invocation per contact of a bin (indirect dispatch sized by contacts.wgsl, zero
//      workgroups for an empty bin); chain and edge kernels share every line but the shape load.

fn collide_edge_circle(edge: Edge, xfA: Xf, circle: Circle, xfB: Xf) -> Manifold {
  var m = empty_manifold();
  let Q = mul_txv(xfA, mul_xv(xfB, circle.p));
  let A = edge.v1;
  let B = edge.v2;
  let ex = B.x - A.x;
  let ey = B.y - A.y;

  // Barycentric coordinates.
  let u = ex * (B.x - Q.x) + ey * (B.y - Q.y);
  let v = ex * (Q.x - A.x) + ey * (Q.y - A.y);
  let radius = edge.radius + circle.radius;

  // Region A.
  if (v <= 0.0) {
    let dx = Q.x - A.x;
    let dy = Q.y - A.y;
    if (dx * dx + dy * dy > radius * radius) {
      return m;
    }
    if (edge.has0) {
      let A1 = edge.v0;
      let e1x = A.x - A1.x;
      let e1y = A.y - A1.y;
      let u1 = e1x * (A.x - Q.x) + e1y * (A.y - Q.y);
      if (u1 > 0.0) {
        return m;
      }
    }
    m.kind = E_CIRCLES;
    m.count = 1u;
    m.point = A;
    m.p0 = circle.p;
    m.id0 = feature(0u, 0u, F_VERTEX, F_VERTEX);
    return m;
  }

  // Region B.
  if (u <= 0.0) {
    let dx = Q.x - B.x;
    let dy = Q.y - B.y;
    if (dx * dx + dy * dy > radius * radius) {
      return m;
    }
    if (edge.has3) {
      let B2 = edge.v3;
      let e2x = B2.x - B.x;
      let e2y = B2.y - B.y;
      let v2 = e2x * (Q.x - B.x) + e2y * (Q.y - B.y);
      if (v2 > 0.0) {
        return m;
      }
    }
    m.kind = E_CIRCLES;
    m.count = 1u;
    m.point = B;
    m.p0 = circle.p;
    m.id0 = feature(1u, 0u, F_VERTEX, F_VERTEX);
    return m;
  }

  // Region AB.
  let den = ex * ex + ey * ey;
  let Px = (1.0 / den) * (u * A.x + v * B.x);
  let Py = (1.0 / den) * (u * A.y + v * B.y);
  let dx = Q.x - Px;
  let dy = Q.y - Py;
  if (dx * dx + dy * dy > radius * radius) {
    return m;
  }
  var n = vec2<f32>(-ey, ex);
  if (n.x * (Q.x - A.x) + n.y * (Q.y - A.y) < 0.0) {
    n = vec2<f32>(-n.x, -n.y);
  }
  m.kind = E_FACE_A;
  m.count = 1u;
  m.normal = normalize2(n);
  m.point = A;
  m.p0 = circle.p;
  m.id0 = feature(0u, 0u, F_FACE, F_VERTEX);
  return m;
}

// b2EPAxis::Type
const AXIS_UNKNOWN: u32 = 0u;
const AXIS_EDGE_A: u32 = 1u;
const AXIS_EDGE_B: u32 = 2u;

struct Axis {
  kind: u32,
  index: u32,
  separation: f32,
}

fn collide_edge_polygon(edge: Edge, xfA: Xf, polygonB: ptr<function, Polygon>, xfB: Xf) -> Manifold {
  var m = empty_manifold();
  let xf = mul_txx(xfA, xfB);
  let centroidB = mul_xv(xf, (*polygonB).centroid);
  let v0 = edge.v0;
  let v1 = edge.v1;
  let v2 = edge.v2;
  let v3 = edge.v3;
  let hasVertex0 = edge.has0;
  let hasVertex3 = edge.has3;

  let edge1 = normalize2(vec2<f32>(v2.x - v1.x, v2.y - v1.y));
  let normal1 = vec2<f32>(edge1.y, -edge1.x);
  let offset1 = normal1.x * (centroidB.x - v1.x) + normal1.y * (centroidB.y - v1.y);
  var offset0 = 0.0;
  var offset2 = 0.0;
  var convex1 = false;
  var convex2 = false;
  var normal0 = vec2<f32>(0.0);
  var normal2 = vec2<f32>(0.0);

  if (hasVertex0) {
    let edge0 = normalize2(vec2<f32>(v1.x - v0.x, v1.y - v0.y));
    normal0 = vec2<f32>(edge0.y, -edge0.x);
    convex1 = edge0.x * edge1.y - edge0.y * edge1.x >= 0.0;
    offset0 = normal0.x * (centroidB.x - v0.x) + normal0.y * (centroidB.y - v0.y);
  }
  if (hasVertex3) {
    let edge2 = normalize2(vec2<f32>(v3.x - v2.x, v3.y - v2.y));
    normal2 = vec2<f32>(edge2.y, -edge2.x);
    convex2 = edge1.x * edge2.y - edge1.y * edge2.x > 0.0;
    offset2 = normal2.x * (centroidB.x - v2.x) + normal2.y * (centroidB.y - v2.y);
  }

  // Front or back collision, and the normal limits.
  var front: bool;
  var normal: vec2<f32>;
  var lowerLimit: vec2<f32>;
  var upperLimit: vec2<f32>;
  let neg1 = vec2<f32>(-normal1.x, -normal1.y);
  let neg0 = vec2<f32>(-normal0.x, -normal0.y);
  let neg2 = vec2<f32>(-normal2.x, -normal2.y);
  if (hasVertex0 && hasVertex3) {
    if (convex1 && convex2) {
      front = offset0 >= 0.0 || offset1 >= 0.0 || offset2 >= 0.0;
      if (front) {
        normal = normal1; lowerLimit = normal0; upperLimit = normal2;
      } else {
        normal = neg1; lowerLimit = neg1; upperLimit = neg1;
      }
    } else if (convex1) {
      front = offset0 >= 0.0 || (offset1 >= 0.0 && offset2 >= 0.0);
      if (front) {
        normal = normal1; lowerLimit = normal0; upperLimit = normal1;
      } else {
        normal = neg1; lowerLimit = neg2; upperLimit = neg1;
      }
    } else if (convex2) {
      front = offset2 >= 0.0 || (offset0 >= 0.0 && offset1 >= 0.0);
      if (front) {
        normal = normal1; lowerLimit = normal1; upperLimit = normal2;
      } else {
        normal = neg1; lowerLimit = neg1; upperLimit = neg0;
      }
    } else {
      front = offset0 >= 0.0 && offset1 >= 0.0 && offset2 >= 0.0;
      if (front) {
        normal = normal1; lowerLimit = normal1; upperLimit = normal1;
      } else {
        normal = neg1; lowerLimit = neg2; upperLimit = neg0;
      }
    }
  } else if (hasVertex0) {
    if (convex1) {
      front = offset0 >= 0.0 || offset1 >= 0.0;
      if (front) {
        normal = normal1; lowerLimit = normal0; upperLimit = neg1;
      } else {
        normal = neg1; lowerLimit = normal1; upperLimit = neg1;
      }
    } else {
      front = offset0 >= 0.0 && offset1 >= 0.0;
      if (front) {
        normal = normal1; lowerLimit = normal1; upperLimit = neg1;
      } else {
        normal = neg1; lowerLimit = normal1; upperLimit = neg0;
      }
    }
  } else if (hasVertex3) {
    if (convex2) {
      front = offset1 >= 0.0 || offset2 >= 0.0;
      if (front) {
        normal = normal1; lowerLimit = neg1; upperLimit = normal2;
      } else {
        normal = neg1; lowerLimit = neg1; upperLimit = normal1;
      }
    } else {
      front = offset1 >= 0.0 && offset2 >= 0.0;
      if (front) {
        normal = normal1; lowerLimit = neg1; upperLimit = normal1;
      } else {
        normal = neg1; lowerLimit = neg2; upperLimit = normal1;
      }
    }
  } else {
    front = offset1 >= 0.0;
    if (front) {
      normal = normal1; lowerLimit = neg1; upperLimit = neg1;
    } else {
      normal = neg1; lowerLimit = normal1; upperLimit = normal1;
    }
  }

  // Polygon B in frame A.
  let count = (*polygonB).count;
  var pv: array<vec2<f32>, 8>;
  var pn: array<vec2<f32>, 8>;
  for (var i = 0u; i < 8u; i = i + 1u) {
    pv[i] = vec2<f32>(0.0);
    pn[i] = vec2<f32>(0.0);
  }
  for (var i = 0u; i < count; i = i + 1u) {
    pv[i] = mul_xv(xf, (*polygonB).v[i]);
    pn[i] = mul_rv(xf, (*polygonB).n[i]);
  }
  let radius = 2.0 * POLYGON_RADIUS;

  // ComputeEdgeSeparation.
  var edgeAxis = Axis(AXIS_EDGE_A, select(1u, 0u, front), MAX_FLOAT);
  for (var i = 0u; i < count; i = i + 1u) {
    let s = normal.x * (pv[i].x - v1.x) + normal.y * (pv[i].y - v1.y);
    if (s < edgeAxis.separation) {
      edgeAxis.separation = s;
    }
  }
  if (edgeAxis.separation > radius) {
    return m;
  }

  // ComputePolygonSeparation.
  var polygonAxis = Axis(AXIS_UNKNOWN, NO_CONTACT, -MAX_FLOAT);
  let perp = vec2<f32>(-normal.y, normal.x);
  for (var i = 0u; i < count; i = i + 1u) {
    let n = vec2<f32>(-pn[i].x, -pn[i].y);
    let s1 = n.x * (pv[i].x - v1.x) + n.y * (pv[i].y - v1.y);
    let s2 = n.x * (pv[i].x - v2.x) + n.y * (pv[i].y - v2.y);
    let s = select(s2, s1, s1 < s2);
    if (s > radius) {
      // No collision.
      polygonAxis = Axis(AXIS_EDGE_B, i, s);
      break;
    }
    // Adjacency.
    if (n.x * perp.x + n.y * perp.y >= 0.0) {
      if ((n.x - upperLimit.x) * normal.x + (n.y - upperLimit.y) * normal.y < -ANGULAR_SLOP) {
        continue;
      }
    } else {
      if ((n.x - lowerLimit.x) * normal.x + (n.y - lowerLimit.y) * normal.y < -ANGULAR_SLOP) {
        continue;
      }
    }
    if (s > polygonAxis.separation) {
      polygonAxis = Axis(AXIS_EDGE_B, i, s);
    }
  }
  if (polygonAxis.kind != AXIS_UNKNOWN && polygonAxis.separation > radius) {
    return m;
  }

  // Hysteresis for jitter reduction.
  let k_relativeTol = 0.98;
  let k_absoluteTol = 0.001;
  var primary = edgeAxis;
  if (polygonAxis.kind != AXIS_UNKNOWN && polygonAxis.separation > k_relativeTol * edgeAxis.separation + k_absoluteTol) {
    primary = polygonAxis;
  }

  var ie: Clip;
  var rfI1: u32;
  var rfI2: u32;
  var rfV1: vec2<f32>;
  var rfV2: vec2<f32>;
  var rfNormal: vec2<f32>;
  if (primary.kind == AXIS_EDGE_A) {
    m.kind = E_FACE_A;
    // The polygon normal most anti-parallel to the edge normal.
    var bestIndex = 0u;
    var bestValue = dot2(normal, pn[0]);
    for (var i = 1u; i < count; i = i + 1u) {
      let value = dot2(normal, pn[i]);
      if (value < bestValue) {
        bestValue = value;
        bestIndex = i;
      }
    }
    let i1 = bestIndex;
    let i2 = select(0u, i1 + 1u, i1 + 1u < count);
    ie = Clip(pv[i1], pv[i2], feature(0u, i1, F_FACE, F_VERTEX), feature(0u, i2, F_FACE, F_VERTEX), 2u);
    if (front) {
      rfI1 = 0u; rfI2 = 1u; rfV1 = v1; rfV2 = v2; rfNormal = normal1;
    } else {
      rfI1 = 1u; rfI2 = 0u; rfV1 = v2; rfV2 = v1; rfNormal = neg1;
    }
  } else {
    m.kind = E_FACE_B;
    ie = Clip(v1, v2, feature(0u, primary.index, F_VERTEX, F_FACE), feature(0u, primary.index, F_VERTEX, F_FACE), 2u);
    rfI1 = primary.index;
    rfI2 = select(0u, rfI1 + 1u, rfI1 + 1u < count);
    rfV1 = pv[rfI1];
    rfV2 = pv[rfI2];
    rfNormal = pn[rfI1];
  }

  let sideNormal1 = vec2<f32>(rfNormal.y, -rfNormal.x);
  let sideNormal2 = vec2<f32>(-sideNormal1.x, -sideNormal1.y);
  let sideOffset1 = dot2(sideNormal1, rfV1);
  let sideOffset2 = dot2(sideNormal2, rfV2);

  let clip1 = clip_segment(ie.v0, ie.id0, ie.v1, ie.id1, sideNormal1, sideOffset1, rfI1);
  if (clip1.count < 2u) {
    return empty_manifold();
  }
  let clip2 = clip_segment(clip1.v0, clip1.id0, clip1.v1, clip1.id1, sideNormal2, sideOffset2, rfI2);
  if (clip2.count < 2u) {
    return empty_manifold();
  }

  if (primary.kind == AXIS_EDGE_A) {
    m.normal = rfNormal;
    m.point = rfV1;
  } else {
    m.normal = (*polygonB).n[rfI1];
    m.point = (*polygonB).v[rfI1];
  }

  for (var i = 0u; i < 2u; i = i + 1u) {
    let cv = select(clip2.v0, clip2.v1, i == 1u);
    let cid = select(clip2.id0, clip2.id1, i == 1u);
    let separation = rfNormal.x * (cv.x - rfV1.x) + rfNormal.y * (cv.y - rfV1.y);
    if (separation <= radius) {
      var lp: vec2<f32>;
      var id: u32;
      if (primary.kind == AXIS_EDGE_A) {
        lp = mul_txv(xf, cv);
        id = cid;
      } else {
        lp = cv;
        id = swap_feature(cid);
      }
      if (m.count == 0u) {
        m.p0 = lp;
        m.id0 = id;
      } else {
        m.p1 = lp;
        m.id1 = id;
      }
      m.count = m.count + 1u;
    }
  }
  if (m.count == 0u) {
    return empty_manifold();
  }
  return m;
}

fn edge_circle_contact(c: u32) {
  let refA = contactRef[2u * c];
  let refB = contactRef[2u * c + 1u];
  let origin = bodyCell[refA.z];
  let m = collide_edge_circle(load_edge(refA.x, refA.y), body_transform(refA.z, origin), load_circle(refB.x), body_transform(refB.z, origin));
  store_manifold(c, m);
}

fn edge_polygon_contact(c: u32) {
  let refA = contactRef[2u * c];
  let refB = contactRef[2u * c + 1u];
  let origin = bodyCell[refA.z];
  var poly = load_polygon(refB.x);
  let m = collide_edge_polygon(load_edge(refA.x, refA.y), body_transform(refA.z, origin), &poly, body_transform(refB.z, origin));
  store_manifold(c, m);
}

@compute @workgroup_size(256)
fn edge_circle(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
               @builtin(local_invocation_index) lid: u32) {
  let c = binned_contact(BIN_EDGE_CIRCLE, wid, nwg, lid);
  if (c != NO_CONTACT) {
    edge_circle_contact(c);
  }
}

@compute @workgroup_size(256)
fn chain_circle(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
                @builtin(local_invocation_index) lid: u32) {
  let c = binned_contact(BIN_CHAIN_CIRCLE, wid, nwg, lid);
  if (c != NO_CONTACT) {
    edge_circle_contact(c);
  }
}

@compute @workgroup_size(256)
fn edge_polygon(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
                @builtin(local_invocation_index) lid: u32) {
  let c = binned_contact(BIN_EDGE_POLYGON, wid, nwg, lid);
  if (c != NO_CONTACT) {
    edge_polygon_contact(c);
  }
}

@compute @workgroup_size(256)
fn chain_polygon(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
                 @builtin(local_invocation_index) lid: u32) {
  let c = binned_contact(BIN_CHAIN_POLYGON, wid, nwg, lid);
  if (c != NO_CONTACT) {
    edge_polygon_contact(c);
  }
}
