// distance.wgsl: b2Distance (GJK) in float32, shared by the narrow phase's sensor test
// (overlap.wgsl) and continuous collision (timeOfImpact.wgsl); the host prepends it to both after
// common.wgsl and manifold.wgsl (Xf, mul_xv, mul_trv, dot2, EPSILON, fixtureShape, shapePool).
//
// In:  two b2DistanceProxy (load_proxy: a fixture's child as b2DistanceProxy::Set builds it: a
//      chain child is (v[i], v[i + 1])), their transforms, a b2SimplexCache.
// Out: the distance between the proxies' cores (no radii) and the final simplex in the cache.
// Invariants: the engine's operation order (b2Distance.ts), at most 20 GJK iterations (k_maxIters).

struct Proxy {
  v: array<vec2<f32>, 8>,
  count: u32,
  radius: f32,
}

struct SimplexVertex {
  wA: vec2<f32>,
  wB: vec2<f32>,
  w: vec2<f32>,
  a: f32,
  indexA: u32,
  indexB: u32,
}

// b2DistanceProxy::Set.
fn load_proxy(fixture: u32, child: u32) -> Proxy {
  let shape = fixtureShape[fixture];
  var p: Proxy;
  for (var i = 0u; i < 8u; i = i + 1u) {
    p.v[i] = vec2<f32>(0.0);
  }
  p.radius = bitcast<f32>(shape.w);
  let base = shape.y;
  switch (shape.x & 0xfu) {
    case SHAPE_CIRCLE: {
      p.v[0] = shapePool[base];
      p.count = 1u;
    }
    case SHAPE_POLYGON: {
      let count = (shape.x >> 8u) & 0xffu;
      for (var i = 0u; i < count; i = i + 1u) {
        p.v[i] = shapePool[base + i];
      }
      p.count = count;
    }
    case SHAPE_EDGE: {
      p.v[0] = shapePool[base];
      p.v[1] = shapePool[base + 1u];
      p.count = 2u;
    }
    default: {
      let count = (shape.x >> 8u) & 0xffffffu;
      p.v[0] = shapePool[base + child];
      p.v[1] = shapePool[base + select(0u, child + 1u, child + 1u < count)];
      p.count = 2u;
    }
  }
  return p;
}

fn support(p: ptr<function, Proxy>, d: vec2<f32>) -> u32 {
  var bestIndex = 0u;
  var bestValue = dot2((*p).v[0], d);
  for (var i = 1u; i < (*p).count; i = i + 1u) {
    let value = dot2((*p).v[i], d);
    if (value > bestValue) {
      bestIndex = i;
      bestValue = value;
    }
  }
  return bestIndex;
}

fn cross2(a: vec2<f32>, b: vec2<f32>) -> f32 {
  return a.x * b.y - a.y * b.x;
}

// b2Simplex::ReadCache / WriteCache's b2SimplexCache: the support indices of the last simplex and
// its metric.
struct SimplexCache {
  count: u32,
  indexA: array<u32, 3>,
  indexB: array<u32, 3>,
  metric: f32,
}

fn empty_cache() -> SimplexCache {
  return SimplexCache(0u, array<u32, 3>(0u, 0u, 0u), array<u32, 3>(0u, 0u, 0u), 0.0);
}

fn simplex_vertex(pA: ptr<function, Proxy>, xfA: Xf, indexA: u32, pB: ptr<function, Proxy>, xfB: Xf, indexB: u32) -> SimplexVertex {
  let wA = mul_xv(xfA, (*pA).v[indexA]);
  let wB = mul_xv(xfB, (*pB).v[indexB]);
  return SimplexVertex(wA, wB, wB - wA, 0.0, indexA, indexB);
}

// b2Simplex::GetMetric.
fn simplex_metric(sv: ptr<function, array<SimplexVertex, 3>>, count: u32) -> f32 {
  if (count == 2u) {
    let d = (*sv)[0].w - (*sv)[1].w;
    return sqrt(d.x * d.x + d.y * d.y);
  }
  if (count == 3u) {
    let w1 = (*sv)[0].w;
    let w2 = (*sv)[1].w;
    let w3 = (*sv)[2].w;
    return (w2.x - w1.x) * (w3.y - w1.y) - (w2.y - w1.y) * (w3.x - w1.x);
  }
  return 0.0;
}

// b2Distance(...).distance without radii (useRadii false), starting from `cache` (ReadCache: the
// cached simplex, flushed when its metric changed by more than a factor of 2) and leaving the
// final simplex in it (WriteCache). An empty cache starts from vertices 0 and 0.
fn gjk_distance_cached(pA: ptr<function, Proxy>, xfA: Xf, pB: ptr<function, Proxy>, xfB: Xf, cache: ptr<function, SimplexCache>) -> f32 {
  var sv: array<SimplexVertex, 3>;
  sv[0] = simplex_vertex(pA, xfA, (*cache).indexA[0], pB, xfB, (*cache).indexB[0]);
  sv[1] = sv[0];
  sv[2] = sv[0];
  var count = (*cache).count;
  for (var i = 1u; i < count; i = i + 1u) {
    sv[i] = simplex_vertex(pA, xfA, (*cache).indexA[i], pB, xfB, (*cache).indexB[i]);
  }
  if (count > 1u) {
    let metric1 = (*cache).metric;
    let metric2 = simplex_metric(&sv, count);
    if (metric2 < 0.5 * metric1 || 2.0 * metric1 < metric2 || metric2 < EPSILON) {
      count = 0u;
    }
  }
  if (count == 0u) {
    sv[0] = simplex_vertex(pA, xfA, 0u, pB, xfB, 0u);
    count = 1u;
  }
  sv[0].a = 1.0;

  var saveA: array<u32, 3>;
  var saveB: array<u32, 3>;
  var iter = 0u;
  while (iter < 20u) {
    let saveCount = count;
    for (var i = 0u; i < 3u; i = i + 1u) {
      saveA[i] = sv[i].indexA;
      saveB[i] = sv[i].indexB;
    }

    if (count == 2u) {
      // Solve2.
      let w1 = sv[0].w;
      let w2 = sv[1].w;
      let e12 = vec2<f32>(w2.x - w1.x, w2.y - w1.y);
      let d12_2 = -(w1.x * e12.x + w1.y * e12.y);
      let d12_1 = w2.x * e12.x + w2.y * e12.y;
      if (d12_2 <= 0.0) {
        sv[0].a = 1.0;
        count = 1u;
      } else if (d12_1 <= 0.0) {
        sv[1].a = 1.0;
        count = 1u;
        sv[0] = sv[1];
      } else {
        let inv_d12 = 1.0 / (d12_1 + d12_2);
        sv[0].a = d12_1 * inv_d12;
        sv[1].a = d12_2 * inv_d12;
        count = 2u;
      }
    } else if (count == 3u) {
      // Solve3.
      let w1 = sv[0].w;
      let w2 = sv[1].w;
      let w3 = sv[2].w;
      let e12 = vec2<f32>(w2.x - w1.x, w2.y - w1.y);
      let w1e12 = w1.x * e12.x + w1.y * e12.y;
      let w2e12 = w2.x * e12.x + w2.y * e12.y;
      let d12_1 = w2e12;
      let d12_2 = -w1e12;
      let e13 = vec2<f32>(w3.x - w1.x, w3.y - w1.y);
      let w1e13 = w1.x * e13.x + w1.y * e13.y;
      let w3e13 = w3.x * e13.x + w3.y * e13.y;
      let d13_1 = w3e13;
      let d13_2 = -w1e13;
      let e23 = vec2<f32>(w3.x - w2.x, w3.y - w2.y);
      let w2e23 = w2.x * e23.x + w2.y * e23.y;
      let w3e23 = w3.x * e23.x + w3.y * e23.y;
      let d23_1 = w3e23;
      let d23_2 = -w2e23;
      let n123 = e12.x * e13.y - e12.y * e13.x;
      let d123_1 = n123 * cross2(w2, w3);
      let d123_2 = n123 * cross2(w3, w1);
      let d123_3 = n123 * cross2(w1, w2);
      if (d12_2 <= 0.0 && d13_2 <= 0.0) {
        sv[0].a = 1.0;
        count = 1u;
      } else if (d12_1 > 0.0 && d12_2 > 0.0 && d123_3 <= 0.0) {
        let inv_d12 = 1.0 / (d12_1 + d12_2);
        sv[0].a = d12_1 * inv_d12;
        sv[1].a = d12_2 * inv_d12;
        count = 2u;
      } else if (d13_1 > 0.0 && d13_2 > 0.0 && d123_2 <= 0.0) {
        let inv_d13 = 1.0 / (d13_1 + d13_2);
        sv[0].a = d13_1 * inv_d13;
        sv[2].a = d13_2 * inv_d13;
        count = 2u;
        sv[1] = sv[2];
      } else if (d12_1 <= 0.0 && d23_2 <= 0.0) {
        sv[1].a = 1.0;
        count = 1u;
        sv[0] = sv[1];
      } else if (d13_1 <= 0.0 && d23_1 <= 0.0) {
        sv[2].a = 1.0;
        count = 1u;
        sv[0] = sv[2];
      } else if (d23_1 > 0.0 && d23_2 > 0.0 && d123_1 <= 0.0) {
        let inv_d23 = 1.0 / (d23_1 + d23_2);
        sv[1].a = d23_1 * inv_d23;
        sv[2].a = d23_2 * inv_d23;
        count = 2u;
        sv[0] = sv[2];
      } else {
        let inv_d123 = 1.0 / (d123_1 + d123_2 + d123_3);
        sv[0].a = d123_1 * inv_d123;
        sv[1].a = d123_2 * inv_d123;
        sv[2].a = d123_3 * inv_d123;
        count = 3u;
      }
    }

    // The origin is in the triangle.
    if (count == 3u) {
      break;
    }

    // The search direction.
    var d: vec2<f32>;
    if (count == 1u) {
      d = vec2<f32>(-sv[0].w.x, -sv[0].w.y);
    } else {
      let w1 = sv[0].w;
      let w2 = sv[1].w;
      let e12 = vec2<f32>(w2.x - w1.x, w2.y - w1.y);
      let sgn = e12.x * -w1.y - e12.y * -w1.x;
      if (sgn > 0.0) {
        d = vec2<f32>(-1.0 * e12.y, 1.0 * e12.x);
      } else {
        d = vec2<f32>(1.0 * e12.y, -1.0 * e12.x);
      }
    }
    if (d.x * d.x + d.y * d.y < EPSILON * EPSILON) {
      break;
    }

    // A tentative new simplex vertex from the support points.
    let indexA = support(pA, mul_trv(xfA, vec2<f32>(-d.x, -d.y)));
    let wA = mul_xv(xfA, (*pA).v[indexA]);
    let indexB = support(pB, mul_trv(xfB, d));
    let wB = mul_xv(xfB, (*pB).v[indexB]);
    iter = iter + 1u;

    // A duplicate support point ends the search (the main termination criterion).
    var duplicate = false;
    for (var i = 0u; i < saveCount; i = i + 1u) {
      if (indexA == saveA[i] && indexB == saveB[i]) {
        duplicate = true;
        break;
      }
    }
    if (duplicate) {
      break;
    }
    sv[count] = SimplexVertex(wA, wB, wB - wA, 0.0, indexA, indexB);
    count = count + 1u;
  }

  // Witness points.
  var pointA: vec2<f32>;
  var pointB: vec2<f32>;
  if (count == 1u) {
    pointA = sv[0].wA;
    pointB = sv[0].wB;
  } else if (count == 2u) {
    pointA = vec2<f32>(sv[0].a * sv[0].wA.x + sv[1].a * sv[1].wA.x, sv[0].a * sv[0].wA.y + sv[1].a * sv[1].wA.y);
    pointB = vec2<f32>(sv[0].a * sv[0].wB.x + sv[1].a * sv[1].wB.x, sv[0].a * sv[0].wB.y + sv[1].a * sv[1].wB.y);
  } else {
    pointA = vec2<f32>(sv[0].a * sv[0].wA.x + sv[1].a * sv[1].wA.x + sv[2].a * sv[2].wA.x,
                       sv[0].a * sv[0].wA.y + sv[1].a * sv[1].wA.y + sv[2].a * sv[2].wA.y);
    pointB = pointA;
  }
  let dx = pointB.x - pointA.x;
  let dy = pointB.y - pointA.y;

  (*cache).metric = simplex_metric(&sv, count);
  (*cache).count = count;
  for (var i = 0u; i < 3u; i = i + 1u) {
    (*cache).indexA[i] = sv[i].indexA;
    (*cache).indexB[i] = sv[i].indexB;
  }
  return sqrt(dx * dx + dy * dy);
}
