/*
 * The subset of C's printf that the Testbed's DrawString calls use: %d, %f, %g, %s and %%, with
 * a width and a precision (`%5.2f`, `%4.0f`, `%3.1f`, `%g`). Numbers print as glibc prints them.
 */

/** C's `%.<precision>g`: shortest of %e and %f with `precision` significant digits, no trailing zeros. */
function formatG(x: number, precision: number): string {
  if (!Number.isFinite(x)) return Number.isNaN(x) ? 'nan' : x > 0 ? 'inf' : '-inf';
  const p = precision === 0 ? 1 : precision;
  if (x === 0) return Object.is(x, -0) ? '-0' : '0';
  const exp = Math.floor(Math.log10(Math.abs(Number(x.toPrecision(p)))));
  let s: string;
  if (exp < -4 || exp >= p) {
    s = x.toExponential(p - 1);
    let [mantissa, e] = s.split('e');
    if (mantissa.includes('.')) mantissa = mantissa.replace(/0+$/, '').replace(/\.$/, '');
    const sign = e[0] === '-' ? '-' : '+';
    const digits = e.replace(/^[+-]/, '').padStart(2, '0');
    return `${mantissa}e${sign}${digits}`;
  }
  s = x.toFixed(Math.max(0, p - 1 - exp));
  if (s.includes('.')) s = s.replace(/0+$/, '').replace(/\.$/, '');
  return s;
}

/** Format like C's sprintf for the conversions above. */
export function sprintf(format: string, ...args: unknown[]): string {
  let next = 0;
  return format.replace(/%(-?)(\d*)(?:\.(\d+))?([dfgsi%])/g, (_match, left: string, width: string, precision: string | undefined, conv: string) => {
    if (conv === '%') return '%';
    const arg = args[next++];
    let s: string;
    switch (conv) {
      case 'd':
      case 'i':
        s = String(Math.trunc(Number(arg)));
        break;
      case 'f':
        s = Number(arg).toFixed(precision === undefined ? 6 : Number(precision));
        break;
      case 'g':
        s = formatG(Number(arg), precision === undefined ? 6 : Number(precision));
        break;
      default:
        s = String(arg);
    }
    const w = width === '' ? 0 : Number(width);
    return left === '-' ? s.padEnd(w) : s.padStart(w);
  });
}
