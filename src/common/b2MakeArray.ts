/*
 * Not in the C++: the fixed-size arrays of its structs (a manifold's points, a polygon's vertices,
 * a fixture's proxies) as JavaScript arrays of preallocated objects.
 */

/**
 * `count` objects from `make` (given each one's index), in an array whose backing store holds
 * exactly `count`: one grown by push keeps room for 17 (V8's first growth), which every manifold
 * and shape would carry (docs/PORTING.md: fixed-size arrays).
 */
export function b2MakeArray<T>(count: number, make: (index: number) => T): T[] {
  return Array.from({ length: count }, (_, index) => make(index));
}
