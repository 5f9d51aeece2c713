/*
 * Helpers for the Box2DWeb 2.1a compatibility layer. The layer adds members to the engine's own
 * prototypes and constructors once, when this package loads, so objects the engine returns
 * (`body.GetPosition().Copy()`) carry them at no per-instance cost. Their types come from
 * declaration merging in the files that install them. The engine never imports this folder.
 */

/**
 * Add methods to a prototype as class methods are (non-enumerable). A name the engine already
 * defines is left alone: the engine's own method wins, and the compat tests notice if its
 * behaviour differs from 2.1a's.
 */
export function defineMethods<T extends object>(proto: T, methods: Partial<T> & ThisType<T>): void {
  for (const name of Object.keys(methods)) {
    if (name in proto) continue;
    Object.defineProperty(proto, name, {
      value: (methods as Record<string, unknown>)[name],
      writable: true,
      configurable: true,
      enumerable: false,
    });
  }
}

/** Replace an engine method by a wrapper that handles a 2.1a calling form and otherwise calls it. */
export function wrapMethod<T extends object, K extends keyof T>(proto: T, name: K, wrap: (original: T[K]) => T[K]): void {
  const original = proto[name];
  if (typeof original !== 'function') {
    throw new Error(`webphysics compat: ${String(name)} is not a method to wrap`);
  }
  Object.defineProperty(proto, name, {
    value: wrap(original),
    writable: true,
    configurable: true,
    enumerable: false,
  });
}

/** A 2.1a field name read and written through its 2.2.1 equivalent. */
export function defineAccessor<T extends object>(proto: T, name: string, get: (this: T) => unknown, set?: (this: T, value: any) => void): void {
  Object.defineProperty(proto, name, { get, set, configurable: true, enumerable: false });
}

/** Static constants (2.1a's `b2Body.b2_dynamicBody`, `b2Shape.e_circleShape`...). */
export function defineStatics(target: object, values: Record<string, unknown>): void {
  for (const name of Object.keys(values)) {
    if (name in target) continue;
    Object.defineProperty(target, name, { value: values[name], writable: false, configurable: true, enumerable: true });
  }
}

/** The error for a 2.1a call that Box2D 2.2 has no equivalent for: what was called, what to use. */
export function removedError(call: string, instead: string): Error {
  return new Error(`${call} is not available: Box2D 2.2 removed it. ${instead}`);
}

/** A method that throws removedError. */
export function removedMethod(call: string, instead: string): (...args: unknown[]) => never {
  return () => {
    throw removedError(call, instead);
  };
}

/** A static or instance property whose every read and write throws removedError. */
export function defineRemovedProperty(target: object, name: string, call: string, instead: string): void {
  Object.defineProperty(target, name, {
    get() {
      throw removedError(call, instead);
    },
    set() {
      throw removedError(call, instead);
    },
    configurable: true,
    enumerable: false,
  });
}

/** A class (2.1a's controllers, b2EdgeChainDef) whose constructor throws removedError. */
export function removedClass(name: string, instead: string): new (...args: unknown[]) => never {
  const cls = class {
    constructor() {
      throw removedError(`new ${name}()`, instead);
    }
  };
  Object.defineProperty(cls, 'name', { value: name });
  return cls as unknown as new (...args: unknown[]) => never;
}

/**
 * An engine class whose constructor also accepts 2.1a's arguments (`new b2World(gravity, doSleep)`,
 * `new b2CircleShape(radius)`). The returned constructor shares the class's prototype and inherits
 * its statics, so `instanceof`, statics, prototypes and subclassing are the engine class's own:
 * objects the engine creates itself are instances of it.
 *
 * A plain function rather than a Proxy: a Proxy's construct trap hands the proxy to the class as
 * new.target, and V8 then builds every object with a map of its own (no shared hidden class), so
 * everything that touched those objects went megamorphic and `new` was 100 times slower. Here a
 * direct `new` constructs the engine class itself (its usual map), and a subclass's super() call
 * constructs with the subclass as new.target, as `class X extends b2World` expects.
 */
export function acceptingArguments<C extends abstract new (...args: any) => any>(
  cls: C,
  construct: (args: readonly unknown[], make: (...engineArgs: unknown[]) => InstanceType<C>) => InstanceType<C>,
): C {
  const engineClass = cls as unknown as new (...args: unknown[]) => InstanceType<C>;
  function compat(this: unknown, ...args: unknown[]): InstanceType<C> {
    const target = new.target;
    if (target === undefined) {
      throw new TypeError(`Class constructor ${cls.name} cannot be invoked without 'new'`);
    }
    if (target === compat) {
      return construct(args, (...engineArgs) => new engineClass(...engineArgs));
    }
    return construct(args, (...engineArgs) => Reflect.construct(engineClass, engineArgs, target) as InstanceType<C>);
  }
  compat.prototype = cls.prototype;
  Object.setPrototypeOf(compat, cls);
  Object.defineProperty(compat, 'name', { value: cls.name });
  return compat as unknown as C;
}
