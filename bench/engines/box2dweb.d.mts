// Types for bench/engines/box2dweb.mjs.
/** Box2DWeb 2.1a from the box2dweb npm package, loaded as described in box2dweb.mjs. */
export function loadBox2DWeb(): any;
declare const adapter: { id: string; name: string; version: string | null };
export default adapter;
