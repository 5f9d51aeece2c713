// collidePolygon.wgsl: narrow phase, polygon against polygon (BIN_POLYGONS): b2CollidePolygons in
// float32 (separating-axis search on both polygons, the reference face with the 0.98 / 0.001
// hysteresis, clipping of the incident edge).
//
// In:  the contacts of the bin (manifold.wgsl: binned list, contactRef, shapes, bodies).
// Out: each contact's manifold (manifold.wgsl's record): e_faceA or e_faceB, the reference face's
//      normal and centre in its polygon's frame, up to two clip points in the incident polygon's
//      frame with b2ContactFeature keys (swapped to A/B order for e_faceB).
// Invariants: one invocation per contact of the bin (indirect dispatch sized by contacts.wgsl,
//      zero workgroups for an empty bin); the local search of b2FindMaxSeparation is bounded by the
//      vertex count (it can only climb that far), so a NaN cannot hang an invocation.

struct Separation {
  edge: u32,
  separation: f32,
}

// b2EdgeSeparation.
fn edge_separation(poly1: ptr<function, Polygon>, xf1: Xf, edge1: u32, poly2: ptr<function, Polygon>, xf2: Xf) -> f32 {
  let n = (*poly1).n[edge1];
  let nwx = xf1.c * n.x - xf1.s * n.y;
  let nwy = xf1.s * n.x + xf1.c * n.y;
  let n1x = xf2.c * nwx + xf2.s * nwy;
  let n1y = -xf2.s * nwx + xf2.c * nwy;

  // Support vertex of poly2 for -normal.
  var index = 0u;
  var minDot = MAX_FLOAT;
  for (var i = 0u; i < (*poly2).count; i = i + 1u) {
    let v = (*poly2).v[i];
    let d = v.x * n1x + v.y * n1y;
    if (d < minDot) {
      minDot = d;
      index = i;
    }
  }

  let a = (*poly1).v[edge1];
  let v1x = xf1.c * a.x - xf1.s * a.y + xf1.p.x;
  let v1y = xf1.s * a.x + xf1.c * a.y + xf1.p.y;
  let b = (*poly2).v[index];
  let v2x = xf2.c * b.x - xf2.s * b.y + xf2.p.x;
  let v2y = xf2.s * b.x + xf2.c * b.y + xf2.p.y;
  return (v2x - v1x) * nwx + (v2y - v1y) * nwy;
}

// b2FindMaxSeparation.
fn find_max_separation(poly1: ptr<function, Polygon>, xf1: Xf, poly2: ptr<function, Polygon>, xf2: Xf) -> Separation {
  let count1 = (*poly1).count;
  let c2 = (*poly2).centroid;
  let c1 = (*poly1).centroid;
  let dx = xf2.c * c2.x - xf2.s * c2.y + xf2.p.x - (xf1.c * c1.x - xf1.s * c1.y + xf1.p.x);
  let dy = xf2.s * c2.x + xf2.c * c2.y + xf2.p.y - (xf1.s * c1.x + xf1.c * c1.y + xf1.p.y);
  let dLocal1X = xf1.c * dx + xf1.s * dy;
  let dLocal1Y = -xf1.s * dx + xf1.c * dy;

  // The edge normal of poly1 with the largest projection onto d.
  var edge = 0u;
  var maxDot = -MAX_FLOAT;
  for (var i = 0u; i < count1; i = i + 1u) {
    let n = (*poly1).n[i];
    let d = n.x * dLocal1X + n.y * dLocal1Y;
    if (d > maxDot) {
      maxDot = d;
      edge = i;
    }
  }

  let s = edge_separation(poly1, xf1, edge, poly2, xf2);
  let prevEdge = select(count1 - 1u, edge - 1u, edge > 0u);
  let sPrev = edge_separation(poly1, xf1, prevEdge, poly2, xf2);
  let nextEdge = select(0u, edge + 1u, edge + 1u < count1);
  let sNext = edge_separation(poly1, xf1, nextEdge, poly2, xf2);

  var bestEdge: u32;
  var bestSeparation: f32;
  var backwards: bool;
  if (sPrev > s && sPrev > sNext) {
    backwards = true;
    bestEdge = prevEdge;
    bestSeparation = sPrev;
  } else if (sNext > s) {
    backwards = false;
    bestEdge = nextEdge;
    bestSeparation = sNext;
  } else {
    return Separation(edge, s);
  }

  // Local search for the best edge normal.
  for (var step = 0u; step < count1; step = step + 1u) {
    var e: u32;
    if (backwards) {
      e = select(count1 - 1u, bestEdge - 1u, bestEdge > 0u);
    } else {
      e = select(0u, bestEdge + 1u, bestEdge + 1u < count1);
    }
    let se = edge_separation(poly1, xf1, e, poly2, xf2);
    if (se > bestSeparation) {
      bestEdge = e;
      bestSeparation = se;
    } else {
      break;
    }
  }
  return Separation(bestEdge, bestSeparation);
}

// b2FindIncidentEdge: the two clip vertices of poly2's edge most anti-parallel to edge1's normal.
fn find_incident_edge(poly1: ptr<function, Polygon>, xf1: Xf, edge1: u32, poly2: ptr<function, Polygon>, xf2: Xf) -> Clip {
  let n = (*poly1).n[edge1];
  let wx = xf1.c * n.x - xf1.s * n.y;
  let wy = xf1.s * n.x + xf1.c * n.y;
  let normal1X = xf2.c * wx + xf2.s * wy;
  let normal1Y = -xf2.s * wx + xf2.c * wy;

  let count2 = (*poly2).count;
  var index = 0u;
  var minDot = MAX_FLOAT;
  for (var i = 0u; i < count2; i = i + 1u) {
    let n2 = (*poly2).n[i];
    let d = normal1X * n2.x + normal1Y * n2.y;
    if (d < minDot) {
      minDot = d;
      index = i;
    }
  }

  let i1 = index;
  let i2 = select(0u, i1 + 1u, i1 + 1u < count2);
  let a = (*poly2).v[i1];
  let b = (*poly2).v[i2];
  return Clip(
    vec2<f32>(xf2.c * a.x - xf2.s * a.y + xf2.p.x, xf2.s * a.x + xf2.c * a.y + xf2.p.y),
    vec2<f32>(xf2.c * b.x - xf2.s * b.y + xf2.p.x, xf2.s * b.x + xf2.c * b.y + xf2.p.y),
    feature(edge1, i1, F_FACE, F_VERTEX),
    feature(edge1, i2, F_FACE, F_VERTEX),
    2u,
  );
}

// b2CollidePolygons from the choice of the reference face on: poly1 holds the reference edge.
fn clip_polygons(poly1: ptr<function, Polygon>, xf1: Xf, edge1: u32, poly2: ptr<function, Polygon>, xf2: Xf,
                 kind: u32, flip: bool, totalRadius: f32) -> Manifold {
  var m = empty_manifold();
  let incident = find_incident_edge(poly1, xf1, edge1, poly2, xf2);

  let count1 = (*poly1).count;
  let iv1 = edge1;
  let iv2 = select(0u, edge1 + 1u, edge1 + 1u < count1);
  let v11 = (*poly1).v[iv1];
  let v12 = (*poly1).v[iv2];

  let localTangent = normalize2(vec2<f32>(v12.x - v11.x, v12.y - v11.y));
  let localNormal = vec2<f32>(1.0 * localTangent.y, -1.0 * localTangent.x);
  let planePoint = vec2<f32>(0.5 * (v11.x + v12.x), 0.5 * (v11.y + v12.y));

  let qc = xf1.c;
  let qs = xf1.s;
  let tangent = vec2<f32>(qc * localTangent.x - qs * localTangent.y, qs * localTangent.x + qc * localTangent.y);
  let normal = vec2<f32>(1.0 * tangent.y, -1.0 * tangent.x);

  let v11w = vec2<f32>(qc * v11.x - qs * v11.y + xf1.p.x, qs * v11.x + qc * v11.y + xf1.p.y);
  let v12w = vec2<f32>(qc * v12.x - qs * v12.y + xf1.p.x, qs * v12.x + qc * v12.y + xf1.p.y);

  let frontOffset = normal.x * v11w.x + normal.y * v11w.y;
  let sideOffset1 = -(tangent.x * v11w.x + tangent.y * v11w.y) + totalRadius;
  let sideOffset2 = tangent.x * v12w.x + tangent.y * v12w.y + totalRadius;

  let clip1 = clip_segment(incident.v0, incident.id0, incident.v1, incident.id1, vec2<f32>(-tangent.x, -tangent.y), sideOffset1, iv1);
  if (clip1.count < 2u) {
    return m;
  }
  let clip2 = clip_segment(clip1.v0, clip1.id0, clip1.v1, clip1.id1, tangent, sideOffset2, iv2);
  if (clip2.count < 2u) {
    return m;
  }

  m.kind = kind;
  m.normal = localNormal;
  m.point = planePoint;
  for (var i = 0u; i < 2u; i = i + 1u) {
    let cv = select(clip2.v0, clip2.v1, i == 1u);
    var id = select(clip2.id0, clip2.id1, i == 1u);
    let separation = normal.x * cv.x + normal.y * cv.y - frontOffset;
    if (separation <= totalRadius) {
      let px = cv.x - xf2.p.x;
      let py = cv.y - xf2.p.y;
      let lp = vec2<f32>(xf2.c * px + xf2.s * py, -xf2.s * px + xf2.c * py);
      if (flip) {
        id = swap_feature(id);
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

fn collide_polygons(polyA: ptr<function, Polygon>, xfA: Xf, polyB: ptr<function, Polygon>, xfB: Xf) -> Manifold {
  let totalRadius = (*polyA).radius + (*polyB).radius;
  let a = find_max_separation(polyA, xfA, polyB, xfB);
  if (a.separation > totalRadius) {
    return empty_manifold();
  }
  let b = find_max_separation(polyB, xfB, polyA, xfA);
  if (b.separation > totalRadius) {
    return empty_manifold();
  }
  let k_relativeTol = 0.98;
  let k_absoluteTol = 0.001;
  if (b.separation > k_relativeTol * a.separation + k_absoluteTol) {
    return clip_polygons(polyB, xfB, b.edge, polyA, xfA, E_FACE_B, true, totalRadius);
  }
  return clip_polygons(polyA, xfA, a.edge, polyB, xfB, E_FACE_A, false, totalRadius);
}

@compute @workgroup_size(256)
fn polygons(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
            @builtin(local_invocation_index) lid: u32) {
  let c = binned_contact(BIN_POLYGONS, wid, nwg, lid);
  if (c == NO_CONTACT) {
    return;
  }
  let refA = contactRef[2u * c];
  let refB = contactRef[2u * c + 1u];
  let origin = bodyCell[refA.z];
  var polyA = load_polygon(refA.x);
  var polyB = load_polygon(refB.x);
  let m = collide_polygons(&polyA, body_transform(refA.z, origin), &polyB, body_transform(refB.z, origin));
  store_manifold(c, m);
}
