// Reference data for test/collision/b2DynamicTree.test.ts and b2BroadPhase.test.ts: the digests
// those tests expect were printed by this program. Build it against a copy of Box2D 2.2.1's
// Box2D/ folder made float64 the way the golden data was (float32 = double, `f` suffixes stripped
// so 0.1f is the double 0.1), with asserts on:
//   sed -i 's/typedef float float32;/typedef double float32;/' Box2D/Common/b2Settings.h
//   find Box2D -name '*.h' -o -name '*.cpp' | xargs sed -i -E 's/\b([0-9]+\.[0-9]*|\.[0-9]+)f\b/\1/g'
//   g++ -O2 -ffp-contract=off -I. b2DynamicTree.reference.cpp Box2D/Common/b2Settings.cpp \
//       Box2D/Collision/b2DynamicTree.cpp Box2D/Collision/b2BroadPhase.cpp -o reference
#define private public
#include <Box2D/Collision/b2DynamicTree.h>
#include <Box2D/Collision/b2BroadPhase.h>
#undef private
#include <cstdio>
#include <cstring>
#include <cstdint>

static uint32_t s_seed;
static double rnd()
{
	s_seed += 0x6d2b79f5u;
	uint32_t t = s_seed;
	t = (t ^ (t >> 15)) * (t | 1u);
	t ^= t + (t ^ (t >> 7)) * (t | 61u);
	return (double)((t ^ (t >> 14))) / 4294967296.0;
}

static uint32_t s_hash;
static void hashBytes(const void* p, int n)
{
	const unsigned char* b = (const unsigned char*)p;
	for (int i = 0; i < n; ++i) { s_hash ^= b[i]; s_hash *= 16777619u; }
}
static void hashI(int32 v) { hashBytes(&v, 4); }
static void hashD(double v) { hashBytes(&v, 8); }

static int32 tagOf(void* userData) { return (int32)(intptr_t)userData; }

static void randomAABB(b2AABB* aabb, double range, double size)
{
	double cx = rnd() * (2.0 * range) - range;
	double cy = rnd() * (2.0 * range) - range;
	double hw = rnd() * size + 0.05;
	double hh = rnd() * size + 0.05;
	aabb->lowerBound.Set(cx - hw, cy - hh);
	aabb->upperBound.Set(cx + hw, cy + hh);
}

static void hashTree(const b2DynamicTree& tree)
{
	hashI(tree.m_root); hashI(tree.m_nodeCount); hashI(tree.m_nodeCapacity);
	hashI(tree.m_freeList); hashI(tree.m_insertionCount);
	for (int32 i = 0; i < tree.m_nodeCapacity; ++i)
	{
		const b2TreeNode& n = tree.m_nodes[i];
		hashI(n.height);
		if (n.height < 0) { hashI(n.next); continue; }
		hashI(n.parent); hashI(n.child1); hashI(n.child2); hashI(tagOf(n.userData));
		hashD(n.aabb.lowerBound.x); hashD(n.aabb.lowerBound.y);
		hashD(n.aabb.upperBound.x); hashD(n.aabb.upperBound.y);
	}
}

struct QueryRecorder
{
	int32 limit; int32 count;
	bool QueryCallback(int32 id) { hashI(id); ++count; return count != limit; }
};

struct RayRecorder
{
	int32 count;
	float32 RayCastCallback(const b2RayCastInput& input, int32 id)
	{
		hashI(id); hashD(input.maxFraction); ++count;
		if (count == 10) return 0.0;
		if (id % 3 == 0) return -1.0;
		if (id % 3 == 1) return input.maxFraction * 0.75;
		return input.maxFraction;
	}
};

template <typename Tree>
static void probe(const Tree& tree, double range)
{
	b2AABB box; randomAABB(&box, range, 8.0);
	QueryRecorder q = { -1, 0 };
	tree.Query(&q, box); hashI(q.count);
	QueryRecorder q3 = { 3, 0 };
	tree.Query(&q3, box); hashI(q3.count);
	b2RayCastInput input;
	input.p1.x = rnd() * (2.0 * range) - range; input.p1.y = rnd() * (2.0 * range) - range;
	input.p2.x = rnd() * (2.0 * range) - range; input.p2.y = rnd() * (2.0 * range) - range;
	input.maxFraction = 1.0;
	RayRecorder r = { 0 };
	tree.RayCast(&r, input); hashI(r.count);
}

static void treeScenario()
{
	s_seed = 12345; s_hash = 2166136261u;
	b2DynamicTree tree;
	static int32 ids[4000]; static b2AABB boxes[4000]; static int32 live[4000];
	int32 liveCount = 0, tagCount = 0;
	for (int32 i = 0; i < 40; ++i)
	{
		randomAABB(boxes + tagCount, 30.0, 1.5);
		ids[tagCount] = tree.CreateProxy(boxes[tagCount], (void*)(intptr_t)(tagCount + 1));
		hashI(ids[tagCount]); live[liveCount++] = tagCount++;
	}
	for (int32 step = 0; step < 3000; ++step)
	{
		double r = rnd();
		if (r < 0.45 && liveCount > 0)
		{
			int32 k = (int32)(rnd() * liveCount); int32 tag = live[k];
			b2Vec2 d; d.x = (rnd() * 2.0 - 1.0) * 0.6; d.y = (rnd() * 2.0 - 1.0) * 0.6;
			boxes[tag].lowerBound += d; boxes[tag].upperBound += d;
			hashI(tree.MoveProxy(ids[tag], boxes[tag], d) ? 1 : 0);
		}
		else if (r < 0.75 && liveCount < 300)
		{
			randomAABB(boxes + tagCount, 30.0, 1.5);
			ids[tagCount] = tree.CreateProxy(boxes[tagCount], (void*)(intptr_t)(tagCount + 1));
			hashI(ids[tagCount]); live[liveCount++] = tagCount++;
		}
		else if (liveCount > 0)
		{
			int32 k = (int32)(rnd() * liveCount); int32 tag = live[k];
			tree.DestroyProxy(ids[tag]); hashI(ids[tag]);
			live[k] = live[--liveCount];
		}
		if (step % 100 == 99)
		{
			tree.Validate(); hashTree(tree); probe(tree, 30.0);
			printf("tree step %d live %d height %d balance %d hash %08x\n", step, liveCount, tree.GetHeight(), tree.GetMaxBalance(), s_hash);
		}
	}
	printf("tree final height %d balance %d ratio %.17g capacity %d hash %08x\n", tree.GetHeight(), tree.GetMaxBalance(), tree.GetAreaRatio(), tree.m_nodeCapacity, s_hash);
	tree.RebuildBottomUp(); hashTree(tree); probe(tree, 30.0);
	printf("tree rebuilt height %d balance %d ratio %.17g hash %08x\n", tree.GetHeight(), tree.GetMaxBalance(), tree.GetAreaRatio(), s_hash);
}

struct PairRecorder
{
	int32 count;
	void AddPair(void* a, void* b) { hashI(tagOf(a)); hashI(tagOf(b)); ++count; }
};

static void broadPhaseScenario()
{
	s_seed = 777; s_hash = 2166136261u;
	b2BroadPhase bp;
	static int32 ids[4000]; static b2AABB boxes[4000]; static int32 live[4000];
	int32 liveCount = 0, tagCount = 0, totalPairs = 0;
	for (int32 i = 0; i < 60; ++i)
	{
		randomAABB(boxes + tagCount, 10.0, 1.0);
		ids[tagCount] = bp.CreateProxy(boxes[tagCount], (void*)(intptr_t)(tagCount + 1));
		live[liveCount++] = tagCount++;
	}
	PairRecorder first = { 0 };
	bp.UpdatePairs(&first); hashI(first.count); totalPairs += first.count;
	printf("bp initial pairs %d hash %08x\n", first.count, s_hash);
	for (int32 step = 0; step < 2000; ++step)
	{
		double r = rnd();
		if (r < 0.55 && liveCount > 0)
		{
			int32 k = (int32)(rnd() * liveCount); int32 tag = live[k];
			b2Vec2 d; d.x = (rnd() * 2.0 - 1.0) * 0.3; d.y = (rnd() * 2.0 - 1.0) * 0.3;
			boxes[tag].lowerBound += d; boxes[tag].upperBound += d;
			bp.MoveProxy(ids[tag], boxes[tag], d);
		}
		else if (r < 0.65 && liveCount > 0)
		{
			int32 k = (int32)(rnd() * liveCount);
			bp.TouchProxy(ids[live[k]]);
		}
		else if (r < 0.82 && liveCount < 200)
		{
			randomAABB(boxes + tagCount, 10.0, 1.0);
			ids[tagCount] = bp.CreateProxy(boxes[tagCount], (void*)(intptr_t)(tagCount + 1));
			hashI(ids[tagCount]); live[liveCount++] = tagCount++;
		}
		else if (liveCount > 0)
		{
			int32 k = (int32)(rnd() * liveCount); int32 tag = live[k];
			bp.DestroyProxy(ids[tag]); hashI(ids[tag]);
			live[k] = live[--liveCount];
		}
		if (step % 20 == 19)
		{
			PairRecorder pr = { 0 };
			bp.UpdatePairs(&pr); hashI(pr.count); totalPairs += pr.count;
		}
	}
	hashTree(bp.m_tree); probe(bp, 10.0);
	printf("bp final proxies %d totalPairs %d height %d balance %d quality %.17g pairCapacity %d moveCapacity %d hash %08x\n",
		bp.GetProxyCount(), totalPairs, bp.GetTreeHeight(), bp.GetTreeBalance(), bp.GetTreeQuality(), bp.m_pairCapacity, bp.m_moveCapacity, s_hash);
}

int main()
{
	treeScenario();
	broadPhaseScenario();
	return 0;
}
