// npm run docs: the API reference, from the TSDoc comments of the package's two entries, into
// docs/api/ (git-ignored). scripts/typedoc/ holds the entries as TypeDoc reads them: `webphysics`
// (src/index.ts) and `webphysics/gpu` (src-gpu/index.ts). @internal declarations (the GPU
// backend's parts: GpuWorld, GpuPipeline...) and private members are left out. A warning fails the
// build (test/build/docs.test.ts).
import { OptionDefaults } from 'typedoc';

/** @type {Partial<import('typedoc').TypeDocOptions>} */
export default {
  name: 'webphysics',
  entryPoints: ['scripts/typedoc/webphysics.ts', 'scripts/typedoc/gpu.ts'],
  tsconfig: 'scripts/typedoc/tsconfig.json',
  out: 'docs/api',
  readme: 'none',
  excludeInternal: true,
  excludePrivate: true,
  treatWarningsAsErrors: true,
  // No "Defined in" links: the repository has no host to link to.
  disableSources: true,
  // Box2D's own comments say @warning, as its C++ headers do.
  blockTags: [...OptionDefaults.blockTags, '@warning'],
  // Types of public members that the package does not export: the engine's pair set behind
  // b2ContactManager.m_pairs, and the GPU backend's solver options and upload counts.
  intentionallyNotExported: ['b2ProxyPairSet', 'GpuSolverOptions', 'UploadStats'],
};
