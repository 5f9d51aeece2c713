// npm run lint: ESLint with typescript-eslint, on the code as it is written. The rules are the
// recommended sets, less those whose pattern the code uses on purpose (each named below, with why),
// and one rule of this repository that states the architecture (webphysics/layers). The import
// cycles are checked by scripts/check-cycles.mjs (npm run lint runs it after ESLint).
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import js from '@eslint/js';
import { defineConfig } from 'eslint/config';
import globals from 'globals';
import tseslint from 'typescript-eslint';

const root = path.dirname(fileURLToPath(import.meta.url));

/**
 * The modules of src/ that may import the Box2DWeb 2.1a layer (src/api/): the package entry
 * `webphysics` loads it (src/index.ts), besides src/api's own modules. The classic-script entry
 * (src/api/classic.ts) is in src/api.
 */
const kApiImporters = new Set(['src/index.ts']);

/**
 * webphysics/layers: the engine (src/) is the bottom layer. Its modules import only src/ and
 * packages: never src-gpu/ (the WebGPU backend sits on the engine, through b2WorldBackend), nor
 * demos/, bench/, test/, scripts/, nor the package by its own name; and only src/api/ and the
 * entries in kApiImporters import src/api/, the compatibility layer that patches the engine's
 * classes. src-gpu/ does not import src/api/ either: a GPU world is an engine b2World.
 */
const layers = {
  meta: {
    type: 'problem',
    docs: { description: 'src/ imports only src/ (src/api/ only from src/api/ and src/index.ts); src-gpu/ does not import src/api/' },
    schema: [],
    messages: {
      outsideEngine: "src/ imports only src/ and packages: '{{specifier}}' is {{target}}",
      api: "'{{specifier}}' is the Box2DWeb 2.1a layer (src/api/), which only src/api/ and src/index.ts import",
      gpuApi: "'{{specifier}}' is the Box2DWeb 2.1a layer (src/api/): src-gpu/ builds on the engine's own modules",
      self: "src/ does not import the package by its name ('{{specifier}}')",
    },
  },
  create(context) {
    const file = path.relative(root, context.filename).split(path.sep).join('/');
    const inEngine = file.startsWith('src/');
    const inGpu = file.startsWith('src-gpu/');
    if (!inEngine && !inGpu) return {};
    const check = (node) => {
      if (node?.type !== 'Literal' || typeof node.value !== 'string') return;
      const specifier = node.value;
      if (!specifier.startsWith('.')) {
        if (inEngine && /^webphysics(\/|$)/.test(specifier)) context.report({ node, messageId: 'self', data: { specifier } });
        return;
      }
      const target = path
        .relative(root, path.resolve(path.dirname(context.filename), specifier))
        .split(path.sep)
        .join('/');
      const inApi = target === 'src/api' || target.startsWith('src/api/');
      if (inEngine) {
        if (!target.startsWith('src/')) context.report({ node, messageId: 'outsideEngine', data: { specifier, target } });
        else if (inApi && !file.startsWith('src/api/') && !kApiImporters.has(file)) context.report({ node, messageId: 'api', data: { specifier } });
      } else if (inApi) context.report({ node, messageId: 'gpuApi', data: { specifier } });
    };
    return {
      ImportDeclaration: (node) => check(node.source),
      ExportNamedDeclaration: (node) => check(node.source),
      ExportAllDeclaration: (node) => check(node.source),
      ImportExpression: (node) => check(node.source),
      TSImportType: (node) => check(node.argument?.literal ?? node.argument),
    };
  },
};

export default defineConfig(
  {
    ignores: [
      '**/dist/**',
      'coverage/**',
      'docs/api/**',
      'test-artifacts/**',
      'bench/results/**',
      '.device/**',
      // Apps compiled against the built package by test/api/types.test.ts, not part of this project.
      'test/api/fixtures/types/**',
    ],
  },
  js.configs.recommended,
  tseslint.configs.recommended,
  {
    languageOptions: { globals: { ...globals.node, ...globals.browser } },
    plugins: { webphysics: { rules: { layers } } },
    linterOptions: { reportUnusedDisableDirectives: 'error' },
    rules: {
      'webphysics/layers': 'error',
      // As tsconfig's noUnusedParameters: false: Box2D's virtual methods keep the C++ parameters
      // (b2Shape.ComputeMass(massData, density), listener callbacks) whether an override reads them or not.
      '@typescript-eslint/no-unused-vars': ['error', { args: 'none', caughtErrors: 'none', ignoreRestSiblings: true }],
      // userData is Box2D's void*, and the 2.1a layer patches constructors of any arguments.
      '@typescript-eslint/no-explicit-any': 'off',
      // Literals are copied digit for digit from fdlibm and the C++ (b2Trig's atan2 constants).
      'no-loss-of-precision': 'off',
      // `let [mantissa, e] = ...` where one of the two is reassigned.
      'prefer-const': ['error', { destructuring: 'all' }],
      '@typescript-eslint/no-unused-expressions': ['error', { allowTernary: true, allowShortCircuit: true }],
      // `interface B extends A {}` declares what a class gets from A's prototype (see below).
      '@typescript-eslint/no-empty-object-type': ['error', { allowInterfaces: 'with-single-extends' }],
    },
  },
  {
    // Box2DWeb's namespaces (Box2D.Dynamics.b2World...), as the 2.1a layer spells them.
    files: ['src/api/**/*.ts'],
    rules: { '@typescript-eslint/no-namespace': 'off' },
  },
  {
    // The record views (b2RecordVec2, b2RecordContactID) take b2Vec2's or b2ContactID's prototype
    // (Object.setPrototypeOf) and declare so by merging an interface into the class.
    files: ['src/common/b2Record.ts', 'src/collision/b2Collision.ts'],
    rules: { '@typescript-eslint/no-unsafe-declaration-merging': 'off' },
  },
  {
    // b2RevoluteJoint's flag enum holds bits and a shift, two of them equal to 2.
    files: ['src/dynamics/joints/b2RevoluteJoint.ts'],
    rules: { '@typescript-eslint/no-duplicate-enum-values': 'off' },
  },
  {
    // Box2DWeb programs as pages run them: classic scripts on the global Box2D, whose top-level
    // `var`s are globals and may be declared twice, as Box2DWeb's demos do.
    files: ['test/api/fixtures/*.js'],
    languageOptions: { sourceType: 'script', globals: { Box2D: 'readonly', RecordingContext: 'writable' } },
    rules: { 'no-redeclare': 'off', '@typescript-eslint/no-unused-vars': ['error', { vars: 'local', args: 'none' }] },
  },
);
