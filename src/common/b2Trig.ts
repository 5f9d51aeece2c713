/*
 * Deterministic sine, cosine and arctangent.
 *
 * Box2D calls sinf/cosf in b2Rot::Set and atan2 in b2Rot::GetAngle and b2Rope. The reference
 * trajectories were produced with fdlibm 5.3's algorithms (the ones V8 uses for Math.sin,
 * Math.cos and Math.atan2 in Node 20), and JavaScript engines are free to round those built-ins
 * differently in the last bit. Computing them here, with fdlibm's argument reduction, kernels and
 * constants, gives the same bits on every engine.
 *
 * Algorithms: fdlibm 5.3 (Sun Microsystems, 1993): s_sin.c, s_cos.c, k_sin.c, k_cos.c,
 * e_rem_pio2.c, k_rem_pio2.c, s_atan.c, e_atan2.c. The word-level tests (high/low 32 bits of the
 * IEEE-754 double) are kept, because they decide the branches exactly as fdlibm does.
 */

const f64 = new Float64Array(1);
const i32 = new Int32Array(f64.buffer);
// Index of the high word: 1 on little-endian hosts (all mainstream ones), 0 on big-endian.
const HI = new Uint8Array(new Uint16Array([1]).buffer)[0] === 1 ? 1 : 0;
const LO = 1 - HI;

function highWord(x: number): number {
  f64[0] = x;
  return i32[HI];
}

function lowWord(x: number): number {
  f64[0] = x;
  return i32[LO];
}

function fromWords(hi: number, lo: number): number {
  i32[HI] = hi;
  i32[LO] = lo;
  return f64[0];
}

/** x * 2^n, exact for the exponents used here (results stay normal). */
function scalbn(x: number, n: number): number {
  return x * Math.pow(2, n);
}

// Table of 2/pi in 24-bit chunks (396 hex digits).
const two_over_pi = [
  0xa2f983, 0x6e4e44, 0x1529fc, 0x2757d1, 0xf534dd, 0xc0db62, 0x95993c, 0x439041, 0xfe5163, 0xabdebb, 0xc561b7, 0x246e3a, 0x424dd2, 0xe00649, 0x2eea09,
  0xd1921c, 0xfe1deb, 0x1cb129, 0xa73ee8, 0x8235f5, 0x2ebb44, 0x84e99c, 0x7026b4, 0x5f7e41, 0x3991d6, 0x398353, 0x39f49c, 0x845f8b, 0xbdf928, 0x3b1ff8,
  0x97ffde, 0x05980f, 0xef2f11, 0x8b5a0a, 0x6d1f6d, 0x367ecf, 0x27cb09, 0xb74f46, 0x3f669e, 0x5fea2d, 0x7527ba, 0xc7ebe5, 0xf17b3d, 0x0739f7, 0x8a5292,
  0xea6bfb, 0x5fb11f, 0x8d5d08, 0x560330, 0x46fc7b, 0x6babf0, 0xcfbc20, 0x9af436, 0x1da9e3, 0x91615e, 0xe61b08, 0x659985, 0x5f14a0, 0x68408d, 0xffd880,
  0x4d7327, 0x310606, 0x1556ca, 0x73a8c9, 0x60e27b, 0xc08c6b,
];

// High words of n*pi/2 for n = 1..32, to detect cancellation in the medium-range reduction.
const npio2_hw = [
  0x3ff921fb, 0x400921fb, 0x4012d97c, 0x401921fb, 0x401f6a7a, 0x4022d97c, 0x4025fdbb, 0x402921fb, 0x402c463a, 0x402f6a7a, 0x4031475c, 0x4032d97c, 0x40346b9c,
  0x4035fdbb, 0x40378fdb, 0x403921fb, 0x403ab41b, 0x403c463a, 0x403dd85a, 0x403f6a7a, 0x40407e4c, 0x4041475c, 0x4042106c, 0x4042d97c, 0x4043a28c, 0x40446b9c,
  0x404534ac, 0x4045fdbb, 0x4046c6cb, 0x40478fdb, 0x404858eb, 0x404921fb,
];

const PIo2 = [
  1.57079625129699707031, 7.54978941586159635335e-8, 5.39030252995776476554e-15, 3.28200341580791294123e-22, 1.27065575308067607349e-29,
  1.22933308981111328932e-36, 2.73370053816464559624e-44, 2.16741683877804819444e-51,
];

const two24 = 1.6777216e7;
const twon24 = 5.9604644775390625e-8;
const invpio2 = 6.36619772367581382433e-1;
const pio2_1 = 1.57079632673412561417;
const pio2_1t = 6.07710050650619224932e-11;
const pio2_2 = 6.0771005063039659766e-11;
const pio2_2t = 2.02226624879595063154e-21;
const pio2_3 = 2.0222662487111664558e-21;
const pio2_3t = 8.47842766036889956997e-32;

// Scratch for the reduction; the functions below are not re-entrant and never need to be.
// remPio2 takes its argument in remX[0] and leaves y0, y1 in remY: doubles passed to or returned
// from a call V8 does not inline are boxed (a heap allocation each), typed array slots are not.
const remX = new Float64Array(1);
const remY = new Float64Array(2);
const krTx = new Float64Array(3);
const krIq = new Int32Array(20);
const krF = new Float64Array(20);
const krFq = new Float64Array(20);
const krQ = new Float64Array(20);

/**
 * __kernel_rem_pio2 for double precision input (prec = 2, jk = 4): reduces x (given as nx
 * 24-bit pieces scaled by 2^e0) modulo pi/2 into y[0] + y[1]; returns the quadrant (n & 7).
 */
function kernelRemPio2(x: Float64Array, y: Float64Array, e0: number, nx: number): number {
  const jk = 4;
  const jp = jk;
  const iq = krIq;
  const f = krF;
  const fq = krFq;
  const q = krQ;
  let z: number;
  let fw: number;
  let i: number;
  let j: number;
  let k: number;

  const jx = nx - 1;
  let jv = ((e0 - 3) / 24) | 0;
  if (jv < 0) jv = 0;
  let q0 = e0 - 24 * (jv + 1);

  j = jv - jx;
  const m = jx + jk;
  for (i = 0; i <= m; i++, j++) {
    f[i] = j < 0 ? 0.0 : two_over_pi[j];
  }

  for (i = 0; i <= jk; i++) {
    for (j = 0, fw = 0.0; j <= jx; j++) fw += x[j] * f[jx + i - j];
    q[i] = fw;
  }

  let jz = jk;
  let n: number;
  let ih: number;
  let carry: number;
  for (;;) {
    // Distill q[] into iq[] in reverse.
    for (i = 0, j = jz, z = q[jz]; j > 0; i++, j--) {
      fw = (twon24 * z) | 0;
      iq[i] = (z - two24 * fw) | 0;
      z = q[j - 1] + fw;
    }

    z = scalbn(z, q0);
    z -= 8.0 * Math.floor(z * 0.125);
    n = z | 0;
    z -= n;
    ih = 0;
    if (q0 > 0) {
      i = iq[jz - 1] >> (24 - q0);
      n += i;
      iq[jz - 1] -= i << (24 - q0);
      ih = iq[jz - 1] >> (23 - q0);
    } else if (q0 === 0) {
      ih = iq[jz - 1] >> 23;
    } else if (z >= 0.5) {
      ih = 2;
    }

    if (ih > 0) {
      n += 1;
      carry = 0;
      for (i = 0; i < jz; i++) {
        j = iq[i];
        if (carry === 0) {
          if (j !== 0) {
            carry = 1;
            iq[i] = 0x1000000 - j;
          }
        } else {
          iq[i] = 0xffffff - j;
        }
      }
      if (q0 > 0) {
        if (q0 === 1) iq[jz - 1] &= 0x7fffff;
        else if (q0 === 2) iq[jz - 1] &= 0x3fffff;
      }
      if (ih === 2) {
        z = 1.0 - z;
        if (carry !== 0) z -= scalbn(1.0, q0);
      }
    }

    if (z === 0.0) {
      j = 0;
      for (i = jz - 1; i >= jk; i--) j |= iq[i];
      if (j === 0) {
        // Recompute with more terms of 2/pi.
        for (k = 1; jk >= k && iq[jk - k] === 0; k++) {
          /* k = number of terms needed */
        }
        for (i = jz + 1; i <= jz + k; i++) {
          f[jx + i] = two_over_pi[jv + i];
          for (j = 0, fw = 0.0; j <= jx; j++) fw += x[j] * f[jx + i - j];
          q[i] = fw;
        }
        jz += k;
        continue;
      }
    }
    break;
  }

  if (z === 0.0) {
    jz -= 1;
    q0 -= 24;
    while (iq[jz] === 0) {
      jz--;
      q0 -= 24;
    }
  } else {
    z = scalbn(z, -q0);
    if (z >= two24) {
      fw = (twon24 * z) | 0;
      iq[jz] = (z - two24 * fw) | 0;
      jz += 1;
      q0 += 24;
      iq[jz] = fw;
    } else {
      iq[jz] = z | 0;
    }
  }

  fw = scalbn(1.0, q0);
  for (i = jz; i >= 0; i--) {
    q[i] = fw * iq[i];
    fw *= twon24;
  }

  for (i = jz; i >= 0; i--) {
    for (fw = 0.0, k = 0; k <= jp && k <= jz - i; k++) fw += PIo2[k] * q[i + k];
    fq[jz - i] = fw;
  }

  fw = 0.0;
  for (i = jz; i >= 0; i--) fw += fq[i];
  y[0] = ih === 0 ? fw : -fw;
  fw = fq[0] - fw;
  for (i = 1; i <= jz; i++) fw += fq[i];
  y[1] = ih === 0 ? fw : -fw;
  return n & 7;
}

/** __ieee754_rem_pio2: x (in remX[0]) - n*pi/2 in y[0] + y[1], returns n. */
function remPio2(y: Float64Array): number {
  const x = remX[0];
  const hx = highWord(x);
  const ix = hx & 0x7fffffff;
  let z: number;
  if (ix <= 0x3fe921fb) {
    y[0] = x;
    y[1] = 0;
    return 0;
  }
  if (ix < 0x4002d97c) {
    // |x| < 3pi/4: n = +-1.
    if (hx > 0) {
      z = x - pio2_1;
      if (ix !== 0x3ff921fb) {
        y[0] = z - pio2_1t;
        y[1] = z - y[0] - pio2_1t;
      } else {
        z -= pio2_2;
        y[0] = z - pio2_2t;
        y[1] = z - y[0] - pio2_2t;
      }
      return 1;
    }
    z = x + pio2_1;
    if (ix !== 0x3ff921fb) {
      y[0] = z + pio2_1t;
      y[1] = z - y[0] + pio2_1t;
    } else {
      z += pio2_2;
      y[0] = z + pio2_2t;
      y[1] = z - y[0] + pio2_2t;
    }
    return -1;
  }
  if (ix <= 0x413921fb) {
    // |x| <= 2^19 * pi/2: medium size.
    let t = Math.abs(x);
    const n = (t * invpio2 + 0.5) | 0;
    const fn = n;
    let r = t - fn * pio2_1;
    let w = fn * pio2_1t;
    if (n < 32 && ix !== npio2_hw[n - 1]) {
      y[0] = r - w;
    } else {
      const j = ix >> 20;
      y[0] = r - w;
      // highWord(y[0]) written out here and below: this branch (angles past 32 * pi/2, as in a
      // spinning body) may first run after V8 compiled remPio2, and a call it has not seen run
      // is not inlined, so the double argument would be boxed on every call.
      f64[0] = y[0];
      let i = j - ((i32[HI] >> 20) & 0x7ff);
      if (i > 16) {
        t = r;
        w = fn * pio2_2;
        r = t - w;
        w = fn * pio2_2t - (t - r - w);
        y[0] = r - w;
        f64[0] = y[0];
        i = j - ((i32[HI] >> 20) & 0x7ff);
        if (i > 49) {
          t = r;
          w = fn * pio2_3;
          r = t - w;
          w = fn * pio2_3t - (t - r - w);
          y[0] = r - w;
        }
      }
    }
    y[1] = r - y[0] - w;
    if (hx < 0) {
      y[0] = -y[0];
      y[1] = -y[1];
      return -n;
    }
    return n;
  }
  if (ix >= 0x7ff00000) {
    y[0] = y[1] = x - x;
    return 0;
  }
  // Large arguments: z = scalbn(|x|, ilogb(x) - 23), split into 24-bit pieces.
  const e0 = (ix >> 20) - 1046;
  z = fromWords(ix - (e0 << 20), lowWord(x));
  const tx = krTx;
  for (let i = 0; i < 2; i++) {
    tx[i] = z | 0;
    z = (z - tx[i]) * two24;
  }
  tx[2] = z;
  let nx = 3;
  while (tx[nx - 1] === 0.0) nx--;
  const n = kernelRemPio2(tx, y, e0, nx);
  if (hx < 0) {
    y[0] = -y[0];
    y[1] = -y[1];
    return -n;
  }
  return n;
}

/** The angle b2SinCos reads (see there). */
export const b2SinCosArg = new Float64Array(1);

/**
 * sin and cos of b2SinCosArg[0] into rot.s and rot.c, bit for bit fdlibm's sin and cos (s_sin.c,
 * s_cos.c) sharing one argument reduction, with __kernel_sin and __kernel_cos written out. It is
 * the hot path of b2Rot.Set (once per body or constraint and iteration), so it allocates nothing
 * (the angle comes in through a typed array slot, the results go straight into the fields), and
 * the kernels' coefficients are local constants, which V8 folds into the code: a module's `const`
 * (a `var` in the bundle) costs a load and an unboxing at each use, and there are twelve a call.
 *
 * fdlibm's range tests read the high word of |x|; for a finite or infinite x each is the same as
 * comparing |x| with the double whose high word is the bound and low word zero:
 *   ix <= 0x3fe921fb  <=>  |x| < 0.7853984832763672 (0x3fe921fc 00000000)
 *   ix >= 0x7ff00000  <=>  !(|x| < Infinity), which NaN also meets
 *   ix <  0x3e400000  <=>  |x| < 2^-27
 *   ix <  0x3fd33333  <=>  |x| < 0.2999999523162842 (0x3fd33333 00000000)
 *   ix >  0x3fe90000  <=>  |x| >= 0.7812504768371582 (0x3fe90001 00000000)
 * so only the reduction and __kernel_cos's qx (|x| / 4 with the low word cleared) touch the words.
 */
export function b2SinCos(rot: { s: number; c: number }): void {
  // __kernel_sin
  const S1 = -1.66666666666666324348e-1;
  const S2 = 8.33333333332248946124e-3;
  const S3 = -1.98412698298579493134e-4;
  const S4 = 2.75573137070700676789e-6;
  const S5 = -2.50507602534068634195e-8;
  const S6 = 1.58969099521155010221e-10;
  // __kernel_cos
  const C1 = 4.16666666666666019037e-2;
  const C2 = -1.38888888888741095749e-3;
  const C3 = 2.48015872894767294178e-5;
  const C4 = -2.75573143513906633035e-7;
  const C5 = 2.0875723212981748279e-9;
  const C6 = -1.13596475577881948265e-11;

  const x = b2SinCosArg[0];
  const ax = Math.abs(x);
  let y0: number;
  let y1: number;
  let n: number;
  let iy: number;
  if (ax < 0.7853984832763672) {
    // |x| <= pi/4: sin is __kernel_sin(x, 0.0, 0), cos is __kernel_cos(x, 0.0).
    y0 = x;
    y1 = 0.0;
    n = 0;
    iy = 0;
  } else if (!(ax < Infinity)) {
    rot.s = x - x;
    rot.c = x - x;
    return;
  } else {
    remX[0] = x;
    n = remPio2(remY);
    y0 = remY[0];
    y1 = remY[1];
    iy = 1;
  }

  const ay = Math.abs(y0);
  let ks: number;
  let kc: number;
  if (ay < 7.450580596923828e-9 && (y0 | 0) === 0) {
    // The kernels' tiny-argument exits.
    ks = y0;
    kc = 1.0;
  } else {
    const z = y0 * y0;

    // __kernel_sin(y0, y1, iy)
    const v = z * y0;
    const rs = S2 + z * (S3 + z * (S4 + z * (S5 + z * S6)));
    if (iy === 0) {
      ks = y0 + v * (S1 + z * rs);
    } else {
      ks = y0 - (z * (0.5 * y1 - v * rs) - y1 - v * S1);
    }

    // __kernel_cos(y0, y1)
    const rc = z * (C1 + z * (C2 + z * (C3 + z * (C4 + z * (C5 + z * C6)))));
    if (ay < 0.2999999523162842) {
      kc = 1.0 - (0.5 * z - (z * rc - y0 * y1));
    } else {
      // qx = |y0|/4 with the low word cleared, or 0.28125 past 0.78125: keeps 1 - qx exact.
      let qx: number;
      if (ay >= 0.7812504768371582) {
        qx = 0.28125;
      } else {
        // fromWords(highWord(|y0|) - 0x00200000, 0), written out: a call V8 does not inline
        // would box its double argument and result.
        f64[0] = y0;
        i32[HI] = (i32[HI] & 0x7fffffff) - 0x00200000;
        i32[LO] = 0;
        qx = f64[0];
      }
      const iz = 0.5 * z - qx;
      const a = 1.0 - qx;
      kc = a - (iz - (z * rc - y0 * y1));
    }
  }

  switch (n & 3) {
    case 0:
      rot.s = ks;
      rot.c = kc;
      break;
    case 1:
      rot.s = kc;
      rot.c = -ks;
      break;
    case 2:
      rot.s = -ks;
      rot.c = -kc;
      break;
    default:
      rot.s = -kc;
      rot.c = ks;
      break;
  }
}

const atanhi = [4.63647609000806093515e-1, 7.85398163397448278999e-1, 9.82793723247329054082e-1, 1.570796326794896558];
const atanlo = [2.26987774529616870924e-17, 3.06161699786838301793e-17, 1.39033110312309984516e-17, 6.12323399573676603587e-17];
const aT0 = 3.33333333333329318027e-1;
const aT1 = -1.99999999998764832476e-1;
const aT2 = 1.42857142725034663711e-1;
const aT3 = -1.1111110405462355788e-1;
const aT4 = 9.09088713343650656196e-2;
const aT5 = -7.69187620504482999495e-2;
const aT6 = 6.66107313738753120669e-2;
const aT7 = -5.83357013379057348645e-2;
const aT8 = 4.97687799461593236017e-2;
const aT9 = -3.6531572744216915527e-2;
const aT10 = 1.62858201153657823623e-2;

/** atan(x) (fdlibm s_atan.c). */
function atan(x: number): number {
  const hx = highWord(x);
  const ix = hx & 0x7fffffff;
  let id: number;
  if (ix >= 0x44100000) {
    // |x| >= 2^66
    if (ix > 0x7ff00000 || (ix === 0x7ff00000 && lowWord(x) !== 0)) return x + x;
    return hx > 0 ? atanhi[3] + atanlo[3] : -atanhi[3] - atanlo[3];
  }
  if (ix < 0x3fdc0000) {
    // |x| < 0.4375; tiny values return x itself.
    if (ix < 0x3e400000) return x;
    id = -1;
  } else {
    x = Math.abs(x);
    if (ix < 0x3ff30000) {
      if (ix < 0x3fe60000) {
        id = 0;
        x = (2.0 * x - 1.0) / (2.0 + x);
      } else {
        id = 1;
        x = (x - 1.0) / (x + 1.0);
      }
    } else if (ix < 0x40038000) {
      id = 2;
      x = (x - 1.5) / (1.0 + 1.5 * x);
    } else {
      id = 3;
      x = -1.0 / x;
    }
  }
  const z = x * x;
  const w = z * z;
  const s1 = z * (aT0 + w * (aT2 + w * (aT4 + w * (aT6 + w * (aT8 + w * aT10)))));
  const s2 = w * (aT1 + w * (aT3 + w * (aT5 + w * (aT7 + w * aT9))));
  if (id < 0) return x - x * (s1 + s2);
  const r = atanhi[id] - (x * (s1 + s2) - atanlo[id] - x);
  return hx < 0 ? -r : r;
}

const tiny = 1.0e-300;
const pi_o_4 = 7.85398163397448279e-1;
const pi_o_2 = 1.570796326794896558;
const pi = 3.141592653589793116;
const pi_lo = 1.2246467991473531772e-16;

/** atan2(y, x), bit-identical to fdlibm 5.3 on every JavaScript engine. */
export function b2Atan2(y: number, x: number): number {
  f64[0] = x;
  const hx = i32[HI];
  const lx = i32[LO];
  const ix = hx & 0x7fffffff;
  f64[0] = y;
  const hy = i32[HI];
  const ly = i32[LO];
  const iy = hy & 0x7fffffff;
  if (x !== x || y !== y) return x + y;
  if (((hx - 0x3ff00000) | lx) === 0) return atan(y);
  let m = ((hy >> 31) & 1) | ((hx >> 30) & 2);

  if ((iy | ly) === 0) {
    switch (m) {
      case 0:
      case 1:
        return y;
      case 2:
        return pi + tiny;
      default:
        return -pi - tiny;
    }
  }
  if ((ix | lx) === 0) return hy < 0 ? -pi_o_2 - tiny : pi_o_2 + tiny;

  if (ix === 0x7ff00000) {
    if (iy === 0x7ff00000) {
      switch (m) {
        case 0:
          return pi_o_4 + tiny;
        case 1:
          return -pi_o_4 - tiny;
        case 2:
          return 3.0 * pi_o_4 + tiny;
        default:
          return -3.0 * pi_o_4 - tiny;
      }
    }
    switch (m) {
      case 0:
        return 0.0;
      case 1:
        return -0.0;
      case 2:
        return pi + tiny;
      default:
        return -pi - tiny;
    }
  }
  if (iy === 0x7ff00000) return hy < 0 ? -pi_o_2 - tiny : pi_o_2 + tiny;

  const k = (iy - ix) >> 20;
  let z: number;
  if (k > 60) {
    z = pi_o_2 + 0.5 * pi_lo;
    m &= 1;
  } else if (hx < 0 && k < -60) {
    z = 0.0;
  } else {
    z = atan(Math.abs(y / x));
  }
  switch (m) {
    case 0:
      return z;
    case 1:
      return -z;
    case 2:
      return pi - (z - pi_lo);
    default:
      return z - pi_lo - pi;
  }
}
