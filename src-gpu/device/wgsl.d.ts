/** WGSL sources, imported as text (esbuild's text loader; the vitest config's wgsl plugin). */
declare module '*.wgsl' {
  const source: string;
  export default source;
}
