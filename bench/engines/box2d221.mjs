// A scene of bench/scenes.mjs (plain data) built in a Box2D 2.2.1 API, `B` (WebPhysics' exports):
// the WebPhysics adapter's world, and the accuracy study's (bench/accuracy/scenes.mjs), which also
// reads the b2World itself (`world`). Imports nothing, so the accuracy page can bundle it.

/** The scene's world and the adapter interface (engines/*.mjs), with the b2World as `world`. */
export function createBox2D221World(B, scene, { sleep }) {
  const world = new B.b2World(new B.b2Vec2(scene.gravity[0], scene.gravity[1]));
  world.SetAllowSleeping(sleep);
  const bodies = [];
  const v = (p) => new B.b2Vec2(p[0], p[1]);

  const add = (d) => {
    const bd = new B.b2BodyDef();
    bd.type = d.type === 'dynamic' ? B.b2_dynamicBody : d.type === 'kinematic' ? B.b2_kinematicBody : B.b2_staticBody;
    bd.position.Set(d.x, d.y);
    bd.angle = d.angle;
    bd.linearVelocity.Set(d.vx, d.vy);
    bd.angularVelocity = d.w;
    bd.bullet = d.bullet;
    bd.allowSleep = d.allowSleep;
    const b = world.CreateBody(bd);
    for (const s of d.shapes) {
      let shape;
      if (s.kind === 'box') {
        shape = new B.b2PolygonShape();
        if (s.cx !== undefined) shape.SetAsBox(s.hx, s.hy, new B.b2Vec2(s.cx, s.cy), s.angle);
        else shape.SetAsBox(s.hx, s.hy);
      } else if (s.kind === 'polygon') {
        shape = new B.b2PolygonShape();
        shape.Set(s.vertices.map(v));
      } else if (s.kind === 'circle') {
        shape = new B.b2CircleShape();
        shape.m_radius = s.r;
        shape.m_p.Set(s.cx ?? 0, s.cy ?? 0);
      } else if (s.kind === 'edge') {
        shape = new B.b2EdgeShape();
        shape.Set(v(s.v1), v(s.v2));
      } else if (s.kind === 'chain') {
        shape = new B.b2ChainShape();
        if (s.loop) shape.CreateLoop(s.vertices.map(v));
        else {
          shape.CreateChain(s.vertices.map(v));
          if (s.prev) shape.SetPrevVertex(v(s.prev));
          if (s.next) shape.SetNextVertex(v(s.next));
        }
      }
      const fd = new B.b2FixtureDef();
      fd.shape = shape;
      fd.density = s.density;
      fd.friction = s.friction;
      fd.restitution = s.restitution;
      fd.filter.categoryBits = s.category;
      fd.filter.maskBits = s.mask;
      b.CreateFixture(fd);
    }
    bodies.push(b);
  };
  for (const d of scene.bodies) add(d);
  for (const j of scene.joints) {
    const jd = new B.b2RevoluteJointDef();
    jd.bodyA = bodies[j.a];
    jd.bodyB = bodies[j.b];
    jd.localAnchorA.Set(j.ax, j.ay);
    jd.localAnchorB.Set(j.bx, j.by);
    jd.referenceAngle = j.refAngle;
    jd.collideConnected = j.collideConnected;
    if (j.motor) {
      jd.enableMotor = true;
      jd.motorSpeed = j.motor.speed;
      jd.maxMotorTorque = j.motor.maxTorque;
    }
    world.CreateJoint(jd);
  }

  const dt = scene.dt;
  let vi = scene.velocityIterations;
  let pi = scene.positionIterations;
  return {
    world,
    step: () => world.Step(dt, vi, pi),
    setIterations: (v, p) => {
      vi = v;
      pi = p;
    },
    add,
    bodyCount: () => world.GetBodyCount(),
    contactCount: () => world.GetContactCount(),
    position: (i) => {
      const b = bodies[i];
      if (!b) return null;
      const p = b.GetPosition();
      return [p.x, p.y];
    },
    destroy: () => {
      bodies.length = 0;
    },
  };
}
