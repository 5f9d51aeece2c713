// Where a method fails: the limit of a pass/fail test found by bisection (docs/ACCURACY.md,
// "Stability limits"). The test must be monotone over the range: passing up to the limit and
// failing beyond it (or, with `smallest`, failing below it and passing from it on).

/**
 * The limit of `passes` (a function of a number that resolves to true or false) in [lo, hi]:
 * the largest value that passes, or with { smallest: true } the smallest. With { integer: true }
 * the values are integers and the limit is exact; otherwise the bracket is narrowed to
 * `tolerance` (default 1e-3 of the range). Returns { limit, tests, bracket, outside }:
 * `bracket` holds the last passing and the first failing value tested, `outside` says the limit
 * is not inside the range ('below': not even the safe end passes; 'above': the far end passes too),
 * and then `limit` is null or the far end.
 */
export async function bisectLimit(passes, lo, hi, options = {}) {
  if (!(Number.isFinite(lo) && Number.isFinite(hi) && lo < hi)) throw new RangeError(`bisectLimit: lo (${lo}) must be finite and below hi (${hi})`);
  const integer = options.integer === true;
  const smallest = options.smallest === true;
  const tolerance = options.tolerance ?? (integer ? 1 : 1e-3 * (hi - lo));
  if (!(tolerance > 0)) throw new RangeError(`bisectLimit: tolerance (${tolerance}) must be positive`);
  // `good` passes and `bad` fails; the limit lies between them.
  let good = smallest ? hi : lo;
  let bad = smallest ? lo : hi;
  let tests = 0;
  const test = async (x) => {
    tests++;
    return (await passes(x)) === true;
  };
  if (!(await test(good))) return { limit: null, tests, bracket: null, outside: 'below' };
  if (await test(bad)) return { limit: bad, tests, bracket: null, outside: 'above' };
  while (Math.abs(bad - good) > tolerance) {
    let mid = 0.5 * (good + bad);
    if (integer) {
      mid = Math.floor(mid);
      if (mid === good || mid === bad) break;
    }
    if (await test(mid)) good = mid;
    else bad = mid;
  }
  return { limit: good, tests, bracket: [good, bad], outside: null };
}
