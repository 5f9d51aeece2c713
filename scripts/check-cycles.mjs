// npm run lint, second part: the import cycles of the code (src/, src-gpu/, and the demos, benchmarks,
// scripts and tests) are the ones its design has, and no others. Box2D's classes know each other (a b2World owns b2Bodies, which call back into
// their b2World; a b2Contact creates its b2Fixtures' pairs through b2ContactRegistry...), so the
// port has cycles; each edge of a cycle is listed in scripts/import-cycles.json, and an import that
// closes a new cycle fails here, naming the cycle.
//
// The graph is the modules' runtime imports, read with TypeScript's parser: `import`, `export ...
// from` and `import('...')` of a relative path. `import type` and `export type` are erased at
// compile time and make no edge; `import { type A } from` is an edge, since verbatimModuleSyntax
// keeps it as `import {} from`, which loads the module.
//
// An edge lies on a cycle when both ends are in one strongly connected component. A new cycle is
// made of edges that lie on a cycle, so it has an edge the list does not have, unless every one of
// its edges was already on a cycle, and then the cycle was already there.
//
// node scripts/check-cycles.mjs           check; exit 1 on a cycle edge that is not listed
// node scripts/check-cycles.mjs --write   rewrite the list from the code (after a deliberate change)
import { readdirSync, readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import ts from 'typescript';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const listFile = path.join(root, 'scripts', 'import-cycles.json');
/** The folders whose modules make the graph: the package's code, and the demos, benchmarks, scripts and tests around it. */
const roots = ['src', 'src-gpu', 'demos', 'bench', 'scripts', 'test', 'bin'];
/** Built or installed code, and the apps compiled against the built package (test/api/fixtures/types). */
const skipped = /(^|\/)(dist|node_modules|results)\/|^test\/api\/fixtures\/types\//;

/** Every module under `dir` (repository-relative, '/'-separated): .ts, .mts and .mjs files, not declarations. */
function sources(dir) {
  return readdirSync(path.join(root, dir), { recursive: true })
    .map((file) => `${dir}/${file.split(path.sep).join('/')}`)
    .filter((file) => /\.(ts|mts|mjs)$/.test(file) && !/\.d\.m?ts$/.test(file) && !skipped.test(file))
    .sort();
}

/** The module `specifier`, written in `from`, names (the file itself, a .ts file, a folder's index.ts); null for a package or a file outside the graph. */
function resolve(from, specifier) {
  if (!specifier.startsWith('.')) return null;
  const target = path.posix.normalize(path.posix.join(path.posix.dirname(from), specifier));
  for (const candidate of [target, `${target}.ts`, `${target.replace(/\.js$/, '')}.ts`, `${target}/index.ts`]) if (graph.has(candidate)) return candidate;
  return null;
}

/** The runtime imports of `file`: the specifiers of its imports and re-exports that are not type-only. */
function imports(file) {
  const source = ts.createSourceFile(
    file,
    readFileSync(path.join(root, file), 'utf8'),
    ts.ScriptTarget.Latest,
    false,
    file.endsWith('.mjs') ? ts.ScriptKind.JS : ts.ScriptKind.TS,
  );
  const found = [];
  const visit = (node) => {
    if (ts.isImportDeclaration(node) && !node.importClause?.isTypeOnly) found.push(node.moduleSpecifier.text);
    else if (ts.isExportDeclaration(node) && node.moduleSpecifier && !node.isTypeOnly) found.push(node.moduleSpecifier.text);
    else if (ts.isCallExpression(node) && node.expression.kind === ts.SyntaxKind.ImportKeyword && ts.isStringLiteral(node.arguments[0] ?? node)) {
      found.push(node.arguments[0].text);
    }
    ts.forEachChild(node, visit);
  };
  visit(source);
  return found;
}

const files = roots.flatMap(sources);
/** @type {Map<string, string[]>} */
const graph = new Map(files.map((file) => [file, []]));
for (const file of files) {
  const targets = new Set();
  for (const specifier of imports(file)) {
    const target = resolve(file, specifier);
    if (target !== null && target !== file) targets.add(target);
  }
  graph.set(file, [...targets].sort());
}

// Tarjan's strongly connected components (iterative: the graph's paths are long).
const index = new Map();
const low = new Map();
const component = new Map();
const stack = [];
const onStack = new Set();
let counter = 0;
for (const start of files) {
  if (index.has(start)) continue;
  const work = [[start, 0]];
  index.set(start, counter);
  low.set(start, counter++);
  stack.push(start);
  onStack.add(start);
  while (work.length > 0) {
    const frame = work[work.length - 1];
    const [node, i] = frame;
    const edges = graph.get(node);
    if (i < edges.length) {
      frame[1]++;
      const next = edges[i];
      if (!index.has(next)) {
        index.set(next, counter);
        low.set(next, counter++);
        stack.push(next);
        onStack.add(next);
        work.push([next, 0]);
      } else if (onStack.has(next)) low.set(node, Math.min(low.get(node), index.get(next)));
      continue;
    }
    work.pop();
    if (work.length > 0) {
      const parent = work[work.length - 1][0];
      low.set(parent, Math.min(low.get(parent), low.get(node)));
    }
    if (low.get(node) === index.get(node)) {
      let member;
      do {
        member = stack.pop();
        onStack.delete(member);
        component.set(member, node);
      } while (member !== node);
    }
  }
}

/** Every import edge that lies on a cycle, as 'from -> to'. */
const cyclic = [];
for (const [from, targets] of graph) for (const to of targets) if (component.get(from) === component.get(to)) cyclic.push(`${from} -> ${to}`);
cyclic.sort();

if (process.argv.includes('--write')) {
  const text = `${JSON.stringify(
    {
      $comment:
        'Written by `node scripts/check-cycles.mjs --write`: the import edges of the code that lie on an import cycle, by design. npm run lint fails on any other.',
      edges: cyclic,
    },
    null,
    2,
  )}\n`;
  writeFileSync(listFile, text);
  console.log(`wrote ${path.relative(root, listFile)}: ${cyclic.length} edges on cycles`);
  process.exit(0);
}

const allowed = new Set(JSON.parse(readFileSync(listFile, 'utf8')).edges);

/** A shortest path from `from` to `to` in the graph, both ends included (breadth first). */
function pathBetween(from, to) {
  const previous = new Map([[from, null]]);
  const queue = [from];
  while (queue.length > 0) {
    const node = queue.shift();
    if (node === to) break;
    for (const next of graph.get(node)) {
      if (previous.has(next)) continue;
      previous.set(next, node);
      queue.push(next);
    }
  }
  const steps = [];
  for (let node = to; node !== null; node = previous.get(node)) steps.unshift(node);
  return steps;
}

const added = cyclic.filter((edge) => !allowed.has(edge));
// One cycle through each of the first few new edges: one new import can put hundreds of edges on a cycle.
for (const edge of added.slice(0, 10)) {
  const [from, to] = edge.split(' -> ');
  console.error(`new import cycle: ${[from, ...pathBetween(to, from)].join(' -> ')}`);
}
if (added.length > 10) console.error(`... and cycles through ${added.length - 10} more edges`);
if (added.length > 0) {
  console.error(
    `\n${added.length} import edge(s) close a cycle that scripts/import-cycles.json does not list. Break the cycle (import a type with ` +
      '`import type`, or move the shared code into a module both can import); if the cycle is the design, run `node scripts/check-cycles.mjs --write` and say why in the commit.',
  );
  process.exit(1);
}
const gone = [...allowed].filter((edge) => !cyclic.includes(edge));
console.log(
  `import cycles: ${cyclic.length} edges on cycles in ${files.length} modules, all listed${gone.length > 0 ? ` (${gone.length} listed edges no longer on a cycle: node scripts/check-cycles.mjs --write)` : ''}`,
);
