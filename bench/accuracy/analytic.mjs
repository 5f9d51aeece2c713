// Answers known in closed form, for the analytic cases of the accuracy study (docs/ACCURACY.md):
// the exact motion, and where it differs, what Box2D's integrator (semi-implicit Euler: velocity
// first, then position with the new velocity; b2Island::Solve) gives after n steps.

/**
 * Free fall from y0 at v0 under gravity g (negative down) after n steps of dt, as semi-implicit
 * Euler takes it: v_n = v0 + n dt g, y_n = y0 + n dt v0 + dt² g n (n + 1) / 2; and the exact
 * y(t) = y0 + v0 t + g t² / 2 at t = n dt. The integrator's error is y_n - y(t) = g dt t / 2.
 */
export function freeFall(y0, v0, g, dt, n) {
  const t = n * dt;
  return {
    steps: { y: y0 + n * dt * v0 + dt * dt * g * ((n * (n + 1)) / 2), v: v0 + n * dt * g },
    exact: { y: y0 + v0 * t + 0.5 * g * t * t, v: v0 + g * t },
  };
}

/** The arithmetic-geometric mean of a and b (quadratic convergence; to the last bit). */
export function agm(a, b) {
  for (let i = 0; i < 64 && a !== b; ++i) {
    const m = 0.5 * (a + b);
    const g = Math.sqrt(a * b);
    if (m === a && g === b) break;
    a = m;
    b = g;
  }
  return a;
}

/**
 * The exact period (s) of a pendulum of equivalent length `length` (m; I_pivot / (m d) for a body
 * whose centre is d from the pivot) swinging to amplitude `amplitude` (rad) in gravity `g` (m/s²):
 * T = 2 pi sqrt(L / g) / AGM(1, cos(amplitude / 2)), the complete elliptic integral of the first
 * kind by the arithmetic-geometric mean.
 */
export function pendulumPeriod(length, g, amplitude) {
  return (2 * Math.PI * Math.sqrt(length / g)) / agm(1, Math.cos(amplitude / 2));
}

/** Peak heights (m) of a ball dropped from h0 with restitution e: h_k = e^(2k) h0, k = 0..count-1. */
export function bounceHeights(h0, restitution, count) {
  const out = [];
  for (let k = 0; k < count; ++k) out.push(h0 * restitution ** (2 * k));
  return out;
}

/** The distance (m) a block sliding at v0 covers before friction mu stops it in gravity g: v0² / (2 mu g). */
export function slidingDistance(v0, mu, g) {
  return (v0 * v0) / (2 * mu * g);
}

/** The range (m) of a projectile launched at speed v and angle theta on level ground in gravity g, without drag: v² sin(2 theta) / g. */
export function projectileRange(v, theta, g) {
  return (v * v * Math.sin(2 * theta)) / g;
}
