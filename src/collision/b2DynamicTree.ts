/*
 * The dynamic AABB tree (b2DynamicTree.h, b2DynamicTree.cpp).
 *
 * Node ids are indices into a pool that grows exactly as the C++ one does (capacity 16, doubling,
 * LIFO free list), because proxy ids, and through them pair order, contact order and solver order,
 * are part of the result. Pool entries are objects that stay in place when the pool grows, so the
 * C++ memcpy has no counterpart here, except for m_fatAABBs (the nodes' AABBs again, packed).
 */

import { b2Abs, b2AbsV, b2CrossSV, b2Max, b2Min, b2Vec2, b2Vec2Equals } from '../common/b2Math';
import { b2Assert, b2_aabbExtension, b2_aabbMultiplier, b2_maxFloat } from '../common/b2Settings';
import { b2GrowableStack } from '../common/b2GrowableStack';
import { b2AABB, b2RayCastInput, b2TestOverlap } from './b2Collision';

export const b2_nullNode = -1;

/** The C++ template parameter T of b2DynamicTree::Query. */
export interface b2TreeQueryCallback {
  /** Called for each proxy whose fat AABB overlaps the query box; return false to stop the query. */
  QueryCallback(proxyId: number): boolean;
}

/** The C++ template parameter T of b2DynamicTree::RayCast. */
export interface b2TreeRayCastCallback {
  /**
   * Called for each proxy whose fat AABB the ray reaches. Return 0 to terminate the ray cast, a
   * positive value to clip the ray to that fraction, or a negative value to ignore the proxy.
   */
  RayCastCallback(input: b2RayCastInput, proxyId: number): number;
}

/** A node in the dynamic tree. The client does not interact with this directly. */
export class b2TreeNode {
  /** Enlarged AABB */
  readonly aabb = new b2AABB();

  userData: any = null;

  /** The C++ union { parent; next; }: `next` is an alias of this field while the node is free. */
  parent = b2_nullNode;

  child1 = b2_nullNode;
  child2 = b2_nullNode;

  /** leaf = 0, free node = -1 */
  height = -1;

  get next(): number {
    return this.parent;
  }

  set next(value: number) {
    this.parent = value;
  }

  IsLeaf(): boolean {
    return this.child1 === b2_nullNode;
  }
}

/**
 * Query and RayCast keep their traversal state here. The C++ stack is a local, so a callback may
 * query the tree again; one state per nesting depth keeps that true without allocating per call.
 */
class b2TreeTraversal {
  readonly stack = new b2GrowableStack<number>(256);
  readonly segmentAABB = new b2AABB();
  readonly subInput = new b2RayCastInput();
}

const s_traversals: b2TreeTraversal[] = [];
let s_traversalDepth = 0;

function b2AcquireTraversal(): b2TreeTraversal {
  if (s_traversalDepth === s_traversals.length) {
    s_traversals.push(new b2TreeTraversal());
  }
  const traversal = s_traversals[s_traversalDepth];
  ++s_traversalDepth;
  traversal.stack.Reset();
  return traversal;
}

function b2ReleaseTraversal(): void {
  --s_traversalDepth;
}

const s_combinedAABB = new b2AABB();
const s_r = new b2Vec2();
const s_v = new b2Vec2();
const s_absV = new b2Vec2();

/**
 * A dynamic AABB tree broad-phase, inspired by Nathanael Presson's btDbvt.
 * A dynamic tree arranges data in a binary tree to accelerate
 * queries such as volume queries and ray casts. Leafs are proxies
 * with an AABB. In the tree we expand the proxy AABB by b2_fatAABBFactor
 * so that the proxy AABB is bigger than the client object. This allows the client
 * object to move by small amounts without triggering a tree update.
 *
 * Nodes are pooled and relocatable, so we use node indices rather than pointers.
 */
export class b2DynamicTree {
  m_root: number;

  m_nodes: b2TreeNode[];
  m_nodeCount: number;
  m_nodeCapacity: number;

  m_freeList: number;

  /** This is used to incrementally traverse the tree for re-balancing. */
  m_path: number;

  m_insertionCount: number;

  /**
   * Not in the C++: each node's AABB again (lower x, lower y, upper x, upper y at 4 * node id; free
   * nodes' entries mean nothing), written wherever a node's aabb is, for the per-step reads
   * (MoveProxy's containment test, b2BroadPhase.TestOverlap for every contact, Query for every
   * moved proxy): one typed array, where the node's aabb is a node, an AABB, two vectors and four
   * boxed coordinates to load.
   */
  m_fatAABBs: Float64Array;

  /** Constructing the tree initializes the node pool. */
  constructor() {
    this.m_root = b2_nullNode;

    this.m_nodeCapacity = 16;
    this.m_fatAABBs = new Float64Array(4 * this.m_nodeCapacity);
    this.m_nodeCount = 0;
    this.m_nodes = [];
    for (let i = 0; i < this.m_nodeCapacity; ++i) {
      this.m_nodes.push(new b2TreeNode());
    }

    // Build a linked list for the free list.
    for (let i = 0; i < this.m_nodeCapacity - 1; ++i) {
      this.m_nodes[i].next = i + 1;
      this.m_nodes[i].height = -1;
    }
    this.m_nodes[this.m_nodeCapacity - 1].next = b2_nullNode;
    this.m_nodes[this.m_nodeCapacity - 1].height = -1;
    this.m_freeList = 0;

    this.m_path = 0;

    this.m_insertionCount = 0;
  }

  /** Allocate a node from the pool. Grow the pool if necessary. */
  AllocateNode(): number {
    // Expand the node pool as needed.
    if (this.m_freeList === b2_nullNode) {
      b2Assert(this.m_nodeCount === this.m_nodeCapacity);

      // The free list is empty. Rebuild a bigger pool.
      this.m_nodeCapacity *= 2;
      for (let i = this.m_nodeCount; i < this.m_nodeCapacity; ++i) {
        this.m_nodes.push(new b2TreeNode());
      }
      const fatAABBs = new Float64Array(4 * this.m_nodeCapacity);
      fatAABBs.set(this.m_fatAABBs);
      this.m_fatAABBs = fatAABBs;

      // Build a linked list for the free list. The parent
      // pointer becomes the "next" pointer.
      for (let i = this.m_nodeCount; i < this.m_nodeCapacity - 1; ++i) {
        this.m_nodes[i].next = i + 1;
        this.m_nodes[i].height = -1;
      }
      this.m_nodes[this.m_nodeCapacity - 1].next = b2_nullNode;
      this.m_nodes[this.m_nodeCapacity - 1].height = -1;
      this.m_freeList = this.m_nodeCount;
    }

    // Peel a node off the free list.
    const nodeId = this.m_freeList;
    const node = this.m_nodes[nodeId];
    this.m_freeList = node.next;
    node.parent = b2_nullNode;
    node.child1 = b2_nullNode;
    node.child2 = b2_nullNode;
    node.height = 0;
    node.userData = null;
    ++this.m_nodeCount;
    return nodeId;
  }

  /** Return a node to the pool. */
  FreeNode(nodeId: number): void {
    b2Assert(0 <= nodeId && nodeId < this.m_nodeCapacity);
    b2Assert(0 < this.m_nodeCount);
    this.m_nodes[nodeId].next = this.m_freeList;
    this.m_nodes[nodeId].height = -1;
    // Not in the C++: a free node lets go of its proxy, so destroyed fixtures can be collected.
    this.m_nodes[nodeId].userData = null;
    this.m_freeList = nodeId;
    --this.m_nodeCount;
  }

  /**
   * Create a proxy. Provide a tight fitting AABB and a userData pointer.
   * The proxy is a leaf node; its index is returned instead of a reference so that the node
   * pool can grow.
   */
  CreateProxy(aabb: Readonly<b2AABB>, userData: any): number {
    const proxyId = this.AllocateNode();
    const node = this.m_nodes[proxyId];

    // Fatten the aabb.
    const r = b2_aabbExtension;
    node.aabb.lowerBound.x = aabb.lowerBound.x - r;
    node.aabb.lowerBound.y = aabb.lowerBound.y - r;
    node.aabb.upperBound.x = aabb.upperBound.x + r;
    node.aabb.upperBound.y = aabb.upperBound.y + r;
    this.SetFatAABB(proxyId, node.aabb);
    node.userData = userData;
    node.height = 0;

    this.InsertLeaf(proxyId);

    return proxyId;
  }

  /** Destroy a proxy. This asserts if the id is invalid. */
  DestroyProxy(proxyId: number): void {
    b2Assert(0 <= proxyId && proxyId < this.m_nodeCapacity);
    b2Assert(this.m_nodes[proxyId].IsLeaf());

    this.RemoveLeaf(proxyId);
    this.FreeNode(proxyId);
  }

  /**
   * Move a proxy with a swepted AABB. If the proxy has moved outside of its fattened AABB,
   * then the proxy is removed from the tree and re-inserted. Otherwise
   * the function returns immediately.
   * @return true if the proxy was re-inserted.
   */
  MoveProxy(proxyId: number, aabb: Readonly<b2AABB>, displacement: Readonly<b2Vec2>): boolean {
    b2Assert(0 <= proxyId && proxyId < this.m_nodeCapacity);

    const node = this.m_nodes[proxyId];
    b2Assert(node.IsLeaf());

    // node.aabb.Contains(aabb), on the copy in m_fatAABBs.
    const fat = this.m_fatAABBs;
    const o = 4 * proxyId;
    if (
      fat[o] <= aabb.lowerBound.x &&
      fat[o + 1] <= aabb.lowerBound.y &&
      aabb.upperBound.x <= fat[o + 2] &&
      aabb.upperBound.y <= fat[o + 3]
    ) {
      return false;
    }

    this.RemoveLeaf(proxyId);

    // Extend AABB.
    const r = b2_aabbExtension;
    let lowerX = aabb.lowerBound.x - r;
    let lowerY = aabb.lowerBound.y - r;
    let upperX = aabb.upperBound.x + r;
    let upperY = aabb.upperBound.y + r;

    // Predict AABB displacement.
    const dx = b2_aabbMultiplier * displacement.x;
    const dy = b2_aabbMultiplier * displacement.y;

    if (dx < 0.0) {
      lowerX += dx;
    } else {
      upperX += dx;
    }

    if (dy < 0.0) {
      lowerY += dy;
    } else {
      upperY += dy;
    }

    node.aabb.lowerBound.x = lowerX;
    node.aabb.lowerBound.y = lowerY;
    node.aabb.upperBound.x = upperX;
    node.aabb.upperBound.y = upperY;
    this.SetFatAABB(proxyId, node.aabb);

    this.InsertLeaf(proxyId);
    return true;
  }

  /**
   * Get proxy user data.
   * @return the proxy user data or 0 if the id is invalid.
   */
  GetUserData(proxyId: number): any {
    b2Assert(0 <= proxyId && proxyId < this.m_nodeCapacity);
    return this.m_nodes[proxyId].userData;
  }

  /** Get the fat AABB for a proxy. */
  GetFatAABB(proxyId: number): Readonly<b2AABB> {
    b2Assert(0 <= proxyId && proxyId < this.m_nodeCapacity);
    return this.m_nodes[proxyId].aabb;
  }

  /** Not in the C++: copies node `id`'s AABB into m_fatAABBs. */
  private SetFatAABB(id: number, aabb: Readonly<b2AABB>): void {
    const fat = this.m_fatAABBs;
    const o = 4 * id;
    fat[o] = aabb.lowerBound.x;
    fat[o + 1] = aabb.lowerBound.y;
    fat[o + 2] = aabb.upperBound.x;
    fat[o + 3] = aabb.upperBound.y;
  }

  /**
   * Not in the C++: refills m_fatAABBs from the nodes, for a reader that has set m_nodes and
   * m_nodeCapacity itself.
   */
  SyncFatAABBs(): void {
    this.m_fatAABBs = new Float64Array(4 * this.m_nodeCapacity);
    for (let i = 0; i < this.m_nodeCapacity; ++i) {
      if (this.m_nodes[i].height >= 0) {
        this.SetFatAABB(i, this.m_nodes[i].aabb);
      }
    }
  }

  /**
   * Query an AABB for overlapping proxies. The callback class
   * is called for each proxy that overlaps the supplied AABB.
   */
  Query(callback: b2TreeQueryCallback, aabb: Readonly<b2AABB>): void {
    const stack = b2AcquireTraversal().stack;
    try {
      stack.Push(this.m_root);

      while (stack.GetCount() > 0) {
        const nodeId = stack.Pop();
        if (nodeId === b2_nullNode) {
          continue;
        }

        // b2TestOverlap(node.aabb, aabb) on the copy in m_fatAABBs (read here each time: a
        // callback may add proxies, which can replace it): the same subtractions and tests.
        const fat = this.m_fatAABBs;
        const o = 4 * nodeId;
        if (
          aabb.lowerBound.x - fat[o + 2] > 0.0 ||
          aabb.lowerBound.y - fat[o + 3] > 0.0 ||
          fat[o] - aabb.upperBound.x > 0.0 ||
          fat[o + 1] - aabb.upperBound.y > 0.0
        ) {
          continue;
        }

        const node = this.m_nodes[nodeId];
        if (node.IsLeaf()) {
          const proceed = callback.QueryCallback(nodeId);
          if (proceed === false) {
            return;
          }
        } else {
          stack.Push(node.child1);
          stack.Push(node.child2);
        }
      }
    } finally {
      b2ReleaseTraversal();
    }
  }

  /**
   * Ray-cast against the proxies in the tree. This relies on the callback
   * to perform a exact ray-cast in the case were the proxy contains a shape.
   * The callback also performs the any collision filtering. This has performance
   * roughly equal to k * log(n), where k is the number of collisions and n is the
   * number of proxies in the tree.
   * @param input the ray-cast input data. The ray extends from p1 to p1 + maxFraction * (p2 - p1).
   * @param callback a callback class that is called for each proxy that is hit by the ray.
   */
  RayCast(callback: b2TreeRayCastCallback, input: Readonly<b2RayCastInput>): void {
    const p1x = input.p1.x;
    const p1y = input.p1.y;
    const p2x = input.p2.x;
    const p2y = input.p2.y;
    const r = s_r.Set(p2x - p1x, p2y - p1y);
    b2Assert(r.LengthSquared() > 0.0);
    r.Normalize();

    // v is perpendicular to the segment.
    const v = b2CrossSV(1.0, r, s_v);
    const abs_v = b2AbsV(v, s_absV);
    const vx = v.x;
    const vy = v.y;
    const absVx = abs_v.x;
    const absVy = abs_v.y;

    // Separating axis for segment (Gino, p80).
    // |dot(v, p1 - c)| > dot(|v|, h)

    let maxFraction = input.maxFraction;

    const traversal = b2AcquireTraversal();
    try {
      // Build a bounding box for the segment.
      const segmentAABB = traversal.segmentAABB;
      {
        const tx = p1x + maxFraction * (p2x - p1x);
        const ty = p1y + maxFraction * (p2y - p1y);
        segmentAABB.lowerBound.x = b2Min(p1x, tx);
        segmentAABB.lowerBound.y = b2Min(p1y, ty);
        segmentAABB.upperBound.x = b2Max(p1x, tx);
        segmentAABB.upperBound.y = b2Max(p1y, ty);
      }

      const subInput = traversal.subInput;
      const stack = traversal.stack;
      stack.Push(this.m_root);

      while (stack.GetCount() > 0) {
        const nodeId = stack.Pop();
        if (nodeId === b2_nullNode) {
          continue;
        }

        const node = this.m_nodes[nodeId];

        if (b2TestOverlap(node.aabb, segmentAABB) === false) {
          continue;
        }

        // Separating axis for segment (Gino, p80).
        // |dot(v, p1 - c)| > dot(|v|, h)
        const lower = node.aabb.lowerBound;
        const upper = node.aabb.upperBound;
        const cx = 0.5 * (lower.x + upper.x);
        const cy = 0.5 * (lower.y + upper.y);
        const hx = 0.5 * (upper.x - lower.x);
        const hy = 0.5 * (upper.y - lower.y);
        const separation = b2Abs(vx * (p1x - cx) + vy * (p1y - cy)) - (absVx * hx + absVy * hy);
        if (separation > 0.0) {
          continue;
        }

        if (node.IsLeaf()) {
          subInput.p1.Assign(input.p1);
          subInput.p2.Assign(input.p2);
          subInput.maxFraction = maxFraction;

          const value = callback.RayCastCallback(subInput, nodeId);

          if (value === 0.0) {
            // The client has terminated the ray cast.
            return;
          }

          if (value > 0.0) {
            // Update segment bounding box.
            maxFraction = value;
            const tx = p1x + maxFraction * (p2x - p1x);
            const ty = p1y + maxFraction * (p2y - p1y);
            segmentAABB.lowerBound.x = b2Min(p1x, tx);
            segmentAABB.lowerBound.y = b2Min(p1y, ty);
            segmentAABB.upperBound.x = b2Max(p1x, tx);
            segmentAABB.upperBound.y = b2Max(p1y, ty);
          }
        } else {
          stack.Push(node.child1);
          stack.Push(node.child2);
        }
      }
    } finally {
      b2ReleaseTraversal();
    }
  }

  InsertLeaf(leaf: number): void {
    ++this.m_insertionCount;

    const nodes = this.m_nodes;

    if (this.m_root === b2_nullNode) {
      this.m_root = leaf;
      nodes[this.m_root].parent = b2_nullNode;
      return;
    }

    // Find the best sibling for this node. The leaf's AABB does not change during insertion,
    // so it is read in place where the C++ copies it. The AABB combinations and perimeters
    // (b2AABB.Combine2 with b2Min/b2Max's ternaries, GetPerimeter) are written out on scalars,
    // the same operations in the same argument order: the loop calls them more often than V8
    // inlines, and a perimeter returned from a call that is not inlined is a boxed double.
    const leafAABB = nodes[leaf].aabb;
    const leafLowerX = leafAABB.lowerBound.x;
    const leafLowerY = leafAABB.lowerBound.y;
    const leafUpperX = leafAABB.upperBound.x;
    const leafUpperY = leafAABB.upperBound.y;
    let index = this.m_root;
    while (nodes[index].IsLeaf() === false) {
      const node = nodes[index];
      const child1 = node.child1;
      const child2 = node.child2;

      const nodeLower = node.aabb.lowerBound;
      const nodeUpper = node.aabb.upperBound;
      const area = 2.0 * (nodeUpper.x - nodeLower.x + (nodeUpper.y - nodeLower.y));

      // combinedAABB.Combine2(nodes[index].aabb, leafAABB)
      const combinedLowerX = nodeLower.x < leafLowerX ? nodeLower.x : leafLowerX;
      const combinedLowerY = nodeLower.y < leafLowerY ? nodeLower.y : leafLowerY;
      const combinedUpperX = nodeUpper.x > leafUpperX ? nodeUpper.x : leafUpperX;
      const combinedUpperY = nodeUpper.y > leafUpperY ? nodeUpper.y : leafUpperY;
      const combinedArea = 2.0 * (combinedUpperX - combinedLowerX + (combinedUpperY - combinedLowerY));

      // Cost of creating a new parent for this node and the new leaf
      const cost = 2.0 * combinedArea;

      // Minimum cost of pushing the leaf further down the tree
      const inheritanceCost = 2.0 * (combinedArea - area);

      // Cost of descending into child1
      let cost1: number;
      {
        // aabb.Combine2(leafAABB, nodes[child1].aabb)
        const childLower = nodes[child1].aabb.lowerBound;
        const childUpper = nodes[child1].aabb.upperBound;
        const lowerX = leafLowerX < childLower.x ? leafLowerX : childLower.x;
        const lowerY = leafLowerY < childLower.y ? leafLowerY : childLower.y;
        const upperX = leafUpperX > childUpper.x ? leafUpperX : childUpper.x;
        const upperY = leafUpperY > childUpper.y ? leafUpperY : childUpper.y;
        const newArea = 2.0 * (upperX - lowerX + (upperY - lowerY));
        if (nodes[child1].IsLeaf()) {
          cost1 = newArea + inheritanceCost;
        } else {
          const oldArea = 2.0 * (childUpper.x - childLower.x + (childUpper.y - childLower.y));
          cost1 = newArea - oldArea + inheritanceCost;
        }
      }

      // Cost of descending into child2
      let cost2: number;
      {
        // aabb.Combine2(leafAABB, nodes[child2].aabb)
        const childLower = nodes[child2].aabb.lowerBound;
        const childUpper = nodes[child2].aabb.upperBound;
        const lowerX = leafLowerX < childLower.x ? leafLowerX : childLower.x;
        const lowerY = leafLowerY < childLower.y ? leafLowerY : childLower.y;
        const upperX = leafUpperX > childUpper.x ? leafUpperX : childUpper.x;
        const upperY = leafUpperY > childUpper.y ? leafUpperY : childUpper.y;
        const newArea = 2.0 * (upperX - lowerX + (upperY - lowerY));
        if (nodes[child2].IsLeaf()) {
          cost2 = newArea + inheritanceCost;
        } else {
          const oldArea = 2.0 * (childUpper.x - childLower.x + (childUpper.y - childLower.y));
          cost2 = newArea - oldArea + inheritanceCost;
        }
      }

      // Descend according to the minimum cost.
      if (cost < cost1 && cost < cost2) {
        break;
      }

      // Descend
      if (cost1 < cost2) {
        index = child1;
      } else {
        index = child2;
      }
    }

    const sibling = index;

    // Create a new parent.
    const oldParent = nodes[sibling].parent;
    const newParent = this.AllocateNode();
    // AllocateNode may have grown the pool; the array object is the same one.
    nodes[newParent].parent = oldParent;
    nodes[newParent].userData = null;
    nodes[newParent].aabb.Combine2(leafAABB, nodes[sibling].aabb);
    this.SetFatAABB(newParent, nodes[newParent].aabb);
    nodes[newParent].height = nodes[sibling].height + 1;

    if (oldParent !== b2_nullNode) {
      // The sibling was not the root.
      if (nodes[oldParent].child1 === sibling) {
        nodes[oldParent].child1 = newParent;
      } else {
        nodes[oldParent].child2 = newParent;
      }

      nodes[newParent].child1 = sibling;
      nodes[newParent].child2 = leaf;
      nodes[sibling].parent = newParent;
      nodes[leaf].parent = newParent;
    } else {
      // The sibling was the root.
      nodes[newParent].child1 = sibling;
      nodes[newParent].child2 = leaf;
      nodes[sibling].parent = newParent;
      nodes[leaf].parent = newParent;
      this.m_root = newParent;
    }

    // Walk back up the tree fixing heights and AABBs
    index = nodes[leaf].parent;
    while (index !== b2_nullNode) {
      index = this.Balance(index);

      const child1 = nodes[index].child1;
      const child2 = nodes[index].child2;

      b2Assert(child1 !== b2_nullNode);
      b2Assert(child2 !== b2_nullNode);

      nodes[index].height = 1 + b2Max(nodes[child1].height, nodes[child2].height);
      nodes[index].aabb.Combine2(nodes[child1].aabb, nodes[child2].aabb);
      this.SetFatAABB(index, nodes[index].aabb);

      index = nodes[index].parent;
    }
  }

  RemoveLeaf(leaf: number): void {
    if (leaf === this.m_root) {
      this.m_root = b2_nullNode;
      return;
    }

    const nodes = this.m_nodes;
    const parent = nodes[leaf].parent;
    const grandParent = nodes[parent].parent;
    let sibling: number;
    if (nodes[parent].child1 === leaf) {
      sibling = nodes[parent].child2;
    } else {
      sibling = nodes[parent].child1;
    }

    if (grandParent !== b2_nullNode) {
      // Destroy parent and connect sibling to grandParent.
      if (nodes[grandParent].child1 === parent) {
        nodes[grandParent].child1 = sibling;
      } else {
        nodes[grandParent].child2 = sibling;
      }
      nodes[sibling].parent = grandParent;
      this.FreeNode(parent);

      // Adjust ancestor bounds.
      let index = grandParent;
      while (index !== b2_nullNode) {
        index = this.Balance(index);

        const child1 = nodes[index].child1;
        const child2 = nodes[index].child2;

        nodes[index].aabb.Combine2(nodes[child1].aabb, nodes[child2].aabb);
        this.SetFatAABB(index, nodes[index].aabb);
        nodes[index].height = 1 + b2Max(nodes[child1].height, nodes[child2].height);

        index = nodes[index].parent;
      }
    } else {
      this.m_root = sibling;
      nodes[sibling].parent = b2_nullNode;
      this.FreeNode(parent);
    }
  }

  /**
   * Perform a left or right rotation if node A is imbalanced.
   * Returns the new root index.
   */
  Balance(iA: number): number {
    b2Assert(iA !== b2_nullNode);

    const nodes = this.m_nodes;
    const A = nodes[iA];
    if (A.IsLeaf() || A.height < 2) {
      return iA;
    }

    const iB = A.child1;
    const iC = A.child2;
    b2Assert(0 <= iB && iB < this.m_nodeCapacity);
    b2Assert(0 <= iC && iC < this.m_nodeCapacity);

    const B = nodes[iB];
    const C = nodes[iC];

    const balance = C.height - B.height;

    // Rotate C up
    if (balance > 1) {
      const iF = C.child1;
      const iG = C.child2;
      const F = nodes[iF];
      const G = nodes[iG];
      b2Assert(0 <= iF && iF < this.m_nodeCapacity);
      b2Assert(0 <= iG && iG < this.m_nodeCapacity);

      // Swap A and C
      C.child1 = iA;
      C.parent = A.parent;
      A.parent = iC;

      // A's old parent should point to C
      if (C.parent !== b2_nullNode) {
        if (nodes[C.parent].child1 === iA) {
          nodes[C.parent].child1 = iC;
        } else {
          b2Assert(nodes[C.parent].child2 === iA);
          nodes[C.parent].child2 = iC;
        }
      } else {
        this.m_root = iC;
      }

      // Rotate
      if (F.height > G.height) {
        C.child2 = iF;
        A.child2 = iG;
        G.parent = iA;
        A.aabb.Combine2(B.aabb, G.aabb);
        C.aabb.Combine2(A.aabb, F.aabb);
        this.SetFatAABB(iA, A.aabb);
        this.SetFatAABB(iC, C.aabb);

        A.height = 1 + b2Max(B.height, G.height);
        C.height = 1 + b2Max(A.height, F.height);
      } else {
        C.child2 = iG;
        A.child2 = iF;
        F.parent = iA;
        A.aabb.Combine2(B.aabb, F.aabb);
        C.aabb.Combine2(A.aabb, G.aabb);
        this.SetFatAABB(iA, A.aabb);
        this.SetFatAABB(iC, C.aabb);

        A.height = 1 + b2Max(B.height, F.height);
        C.height = 1 + b2Max(A.height, G.height);
      }

      return iC;
    }

    // Rotate B up
    if (balance < -1) {
      const iD = B.child1;
      const iE = B.child2;
      const D = nodes[iD];
      const E = nodes[iE];
      b2Assert(0 <= iD && iD < this.m_nodeCapacity);
      b2Assert(0 <= iE && iE < this.m_nodeCapacity);

      // Swap A and B
      B.child1 = iA;
      B.parent = A.parent;
      A.parent = iB;

      // A's old parent should point to B
      if (B.parent !== b2_nullNode) {
        if (nodes[B.parent].child1 === iA) {
          nodes[B.parent].child1 = iB;
        } else {
          b2Assert(nodes[B.parent].child2 === iA);
          nodes[B.parent].child2 = iB;
        }
      } else {
        this.m_root = iB;
      }

      // Rotate
      if (D.height > E.height) {
        B.child2 = iD;
        A.child1 = iE;
        E.parent = iA;
        A.aabb.Combine2(C.aabb, E.aabb);
        B.aabb.Combine2(A.aabb, D.aabb);
        this.SetFatAABB(iA, A.aabb);
        this.SetFatAABB(iB, B.aabb);

        A.height = 1 + b2Max(C.height, E.height);
        B.height = 1 + b2Max(A.height, D.height);
      } else {
        B.child2 = iE;
        A.child1 = iD;
        D.parent = iA;
        A.aabb.Combine2(C.aabb, D.aabb);
        B.aabb.Combine2(A.aabb, E.aabb);
        this.SetFatAABB(iA, A.aabb);
        this.SetFatAABB(iB, B.aabb);

        A.height = 1 + b2Max(C.height, D.height);
        B.height = 1 + b2Max(A.height, E.height);
      }

      return iB;
    }

    return iA;
  }

  /**
   * Compute the height of the binary tree in O(N) time. Should not be
   * called often.
   */
  GetHeight(): number {
    if (this.m_root === b2_nullNode) {
      return 0;
    }

    return this.m_nodes[this.m_root].height;
  }

  /** Get the ratio of the sum of the node areas to the root area. */
  GetAreaRatio(): number {
    if (this.m_root === b2_nullNode) {
      return 0.0;
    }

    const root = this.m_nodes[this.m_root];
    const rootArea = root.aabb.GetPerimeter();

    let totalArea = 0.0;
    for (let i = 0; i < this.m_nodeCapacity; ++i) {
      const node = this.m_nodes[i];
      if (node.height < 0) {
        // Free node in pool
        continue;
      }

      totalArea += node.aabb.GetPerimeter();
    }

    return totalArea / rootArea;
  }

  /**
   * Compute the height of a sub-tree, or of the whole tree when nodeId is omitted. The C++
   * whole-tree overload reads m_nodes[-1] for an empty tree; here an empty tree has height 0, as
   * GetHeight says, so Validate and RebuildBottomUp work on it.
   */
  ComputeHeight(nodeId?: number): number {
    if (nodeId === undefined) {
      if (this.m_root === b2_nullNode) {
        return 0;
      }
      return this.ComputeHeight(this.m_root);
    }

    b2Assert(0 <= nodeId && nodeId < this.m_nodeCapacity);
    const node = this.m_nodes[nodeId];

    if (node.IsLeaf()) {
      return 0;
    }

    const height1 = this.ComputeHeight(node.child1);
    const height2 = this.ComputeHeight(node.child2);
    return 1 + b2Max(height1, height2);
  }

  ValidateStructure(index: number): void {
    if (index === b2_nullNode) {
      return;
    }

    if (index === this.m_root) {
      b2Assert(this.m_nodes[index].parent === b2_nullNode);
    }

    const node = this.m_nodes[index];

    const child1 = node.child1;
    const child2 = node.child2;

    if (node.IsLeaf()) {
      b2Assert(child1 === b2_nullNode);
      b2Assert(child2 === b2_nullNode);
      b2Assert(node.height === 0);
      return;
    }

    b2Assert(0 <= child1 && child1 < this.m_nodeCapacity);
    b2Assert(0 <= child2 && child2 < this.m_nodeCapacity);

    b2Assert(this.m_nodes[child1].parent === index);
    b2Assert(this.m_nodes[child2].parent === index);

    this.ValidateStructure(child1);
    this.ValidateStructure(child2);
  }

  ValidateMetrics(index: number): void {
    if (index === b2_nullNode) {
      return;
    }

    const node = this.m_nodes[index];

    const child1 = node.child1;
    const child2 = node.child2;

    if (node.IsLeaf()) {
      b2Assert(child1 === b2_nullNode);
      b2Assert(child2 === b2_nullNode);
      b2Assert(node.height === 0);
      return;
    }

    b2Assert(0 <= child1 && child1 < this.m_nodeCapacity);
    b2Assert(0 <= child2 && child2 < this.m_nodeCapacity);

    const height1 = this.m_nodes[child1].height;
    const height2 = this.m_nodes[child2].height;
    const height = 1 + b2Max(height1, height2);
    b2Assert(node.height === height);

    const aabb = s_combinedAABB;
    aabb.Combine2(this.m_nodes[child1].aabb, this.m_nodes[child2].aabb);

    b2Assert(b2Vec2Equals(aabb.lowerBound, node.aabb.lowerBound));
    b2Assert(b2Vec2Equals(aabb.upperBound, node.aabb.upperBound));

    this.ValidateMetrics(child1);
    this.ValidateMetrics(child2);
  }

  /** Validate this tree. For testing. */
  Validate(): void {
    this.ValidateStructure(this.m_root);
    this.ValidateMetrics(this.m_root);

    let freeCount = 0;
    let freeIndex = this.m_freeList;
    while (freeIndex !== b2_nullNode) {
      b2Assert(0 <= freeIndex && freeIndex < this.m_nodeCapacity);
      freeIndex = this.m_nodes[freeIndex].next;
      ++freeCount;
    }

    b2Assert(this.GetHeight() === this.ComputeHeight());

    b2Assert(this.m_nodeCount + freeCount === this.m_nodeCapacity);
  }

  /**
   * Get the maximum balance of an node in the tree. The balance is the difference
   * in height of the two children of a node.
   */
  GetMaxBalance(): number {
    let maxBalance = 0;
    for (let i = 0; i < this.m_nodeCapacity; ++i) {
      const node = this.m_nodes[i];
      if (node.height <= 1) {
        continue;
      }

      b2Assert(node.IsLeaf() === false);

      const child1 = node.child1;
      const child2 = node.child2;
      // int32 in C++: b2Abs(0) must not leave a negative zero behind.
      const balance = b2Abs(this.m_nodes[child2].height - this.m_nodes[child1].height) | 0;
      maxBalance = b2Max(maxBalance, balance);
    }

    return maxBalance;
  }

  /** Build an optimal tree. Very expensive. For testing. */
  RebuildBottomUp(): void {
    const nodes: number[] = new Array<number>(this.m_nodeCount);
    let count = 0;

    // Build array of leaves. Free the rest.
    for (let i = 0; i < this.m_nodeCapacity; ++i) {
      if (this.m_nodes[i].height < 0) {
        // free node in pool
        continue;
      }

      if (this.m_nodes[i].IsLeaf()) {
        this.m_nodes[i].parent = b2_nullNode;
        nodes[count] = i;
        ++count;
      } else {
        this.FreeNode(i);
      }
    }

    while (count > 1) {
      let minCost = +b2_maxFloat; // unary plus: docs/PORTING.md
      let iMin = -1;
      let jMin = -1;
      for (let i = 0; i < count; ++i) {
        const aabbi = this.m_nodes[nodes[i]].aabb;

        for (let j = i + 1; j < count; ++j) {
          const aabbj = this.m_nodes[nodes[j]].aabb;
          const b = s_combinedAABB;
          b.Combine2(aabbi, aabbj);
          const cost = b.GetPerimeter();
          if (cost < minCost) {
            iMin = i;
            jMin = j;
            minCost = cost;
          }
        }
      }

      const index1 = nodes[iMin];
      const index2 = nodes[jMin];
      const child1 = this.m_nodes[index1];
      const child2 = this.m_nodes[index2];

      const parentIndex = this.AllocateNode();
      const parent = this.m_nodes[parentIndex];
      parent.child1 = index1;
      parent.child2 = index2;
      parent.height = 1 + b2Max(child1.height, child2.height);
      parent.aabb.Combine2(child1.aabb, child2.aabb);
      this.SetFatAABB(parentIndex, parent.aabb);
      parent.parent = b2_nullNode;

      child1.parent = parentIndex;
      child2.parent = parentIndex;

      nodes[jMin] = nodes[count - 1];
      nodes[iMin] = parentIndex;
      --count;
    }

    // The C++ reads nodes[0] even for an empty tree (undefined there); an empty tree stays empty.
    this.m_root = count > 0 ? nodes[0] : b2_nullNode;

    this.Validate();
  }
}
