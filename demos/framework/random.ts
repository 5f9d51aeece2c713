/*
 * The Testbed's RandomFloat (Test.h) on a reproducible generator: std::rand() as glibc implements
 * it (the additive feedback generator of random_r, TYPE_3: x[i] = x[i-3] + x[i-31] mod 2^32,
 * returning x >> 1), seeded by srand() as glibc seeds it. The testbed calls srand(1), the state of
 * a fresh process, whenever a test is (re)started, so every test starts with the random numbers it
 * gets as the first test of a freshly started Linux Testbed, and runs are reproducible.
 */

const RAND_DEG = 31;
const RAND_SEP = 3;
const RAND_LIMIT = 32767;

const s_state = new Int32Array(RAND_DEG);
let s_front = RAND_SEP;
let s_rear = 0;

/** glibc random_r: the next value in [0, 2^31). */
export function rand(): number {
  s_state[s_front] = (s_state[s_front] + s_state[s_rear]) | 0;
  const result = (s_state[s_front] >>> 0) >>> 1;
  if (++s_front >= RAND_DEG) {
    s_front = 0;
    ++s_rear;
  } else if (++s_rear >= RAND_DEG) {
    s_rear = 0;
  }
  return result;
}

/** glibc srandom_r. */
export function srand(seed: number): void {
  let word = seed >>> 0 === 0 ? 1 : seed | 0;
  s_state[0] = word;
  for (let i = 1; i < RAND_DEG; ++i) {
    // state[i] = (16807 * state[i - 1]) % 2147483647 without overflowing 31 bits.
    const hi = Math.trunc(word / 127773);
    const lo = word % 127773;
    word = 16807 * lo - 2836 * hi;
    if (word < 0) word += 2147483647;
    s_state[i] = word;
  }
  s_front = RAND_SEP;
  s_rear = 0;
  for (let i = 0; i < RAND_DEG * 10; ++i) rand();
}

srand(1);

/** Random number in range [-1, 1] (Test.h's RandomFloat()). */
export function RandomFloat(): number;
/** Random floating point number in range [lo, hi] (Test.h's RandomFloat(lo, hi)). */
export function RandomFloat(lo: number, hi: number): number;
export function RandomFloat(lo?: number, hi?: number): number {
  let r = rand() & RAND_LIMIT;
  r /= RAND_LIMIT;
  if (lo === undefined || hi === undefined) return 2.0 * r - 1.0;
  return (hi - lo) * r + lo;
}
