// Terminal tables and SVG charts for the benchmark results (no dependencies).

export function formatBytes(n) {
  if (n === null || n === undefined || !Number.isFinite(n)) return '-';
  const sign = n < 0 ? '-' : '';
  const a = Math.abs(n);
  if (a < 1024) return `${sign}${Math.round(a)} B`;
  if (a < 1024 * 1024) return `${sign}${(a / 1024).toFixed(1)} KiB`;
  return `${sign}${(a / 1024 / 1024).toFixed(1)} MiB`;
}

/** The median of the fastest round: the figure least disturbed by other load on the machine. */
export const bestRound = (t) => (t?.roundMedians?.length ? Math.min(...t.roundMedians) : null);

const ms = (v) => (v === null || v === undefined ? '-' : v >= 100 ? v.toFixed(0) : v >= 10 ? v.toFixed(1) : v.toFixed(2));

function table(header, rows, align) {
  const widths = header.map((h, i) => Math.max(h.length, ...rows.map((r) => String(r[i]).length)));
  const line = (cells) => cells.map((c, i) => (align[i] === 'r' ? String(c).padStart(widths[i]) : String(c).padEnd(widths[i]))).join('  ');
  return [line(header), widths.map((w) => '-'.repeat(w)).join('  '), ...rows.map(line)].join('\n');
}

/** The terminal table of one scene for one sleep setting. */
export function formatSceneTables(scene, engines, sleep) {
  const { protocol: p, settings: st } = scene;
  const head =
    `\n${scene.title} — sleeping ${sleep ? 'on' : 'off'}  (${scene.bodies} bodies${scene.joints ? `, ${scene.joints} joints` : ''}; ` +
    `${st.velocityIterations}/${st.positionIterations} iterations, dt 1/${Math.round(1 / st.dt)}; ` +
    `${p.preroll} warm-up + ${p.rounds} x ${p.steps} timed steps)`;
  const rows = [];
  const notes = [];
  for (const r of scene.results.filter((x) => x.sleep === sleep)) {
    const e = engines.find((x) => x.id === r.engine);
    const name = `${e.name}${e.version ? ' ' + e.version : ''}`;
    if (r.status !== 'ok') {
      rows.push([name, '-', '-', '-', '-', '-', '-', '-', '-', '-', '-', r.status]);
      notes.push(`  ${e.name}: ${r.status}: ${r.reason}`);
      continue;
    }
    const t = r.timing;
    const m = r.memory ?? {};
    if (r.check && !r.check.ok) notes.push(`  ${e.name}: sanity check FAILED: ${r.check.detail}`);
    if (r.memory && r.memory.worldBytes === null) {
      notes.push(`  ${e.name}: world heap not above an empty world's (within the noise), or not measured`);
    }
    rows.push([
      name,
      ms(t.medianMs),
      ms(bestRound(t)),
      ms(t.p95Ms),
      t.stepsPerSecond >= 100 ? t.stepsPerSecond.toFixed(0) : t.stepsPerSecond.toFixed(1),
      r.ratioToOurs === null ? '-' : r.ratioToOurs.toFixed(2),
      formatBytes(m.allocBytesPerStep),
      formatBytes(m.heapGrowthBytes),
      m.wasmBytes ? `${formatBytes(m.worldBytes)} + wasm ${formatBytes(m.wasmBytes)}` : formatBytes(m.worldBytes),
      r.counts?.bodies ?? '-',
      r.counts?.contacts ?? '-',
      r.check ? (r.check.ok ? 'ok' : 'FAIL') : '-',
    ]);
  }
  const t = table(
    ['engine', 'median ms', 'best round', 'p95 ms', 'steps/s', 'x ours', 'alloc/step', 'heap growth', 'world heap', 'bodies', 'contacts', 'check'],
    rows,
    ['l', 'r', 'r', 'r', 'r', 'r', 'r', 'r', 'r', 'r', 'r', 'l'],
  );
  return [head, t, ...notes].join('\n');
}

const esc = (s) => String(s).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');

function niceMax(v) {
  if (!(v > 0)) return 1;
  const p = 10 ** Math.floor(Math.log10(v));
  for (const m of [1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 8, 10]) if (m * p >= v) return m * p;
  return 10 * p;
}

/**
 * An SVG bar chart of one scene: per engine, the median ms per step as a bar and the p95 as a
 * whisker, sleeping off and on side by side.
 */
export function chartSvg(scene, run) {
  const engines = run.engines;
  const sleeps = [...new Set(scene.results.map((r) => r.sleep))].sort();
  const colors = { false: '#4e79a7', true: '#f28e2b' };
  const ids = [...new Set(scene.results.map((r) => r.engine))];
  const maxP95 = Math.max(0, ...scene.results.filter((r) => r.timing).map((r) => r.timing.p95Ms));
  const max = niceMax(maxP95 * 1.02);
  const left = 210;
  const plotW = 520;
  const right = 110;
  const top = 70;
  const barH = 13;
  const rowH = sleeps.length * (barH + 3) + 12;
  const height = top + ids.length * rowH + 40;
  const width = left + plotW + right;
  const x = (v) => left + (v / max) * plotW;
  const st = scene.settings;
  const parts = [];
  parts.push(
    `<svg xmlns="http://www.w3.org/2000/svg" width="${width}" height="${height}" viewBox="0 0 ${width} ${height}" font-family="Helvetica, Arial, sans-serif" font-size="12">`,
    `<rect width="100%" height="100%" fill="#ffffff"/>`,
    `<text x="12" y="22" font-size="15" font-weight="bold">${esc(scene.title)}: ms per step (bar: median, whisker: p95; shorter is faster)</text>`,
    `<text x="12" y="40" fill="#555">${esc(
      `${scene.bodies} bodies${scene.joints ? `, ${scene.joints} joints` : ''}; ${st.velocityIterations}/${st.positionIterations} iterations (v3 and Rapier: 4 substeps); ${scene.protocol.rounds} x ${scene.protocol.steps} steps after ${scene.protocol.preroll}`,
    )}</text>`,
    `<text x="12" y="56" fill="#555">${esc(`Node ${run.machine.node}, ${run.machine.cpus} x ${run.machine.cpuModel}, ${run.date.slice(0, 10)}`)}</text>`,
  );
  // Legend.
  sleeps.forEach((s, i) => {
    const lx = width - 220 + i * 105;
    parts.push(
      `<rect x="${lx}" y="${top - 16}" width="12" height="10" fill="${colors[s]}"/>`,
      `<text x="${lx + 16}" y="${top - 7}">sleeping ${s ? 'on' : 'off'}</text>`,
    );
  });
  // Grid and axis.
  const plotBottom = top + ids.length * rowH;
  for (let k = 0; k <= 5; k++) {
    const v = (max * k) / 5;
    const gx = x(v);
    parts.push(
      `<line x1="${gx.toFixed(1)}" y1="${top}" x2="${gx.toFixed(1)}" y2="${plotBottom}" stroke="#e3e3e3"/>`,
      `<text x="${gx.toFixed(1)}" y="${plotBottom + 16}" text-anchor="middle" fill="#555">${esc(+v.toPrecision(3))}</text>`,
    );
  }
  parts.push(`<text x="${left + plotW / 2}" y="${plotBottom + 32}" text-anchor="middle" fill="#555">ms per step</text>`);
  ids.forEach((id, row) => {
    const e = engines.find((x) => x.id === id);
    const y0 = top + row * rowH + 6;
    const bold = id === 'webphysics' ? ' font-weight="bold"' : '';
    parts.push(`<text x="${left - 8}" y="${y0 + rowH / 2 - 2}" text-anchor="end"${bold}>${esc(`${e.name}${e.version ? ' ' + e.version : ''}`)}</text>`);
    sleeps.forEach((s, i) => {
      const r = scene.results.find((q) => q.engine === id && q.sleep === s);
      const by = y0 + i * (barH + 3);
      if (!r || !r.timing) {
        parts.push(`<text x="${left + 4}" y="${by + barH - 2}" fill="#999">${esc(r ? `${r.status}: ${r.reason ?? ''}`.slice(0, 80) : 'not run')}</text>`);
        return;
      }
      const t = r.timing;
      const xm = x(t.medianMs);
      const xp = x(t.p95Ms);
      const cy = by + barH / 2;
      parts.push(
        `<rect x="${left}" y="${by}" width="${Math.max(1, xm - left).toFixed(1)}" height="${barH}" fill="${colors[s]}"><title>${esc(`${e.name}, sleeping ${s ? 'on' : 'off'}: median ${t.medianMs.toFixed(3)} ms, p95 ${t.p95Ms.toFixed(3)} ms`)}</title></rect>`,
        `<line x1="${xm.toFixed(1)}" y1="${cy}" x2="${xp.toFixed(1)}" y2="${cy}" stroke="#333"/>`,
        `<line x1="${xp.toFixed(1)}" y1="${by + 2}" x2="${xp.toFixed(1)}" y2="${by + barH - 2}" stroke="#333"/>`,
        `<text x="${(Math.max(xp, xm) + 5).toFixed(1)}" y="${by + barH - 2}" fill="#333">${esc(t.medianMs.toFixed(t.medianMs >= 10 ? 1 : 2))}${r.check && !r.check.ok ? ' (check failed)' : ''}</text>`,
      );
    });
  });
  parts.push('</svg>');
  return parts.join('\n') + '\n';
}

const md = (v) => (v === null || v === undefined ? '–' : ms(v));

/**
 * "L1 48 KiB, L2 2 MiB, L3 480 MiB shared by 2 CPUs": a machine's data caches (harness.mjs
 * cpuCaches) in words; "" for none (results from before they were recorded have none).
 */
export function describeCaches(caches = []) {
  const size = (kib) => (kib >= 1024 && kib % 1024 === 0 ? `${kib / 1024} MiB` : `${kib} KiB`);
  return caches.map((c) => `L${c.level} ${size(c.kib)}${c.sharedBy > 1 ? ` shared by ${c.sharedBy} CPUs` : ''}`).join(', ');
}

/**
 * Markdown tables of a results object, one per scene: median (p95) ms per step with sleeping off
 * and on, the ratio to WebPhysics, and allocation per step. For the README's Benchmarks section.
 */
export function markdownSummary(run, chartDir = 'bench/results') {
  const out = [];
  const m = run.machine;
  out.push(
    `Measured ${run.date.slice(0, 10)} on ${m.cpus} cores (${m.cpuModel}${m.caches?.length ? `; ${describeCaches(m.caches)}` : ''}), Node ${m.node}, ${m.platform}; ` +
      `whole run ${Math.round(run.durationSeconds / 60)} min. Median (p95) ms per step; x ours = median / WebPhysics median ` +
      `(below 1: faster than WebPhysics); alloc = JavaScript heap bytes allocated per step (with sleeping off when that was run).`,
  );
  for (const s of run.scenes) {
    if (s.skipped) continue;
    out.push(
      '',
      `**${s.title}** — ${s.description}. ${s.protocol.rounds} x ${s.protocol.steps} timed steps after ${s.protocol.preroll}. ![${s.title}](${chartDir}/${s.id}.svg)`,
      '',
    );
    out.push('| engine | sleep off: median (p95) | best round | x ours | sleep on: median (p95) | best round | x ours | alloc/step | check |');
    out.push('| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- |');
    const ids = [...new Set(s.results.map((r) => r.engine))];
    for (const id of ids) {
      const e = run.engines.find((x) => x.id === id);
      const off = s.results.find((r) => r.engine === id && r.sleep === false);
      const on = s.results.find((r) => r.engine === id && r.sleep === true);
      const cell = (r) => (r?.timing ? `${md(r.timing.medianMs)} (${md(r.timing.p95Ms)})` : r ? r.status : '–');
      const ratio = (r) => (r?.ratioToOurs ? r.ratioToOurs.toFixed(2) : '–');
      const checks = [off, on].filter((r) => r?.check);
      const check = checks.length === 0 ? '–' : checks.every((r) => r.check.ok) ? 'ok' : 'FAIL: ' + checks.find((r) => !r.check.ok).check.detail;
      const name = `${e.name}${e.version && !e.name.includes(e.version) ? ' ' + e.version : ''}`;
      out.push(
        `| ${id === 'webphysics' ? `**${name}**` : name} | ${cell(off)} | ${md(bestRound(off?.timing))} | ${ratio(off)} | ${cell(on)} | ${md(bestRound(on?.timing))} | ${ratio(on)} | ${formatBytes((off ?? on)?.memory?.allocBytesPerStep)} | ${
          off?.status === 'skipped' ? 'n/a: ' + off.reason : check
        } |`,
      );
    }
  }
  return out.join('\n');
}

/**
 * One compact table for one sleep setting: engines down, scenes across; each cell the best-round
 * median ms per step and, in brackets, its ratio to WebPhysics' best-round median.
 */
export function compactSummary(run, sleep) {
  const scenes = run.scenes.filter((s) => !s.skipped);
  const ours = (s) => bestRound(s.results.find((q) => q.engine === 'webphysics' && q.sleep === sleep)?.timing);
  const head = `| engine | ${scenes.map((s) => s.title).join(' | ')} |`;
  const rule = `| --- | ${scenes.map(() => '---:').join(' | ')} |`;
  const rows = run.engines.map((e) => {
    const cells = scenes.map((s) => {
      const r = s.results.find((q) => q.engine === e.id && q.sleep === sleep);
      if (!r) return '–';
      if (!r.timing) return r.status === 'skipped' ? 'n/a' : r.status;
      const flag = r.check && !r.check.ok ? ' ✗' : '';
      const b = bestRound(r.timing);
      return `${md(b)} (${ours(s) ? (b / ours(s)).toFixed(2) : '–'})${flag}`;
    });
    const name = `${e.name}${e.version && !e.name.includes(e.version) ? ' ' + e.version : ''}`;
    return `| ${e.id === 'webphysics' ? `**${name}**` : name} | ${cells.join(' | ')} |`;
  });
  return [head, rule, ...rows].join('\n');
}
