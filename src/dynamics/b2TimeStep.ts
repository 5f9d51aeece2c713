/*
 * Time step and solver state types (b2TimeStep.h). The C++ copies these structs by value; here
 * every one has Assign and Clone, and code that keeps a copy fills a preallocated object.
 */

import { b2Vec2 } from '../common/b2Math';

/** Profiling data. Times are in milliseconds. */
export class b2Profile {
  step = 0.0;
  collide = 0.0;
  solve = 0.0;
  solveInit = 0.0;
  solveVelocity = 0.0;
  solvePosition = 0.0;
  broadphase = 0.0;
  solveTOI = 0.0;

  Clone(): b2Profile {
    return new b2Profile().Assign(this);
  }

  Assign(p: Readonly<b2Profile>): this {
    this.step = p.step;
    this.collide = p.collide;
    this.solve = p.solve;
    this.solveInit = p.solveInit;
    this.solveVelocity = p.solveVelocity;
    this.solvePosition = p.solvePosition;
    this.broadphase = p.broadphase;
    this.solveTOI = p.solveTOI;
    return this;
  }
}

/** This is an internal structure. */
export class b2TimeStep {
  /** time step */
  dt = 0.0;
  /** inverse time step (0 if dt == 0). */
  inv_dt = 0.0;
  /** dt * inv_dt0 */
  dtRatio = 0.0;
  velocityIterations = 0;
  positionIterations = 0;
  warmStarting = false;

  Clone(): b2TimeStep {
    return new b2TimeStep().Assign(this);
  }

  Assign(step: Readonly<b2TimeStep>): this {
    this.dt = step.dt;
    this.inv_dt = step.inv_dt;
    this.dtRatio = step.dtRatio;
    this.velocityIterations = step.velocityIterations;
    this.positionIterations = step.positionIterations;
    this.warmStarting = step.warmStarting;
    return this;
  }
}

/**
 * This is an internal structure. The solver keeps these as records in a Float64Array (see
 * b2SolverData); the class remains as the C++ declares it.
 */
export class b2Position {
  readonly c = new b2Vec2();
  a = 0.0;

  Clone(): b2Position {
    return new b2Position().Assign(this);
  }

  Assign(p: Readonly<b2Position>): this {
    this.c.Assign(p.c);
    this.a = p.a;
    return this;
  }
}

/**
 * This is an internal structure. The solver keeps these as records in a Float64Array (see
 * b2SolverData); the class remains as the C++ declares it.
 */
export class b2Velocity {
  readonly v = new b2Vec2();
  w = 0.0;

  Clone(): b2Velocity {
    return new b2Velocity().Assign(this);
  }

  Assign(v: Readonly<b2Velocity>): this {
    this.v.Assign(v.v);
    this.w = v.w;
    return this;
  }
}

/**
 * Solver Data. The C++'s `b2Position* positions` and `b2Velocity* velocities` are the island's
 * arrays of those structs; here each is a Float64Array of the same records, three doubles a body
 * (b2Position: c.x, c.y, a; b2Velocity: v.x, v.y, w), so body i's record starts at 3 * i. Typed
 * arrays keep the doubles unboxed and together, where b2Position objects would cost four heap
 * objects a body. They are shared by reference as the C++ pointers are; `step` is a copy.
 */
export class b2SolverData {
  readonly step = new b2TimeStep();
  positions = new Float64Array(0);
  velocities = new Float64Array(0);
  /**
   * Not in the C++: the island's joint solver records (b2RevoluteJoint's), the first
   * jointRecordCount doubles, one joint's after another in the order the island initialises them,
   * so the solver's passes read them in one sweep through memory instead of one small array per
   * joint. b2Island.Solve empties it before the joints' InitVelocityConstraints.
   */
  jointRecords = new Float64Array(0);
  jointRecordCount = 0;

  Clone(): b2SolverData {
    return new b2SolverData().Assign(this);
  }

  Assign(data: Readonly<b2SolverData>): this {
    this.step.Assign(data.step);
    this.positions = data.positions;
    this.velocities = data.velocities;
    this.jointRecords = data.jointRecords;
    this.jointRecordCount = data.jointRecordCount;
    return this;
  }

  /**
   * Not in the C++: the offset in jointRecords of `size` doubles for one joint. When they do not
   * fit, jointRecords becomes a larger array; the joints given the old one keep it, so every
   * record stays where its joint wrote it.
   */
  AllocateJointRecord(size: number): number {
    const offset = this.jointRecordCount;
    const end = offset + size;
    if (end > this.jointRecords.length) {
      this.jointRecords = new Float64Array(Math.max(2 * this.jointRecords.length, end, 64));
    }
    this.jointRecordCount = end;
    return offset;
  }
}
