// Readers of valgrind's cache simulator output for bench/cachesim.mjs.

/** The event totals of a cachegrind or callgrind output file (its text), by event name. */
export function eventTotals(text) {
  const events = /^events: (.*)$/m.exec(text);
  const summary = /^(?:summary|totals): (.*)$/m.exec(text);
  if (!events || !summary) throw new Error('not a cachegrind or callgrind output file (no events or summary line)');
  const names = events[1].trim().split(/\s+/);
  const values = summary[1].trim().split(/\s+/).map(Number);
  return Object.fromEntries(names.map((e, i) => [e, values[i] ?? 0]));
}

/**
 * Callgrind's per-instruction costs (a run with --dump-instr=yes) summed per code object of a perf
 * map (V8's --perf-basic-prof: one `start size name` line per code object, hexadecimal): the
 * JavaScript functions (`JS:*name` is optimised code) and V8's builtins; costs outside every
 * object go to "(native)". The line after a `calls=` line is the call's inclusive cost, already
 * counted where the callee's instructions ran, so it is skipped.
 */
export function costsByCodeObject(callgrindText, perfMapText) {
  const objects = perfMapText
    .split('\n')
    .filter(Boolean)
    .map((line) => {
      const [start, size, ...name] = line.split(' ');
      const from = parseInt(start, 16);
      return { from, to: from + parseInt(size, 16), name: name.join(' ') };
    })
    .sort((a, b) => a.from - b.from);
  const nameAt = (address) => {
    let lo = 0;
    let hi = objects.length - 1;
    while (lo <= hi) {
      const mid = (lo + hi) >> 1;
      if (objects[mid].from <= address) lo = mid + 1;
      else hi = mid - 1;
    }
    const o = objects[hi];
    return o !== undefined && address < o.to ? o.name : '(native)';
  };
  const number = (s) => (s.startsWith('0x') ? parseInt(s, 16) : Number(s));
  let positions = 1;
  let events = [];
  let address = 0;
  let callCost = false;
  const costs = new Map();
  for (const line of callgrindText.split('\n')) {
    if (line.startsWith('positions:')) positions = line.trim().split(/\s+/).length - 1;
    else if (line.startsWith('events:')) events = line.trim().split(/\s+/).slice(1);
    else if (line.startsWith('calls=')) callCost = true;
    else if (/^[0-9+\-*]/.test(line)) {
      const parts = line.trim().split(/\s+/);
      const p = parts[0];
      if (p.startsWith('+')) address += number(p.slice(1));
      else if (p.startsWith('-')) address -= number(p.slice(1));
      else if (p !== '*') address = number(p);
      if (callCost) {
        callCost = false;
        continue;
      }
      const name = nameAt(address);
      let sum = costs.get(name);
      if (sum === undefined) costs.set(name, (sum = new Array(events.length).fill(0)));
      for (let k = positions; k < parts.length; k++) sum[k - positions] += Number(parts[k]);
    }
  }
  return { events, costs };
}
