/*
 * The dynamic AABB tree (b2DynamicTree.h, b2DynamicTree.cpp).
 *
 * Node ids are indices into a pool that grows exactly as the C++ one does (capacity 16, doubling,
 * LIFO free list), because proxy ids, and through them pair order, contact order and solver order,
 * are part of the result. The pool is three arrays instead of the C++ array of b2TreeNode: each
 * node's fat AABB in m_fatAABBs, its parent (or next), children and height in m_links, its user
 * data in m_userData. A node object would be an AABB, two vectors and four boxed coordinates
 * (docs/PORTING.md), and insertion, removal and queries visit thousands of nodes a step on scenes
 * where every body moves. b2TreeNode remains as the C++ struct, for GetNode's copies and SetNodes.
 */

import { b2Abs, b2AbsV, b2CrossSV, b2Max, b2Min, b2Vec2 } from '../common/b2Math';
import { b2Assert, b2_aabbExtension, b2_aabbMultiplier, b2_maxFloat } from '../common/b2Settings';
import { b2GrowableStack } from '../common/b2GrowableStack';
import { b2AABB, b2RayCastInput } from './b2Collision';

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

/**
 * A node in the dynamic tree. The client does not interact with this directly. The tree keeps its
 * nodes in arrays (see above); this struct holds a copy of one (GetNode) or one to load (SetNodes).
 */
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

/** A node's integers in m_links, at 4 * node id; `parent` is the C++ union { parent; next; }. */
const enum Link {
  parent = 0,
  child1 = 1,
  child2 = 2,
  /** leaf = 0, free node = -1 */
  height = 3,
}

/** A node's AABB in m_fatAABBs, at 4 * node id. */
const enum Box {
  lowerX = 0,
  lowerY = 1,
  upperX = 2,
  upperY = 3,
}

/**
 * Query and RayCast keep their traversal state here. The C++ stack is a local, so a callback may
 * query the tree again; one state per nesting depth keeps that true without allocating per call.
 */
class b2TreeTraversal {
  readonly stack = new b2GrowableStack<number>(256);
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

  /** Each node's AABB: lower x, lower y, upper x, upper y at 4 * node id (Box). */
  m_fatAABBs: Float64Array;
  /** Each node's parent (or next), child1, child2 and height at 4 * node id (Link). */
  m_links: Int32Array;
  /** Each node's user data; null for inner and free nodes. */
  m_userData: any[];
  m_nodeCount: number;
  m_nodeCapacity: number;

  m_freeList: number;

  /** This is used to incrementally traverse the tree for re-balancing. */
  m_path: number;

  m_insertionCount: number;

  /** Constructing the tree initializes the node pool. */
  constructor() {
    this.m_root = b2_nullNode;

    this.m_nodeCapacity = 0;
    this.m_nodeCount = 0;
    this.m_fatAABBs = new Float64Array(0);
    this.m_links = new Int32Array(0);
    this.m_userData = [];
    this.Reserve(16);

    // Build a linked list for the free list.
    const links = this.m_links;
    for (let i = 0; i < this.m_nodeCapacity - 1; ++i) {
      links[4 * i + Link.parent] = i + 1;
      links[4 * i + Link.height] = -1;
    }
    links[4 * (this.m_nodeCapacity - 1) + Link.parent] = b2_nullNode;
    links[4 * (this.m_nodeCapacity - 1) + Link.height] = -1;
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
      this.Reserve(2 * this.m_nodeCapacity);

      // Build a linked list for the free list. The parent
      // pointer becomes the "next" pointer.
      const links = this.m_links;
      for (let i = this.m_nodeCount; i < this.m_nodeCapacity - 1; ++i) {
        links[4 * i + Link.parent] = i + 1;
        links[4 * i + Link.height] = -1;
      }
      links[4 * (this.m_nodeCapacity - 1) + Link.parent] = b2_nullNode;
      links[4 * (this.m_nodeCapacity - 1) + Link.height] = -1;
      this.m_freeList = this.m_nodeCount;
    }

    // Peel a node off the free list.
    const nodeId = this.m_freeList;
    const links = this.m_links;
    const o = 4 * nodeId;
    this.m_freeList = links[o + Link.parent];
    links[o + Link.parent] = b2_nullNode;
    links[o + Link.child1] = b2_nullNode;
    links[o + Link.child2] = b2_nullNode;
    links[o + Link.height] = 0;
    this.m_userData[nodeId] = null;
    ++this.m_nodeCount;
    return nodeId;
  }

  /**
   * Not in the C++: sets the pool's capacity, keeping the nodes below it. New nodes read as the
   * C++ ones are never read (children null, height -1); AllocateNode links them into the free list.
   */
  private Reserve(capacity: number): void {
    const count = b2Min(this.m_nodeCapacity, capacity);
    const fatAABBs = new Float64Array(4 * capacity);
    fatAABBs.set(this.m_fatAABBs.subarray(0, 4 * count));
    const links = new Int32Array(4 * capacity);
    links.set(this.m_links.subarray(0, 4 * count));
    for (let i = count; i < capacity; ++i) {
      links[4 * i + Link.parent] = b2_nullNode;
      links[4 * i + Link.child1] = b2_nullNode;
      links[4 * i + Link.child2] = b2_nullNode;
      links[4 * i + Link.height] = -1;
    }
    this.m_userData.length = count;
    for (let i = count; i < capacity; ++i) {
      this.m_userData.push(null);
    }
    this.m_fatAABBs = fatAABBs;
    this.m_links = links;
    this.m_nodeCapacity = capacity;
  }

  /** Return a node to the pool. */
  FreeNode(nodeId: number): void {
    b2Assert(0 <= nodeId && nodeId < this.m_nodeCapacity);
    b2Assert(0 < this.m_nodeCount);
    this.m_links[4 * nodeId + Link.parent] = this.m_freeList;
    this.m_links[4 * nodeId + Link.height] = -1;
    // Not in the C++: a free node lets go of its proxy, so destroyed fixtures can be collected.
    this.m_userData[nodeId] = null;
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

    // Fatten the aabb.
    const r = b2_aabbExtension;
    const fat = this.m_fatAABBs;
    const o = 4 * proxyId;
    fat[o + Box.lowerX] = aabb.lowerBound.x - r;
    fat[o + Box.lowerY] = aabb.lowerBound.y - r;
    fat[o + Box.upperX] = aabb.upperBound.x + r;
    fat[o + Box.upperY] = aabb.upperBound.y + r;
    this.m_userData[proxyId] = userData;
    this.m_links[o + Link.height] = 0;

    this.InsertLeaf(proxyId);

    return proxyId;
  }

  /** Destroy a proxy. This asserts if the id is invalid. */
  DestroyProxy(proxyId: number): void {
    b2Assert(0 <= proxyId && proxyId < this.m_nodeCapacity);
    b2Assert(this.IsLeaf(proxyId));

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

    b2Assert(this.IsLeaf(proxyId));

    // node.aabb.Contains(aabb)
    const fat = this.m_fatAABBs;
    const o = 4 * proxyId;
    if (
      fat[o + Box.lowerX] <= aabb.lowerBound.x &&
      fat[o + Box.lowerY] <= aabb.lowerBound.y &&
      aabb.upperBound.x <= fat[o + Box.upperX] &&
      aabb.upperBound.y <= fat[o + Box.upperY]
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

    // RemoveLeaf frees a node and allocates none, so the array read above is still the pool's.
    fat[o + Box.lowerX] = lowerX;
    fat[o + Box.lowerY] = lowerY;
    fat[o + Box.upperX] = upperX;
    fat[o + Box.upperY] = upperY;

    this.InsertLeaf(proxyId);
    return true;
  }

  /**
   * Get proxy user data.
   * @return the proxy user data or 0 if the id is invalid.
   */
  GetUserData(proxyId: number): any {
    b2Assert(0 <= proxyId && proxyId < this.m_nodeCapacity);
    return this.m_userData[proxyId];
  }

  /**
   * Get the fat AABB for a proxy. The C++ returns a reference to the node's AABB; the tree keeps
   * it in an array here, so this copies it into `aabb` (a new one when omitted) and returns that.
   */
  GetFatAABB(proxyId: number, aabb: b2AABB = new b2AABB()): b2AABB {
    b2Assert(0 <= proxyId && proxyId < this.m_nodeCapacity);
    const fat = this.m_fatAABBs;
    const o = 4 * proxyId;
    aabb.lowerBound.x = fat[o + Box.lowerX];
    aabb.lowerBound.y = fat[o + Box.lowerY];
    aabb.upperBound.x = fat[o + Box.upperX];
    aabb.upperBound.y = fat[o + Box.upperY];
    return aabb;
  }

  /** Not in the C++: whether node `nodeId` is a leaf (b2TreeNode::IsLeaf). */
  IsLeaf(nodeId: number): boolean {
    return this.m_links[4 * nodeId + Link.child1] === b2_nullNode;
  }

  /** Not in the C++: a copy of node `nodeId` (into `node`, a new one when omitted). */
  GetNode(nodeId: number, node: b2TreeNode = new b2TreeNode()): b2TreeNode {
    b2Assert(0 <= nodeId && nodeId < this.m_nodeCapacity);
    this.GetFatAABB(nodeId, node.aabb);
    node.userData = this.m_userData[nodeId];
    const o = 4 * nodeId;
    node.parent = this.m_links[o + Link.parent];
    node.child1 = this.m_links[o + Link.child1];
    node.child2 = this.m_links[o + Link.child2];
    node.height = this.m_links[o + Link.height];
    return node;
  }

  /**
   * Not in the C++: replaces the node pool with `nodes`, node i at id i (a saved tree's, for a
   * reader that sets m_root, m_nodeCount and m_freeList to match). A free node's AABB is not read.
   */
  SetNodes(nodes: readonly b2TreeNode[]): void {
    this.m_nodeCapacity = 0;
    this.Reserve(nodes.length);
    const fat = this.m_fatAABBs;
    const links = this.m_links;
    for (let i = 0; i < nodes.length; ++i) {
      const node = nodes[i];
      const o = 4 * i;
      links[o + Link.parent] = node.parent;
      links[o + Link.child1] = node.child1;
      links[o + Link.child2] = node.child2;
      links[o + Link.height] = node.height;
      this.m_userData[i] = node.userData;
      if (node.height >= 0) {
        fat[o + Box.lowerX] = node.aabb.lowerBound.x;
        fat[o + Box.lowerY] = node.aabb.lowerBound.y;
        fat[o + Box.upperX] = node.aabb.upperBound.x;
        fat[o + Box.upperY] = node.aabb.upperBound.y;
      }
    }
  }

  /** Not in the C++: node `target`'s AABB becomes the union of nodes a's and b's (b2AABB::Combine2). */
  private Combine2(target: number, a: number, b: number): void {
    const fat = this.m_fatAABBs;
    const t = 4 * target;
    const oa = 4 * a;
    const ob = 4 * b;
    fat[t + Box.lowerX] = b2Min(fat[oa + Box.lowerX], fat[ob + Box.lowerX]);
    fat[t + Box.lowerY] = b2Min(fat[oa + Box.lowerY], fat[ob + Box.lowerY]);
    fat[t + Box.upperX] = b2Max(fat[oa + Box.upperX], fat[ob + Box.upperX]);
    fat[t + Box.upperY] = b2Max(fat[oa + Box.upperY], fat[ob + Box.upperY]);
  }

  /** Not in the C++: node `nodeId`'s aabb.GetPerimeter(). */
  private GetPerimeter(nodeId: number): number {
    const fat = this.m_fatAABBs;
    const o = 4 * nodeId;
    const wx = fat[o + Box.upperX] - fat[o + Box.lowerX];
    const wy = fat[o + Box.upperY] - fat[o + Box.lowerY];
    return 2.0 * (wx + wy);
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

        // b2TestOverlap(node.aabb, aabb): the same subtractions and tests. The arrays are read
        // each time: a callback may add proxies, which can replace them.
        const fat = this.m_fatAABBs;
        const o = 4 * nodeId;
        if (
          aabb.lowerBound.x - fat[o + Box.upperX] > 0.0 ||
          aabb.lowerBound.y - fat[o + Box.upperY] > 0.0 ||
          fat[o + Box.lowerX] - aabb.upperBound.x > 0.0 ||
          fat[o + Box.lowerY] - aabb.upperBound.y > 0.0
        ) {
          continue;
        }

        const links = this.m_links;
        if (links[o + Link.child1] === b2_nullNode) {
          const proceed = callback.QueryCallback(nodeId);
          if (proceed === false) {
            return;
          }
        } else {
          stack.Push(links[o + Link.child1]);
          stack.Push(links[o + Link.child2]);
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

    // Build a bounding box for the segment.
    let tx = p1x + maxFraction * (p2x - p1x);
    let ty = p1y + maxFraction * (p2y - p1y);
    let segmentLowerX = b2Min(p1x, tx);
    let segmentLowerY = b2Min(p1y, ty);
    let segmentUpperX = b2Max(p1x, tx);
    let segmentUpperY = b2Max(p1y, ty);

    const traversal = b2AcquireTraversal();
    try {
      const subInput = traversal.subInput;
      const stack = traversal.stack;
      stack.Push(this.m_root);

      while (stack.GetCount() > 0) {
        const nodeId = stack.Pop();
        if (nodeId === b2_nullNode) {
          continue;
        }

        // b2TestOverlap(node.aabb, segmentAABB). The arrays are read each time: a callback may
        // add proxies, which can replace them.
        const fat = this.m_fatAABBs;
        const o = 4 * nodeId;
        const lowerX = fat[o + Box.lowerX];
        const lowerY = fat[o + Box.lowerY];
        const upperX = fat[o + Box.upperX];
        const upperY = fat[o + Box.upperY];
        if (segmentLowerX - upperX > 0.0 || segmentLowerY - upperY > 0.0 || lowerX - segmentUpperX > 0.0 || lowerY - segmentUpperY > 0.0) {
          continue;
        }

        // Separating axis for segment (Gino, p80).
        // |dot(v, p1 - c)| > dot(|v|, h)
        const cx = 0.5 * (lowerX + upperX);
        const cy = 0.5 * (lowerY + upperY);
        const hx = 0.5 * (upperX - lowerX);
        const hy = 0.5 * (upperY - lowerY);
        const separation = b2Abs(vx * (p1x - cx) + vy * (p1y - cy)) - (absVx * hx + absVy * hy);
        if (separation > 0.0) {
          continue;
        }

        const links = this.m_links;
        if (links[o + Link.child1] === b2_nullNode) {
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
            tx = p1x + maxFraction * (p2x - p1x);
            ty = p1y + maxFraction * (p2y - p1y);
            segmentLowerX = b2Min(p1x, tx);
            segmentLowerY = b2Min(p1y, ty);
            segmentUpperX = b2Max(p1x, tx);
            segmentUpperY = b2Max(p1y, ty);
          }
        } else {
          stack.Push(links[o + Link.child1]);
          stack.Push(links[o + Link.child2]);
        }
      }
    } finally {
      b2ReleaseTraversal();
    }
  }

  InsertLeaf(leaf: number): void {
    ++this.m_insertionCount;

    if (this.m_root === b2_nullNode) {
      this.m_root = leaf;
      this.m_links[4 * this.m_root + Link.parent] = b2_nullNode;
      return;
    }

    // Find the best sibling for this node. The leaf's AABB does not change during insertion,
    // so it is read once where the C++ copies it. The AABB combinations and perimeters
    // (b2AABB.Combine2 with b2Min/b2Max's ternaries, GetPerimeter) are written out on scalars,
    // the same operations in the same argument order: the loop calls them more often than V8
    // inlines, and a perimeter returned from a call that is not inlined is a boxed double.
    let fat = this.m_fatAABBs;
    let links = this.m_links;
    const leafLowerX = fat[4 * leaf + Box.lowerX];
    const leafLowerY = fat[4 * leaf + Box.lowerY];
    const leafUpperX = fat[4 * leaf + Box.upperX];
    const leafUpperY = fat[4 * leaf + Box.upperY];
    let index = this.m_root;
    while (links[4 * index + Link.child1] !== b2_nullNode) {
      const o = 4 * index;
      const child1 = links[o + Link.child1];
      const child2 = links[o + Link.child2];

      const nodeLowerX = fat[o + Box.lowerX];
      const nodeLowerY = fat[o + Box.lowerY];
      const nodeUpperX = fat[o + Box.upperX];
      const nodeUpperY = fat[o + Box.upperY];
      const area = 2.0 * (nodeUpperX - nodeLowerX + (nodeUpperY - nodeLowerY));

      // combinedAABB.Combine2(nodes[index].aabb, leafAABB)
      const combinedLowerX = nodeLowerX < leafLowerX ? nodeLowerX : leafLowerX;
      const combinedLowerY = nodeLowerY < leafLowerY ? nodeLowerY : leafLowerY;
      const combinedUpperX = nodeUpperX > leafUpperX ? nodeUpperX : leafUpperX;
      const combinedUpperY = nodeUpperY > leafUpperY ? nodeUpperY : leafUpperY;
      const combinedArea = 2.0 * (combinedUpperX - combinedLowerX + (combinedUpperY - combinedLowerY));

      // Cost of creating a new parent for this node and the new leaf
      const cost = 2.0 * combinedArea;

      // Minimum cost of pushing the leaf further down the tree
      const inheritanceCost = 2.0 * (combinedArea - area);

      // Cost of descending into child1
      let cost1: number;
      {
        // aabb.Combine2(leafAABB, nodes[child1].aabb)
        const c = 4 * child1;
        const childLowerX = fat[c + Box.lowerX];
        const childLowerY = fat[c + Box.lowerY];
        const childUpperX = fat[c + Box.upperX];
        const childUpperY = fat[c + Box.upperY];
        const lowerX = leafLowerX < childLowerX ? leafLowerX : childLowerX;
        const lowerY = leafLowerY < childLowerY ? leafLowerY : childLowerY;
        const upperX = leafUpperX > childUpperX ? leafUpperX : childUpperX;
        const upperY = leafUpperY > childUpperY ? leafUpperY : childUpperY;
        const newArea = 2.0 * (upperX - lowerX + (upperY - lowerY));
        if (links[c + Link.child1] === b2_nullNode) {
          cost1 = newArea + inheritanceCost;
        } else {
          const oldArea = 2.0 * (childUpperX - childLowerX + (childUpperY - childLowerY));
          cost1 = newArea - oldArea + inheritanceCost;
        }
      }

      // Cost of descending into child2
      let cost2: number;
      {
        // aabb.Combine2(leafAABB, nodes[child2].aabb)
        const c = 4 * child2;
        const childLowerX = fat[c + Box.lowerX];
        const childLowerY = fat[c + Box.lowerY];
        const childUpperX = fat[c + Box.upperX];
        const childUpperY = fat[c + Box.upperY];
        const lowerX = leafLowerX < childLowerX ? leafLowerX : childLowerX;
        const lowerY = leafLowerY < childLowerY ? leafLowerY : childLowerY;
        const upperX = leafUpperX > childUpperX ? leafUpperX : childUpperX;
        const upperY = leafUpperY > childUpperY ? leafUpperY : childUpperY;
        const newArea = 2.0 * (upperX - lowerX + (upperY - lowerY));
        if (links[c + Link.child1] === b2_nullNode) {
          cost2 = newArea + inheritanceCost;
        } else {
          const oldArea = 2.0 * (childUpperX - childLowerX + (childUpperY - childLowerY));
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
    const oldParent = links[4 * sibling + Link.parent];
    const newParent = this.AllocateNode();
    // AllocateNode may have grown the pool, replacing the arrays.
    fat = this.m_fatAABBs;
    links = this.m_links;
    links[4 * newParent + Link.parent] = oldParent;
    this.m_userData[newParent] = null;
    this.Combine2(newParent, leaf, sibling);
    links[4 * newParent + Link.height] = links[4 * sibling + Link.height] + 1;

    if (oldParent !== b2_nullNode) {
      // The sibling was not the root.
      if (links[4 * oldParent + Link.child1] === sibling) {
        links[4 * oldParent + Link.child1] = newParent;
      } else {
        links[4 * oldParent + Link.child2] = newParent;
      }

      links[4 * newParent + Link.child1] = sibling;
      links[4 * newParent + Link.child2] = leaf;
      links[4 * sibling + Link.parent] = newParent;
      links[4 * leaf + Link.parent] = newParent;
    } else {
      // The sibling was the root.
      links[4 * newParent + Link.child1] = sibling;
      links[4 * newParent + Link.child2] = leaf;
      links[4 * sibling + Link.parent] = newParent;
      links[4 * leaf + Link.parent] = newParent;
      this.m_root = newParent;
    }

    // Walk back up the tree fixing heights and AABBs
    index = links[4 * leaf + Link.parent];
    while (index !== b2_nullNode) {
      index = this.Balance(index);

      const o = 4 * index;
      const child1 = links[o + Link.child1];
      const child2 = links[o + Link.child2];

      b2Assert(child1 !== b2_nullNode);
      b2Assert(child2 !== b2_nullNode);

      links[o + Link.height] = 1 + b2Max(links[4 * child1 + Link.height], links[4 * child2 + Link.height]);
      this.Combine2(index, child1, child2);

      index = links[o + Link.parent];
    }
  }

  RemoveLeaf(leaf: number): void {
    if (leaf === this.m_root) {
      this.m_root = b2_nullNode;
      return;
    }

    const links = this.m_links;
    const parent = links[4 * leaf + Link.parent];
    const grandParent = links[4 * parent + Link.parent];
    let sibling: number;
    if (links[4 * parent + Link.child1] === leaf) {
      sibling = links[4 * parent + Link.child2];
    } else {
      sibling = links[4 * parent + Link.child1];
    }

    if (grandParent !== b2_nullNode) {
      // Destroy parent and connect sibling to grandParent.
      if (links[4 * grandParent + Link.child1] === parent) {
        links[4 * grandParent + Link.child1] = sibling;
      } else {
        links[4 * grandParent + Link.child2] = sibling;
      }
      links[4 * sibling + Link.parent] = grandParent;
      this.FreeNode(parent);

      // Adjust ancestor bounds.
      let index = grandParent;
      while (index !== b2_nullNode) {
        index = this.Balance(index);

        const o = 4 * index;
        const child1 = links[o + Link.child1];
        const child2 = links[o + Link.child2];

        this.Combine2(index, child1, child2);
        links[o + Link.height] = 1 + b2Max(links[4 * child1 + Link.height], links[4 * child2 + Link.height]);

        index = links[o + Link.parent];
      }
    } else {
      this.m_root = sibling;
      links[4 * sibling + Link.parent] = b2_nullNode;
      this.FreeNode(parent);
    }
  }

  /**
   * Perform a left or right rotation if node A is imbalanced.
   * Returns the new root index.
   */
  Balance(iA: number): number {
    b2Assert(iA !== b2_nullNode);

    const links = this.m_links;
    const A = 4 * iA;
    if (links[A + Link.child1] === b2_nullNode || links[A + Link.height] < 2) {
      return iA;
    }

    const iB = links[A + Link.child1];
    const iC = links[A + Link.child2];
    b2Assert(0 <= iB && iB < this.m_nodeCapacity);
    b2Assert(0 <= iC && iC < this.m_nodeCapacity);

    const B = 4 * iB;
    const C = 4 * iC;

    const balance = links[C + Link.height] - links[B + Link.height];

    // Rotate C up
    if (balance > 1) {
      const iF = links[C + Link.child1];
      const iG = links[C + Link.child2];
      const F = 4 * iF;
      const G = 4 * iG;
      b2Assert(0 <= iF && iF < this.m_nodeCapacity);
      b2Assert(0 <= iG && iG < this.m_nodeCapacity);

      // Swap A and C
      links[C + Link.child1] = iA;
      links[C + Link.parent] = links[A + Link.parent];
      links[A + Link.parent] = iC;

      // A's old parent should point to C
      const parent = links[C + Link.parent];
      if (parent !== b2_nullNode) {
        if (links[4 * parent + Link.child1] === iA) {
          links[4 * parent + Link.child1] = iC;
        } else {
          b2Assert(links[4 * parent + Link.child2] === iA);
          links[4 * parent + Link.child2] = iC;
        }
      } else {
        this.m_root = iC;
      }

      // Rotate
      if (links[F + Link.height] > links[G + Link.height]) {
        links[C + Link.child2] = iF;
        links[A + Link.child2] = iG;
        links[G + Link.parent] = iA;
        this.Combine2(iA, iB, iG);
        this.Combine2(iC, iA, iF);

        links[A + Link.height] = 1 + b2Max(links[B + Link.height], links[G + Link.height]);
        links[C + Link.height] = 1 + b2Max(links[A + Link.height], links[F + Link.height]);
      } else {
        links[C + Link.child2] = iG;
        links[A + Link.child2] = iF;
        links[F + Link.parent] = iA;
        this.Combine2(iA, iB, iF);
        this.Combine2(iC, iA, iG);

        links[A + Link.height] = 1 + b2Max(links[B + Link.height], links[F + Link.height]);
        links[C + Link.height] = 1 + b2Max(links[A + Link.height], links[G + Link.height]);
      }

      return iC;
    }

    // Rotate B up
    if (balance < -1) {
      const iD = links[B + Link.child1];
      const iE = links[B + Link.child2];
      const D = 4 * iD;
      const E = 4 * iE;
      b2Assert(0 <= iD && iD < this.m_nodeCapacity);
      b2Assert(0 <= iE && iE < this.m_nodeCapacity);

      // Swap A and B
      links[B + Link.child1] = iA;
      links[B + Link.parent] = links[A + Link.parent];
      links[A + Link.parent] = iB;

      // A's old parent should point to B
      const parent = links[B + Link.parent];
      if (parent !== b2_nullNode) {
        if (links[4 * parent + Link.child1] === iA) {
          links[4 * parent + Link.child1] = iB;
        } else {
          b2Assert(links[4 * parent + Link.child2] === iA);
          links[4 * parent + Link.child2] = iB;
        }
      } else {
        this.m_root = iB;
      }

      // Rotate
      if (links[D + Link.height] > links[E + Link.height]) {
        links[B + Link.child2] = iD;
        links[A + Link.child1] = iE;
        links[E + Link.parent] = iA;
        this.Combine2(iA, iC, iE);
        this.Combine2(iB, iA, iD);

        links[A + Link.height] = 1 + b2Max(links[C + Link.height], links[E + Link.height]);
        links[B + Link.height] = 1 + b2Max(links[A + Link.height], links[D + Link.height]);
      } else {
        links[B + Link.child2] = iE;
        links[A + Link.child1] = iD;
        links[D + Link.parent] = iA;
        this.Combine2(iA, iC, iD);
        this.Combine2(iB, iA, iE);

        links[A + Link.height] = 1 + b2Max(links[C + Link.height], links[D + Link.height]);
        links[B + Link.height] = 1 + b2Max(links[A + Link.height], links[E + Link.height]);
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

    return this.m_links[4 * this.m_root + Link.height];
  }

  /** Get the ratio of the sum of the node areas to the root area. */
  GetAreaRatio(): number {
    if (this.m_root === b2_nullNode) {
      return 0.0;
    }

    const rootArea = this.GetPerimeter(this.m_root);

    let totalArea = 0.0;
    for (let i = 0; i < this.m_nodeCapacity; ++i) {
      if (this.m_links[4 * i + Link.height] < 0) {
        // Free node in pool
        continue;
      }

      totalArea += this.GetPerimeter(i);
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

    if (this.IsLeaf(nodeId)) {
      return 0;
    }

    const height1 = this.ComputeHeight(this.m_links[4 * nodeId + Link.child1]);
    const height2 = this.ComputeHeight(this.m_links[4 * nodeId + Link.child2]);
    return 1 + b2Max(height1, height2);
  }

  ValidateStructure(index: number): void {
    if (index === b2_nullNode) {
      return;
    }

    const links = this.m_links;
    if (index === this.m_root) {
      b2Assert(links[4 * index + Link.parent] === b2_nullNode);
    }

    const child1 = links[4 * index + Link.child1];
    const child2 = links[4 * index + Link.child2];

    if (this.IsLeaf(index)) {
      b2Assert(child1 === b2_nullNode);
      b2Assert(child2 === b2_nullNode);
      b2Assert(links[4 * index + Link.height] === 0);
      return;
    }

    b2Assert(0 <= child1 && child1 < this.m_nodeCapacity);
    b2Assert(0 <= child2 && child2 < this.m_nodeCapacity);

    b2Assert(links[4 * child1 + Link.parent] === index);
    b2Assert(links[4 * child2 + Link.parent] === index);

    this.ValidateStructure(child1);
    this.ValidateStructure(child2);
  }

  ValidateMetrics(index: number): void {
    if (index === b2_nullNode) {
      return;
    }

    const links = this.m_links;
    const child1 = links[4 * index + Link.child1];
    const child2 = links[4 * index + Link.child2];

    if (this.IsLeaf(index)) {
      b2Assert(child1 === b2_nullNode);
      b2Assert(child2 === b2_nullNode);
      b2Assert(links[4 * index + Link.height] === 0);
      return;
    }

    b2Assert(0 <= child1 && child1 < this.m_nodeCapacity);
    b2Assert(0 <= child2 && child2 < this.m_nodeCapacity);

    const height1 = links[4 * child1 + Link.height];
    const height2 = links[4 * child2 + Link.height];
    const height = 1 + b2Max(height1, height2);
    b2Assert(links[4 * index + Link.height] === height);

    // aabb.Combine2(child1's, child2's) equals the node's aabb
    const fat = this.m_fatAABBs;
    const o = 4 * index;
    const o1 = 4 * child1;
    const o2 = 4 * child2;
    b2Assert(b2Min(fat[o1 + Box.lowerX], fat[o2 + Box.lowerX]) === fat[o + Box.lowerX]);
    b2Assert(b2Min(fat[o1 + Box.lowerY], fat[o2 + Box.lowerY]) === fat[o + Box.lowerY]);
    b2Assert(b2Max(fat[o1 + Box.upperX], fat[o2 + Box.upperX]) === fat[o + Box.upperX]);
    b2Assert(b2Max(fat[o1 + Box.upperY], fat[o2 + Box.upperY]) === fat[o + Box.upperY]);

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
      freeIndex = this.m_links[4 * freeIndex + Link.parent];
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
    const links = this.m_links;
    let maxBalance = 0;
    for (let i = 0; i < this.m_nodeCapacity; ++i) {
      if (links[4 * i + Link.height] <= 1) {
        continue;
      }

      b2Assert(this.IsLeaf(i) === false);

      const child1 = links[4 * i + Link.child1];
      const child2 = links[4 * i + Link.child2];
      // int32 in C++: b2Abs(0) must not leave a negative zero behind.
      const balance = b2Abs(links[4 * child2 + Link.height] - links[4 * child1 + Link.height]) | 0;
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
      if (this.m_links[4 * i + Link.height] < 0) {
        // free node in pool
        continue;
      }

      if (this.IsLeaf(i)) {
        this.m_links[4 * i + Link.parent] = b2_nullNode;
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
      const fat = this.m_fatAABBs;
      for (let i = 0; i < count; ++i) {
        const oi = 4 * nodes[i];

        for (let j = i + 1; j < count; ++j) {
          const oj = 4 * nodes[j];
          // b.Combine2(aabbi, aabbj); cost = b.GetPerimeter()
          const lowerX = b2Min(fat[oi + Box.lowerX], fat[oj + Box.lowerX]);
          const lowerY = b2Min(fat[oi + Box.lowerY], fat[oj + Box.lowerY]);
          const upperX = b2Max(fat[oi + Box.upperX], fat[oj + Box.upperX]);
          const upperY = b2Max(fat[oi + Box.upperY], fat[oj + Box.upperY]);
          const cost = 2.0 * (upperX - lowerX + (upperY - lowerY));
          if (cost < minCost) {
            iMin = i;
            jMin = j;
            minCost = cost;
          }
        }
      }

      const index1 = nodes[iMin];
      const index2 = nodes[jMin];

      const parentIndex = this.AllocateNode();
      const links = this.m_links;
      const p = 4 * parentIndex;
      links[p + Link.child1] = index1;
      links[p + Link.child2] = index2;
      links[p + Link.height] = 1 + b2Max(links[4 * index1 + Link.height], links[4 * index2 + Link.height]);
      this.Combine2(parentIndex, index1, index2);
      links[p + Link.parent] = b2_nullNode;

      links[4 * index1 + Link.parent] = parentIndex;
      links[4 * index2 + Link.parent] = parentIndex;

      nodes[jMin] = nodes[count - 1];
      nodes[iMin] = parentIndex;
      --count;
    }

    // The C++ reads nodes[0] even for an empty tree (undefined there); an empty tree stays empty.
    this.m_root = count > 0 ? nodes[0] : b2_nullNode;

    this.Validate();
  }
}
