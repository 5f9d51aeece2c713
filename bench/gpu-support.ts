/*
 * Helpers shared by the GPU benchmarks (bench/gpu-*.ts): a seeded random generator, medians,
 * number formatting for the tables, the adapter's name, the shapes they build, the log-log chart,
 * and a synthetic world of bodies for GpuWorld.
 */
import type { b2ChainShape } from '../src/collision/shapes/b2ChainShape';
import { b2CircleShape } from '../src/collision/shapes/b2CircleShape';
import { b2PolygonShape } from '../src/collision/shapes/b2PolygonShape';
import type { b2Shape } from '../src/collision/shapes/b2Shape';
import { b2Transform, b2Vec2 } from '../src/common/b2Math';
import type { b2World } from '../src/dynamics/b2World';
import type { GpuAdapterSummary } from '../src-gpu/device/device';

/** mulberry32: a small seeded generator, so every run builds the same scene. */
export function rng(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

export function median(values: number[]): number {
  if (values.length === 0) return NaN;
  const v = values.slice().sort((a, b) => a - b);
  return v[Math.floor(v.length / 2)];
}

/**
 * A full garbage collection when the process runs with --expose-gc (the benchmarks' commands pass
 * it): a phase timed after another then does not pay for collecting the previous phase's world,
 * which at 10^6 bodies is gigabytes of objects. Returns whether it collected.
 */
export function settleHeap(): boolean {
  const gc = (globalThis as { gc?: () => void }).gc;
  if (gc === undefined) return false;
  gc();
  return true;
}

/** Three significant digits, whole numbers from 100; '–' for a missing value. */
/** The adapter in one line for the tables: vendor, architecture, device, description, and whether it is software. */
export function deviceName(a: GpuAdapterSummary): string {
  return `${a.vendor} ${a.architecture} ${a.device} ${a.description}`.replace(/\s+/g, ' ').trim() + (a.software ? ' (software)' : '');
}

export function fmt(v: number | undefined, digits = 3): string {
  if (v === undefined || !Number.isFinite(v)) return '–';
  return v >= 100 ? v.toFixed(0) : v >= 10 ? v.toFixed(1) : v.toPrecision(digits);
}

export function box(hx: number, hy: number, centre?: b2Vec2): b2PolygonShape {
  const s = new b2PolygonShape();
  if (centre) s.SetAsBox(hx, hy, centre, 0);
  else s.SetAsBox(hx, hy);
  return s;
}

export function circle(r: number): b2CircleShape {
  const s = new b2CircleShape();
  s.m_radius = r;
  return s;
}

/** Where the GPU overtakes the JavaScript engine in one scene. */
export interface Crossover {
  scene: string;
  /** Smallest measured size where the GPU step beats the engine, or null. */
  measured: number | null;
  /** Where JS/GPU crosses 1, interpolated in log-log between two measured sizes, or null. */
  interpolated: number | null;
  text: string;
}

/** 12000 -> '1.2e4'. */
export function sizeText(n: number): string {
  return n
    .toExponential(2)
    .replace(/\.?0+e/, 'e')
    .replace('e+', 'e');
}

/** The crossover of one scene from its sizes measured on both (milliseconds per step). */
export function crossover(scene: string, measured: { n: number; jsMs: number; gpuMs: number }[]): Crossover {
  const pts = measured
    .filter((m) => Number.isFinite(m.jsMs) && Number.isFinite(m.gpuMs))
    .map((m) => ({ n: m.n, ratio: m.jsMs / m.gpuMs }))
    .sort((a, b) => a.n - b.n);
  if (pts.length === 0) return { scene, measured: null, interpolated: null, text: 'no size measured on both' };
  const first = pts.findIndex((p) => p.ratio > 1);
  if (first < 0) {
    const top = pts[pts.length - 1];
    return { scene, measured: null, interpolated: null, text: `not reached up to ${sizeText(top.n)} bodies (JS/GPU ${fmt(top.ratio)} there)` };
  }
  const at = pts[first].n;
  if (first === 0) return { scene, measured: at, interpolated: null, text: `GPU faster at every measured size (from ${sizeText(at)} bodies)` };
  const a = pts[first - 1];
  const b = pts[first];
  const t = -Math.log(a.ratio) / (Math.log(b.ratio) - Math.log(a.ratio));
  const interpolated = Math.exp(Math.log(a.n) + t * (Math.log(b.n) - Math.log(a.n)));
  return {
    scene,
    measured: at,
    interpolated,
    text: `GPU faster from ${sizeText(at)} bodies (measured); JS/GPU = 1 at about ${sizeText(interpolated)} bodies (interpolated in log-log between ${sizeText(a.n)} and ${sizeText(b.n)})`,
  };
}

/** One line per (group, series) of a log-log chart: its label, value and dash pattern. */
export interface ChartSeries<R> {
  label: string;
  value: (row: R) => number | undefined;
  dash: string;
}

export interface LogLogChart<R> {
  title: string;
  /** The x axis: its label, each row's value, and the tick text of a value. */
  xLabel: string;
  x: (row: R) => number;
  xText: (x: number) => string;
  /** Rows of one group share a colour (colours[group], grey when missing). */
  group: (row: R) => string;
  colours: Record<string, string>;
  series: ChartSeries<R>[];
}

/** A log-log SVG line chart in milliseconds, with a legend on the right (no chart library). */
export function logLogChart<R>(rows: R[], chart: LogLogChart<R>): string {
  const W = 760;
  const H = 460;
  const m = { l: 70, r: 210, t: 30, b: 50 };
  const ok = (v: number | undefined): v is number => v !== undefined && v > 0 && Number.isFinite(v);
  const xs = rows.map(chart.x);
  const ys = rows.flatMap((r) => chart.series.map((s) => s.value(r)).filter(ok));
  if (ys.length === 0) ys.push(1);
  const x0 = Math.log10(Math.min(...xs)) - 0.1;
  const x1 = Math.log10(Math.max(...xs)) + 0.1;
  const y0 = Math.floor(Math.log10(Math.min(...ys)));
  const y1 = Math.ceil(Math.log10(Math.max(...ys)));
  const px = (v: number) => m.l + ((Math.log10(v) - x0) / (x1 - x0 || 1)) * (W - m.l - m.r);
  const py = (v: number) => H - m.b - ((Math.log10(v) - y0) / (y1 - y0 || 1)) * (H - m.t - m.b);
  const out: string[] = [
    `<svg xmlns="http://www.w3.org/2000/svg" width="${W}" height="${H}" font-family="sans-serif" font-size="12">`,
    `<rect width="${W}" height="${H}" fill="white"/>`,
    `<text x="${m.l}" y="18" font-size="14">${chart.title}</text>`,
  ];
  for (let e = y0; e <= y1; ++e) {
    const y = py(10 ** e);
    out.push(
      `<line x1="${m.l}" x2="${W - m.r}" y1="${y}" y2="${y}" stroke="#ddd"/><text x="${m.l - 8}" y="${y + 4}" text-anchor="end">${10 ** e >= 1 ? 10 ** e : (10 ** e).toPrecision(1)} ms</text>`,
    );
  }
  for (const v of [...new Set(xs)]) {
    const x = px(v);
    out.push(
      `<line x1="${x}" x2="${x}" y1="${m.t}" y2="${H - m.b}" stroke="#eee"/><text x="${x}" y="${H - m.b + 18}" text-anchor="middle">${chart.xText(v)}</text>`,
    );
  }
  out.push(`<text x="${(m.l + W - m.r) / 2}" y="${H - 12}" text-anchor="middle">${chart.xLabel}</text>`);
  let legend = 0;
  for (const group of [...new Set(rows.map(chart.group))]) {
    for (const s of chart.series) {
      const pts = rows
        .filter((r) => chart.group(r) === group)
        .map((r) => [chart.x(r), s.value(r)] as const)
        .filter((p): p is readonly [number, number] => ok(p[1]));
      if (pts.length === 0) continue;
      const colour = chart.colours[group] ?? '#555';
      const dash = s.dash ? `stroke-dasharray="${s.dash}"` : '';
      out.push(
        `<polyline fill="none" stroke="${colour}" stroke-width="2" ${dash} points="${pts.map(([x, y]) => `${px(x).toFixed(1)},${py(y).toFixed(1)}`).join(' ')}"/>`,
      );
      for (const [x, y] of pts) out.push(`<circle cx="${px(x).toFixed(1)}" cy="${py(y).toFixed(1)}" r="2.5" fill="${colour}"/>`);
      const ly = m.t + 16 * legend++;
      out.push(
        `<line x1="${W - m.r + 12}" x2="${W - m.r + 40}" y1="${ly}" y2="${ly}" stroke="${colour}" stroke-width="2" ${dash}/><text x="${W - m.r + 46}" y="${ly + 4}">${group}, ${s.label}</text>`,
      );
    }
  }
  out.push('</svg>');
  return out.join('\n');
}

/** A body of syntheticWorld: one fixture per shape. */
export interface SyntheticBody {
  x: number;
  y: number;
  angle: number;
  vx: number;
  vy: number;
  w: number;
  dynamic: boolean;
  shapes: b2Shape[];
  sensor: boolean;
}

/**
 * The bodies as the fields GpuWorld reads (a b2World's bodies, fixtures and shapes): building a
 * real b2World of a million bodies would also build its dynamic tree, which is not measured here.
 * No change listener: the mirror walks everything at each sync.
 */
export function syntheticWorld(bodies: SyntheticBody[]): b2World {
  let head: object | null = null;
  for (let i = bodies.length - 1; i >= 0; --i) {
    const b = bodies[i];
    const xf = new b2Transform();
    xf.p.Set(b.x, b.y);
    xf.q.Set(b.angle);
    const c = new b2Vec2(b.x, b.y);
    const body: Record<string, unknown> = {
      m_type: b.dynamic ? 2 : 0,
      m_flags: 0x26,
      m_xf: xf,
      m_sweep: { localCenter: new b2Vec2(), c0: c, c, a0: b.angle, a: b.angle, alpha0: 0 },
      m_linearVelocity: new b2Vec2(b.vx, b.vy),
      m_angularVelocity: b.w,
      m_force: new b2Vec2(),
      m_torque: 0,
      m_invMass: b.dynamic ? 1 : 0,
      m_invI: b.dynamic ? 1 : 0,
      m_linearDamping: 0,
      m_angularDamping: 0,
      m_gravityScale: 1,
      m_sleepTime: 0,
      m_jointList: null,
      m_next: head,
    };
    let next: object | null = null;
    for (let k = b.shapes.length - 1; k >= 0; --k) {
      const shape = b.shapes[k];
      next = {
        m_shape: shape,
        m_filter: { categoryBits: 1, maskBits: 0xffff, groupIndex: 0 },
        m_isSensor: b.sensor,
        m_friction: 0.2,
        m_restitution: 0,
        m_density: 1,
        m_proxyCount: shape.m_type === 3 ? (shape as b2ChainShape).m_count - 1 : 1,
        m_next: next,
        m_body: body,
      };
    }
    body.m_fixtureList = next;
    head = body;
  }
  return {
    m_bodyList: head,
    m_jointList: null,
    m_contactManager: { m_contactFilter: null, m_contactList: null },
    SetChangeListener: () => {},
  } as unknown as b2World;
}
