// Types for bench/features.mjs.

export interface FeatureConfig {
  id: 'defaults' | 'no-continuous' | 'no-sleep';
  label: string;
  continuous: boolean;
  sleep: boolean;
}

export interface FeatureRow {
  scene: string;
  title: string;
  bodies: number;
  configs: { id: FeatureConfig['id']; ms: number; awake: number; bodies: number }[];
}

export interface FeaturesRun {
  date: string;
  quick: boolean;
  steps: number;
  settle: number;
  machine: { cpus: number; cpuModel: string; node: string };
  rows: FeatureRow[];
}

export const FEATURE_CONFIGS: FeatureConfig[];
export function measureFeatures(
  b2: unknown,
  options?: { scenes?: string[]; steps?: number; settle?: number; quick?: boolean; log?: (line: string) => void },
): Promise<FeaturesRun>;
export function featuresMarkdown(run: FeaturesRun): string;
