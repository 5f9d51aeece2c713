// A scene of bench/scenes.mjs (plain data) built in a Box2D 2.2.1 API, `B` (WebPhysics' exports):
// the WebPhysics adapter's world, and the accuracy study's (bench/accuracy/scenes.mjs), which also
// reads the b2World itself (`world`). Imports nothing, so the accuracy page can bundle it.

/** The definition of joint `j` of a scene, between `bodies`; `joints`, the joints made before it. */
function jointDef(B, j, bodies, joints) {
  const kind = j.kind ?? 'revolute';
  if (kind === 'pulley') {
    const jd = new B.b2PulleyJointDef();
    const [ga, gb, aa, ab] = [j.groundA, j.groundB, j.anchorA, j.anchorB].map((p) => new B.b2Vec2(p[0], p[1]));
    jd.Initialize(bodies[j.a], bodies[j.b], ga, gb, aa, ab, j.ratio);
    return jd;
  }
  if (kind === 'gear') {
    const jd = new B.b2GearJointDef();
    jd.bodyA = bodies[j.a];
    jd.bodyB = bodies[j.b];
    jd.joint1 = joints[j.joint1];
    jd.joint2 = joints[j.joint2];
    jd.ratio = j.ratio;
    return jd;
  }
  const jd = kind === 'prismatic' ? new B.b2PrismaticJointDef() : kind === 'weld' ? new B.b2WeldJointDef() : new B.b2RevoluteJointDef();
  jd.bodyA = bodies[j.a];
  jd.bodyB = bodies[j.b];
  jd.localAnchorA.Set(j.ax, j.ay);
  jd.localAnchorB.Set(j.bx, j.by);
  jd.referenceAngle = j.refAngle;
  jd.collideConnected = j.collideConnected;
  if (kind === 'prismatic') jd.localAxisA.Set(j.axis[0], j.axis[1]);
  if (j.limit) {
    jd.enableLimit = true;
    if (kind === 'prismatic') {
      jd.lowerTranslation = j.limit[0];
      jd.upperTranslation = j.limit[1];
    } else {
      jd.lowerAngle = j.limit[0];
      jd.upperAngle = j.limit[1];
    }
  }
  if (j.motor) {
    jd.enableMotor = true;
    jd.motorSpeed = j.motor.speed;
    jd.maxMotorTorque = j.motor.maxTorque;
  }
  return jd;
}

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
  // Revolute joints (the benchmark's), and for the accuracy study's mechanisms prismatic, weld,
  // pulley and gear joints; a gear names two earlier joints of the list.
  const joints = [];
  for (const j of scene.joints) joints.push(world.CreateJoint(jointDef(B, j, bodies, joints)));

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
