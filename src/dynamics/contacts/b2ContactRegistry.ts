/*
 * The body of b2Contact::InitializeRegisters (b2Contact.cpp). It lives outside b2Contact.ts
 * because the concrete contacts extend b2Contact: a base module importing its subclasses breaks
 * ES module load order. b2ContactManager's constructor calls it.
 */

import { b2Shape } from '../../collision/shapes/b2Shape';
import { b2ChainAndCircleContact } from './b2ChainAndCircleContact';
import { b2ChainAndPolygonContact } from './b2ChainAndPolygonContact';
import { b2CircleContact } from './b2CircleContact';
import { b2Contact } from './b2Contact';
import { b2EdgeAndCircleContact } from './b2EdgeAndCircleContact';
import { b2EdgeAndPolygonContact } from './b2EdgeAndPolygonContact';
import { b2PolygonAndCircleContact } from './b2PolygonAndCircleContact';
import { b2PolygonContact } from './b2PolygonContact';

/**
 * Register the seven colliding shape pairs. Edges and chains collide only with circles and
 * polygons. Safe to call more than once.
 */
export function b2InitializeContactRegisters(): void {
  if (b2Contact.s_initialized) {
    return;
  }

  b2Contact.AddType(b2CircleContact.Create, b2CircleContact.Destroy, b2Shape.e_circle, b2Shape.e_circle);
  b2Contact.AddType(b2PolygonAndCircleContact.Create, b2PolygonAndCircleContact.Destroy, b2Shape.e_polygon, b2Shape.e_circle);
  b2Contact.AddType(b2PolygonContact.Create, b2PolygonContact.Destroy, b2Shape.e_polygon, b2Shape.e_polygon);
  b2Contact.AddType(b2EdgeAndCircleContact.Create, b2EdgeAndCircleContact.Destroy, b2Shape.e_edge, b2Shape.e_circle);
  b2Contact.AddType(b2EdgeAndPolygonContact.Create, b2EdgeAndPolygonContact.Destroy, b2Shape.e_edge, b2Shape.e_polygon);
  b2Contact.AddType(b2ChainAndCircleContact.Create, b2ChainAndCircleContact.Destroy, b2Shape.e_chain, b2Shape.e_circle);
  b2Contact.AddType(b2ChainAndPolygonContact.Create, b2ChainAndPolygonContact.Destroy, b2Shape.e_chain, b2Shape.e_polygon);

  b2Contact.s_initialized = true;
}
