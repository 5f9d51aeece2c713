// Reference data for test/dynamics/joints/b2Joints.reference.test.ts: it printed
// b2Joints.reference.json. The scenes exercise joint code paths the golden scenes do not reach
// (the mouse joint, equal limits, fixed rotation, a disabled wheel spring, variable time steps,
// warm starting switched off, prismatic gears between four moving bodies) and world Dump().
//
// Build it against a copy of Box2D 2.2.1's Box2D/ folder made float64 the way the golden data
// was (float32 = double, `f` suffixes stripped), with fdlibm's sin/cos (as the golden data), floor
// in double precision and b2Log writing into a buffer:
//   sed -i 's/typedef float float32;/typedef double float32;/' Box2D/Common/b2Settings.h
//   find Box2D -name '*.h' -o -name '*.cpp' | xargs sed -i -E 's/\b([0-9]+\.[0-9]*|\.[0-9]+)f\b/\1/g'
//   in Box2D/Common/b2Math.h: declare `double refSin(double); double refCos(double);`, call them
//     instead of sinf/cosf in b2Rot, and use floor instead of floorf in b2Sweep::Normalize
//   in Box2D/Common/b2Settings.cpp: b2Log appends with vsnprintf to
//     `char g_logBuffer[1 << 16]; size_t g_logLength;`
//   compile fdlibm 5.3's s_sin.c s_cos.c k_sin.c k_cos.c e_rem_pio2.c k_rem_pio2.c s_floor.c
//     s_scalbn.c s_copysign.c s_fabs.c (the copy used: github.com/nicolas-cellier-aka-nice/fdlibm,
//     fdlibm 5.3 with memcpy word access) into fdlibm/*.o with -O2 -ffp-contract=off -fno-builtin and
//     -Dsin=fd_sin -Dcos=fd_cos -Dfloor=fd_floor -Dscalbn=fd_scalbn -Dcopysign=fd_copysign
//     -Dfabs=fd_fabs (glibc's cos differs from fdlibm's in the last bit for some arguments)
//   g++ -O2 -ffp-contract=off -I. b2Joints.reference.cpp $(find Box2D -name '*.cpp' -not -path '*/Rope/*') fdlibm/*.o -o reference
//
// The program writes every sin/cos argument with fdlibm's results to stderr; when the JSON was
// made all 49,742 of them equalled the port's b2Sin/b2Cos.
#include <Box2D/Box2D.h>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

extern char g_logBuffer[];
extern size_t g_logLength;

extern "C" double fd_sin(double x);
extern "C" double fd_cos(double x);

static std::vector<double> s_trigArgs;
double refSin(double x) { s_trigArgs.push_back(x); return fd_sin(x); }
double refCos(double x) { s_trigArgs.push_back(x); return fd_cos(x); }

static std::vector<b2Body*> s_bodies;

static b2Body* makeBody(b2World* world, b2BodyType type, double x, double y, double angle, bool fixedRotation)
{
	b2BodyDef bd;
	bd.type = type;
	bd.position.Set(x, y);
	bd.angle = angle;
	bd.allowSleep = false;
	bd.fixedRotation = fixedRotation;
	b2Body* body = world->CreateBody(&bd);
	s_bodies.push_back(body);
	return body;
}

static b2Body* ground(b2World* world)
{
	return makeBody(world, b2_staticBody, 0.0, 0.0, 0.0, false);
}

static b2Body* box(b2World* world, double x, double y, double angle, double hx, double hy, double density, bool fixedRotation = false)
{
	b2Body* body = makeBody(world, b2_dynamicBody, x, y, angle, fixedRotation);
	b2PolygonShape shape;
	shape.SetAsBox(hx, hy);
	b2FixtureDef fd;
	fd.shape = &shape;
	fd.density = density;
	fd.filter.categoryBits = 0;
	body->CreateFixture(&fd);
	return body;
}

static b2Body* circle(b2World* world, double x, double y, double radius, double density)
{
	b2Body* body = makeBody(world, b2_dynamicBody, x, y, 0.0, false);
	b2CircleShape shape;
	shape.m_radius = radius;
	b2FixtureDef fd;
	fd.shape = &shape;
	fd.density = density;
	fd.filter.categoryBits = 0;
	body->CreateFixture(&fd);
	return body;
}

static uint32_t digest()
{
	uint32_t h = 2166136261u;
	for (b2Body* b : s_bodies)
	{
		double v[6] = { b->GetPosition().x, b->GetPosition().y, b->GetAngle(),
			b->GetLinearVelocity().x, b->GetLinearVelocity().y, b->GetAngularVelocity() };
		const unsigned char* p = (const unsigned char*)v;
		for (int i = 0; i < 48; ++i) { h ^= p[i]; h *= 16777619u; }
	}
	return h;
}

static bool s_firstScene = true;

static void printScene(const char* name, const std::vector<uint32_t>& digests, const std::string& dump)
{
	printf("%s\n  \"%s\": {\n    \"digests\": [", s_firstScene ? "" : ",", name);
	s_firstScene = false;
	for (size_t i = 0; i < digests.size(); ++i) printf("%s\"%08x\"", i ? ", " : "", digests[i]);
	printf("],\n    \"dump\": \"");
	for (char c : dump)
	{
		if (c == '\n') printf("\\n");
		else if (c == '"' || c == '\\') printf("\\%c", c);
		else putchar(c);
	}
	printf("\"\n  }");
}

typedef void (*Scene)(b2World* world, std::vector<uint32_t>& digests);

static void mouseScene(b2World* world, std::vector<uint32_t>& digests)
{
	b2Body* g = ground(world);
	b2Body* b = box(world, 1.0, 2.0, 0.3, 0.5, 0.25, 2.0);
	b2MouseJointDef md;
	md.bodyA = g;
	md.bodyB = b;
	md.target.Set(1.3, 2.2);
	md.maxForce = 50.0;
	b2MouseJoint* mouse = (b2MouseJoint*)world->CreateJoint(&md);
	for (int k = 1; k <= 120; ++k)
	{
		if (k == 1) mouse->SetTarget(b2Vec2(4.0, -1.0));
		if (k == 61) mouse->SetTarget(b2Vec2(0.0, 5.0));
		if (k == 91) { mouse->SetMaxForce(5.0); mouse->SetFrequency(2.0); mouse->SetDampingRatio(0.3); }
		world->Step(1.0 / 60.0, 8, 3);
		digests.push_back(digest());
	}
}

static void limitsScene(b2World* world, std::vector<uint32_t>& digests)
{
	b2Body* g = ground(world);
	b2Body* bar1 = box(world, 1.0, 5.0, 0.0, 1.0, 0.1, 1.0);
	b2RevoluteJointDef r1;
	r1.Initialize(g, bar1, b2Vec2(0.0, 5.0));
	r1.enableLimit = true;
	r1.lowerAngle = 0.3;
	r1.upperAngle = 0.3;
	r1.enableMotor = true;
	r1.motorSpeed = 1.0;
	r1.maxMotorTorque = 10.0;
	world->CreateJoint(&r1);

	b2Body* bar2 = box(world, 3.0, 5.0, 0.0, 1.0, 0.1, 1.0);
	b2RevoluteJointDef r2;
	r2.Initialize(bar1, bar2, b2Vec2(2.0, 5.0));
	r2.enableLimit = true;
	r2.lowerAngle = -0.25;
	r2.upperAngle = 0.5;
	r2.enableMotor = true;
	r2.motorSpeed = -2.0;
	r2.maxMotorTorque = 3.0;
	b2RevoluteJoint* rev2 = (b2RevoluteJoint*)world->CreateJoint(&r2);

	b2Body* slider = box(world, 6.0, 5.0, 0.2, 0.5, 0.5, 1.0, true);
	b2PrismaticJointDef p1;
	p1.Initialize(g, slider, b2Vec2(6.0, 5.0), b2Vec2(0.6, 0.8));
	p1.enableLimit = true;
	p1.lowerTranslation = 0.0;
	p1.upperTranslation = 0.0;
	world->CreateJoint(&p1);

	b2Body* slider2 = box(world, 9.0, 5.0, 0.0, 0.5, 0.25, 1.0);
	b2PrismaticJointDef p2;
	p2.Initialize(g, slider2, b2Vec2(9.0, 5.0), b2Vec2(1.0, 1.0));
	p2.enableLimit = true;
	p2.lowerTranslation = -0.5;
	p2.upperTranslation = 1.5;
	p2.enableMotor = true;
	p2.motorSpeed = 2.0;
	p2.maxMotorForce = 20.0;
	b2PrismaticJoint* pri2 = (b2PrismaticJoint*)world->CreateJoint(&p2);

	for (int k = 1; k <= 180; ++k)
	{
		if (k == 90) { rev2->EnableLimit(false); pri2->SetLimits(-2.0, 0.5); }
		if (k == 120) { rev2->EnableLimit(true); pri2->EnableMotor(false); }
		world->Step(1.0 / 60.0, 8, 3);
		digests.push_back(digest());
	}
}

static void wheelScene(b2World* world, std::vector<uint32_t>& digests)
{
	b2Body* chassis = box(world, 0.0, 3.0, 0.0, 1.5, 0.3, 1.0);
	b2Body* w1 = circle(world, -1.0, 2.0, 0.4, 1.0);
	b2WheelJointDef d1;
	d1.Initialize(chassis, w1, b2Vec2(-1.0, 2.0), b2Vec2(0.0, 1.0));
	d1.frequencyHz = 0.0;
	d1.enableMotor = true;
	d1.motorSpeed = -3.0;
	d1.maxMotorTorque = 5.0;
	b2WheelJoint* wheel1 = (b2WheelJoint*)world->CreateJoint(&d1);

	b2Body* w2 = circle(world, 1.0, 2.0, 0.4, 1.0);
	b2WheelJointDef d2;
	d2.Initialize(chassis, w2, b2Vec2(1.0, 2.0), b2Vec2(0.2, 1.0));
	d2.frequencyHz = 4.0;
	d2.dampingRatio = 0.7;
	b2WheelJoint* wheel2 = (b2WheelJoint*)world->CreateJoint(&d2);

	for (int k = 1; k <= 120; ++k)
	{
		if (k == 60)
		{
			wheel1->SetSpringFrequencyHz(3.0);
			wheel2->EnableMotor(true);
			wheel2->SetMotorSpeed(4.0);
			wheel2->SetMaxMotorTorque(2.0);
		}
		world->Step(1.0 / 60.0, 8, 3);
		digests.push_back(digest());
	}
}

static void softScene(b2World* world, std::vector<uint32_t>& digests)
{
	b2Body* g = ground(world);
	b2Body* a = box(world, 0.0, 8.0, 0.0, 0.5, 0.5, 1.0);
	b2Body* b = box(world, 2.0, 8.0, 0.0, 0.25, 0.25, 3.0);

	b2RopeJointDef rope1;
	rope1.bodyA = g;
	rope1.bodyB = a;
	rope1.localAnchorA.Set(0.0, 10.0);
	rope1.localAnchorB.Set(0.5, 0.0);
	rope1.maxLength = 3.0;
	world->CreateJoint(&rope1);

	b2RopeJointDef rope2;
	rope2.bodyA = a;
	rope2.bodyB = b;
	rope2.localAnchorA.Set(0.5, 0.0);
	rope2.localAnchorB.Set(-0.25, 0.0);
	rope2.maxLength = 2.0;
	world->CreateJoint(&rope2);

	b2DistanceJointDef dist1;
	dist1.Initialize(g, b, b2Vec2(4.0, 10.0), b2Vec2(2.25, 8.0));
	dist1.frequencyHz = 1.5;
	dist1.dampingRatio = 0.2;
	world->CreateJoint(&dist1);

	b2Body* c = circle(world, 6.0, 8.0, 0.2, 1.0);
	b2DistanceJointDef dist2;
	dist2.Initialize(g, c, b2Vec2(6.0, 8.0), b2Vec2(6.0, 8.0));
	world->CreateJoint(&dist2);

	b2Body* d = box(world, -3.0, 5.0, 0.0, 0.3, 0.3, 1.0);
	b2Body* e = box(world, -6.0, 5.0, 0.0, 0.3, 0.3, 2.0);
	b2PulleyJointDef pulley;
	pulley.Initialize(d, e, b2Vec2(-3.0, 9.0), b2Vec2(-6.0, 9.0), b2Vec2(-3.0, 5.3), b2Vec2(-6.0, 5.3), 1.5);
	world->CreateJoint(&pulley);

	b2Body* f = box(world, 10.0, 0.0, 0.0, 0.5, 0.5, 1.0);
	f->SetLinearVelocity(b2Vec2(3.0, 1.0));
	f->SetAngularVelocity(2.0);
	b2FrictionJointDef friction;
	friction.Initialize(g, f, b2Vec2(10.0, 0.0));
	friction.maxForce = 5.0;
	friction.maxTorque = 2.0;
	world->CreateJoint(&friction);

	b2Body* w = box(world, 12.0, 5.0, 0.0, 1.0, 0.2, 1.0);
	b2WeldJointDef weld;
	weld.Initialize(g, w, b2Vec2(11.0, 5.0));
	weld.frequencyHz = 3.0;
	weld.dampingRatio = 0.5;
	world->CreateJoint(&weld);

	for (int k = 1; k <= 150; ++k)
	{
		world->SetWarmStarting(k <= 100 || k > 120);
		world->Step(k % 3 == 0 ? 1.0 / 30.0 : 1.0 / 60.0, 8, 3);
		digests.push_back(digest());
	}
}

static void gearScene(b2World* world, std::vector<uint32_t>& digests)
{
	b2Body* g = ground(world);
	b2Body* cBody = box(world, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0);
	b2RevoluteJointDef rc;
	rc.Initialize(g, cBody, b2Vec2(0.0, 0.0));
	rc.enableMotor = true;
	rc.motorSpeed = 1.0;
	rc.maxMotorTorque = 100.0;
	b2Joint* revC = world->CreateJoint(&rc);

	b2Body* aBody = box(world, 0.0, 2.0, 0.0, 0.5, 0.2, 1.0);
	b2PrismaticJointDef pa;
	pa.Initialize(cBody, aBody, b2Vec2(0.0, 2.0), b2Vec2(1.0, 0.5));
	b2Joint* joint1 = world->CreateJoint(&pa);

	b2Body* dBody = circle(world, 4.0, 0.0, 0.5, 1.0);
	b2RevoluteJointDef rd;
	rd.Initialize(g, dBody, b2Vec2(4.0, 0.0));
	b2Joint* revD = world->CreateJoint(&rd);

	b2Body* bBody = box(world, 4.0, 2.0, 0.0, 0.3, 0.3, 1.0);
	b2PrismaticJointDef pb;
	pb.Initialize(dBody, bBody, b2Vec2(4.0, 2.0), b2Vec2(0.0, 1.0));
	b2Joint* joint2 = world->CreateJoint(&pb);

	b2GearJointDef g1;
	g1.bodyA = aBody;
	g1.bodyB = bBody;
	g1.joint1 = joint1;
	g1.joint2 = joint2;
	g1.ratio = 0.5;
	world->CreateJoint(&g1);

	b2GearJointDef g2;
	g2.bodyA = cBody;
	g2.bodyB = dBody;
	g2.joint1 = revC;
	g2.joint2 = revD;
	g2.ratio = -2.0;
	world->CreateJoint(&g2);

	for (int k = 1; k <= 120; ++k)
	{
		world->Step(1.0 / 60.0, 8, 3);
		digests.push_back(digest());
	}
}

static void run(const char* name, Scene scene)
{
	s_bodies.clear();
	b2World world(b2Vec2(0.0, -10.0));
	std::vector<uint32_t> digests;
	scene(&world, digests);
	g_logLength = 0;
	world.Dump();
	printScene(name, digests, std::string(g_logBuffer, g_logLength));
}

int main()
{
	printf("{\n\"scenes\": {");
	run("mouse", mouseScene);
	run("limits", limitsScene);
	run("wheels", wheelScene);
	run("soft", softScene);
	run("gears", gearScene);
	printf("\n}\n}\n");
	for (double x : s_trigArgs)
	{
		fprintf(stderr, "%.17g %.17g %.17g\n", x, fd_sin(x), fd_cos(x));
	}
	return 0;
}
