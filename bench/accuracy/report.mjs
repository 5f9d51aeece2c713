// The accuracy study's report: the Pareto front of a scene's points for one measure, its chart
// (SVG, log axes) and the Markdown summary with the stability limits.

/** Units of the measures (docs/ACCURACY.md). */
export const MEASURE_UNITS = {
  'penetration max': 'm',
  'penetration mean': 'm',
  drift: 'm',
  jitter: 'm/s',
  'joint error': 'm',
  'joint angle error': 'rad',
  'range error': 'relative',
  'period error': 'relative',
  'rebound error': 'relative',
  'stopping error': 'relative',
  'energy drift': 'relative',
  'momentum drift': 'relative',
  'angular momentum drift': 'relative',
  'trajectory error': 'm',
};

/** Errors below this are drawn at it on the log axis (an exact answer has no logarithm). */
export const LOG_FLOOR = 1e-12;

/** The charts' colours: the Pareto front (line and points), then points by backend. */
export const COLOURS = { front: '#f28e2b', js: '#4e79a7', webgpu: '#59a14f', peer: '#b07aa1' };

/** A point's colour: the front's, else its backend's (the engine, WebGPU, a peer). */
export function pointColour(r, onFront) {
  return onFront ? COLOURS.front : r.backend === 'webgpu' ? COLOURS.webgpu : r.backend === 'js' ? COLOURS.js : COLOURS.peer;
}

/** A result's name: its method's label (after 'WebGPU, ' on the GPU), or a peer's name and version. */
export function labelOf(run, r) {
  if (r.backend !== 'js' && r.backend !== 'webgpu') {
    const peer = run.peers?.find((p) => p.id === r.backend);
    return peer ? `${peer.name}${peer.version ? ` ${peer.version}` : ''}` : r.backend;
  }
  const label = run.methods.find((m) => m.id === r.method)?.label ?? r.method;
  return r.backend === 'webgpu' ? `WebGPU, ${label}` : label;
}

/**
 * The results no other result beats on both cost and `measure` (lower time per simulated second
 * and lower error), cheapest first; results whose error is not finite (a failed run) or that
 * were not timed (the GPU on a software adapter) are left out.
 */
export function paretoFront(results, measure) {
  const points = results
    .filter((r) => r.msPerSecond !== null && Number.isFinite(r.measures[measure]))
    .sort((a, b) => a.msPerSecond - b.msPerSecond || a.measures[measure] - b.measures[measure]);
  const front = [];
  let best = Infinity;
  for (const r of points) {
    if (r.measures[measure] < best) {
      front.push(r);
      best = r.measures[measure];
    }
  }
  return front;
}

const esc = (s) => String(s).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');
/** A number in three significant figures ('–' for a measure not taken). */
export function formatNumber(v) {
  if (v === undefined) return '–';
  if (v === 0) return '0';
  if (!Number.isFinite(v)) return String(v);
  return Math.abs(v) >= 0.01 && Math.abs(v) < 1000 ? v.toPrecision(3) : v.toExponential(2);
}

/** Decades covering [lo, hi] (log10 bounds, at least one decade wide). */
export function decades(lo, hi) {
  const a = Math.floor(Math.log10(lo));
  const b = Math.max(a + 1, Math.ceil(Math.log10(hi)));
  return [a, b];
}

/** The chart of one scene and measure: error against milliseconds per simulated second, both log scale. */
export function paretoSvg(scene, measure, run) {
  const points = scene.results.filter((r) => r.msPerSecond !== null && Number.isFinite(r.measures[measure]));
  const untimed = scene.results.filter((r) => r.msPerSecond === null);
  const front = new Set(scene.fronts[measure]);
  const width = 760;
  const height = 460;
  const left = 80;
  const right = 200;
  const top = 72;
  const bottom = 60;
  const xs = points.map((r) => r.msPerSecond);
  const ys = points.map((r) => Math.max(LOG_FLOOR, r.measures[measure]));
  const [x0, x1] = decades(Math.min(...xs, 1), Math.max(...xs, 1));
  const [y0, y1] = decades(Math.min(...ys, 1), Math.max(...ys, 1e-3));
  const px = (v) => left + ((Math.log10(v) - x0) / (x1 - x0)) * (width - left - right);
  const py = (v) => height - bottom - ((Math.log10(Math.max(LOG_FLOOR, v)) - y0) / (y1 - y0)) * (height - top - bottom);
  const parts = [
    `<svg xmlns="http://www.w3.org/2000/svg" width="${width}" height="${height}" viewBox="0 0 ${width} ${height}" font-family="Helvetica, Arial, sans-serif" font-size="12">`,
    `<rect width="100%" height="100%" fill="#ffffff"/>`,
    `<text x="12" y="22" font-size="15" font-weight="bold">${esc(`${scene.title}: ${measure} (${MEASURE_UNITS[measure] ?? ''})`)}</text>`,
    `<text x="12" y="40" fill="#555">against the time to step one simulated second; lower left is better; the Pareto front in orange</text>`,
    `<text x="12" y="56" fill="#555">${esc(`Node ${run.machine.node}, ${run.machine.cpuModel}, ${run.date.slice(0, 10)}`)}</text>`,
  ];
  for (let d = x0; d <= x1; ++d) {
    const gx = px(10 ** d);
    parts.push(
      `<line x1="${gx.toFixed(1)}" y1="${top}" x2="${gx.toFixed(1)}" y2="${height - bottom}" stroke="#e3e3e3"/>`,
      `<text x="${gx.toFixed(1)}" y="${height - bottom + 16}" text-anchor="middle" fill="#555">${esc(formatNumber(10 ** d))}</text>`,
    );
  }
  for (let d = y0; d <= y1; ++d) {
    const gy = py(10 ** d);
    parts.push(
      `<line x1="${left}" y1="${gy.toFixed(1)}" x2="${width - right}" y2="${gy.toFixed(1)}" stroke="#e3e3e3"/>`,
      `<text x="${left - 6}" y="${(gy + 4).toFixed(1)}" text-anchor="end" fill="#555">${esc(formatNumber(10 ** d))}</text>`,
    );
  }
  parts.push(`<text x="${(left + width - right) / 2}" y="${height - 20}" text-anchor="middle" fill="#555">ms of stepping per simulated second (log)</text>`);
  const frontPoints = scene.fronts[measure].map((key) => points.find((r) => r.key === key)).filter(Boolean);
  if (frontPoints.length > 1) {
    parts.push(
      `<polyline fill="none" stroke="${COLOURS.front}" stroke-width="2" points="${frontPoints.map((r) => `${px(r.msPerSecond).toFixed(1)},${py(r.measures[measure]).toFixed(1)}`).join(' ')}"/>`,
    );
  }
  // Front points first, cheapest first, so that their labels win where labels would overlap (a
  // skipped label's point still names its method in its tooltip).
  const placed = [];
  const ordered = [...points].sort((a, b) => Number(front.has(b.key)) - Number(front.has(a.key)) || a.msPerSecond - b.msPerSecond);
  for (const r of ordered) {
    const on = front.has(r.key);
    parts.push(
      `<circle cx="${px(r.msPerSecond).toFixed(1)}" cy="${py(r.measures[measure]).toFixed(1)}" r="${on ? 5 : 4}" fill="${pointColour(r, on)}"><title>${esc(`${labelOf(run, r)}: ${formatNumber(r.msPerSecond)} ms per simulated second, ${measure} ${formatNumber(r.measures[measure])}`)}</title></circle>`,
    );
  }
  for (const r of ordered) {
    const cx = px(r.msPerSecond);
    const cy = py(r.measures[measure]);
    const box = { x: cx + 7, y: cy - 8, w: 6 * r.key.length, h: 11 };
    if (placed.some((b) => box.x < b.x + b.w && b.x < box.x + box.w && box.y < b.y + b.h && b.y < box.y + box.h)) continue;
    placed.push(box);
    parts.push(`<text x="${(cx + 7).toFixed(1)}" y="${(cy + 4).toFixed(1)}" fill="#333" font-size="10">${esc(r.key)}</text>`);
  }
  // Notes at the right: failed runs, exact answers, and the GPU's untimed points with their errors.
  const notes = [];
  const failed = scene.results.filter((r) => r.measures[measure] !== undefined && !Number.isFinite(r.measures[measure]));
  if (failed.length > 0) notes.push([`no answer: ${failed.map((r) => r.key).join(', ')}`, '#a00']);
  if (ys.some((v) => v === LOG_FLOOR)) notes.push([`0 drawn at ${formatNumber(LOG_FLOOR)}`, '#555']);
  if (untimed.length > 0)
    notes.push(['untimed (software adapter):', COLOURS.webgpu], ...untimed.map((r) => [`${r.key}: ${formatNumber(r.measures[measure])}`, COLOURS.webgpu]));
  const unmeasured = scene.results.filter((r) => r.measures[measure] === undefined);
  if (unmeasured.length > 0) notes.push(['not measured (needs a b2World):', '#999'], ...unmeasured.map((r) => [r.key, '#999']));
  notes.forEach(([text, colour], i) =>
    parts.push(`<text x="${width - right + 10}" y="${top + 10 + 16 * i}" fill="${colour}" font-size="11">${esc(text)}</text>`),
  );
  parts.push('</svg>');
  return parts.join('\n') + '\n';
}

/** The study's summary: per scene, each method's cost and measures (front marked), then the limits. */
export function accuracyMarkdown(run) {
  const labels = Object.fromEntries(run.methods.map((m) => [m.id, m.label]));
  const gpu = run.machine.gpu
    ? ` WebGPU: ${run.machine.gpu.description || run.machine.gpu.device} (${run.machine.gpu.software ? 'software: accuracy only, not timed' : 'timed'}).`
    : '';
  const peers = run.peers?.length
    ? ` Peers at their own settings (1/60 s; 8/3 iterations where they have them, Box2D v3 4 substeps, Rapier its default): ${run.peers.map((p) => `${p.name}${p.version ? ` ${p.version}` : ''}`).join(', ')}; – marks a measure that needs a Box2D 2.2.1 world, and the trajectory error is against WebPhysics' converged run.`
    : '';
  const lines = [
    '# Accuracy: speed against error',
    '',
    `Node ${run.machine.node}, ${run.machine.cpus} x ${run.machine.cpuModel}, ${run.date}${run.quick ? ' (quick subset)' : ''}.${gpu}${peers} The measures and scenes: docs/ACCURACY.md. * marks a point on the Pareto front of that measure.`,
    '',
  ];
  for (const scene of run.scenes) {
    lines.push(
      `## ${scene.title} (${scene.seconds} s)`,
      '',
      `| method | ms per simulated second | ${scene.measures.map((m) => `${m} (${MEASURE_UNITS[m] ?? ''})`).join(' | ')} |`,
      `| --- | ---: |${' ---: |'.repeat(scene.measures.length)}`,
    );
    for (const r of scene.results) {
      lines.push(
        `| ${labelOf(run, r)} | ${r.msPerSecond === null ? 'untimed' : formatNumber(r.msPerSecond)} | ${scene.measures.map((m) => `${formatNumber(r.measures[m])}${scene.fronts[m].includes(r.key) ? ' *' : ''}`).join(' | ')} |`,
      );
    }
    lines.push('');
  }
  if (run.limits.length > 0) {
    // One row per method or peer, one column per limit; the tests below.
    const ids = [...new Set(run.limits.map((l) => l.id))];
    const owners = [...new Set(run.limits.map((l) => l.method))];
    const value = (l) => {
      if (l === undefined) return '–';
      // Outside the range: not even the safe end passes ('below'), or the far end passes too ('above').
      const [safe, far] = l.smallest
        ? [`> ${formatNumber(l.range[1])}`, `≤ ${formatNumber(l.range[0])}`]
        : [`< ${formatNumber(l.range[0])}`, `≥ ${formatNumber(l.range[1])}`];
      return l.outside === 'below' ? safe : l.outside === 'above' ? far : formatNumber(l.limit);
    };
    lines.push(
      '## Stability limits',
      '',
      `| method | ${ids.map((id) => `${id} (${run.limits.find((l) => l.id === id).unit})`).join(' | ')} |`,
      `| --- |${' ---: |'.repeat(ids.length)}`,
    );
    for (const owner of owners) {
      // A GPU limit found on another device than this run's says which (merge.mjs).
      const device = run.limits.find((l) => l.method === owner && l.device !== undefined)?.device;
      const label =
        (owner.startsWith('webgpu ')
          ? labelOf(run, { backend: 'webgpu', method: owner.slice(7) })
          : (labels[owner] ?? labelOf(run, { backend: owner, method: 'default' }))) + (device !== undefined ? ` (on ${device})` : '');
      lines.push(`| ${label} | ${ids.map((id) => value(run.limits.find((l) => l.method === owner && l.id === id))).join(' | ')} |`);
    }
    lines.push('', 'The tests (each limit found by bisection; – : not tested for that engine):', '');
    for (const id of ids) {
      const tests = [...new Set(run.limits.filter((l) => l.id === id).map((l) => l.test))];
      for (const test of tests) lines.push(`- ${id}: ${test}`);
    }
    lines.push('');
  }
  return lines.join('\n');
}
