/*
 * The classic-script bundle's entry (dist/box2d.js, box2d.min.js): the Box2D namespace, which the
 * bundle defines as the global `Box2D`, and the two globals Box2DWeb's script also defines and
 * 2.1a code uses: `Vector`, its name for Array (`new Vector()` for vertex lists), and
 * `Vector_a2j_Number(length)`, an array of that many zeros. A page's own globals of those names
 * are left alone. The ES entry defines no globals.
 */

export * from './Box2D';

const page = globalThis as { Vector?: unknown; Vector_a2j_Number?: unknown };
if (page.Vector === undefined) page.Vector = Array;
if (page.Vector_a2j_Number === undefined) {
  page.Vector_a2j_Number = (length = 0): number[] => new Array<number>(length).fill(0);
}
