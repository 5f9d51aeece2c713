import { defineConfig } from 'vitest/config';

export default defineConfig({
  plugins: [
    {
      // WGSL shaders (shaders/*.wgsl) are imported as text, as esbuild's text loader does in the builds.
      name: 'wgsl-text',
      transform(code, id) {
        if (id.endsWith('.wgsl')) return { code: `export default ${JSON.stringify(code)};`, map: null };
        return undefined;
      },
    },
  ],
  test: {
    include: ['test/**/*.test.ts'],
    testTimeout: 120_000,
    // `vitest run --coverage` (npm test) reports line coverage of the engine and its layers (src/)
    // and of the WebGPU backend (src-gpu/, whose tests run on Dawn and SwiftShader in Node).
    coverage: {
      provider: 'v8',
      include: ['src/**/*.ts', 'src-gpu/**/*.ts'],
      // The per-file table lists only files not fully covered.
      reporter: ['text-summary', ['text', { skipFull: true }], 'json-summary'],
      reportsDirectory: 'coverage',
      // Per folder: src-gpu/ stands at 97.5 % of lines under test/gpu alone (SwiftShader; measured with
      // `npx vitest run --coverage test/gpu`), the rest of the suite adding to it.
      thresholds: { 'src/**/*.ts': { lines: 90 }, 'src-gpu/**/*.ts': { lines: 97 } },
    },
  },
});
