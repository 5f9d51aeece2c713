/*
 * C's float functions as the Testbed's tests call them. In the float64 reference build of Box2D
 * (float32 = double) the engine's trigonometry is fdlibm in double, but a test calling cosf or
 * sinf still calls the C float function: its argument is rounded to float and so is its result.
 * These compute the function in double with fdlibm (b2Cos/b2Sin, the same bits on every
 * JavaScript engine) and round as the float call does. Arrays the tests declare `float` rather
 * than `float32` hold float values: `float32Of` rounds a literal as they store it.
 */

import { b2Cos, b2Sin } from '../../src/index';

const fround = Math.fround;

/** C's cosf(x): float argument, float result. */
export function cosf(x: number): number {
  return fround(b2Cos(fround(x)));
}

/** C's sinf(x): float argument, float result. */
export function sinf(x: number): number {
  return fround(b2Sin(fround(x)));
}

/** A value as a C `float` variable stores it (`float friction[5] = {0.35f, ...}`). */
export function floatOf(x: number): number {
  return fround(x);
}
