// Types for bench/accuracy/report.mjs.
import type { AccuracyResult, AccuracyRun, AccuracyScene } from './run.mjs';

export const MEASURE_UNITS: Record<string, string>;
export const LOG_FLOOR: number;
export const COLOURS: { front: string; js: string; webgpu: string; peer: string };
export function pointColour(result: Pick<AccuracyResult, 'backend'>, onFront: boolean): string;
export function formatNumber(v: number | undefined): string;
export function decades(lo: number, hi: number): [number, number];
export function labelOf(run: AccuracyRun, result: AccuracyResult): string;
export function paretoFront(results: AccuracyResult[], measure: string): AccuracyResult[];
export function paretoSvg(scene: AccuracyScene, measure: string, run: AccuracyRun): string;
export function accuracyMarkdown(run: AccuracyRun): string;
