// Box2D 2.2.1 in C++ running one benchmark scene, the native reference of bench/processes.mjs
// (--box2d). bench/native.mjs writes the scene (bench/scenes.mjs) as text and builds this file
// against the C++ source twice: as released (float32) and as the golden trajectories' float64
// engine. Usage: scene FILE STEPS FROM-TO...; prints one line of JSON, the median ms per step of
// each window [FROM, TO) over worlds 2 and 3 of three, each built from FILE and stepped STEPS times
// with sleeping off, as a JavaScript run of bench/processes.mjs measures it (a step's time includes
// the bodies spawned after it).
//
// Scene records, one per line, numbers separated by spaces (shapes follow their body; "spawn S"
// puts the bodies after it into the world right after step S, as a scene's spawn(S) does):
//   world gx gy dt velocityIterations positionIterations
//   body type x y angle vx vy w bullet allowSleep          (type 0 static, 1 kinematic, 2 dynamic)
//   box hx hy cx cy angle MATERIAL
//   circle r cx cy MATERIAL
//   polygon n x1 y1 ... xn yn MATERIAL
//   edge x1 y1 x2 y2 MATERIAL
//   chain loop n x1 y1 ... xn yn hasPrev px py hasNext nx ny MATERIAL
//   revolute a b ax ay bx by refAngle collideConnected enableMotor motorSpeed maxMotorTorque
//   spawn S
// where MATERIAL is density friction restitution categoryBits maskBits.
#include <Box2D/Box2D.h>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Record {
  std::string kind;
  std::vector<double> v;
};

struct Scene {
  Record world;
  std::vector<Record> records;  // bodies, shapes and joints in creation order, spawns included
};

Scene Read(const char* path) {
  std::ifstream in(path);
  if (!in) {
    std::fprintf(stderr, "cannot read %s\n", path);
    std::exit(2);
  }
  Scene scene;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    Record r;
    if (!(words >> r.kind)) continue;
    double x;
    while (words >> x) r.v.push_back(x);
    if (r.kind == "world") scene.world = r;
    else scene.records.push_back(r);
  }
  return scene;
}

void Material(b2FixtureDef* fd, const std::vector<double>& v, size_t i) {
  fd->density = float32(v[i]);
  fd->friction = float32(v[i + 1]);
  fd->restitution = float32(v[i + 2]);
  fd->filter.categoryBits = uint16(v[i + 3]);
  fd->filter.maskBits = uint16(v[i + 4]);
}

std::vector<b2Vec2> Points(const std::vector<double>& v, size_t first, int n) {
  std::vector<b2Vec2> points;
  for (int k = 0; k < n; ++k) points.push_back(b2Vec2(float32(v[first + 2 * k]), float32(v[first + 2 * k + 1])));
  return points;
}

// Creates the records from index `from` up to the next spawn (or the end); returns where it stopped.
size_t Create(b2World* world, const Scene& scene, size_t from, std::vector<b2Body*>* bodies) {
  b2Body* body = NULL;
  size_t i = from;
  for (; i < scene.records.size(); ++i) {
    const Record& r = scene.records[i];
    const std::vector<double>& v = r.v;
    b2FixtureDef fd;
    if (r.kind == "spawn") {
      break;
    } else if (r.kind == "body") {
      b2BodyDef bd;
      bd.type = b2BodyType(int(v[0]));
      bd.position.Set(float32(v[1]), float32(v[2]));
      bd.angle = float32(v[3]);
      bd.linearVelocity.Set(float32(v[4]), float32(v[5]));
      bd.angularVelocity = float32(v[6]);
      bd.bullet = v[7] != 0;
      bd.allowSleep = v[8] != 0;
      body = world->CreateBody(&bd);
      bodies->push_back(body);
    } else if (r.kind == "box") {
      b2PolygonShape shape;
      shape.SetAsBox(float32(v[0]), float32(v[1]), b2Vec2(float32(v[2]), float32(v[3])), float32(v[4]));
      fd.shape = &shape;
      Material(&fd, v, 5);
      body->CreateFixture(&fd);
    } else if (r.kind == "circle") {
      b2CircleShape shape;
      shape.m_radius = float32(v[0]);
      shape.m_p.Set(float32(v[1]), float32(v[2]));
      fd.shape = &shape;
      Material(&fd, v, 3);
      body->CreateFixture(&fd);
    } else if (r.kind == "polygon") {
      int n = int(v[0]);
      std::vector<b2Vec2> points = Points(v, 1, n);
      b2PolygonShape shape;
      shape.Set(&points[0], n);
      fd.shape = &shape;
      Material(&fd, v, 1 + 2 * n);
      body->CreateFixture(&fd);
    } else if (r.kind == "edge") {
      b2EdgeShape shape;
      shape.Set(b2Vec2(float32(v[0]), float32(v[1])), b2Vec2(float32(v[2]), float32(v[3])));
      fd.shape = &shape;
      Material(&fd, v, 4);
      body->CreateFixture(&fd);
    } else if (r.kind == "chain") {
      bool loop = v[0] != 0;
      int n = int(v[1]);
      std::vector<b2Vec2> points = Points(v, 2, n);
      size_t k = 2 + 2 * n;
      b2ChainShape shape;
      if (loop) {
        shape.CreateLoop(&points[0], n);
      } else {
        shape.CreateChain(&points[0], n);
        if (v[k] != 0) shape.SetPrevVertex(b2Vec2(float32(v[k + 1]), float32(v[k + 2])));
        if (v[k + 3] != 0) shape.SetNextVertex(b2Vec2(float32(v[k + 4]), float32(v[k + 5])));
      }
      fd.shape = &shape;
      Material(&fd, v, k + 6);
      body->CreateFixture(&fd);
    } else if (r.kind == "revolute") {
      b2RevoluteJointDef jd;
      jd.bodyA = (*bodies)[size_t(v[0])];
      jd.bodyB = (*bodies)[size_t(v[1])];
      jd.localAnchorA.Set(float32(v[2]), float32(v[3]));
      jd.localAnchorB.Set(float32(v[4]), float32(v[5]));
      jd.referenceAngle = float32(v[6]);
      jd.collideConnected = v[7] != 0;
      jd.enableMotor = v[8] != 0;
      jd.motorSpeed = float32(v[9]);
      jd.maxMotorTorque = float32(v[10]);
      world->CreateJoint(&jd);
    } else {
      std::fprintf(stderr, "unknown record %s\n", r.kind.c_str());
      std::exit(2);
    }
  }
  return i;
}

// bench/harness.mjs's quantile(sorted, 0.5): the mean of the middle two of an even count.
double Median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t lo = (v.size() - 1) / 2;
  return v.size() % 2 ? v[lo] : v[lo] + 0.5 * (v[lo + 1] - v[lo]);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: %s SCENE STEPS FROM-TO...\n", argv[0]);
    return 2;
  }
  const Scene scene = Read(argv[1]);
  const int steps = std::atoi(argv[2]);
  std::vector<int> from, to;
  for (int a = 3; a < argc; ++a) {
    int f = 0, t = 0;
    if (std::sscanf(argv[a], "%d-%d", &f, &t) != 2 || !(0 <= f && f < t && t <= steps)) {
      std::fprintf(stderr, "bad window %s\n", argv[a]);
      return 2;
    }
    from.push_back(f);
    to.push_back(t);
  }
  const std::vector<double>& wv = scene.world.v;
  std::vector<std::vector<double> > kept(from.size());
  for (int round = 0; round < 3; ++round) {
    b2Vec2 gravity;
    gravity.Set(float32(wv[0]), float32(wv[1]));
    b2World world(gravity);
    world.SetAllowSleeping(false);
    std::vector<b2Body*> bodies;
    size_t next = Create(&world, scene, 0, &bodies);
    std::vector<double> t;
    for (int s = 1; s <= steps; ++s) {
      std::chrono::steady_clock::time_point a = std::chrono::steady_clock::now();
      world.Step(float32(wv[2]), int32(wv[3]), int32(wv[4]));
      if (next < scene.records.size() && int(scene.records[next].v[0]) == s) {
        next = Create(&world, scene, next + 1, &bodies);
      }
      std::chrono::steady_clock::time_point b = std::chrono::steady_clock::now();
      t.push_back(std::chrono::duration<double, std::milli>(b - a).count());
    }
    if (round > 0) {
      for (size_t w = 0; w < from.size(); ++w) kept[w].insert(kept[w].end(), t.begin() + from[w], t.begin() + to[w]);
    }
  }
  std::printf("[");
  for (size_t w = 0; w < kept.size(); ++w) std::printf("%s%.6f", w ? "," : "", Median(kept[w]));
  std::printf("]\n");
  return 0;
}
