// Types for bench/accuracy/methods.mjs.
import type { b2World } from '../../src/dynamics/b2World';
import type { AccuracyMethod } from './run.mjs';

export const METHODS: AccuracyMethod[];
export const REFERENCE: AccuracyMethod;
export const DEFAULT_METHOD: AccuracyMethod;
export function methodById(id: string): AccuracyMethod;
/** `world`: a b2World of any build of the engine. */
export function applyMethod(world: b2World, method: AccuracyMethod): void;
export function stepFrame(world: b2World, method: AccuracyMethod): void;
