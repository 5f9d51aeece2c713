/*
 * The test list: TestEntries.cpp's g_testEntries of Box2D 2.2.1, in its order, with Rope restored
 * where its commented-out line stands.
 */

import type { TestEntry } from '../framework/test';
import { AddPair } from './AddPair';
import { ApplyForce } from './ApplyForce';
import { BodyTypes } from './BodyTypes';
import { Breakable } from './Breakable';
import { Bridge } from './Bridge';
import { BulletTest } from './BulletTest';
import { Cantilever } from './Cantilever';
import { Car } from './Car';
import { Chain } from './Chain';
import { CharacterCollision } from './CharacterCollision';
import { CollisionFiltering } from './CollisionFiltering';
import { CollisionProcessing } from './CollisionProcessing';
import { CompoundShapes } from './CompoundShapes';
import { Confined } from './Confined';
import { ContinuousTest } from './ContinuousTest';
import { DistanceTest } from './DistanceTest';
import { Dominos } from './Dominos';
import { DumpShell } from './DumpShell';
import { DynamicTreeTest } from './DynamicTreeTest';
import { EdgeShapes } from './EdgeShapes';
import { EdgeTest } from './EdgeTest';
import { Gears } from './Gears';
import { OneSidedPlatform } from './OneSidedPlatform';
import { Pinball } from './Pinball';
import { PolyCollision } from './PolyCollision';
import { PolyShapes } from './PolyShapes';
import { Prismatic } from './Prismatic';
import { Pulleys } from './Pulleys';
import { Pyramid } from './Pyramid';
import { RayCast } from './RayCast';
import { Revolute } from './Revolute';
import { Rope } from './Rope';
import { RopeJoint } from './RopeJoint';
import { SensorTest } from './SensorTest';
import { ShapeEditing } from './ShapeEditing';
import { SliderCrank } from './SliderCrank';
import { SphereStack } from './SphereStack';
import { TheoJansen } from './TheoJansen';
import { Tiles } from './Tiles';
import { TimeOfImpact } from './TimeOfImpact';
import { Tumbler } from './Tumbler';
import { VaryingFriction } from './VaryingFriction';
import { VaryingRestitution } from './VaryingRestitution';
import { VerticalStack } from './VerticalStack';
import { Web } from './Web';

export const g_testEntries: readonly TestEntry[] = [
  { name: 'Tumbler', createFcn: Tumbler.Create },
  { name: 'Tiles', createFcn: Tiles.Create },
  { name: 'Dump Shell', createFcn: DumpShell.Create },
  { name: 'Gears', createFcn: Gears.Create },
  { name: 'Cantilever', createFcn: Cantilever.Create },
  { name: 'Varying Restitution', createFcn: VaryingRestitution.Create },
  { name: 'Character Collision', createFcn: CharacterCollision.Create },
  { name: 'Edge Test', createFcn: EdgeTest.Create },
  { name: 'Body Types', createFcn: BodyTypes.Create },
  { name: 'Shape Editing', createFcn: ShapeEditing.Create },
  { name: 'Car', createFcn: Car.Create },
  { name: 'Apply Force', createFcn: ApplyForce.Create },
  { name: 'Prismatic', createFcn: Prismatic.Create },
  { name: 'Vertical Stack', createFcn: VerticalStack.Create },
  { name: 'SphereStack', createFcn: SphereStack.Create },
  { name: 'Revolute', createFcn: Revolute.Create },
  { name: 'Pulleys', createFcn: Pulleys.Create },
  { name: 'Polygon Shapes', createFcn: PolyShapes.Create },
  { name: 'Rope', createFcn: Rope.Create },
  { name: 'Web', createFcn: Web.Create },
  { name: 'RopeJoint', createFcn: RopeJoint.Create },
  { name: 'One-Sided Platform', createFcn: OneSidedPlatform.Create },
  { name: 'Pinball', createFcn: Pinball.Create },
  { name: 'Bullet Test', createFcn: BulletTest.Create },
  { name: 'Continuous Test', createFcn: ContinuousTest.Create },
  { name: 'Time of Impact', createFcn: TimeOfImpact.Create },
  { name: 'Ray-Cast', createFcn: RayCast.Create },
  { name: 'Confined', createFcn: Confined.Create },
  { name: 'Pyramid', createFcn: Pyramid.Create },
  { name: "Theo Jansen's Walker", createFcn: TheoJansen.Create },
  { name: 'Edge Shapes', createFcn: EdgeShapes.Create },
  { name: 'PolyCollision', createFcn: PolyCollision.Create },
  { name: 'Bridge', createFcn: Bridge.Create },
  { name: 'Breakable', createFcn: Breakable.Create },
  { name: 'Chain', createFcn: Chain.Create },
  { name: 'Collision Filtering', createFcn: CollisionFiltering.Create },
  { name: 'Collision Processing', createFcn: CollisionProcessing.Create },
  { name: 'Compound Shapes', createFcn: CompoundShapes.Create },
  { name: 'Distance Test', createFcn: DistanceTest.Create },
  { name: 'Dominos', createFcn: Dominos.Create },
  { name: 'Dynamic Tree', createFcn: DynamicTreeTest.Create },
  { name: 'Sensor Test', createFcn: SensorTest.Create },
  { name: 'Slider Crank', createFcn: SliderCrank.Create },
  { name: 'Varying Friction', createFcn: VaryingFriction.Create },
  { name: 'Add Pair Stress Test', createFcn: AddPair.Create },
].map((e) => ({ ...e, group: 'Testbed' as const }));
