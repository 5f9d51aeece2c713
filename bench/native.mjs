// The native reference: Box2D 2.2.1's own C++ built with the host's compiler and run on the
// benchmark scenes by bench/native/scene.cpp, as the engines `box2d-native` (the release's float32)
// and `box2d-native-f64` (float64, as the golden trajectories were made) of bench/processes.mjs:
//   node bench/processes.mjs --box2d DIR --engines webphysics,box2d-native,box2d-native-f64,box2d-wasm
// DIR is a checkout of the official Box2D repository at 2.2.1 (commit 894d4b02, the folder holding
// Box2D/Box2D/Box2D.h) or its Box2D folder. The source is not part of this package and the build
// needs g++ (or $CXX), so no test or CI run depends on it.
//
// The float64 build follows ../shared/golden/README.md: `float32` is `double`, every f-suffixed
// literal is the double it spells, -ffp-contract=off. Its sin and cos are the C library's double
// ones (the golden engine used fdlibm's): the same cost, not the same last bits.
import { spawn } from 'node:child_process';
import { createHash } from 'node:crypto';
import { existsSync, mkdirSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const DRIVER = path.join(here, 'native', 'scene.cpp');
const FLAGS = ['-O2', '-ffp-contract=off', '-DNDEBUG'];

/** The native engines, by id: the name the tables show and the build they run. */
export const NATIVE_ENGINES = {
  'box2d-native': { name: 'Box2D 2.2.1 C++ float32', build: 'float32' },
  'box2d-native-f64': { name: 'Box2D 2.2.1 C++ float64', build: 'float64' },
};

/** The include folder (the one holding Box2D/Box2D.h) for DIR, a repository checkout or its Box2D folder. */
export function box2dIncludeDir(dir) {
  for (const inc of [path.join(dir, 'Box2D'), dir]) {
    if (existsSync(path.join(inc, 'Box2D', 'Box2D.h'))) return path.resolve(inc);
  }
  throw new Error(`--box2d ${dir}: no Box2D/Box2D.h there or in its Box2D folder (a checkout of Box2D 2.2.1 is needed)`);
}

/**
 * One source file of Box2D 2.2.1 as the float64 engine: float32 is double, f-suffixed literals
 * (0.5f, 1e-3f, .25f) lose the suffix, so each is the double its digits spell, and b2Rot's sinf and
 * cosf are sin and cos.
 */
export function float64Source(text) {
  return text
    .replace(/^typedef float float32;/m, 'typedef double float32;')
    .replace(/\b(\d+\.\d*(?:[eE][-+]?\d+)?|\d+[eE][-+]?\d+)f\b/g, '$1')
    .replace(/(^|[^.\w])(\.\d+(?:[eE][-+]?\d+)?)f\b/g, '$1$2')
    .replace(/\b(sin|cos)f\(/g, '$1(');
}

/** The scene (bench/scenes.mjs) in bench/native/scene.cpp's text format, with its spawns up to `steps`. */
export function nativeSceneText(scene, steps) {
  const lines = [`world ${scene.gravity[0]} ${scene.gravity[1]} ${scene.dt} ${scene.velocityIterations} ${scene.positionIterations}`];
  const num = (b) => (b ? 1 : 0);
  const points = (ps) => `${ps.length} ${ps.map((p) => `${p[0]} ${p[1]}`).join(' ')}`;
  const addBody = (d) => {
    const type = d.type === 'dynamic' ? 2 : d.type === 'kinematic' ? 1 : 0;
    lines.push(`body ${type} ${d.x} ${d.y} ${d.angle} ${d.vx} ${d.vy} ${d.w} ${num(d.bullet)} ${num(d.allowSleep)}`);
    for (const s of d.shapes) {
      const material = `${s.density} ${s.friction} ${s.restitution} ${s.category} ${s.mask}`;
      if (s.kind === 'box') lines.push(`box ${s.hx} ${s.hy} ${s.cx ?? 0} ${s.cy ?? 0} ${s.angle ?? 0} ${material}`);
      else if (s.kind === 'circle') lines.push(`circle ${s.r} ${s.cx ?? 0} ${s.cy ?? 0} ${material}`);
      else if (s.kind === 'polygon') lines.push(`polygon ${points(s.vertices)} ${material}`);
      else if (s.kind === 'edge') lines.push(`edge ${s.v1[0]} ${s.v1[1]} ${s.v2[0]} ${s.v2[1]} ${material}`);
      else if (s.kind === 'chain') {
        const prev = s.prev ? `1 ${s.prev[0]} ${s.prev[1]}` : '0 0 0';
        const next = s.next ? `1 ${s.next[0]} ${s.next[1]}` : '0 0 0';
        lines.push(`chain ${num(s.loop)} ${points(s.vertices)} ${prev} ${next} ${material}`);
      } else throw new Error(`shape kind "${s.kind}" has no native record`);
    }
  };
  for (const d of scene.bodies) addBody(d);
  for (const j of scene.joints) {
    if (j.kind !== 'revolute') throw new Error(`joint kind "${j.kind}" has no native record`);
    const m = j.motor;
    lines.push(
      `revolute ${j.a} ${j.b} ${j.ax} ${j.ay} ${j.bx} ${j.by} ${j.refAngle} ${num(j.collideConnected)} ${num(m)} ${m ? m.speed : 0} ${m ? m.maxTorque : 0}`,
    );
  }
  for (let s = 1; scene.spawn && s <= steps; s++) {
    const more = scene.spawn(s);
    if (!more) break;
    lines.push(`spawn ${s}`);
    for (const d of more) addBody(d);
  }
  return `${lines.join('\n')}\n`;
}

function sourceFiles(dir, rel = '') {
  return readdirSync(path.join(dir, rel), { withFileTypes: true }).flatMap((e) => {
    const r = path.join(rel, e.name);
    if (e.isDirectory()) return sourceFiles(dir, r);
    return /\.(cpp|h)$/.test(e.name) ? [r] : [];
  });
}

function compile(cxx, args, log, what) {
  return new Promise((resolve, reject) => {
    const child = spawn(cxx, args, { stdio: ['ignore', 'ignore', 'pipe'] });
    let err = '';
    child.stderr.on('data', (d) => (err += d));
    child.on('error', (e) => reject(new Error(`${what}: cannot run ${cxx} (${e.message}); set CXX to a C++ compiler`)));
    child.on('close', (code) => {
      if (code === 0) {
        log(`built ${what}`);
        resolve();
      } else reject(new Error(`${what}: ${cxx} exited with ${code}: ${err.trim().split('\n').slice(-5).join(' | ')}`));
    });
  });
}

/**
 * Builds (or finds already built) the float32 and float64 scene runners against the Box2D source in
 * `dir`; resolves to { float32, float64 }, the two executables. Builds are kept in the system's
 * temporary folder under a hash of the sources, the driver, the flags and the compiler.
 */
export async function buildNative(dir, log = () => {}) {
  const include = box2dIncludeDir(dir);
  const files = sourceFiles(path.join(include, 'Box2D')).sort();
  const cxx = process.env.CXX || 'g++';
  const sources = new Map(files.map((f) => [f, readFileSync(path.join(include, 'Box2D', f), 'utf8')]));
  const hash = createHash('sha256');
  for (const [f, text] of sources) hash.update(f).update(text);
  hash.update(readFileSync(DRIVER)).update(FLAGS.join(' ')).update(cxx);
  const out = path.join(os.tmpdir(), 'webphysics-native', hash.digest('hex').slice(0, 16));
  const exe = { float32: path.join(out, 'scene-float32'), float64: path.join(out, 'scene-float64') };
  if (existsSync(exe.float32) && existsSync(exe.float64)) return exe;

  // The float64 tree: every file rewritten, in the same layout.
  const inc64 = path.join(out, 'src64');
  for (const [f, text] of sources) {
    const target = path.join(inc64, 'Box2D', f);
    mkdirSync(path.dirname(target), { recursive: true });
    writeFileSync(target, float64Source(text));
  }
  const cpp = files.filter((f) => f.endsWith('.cpp'));
  log(`building Box2D 2.2.1 (${cpp.length} files) twice with ${cxx} ${FLAGS.join(' ')}`);
  await Promise.all(
    [
      ['float32', include],
      ['float64', inc64],
    ].map(([build, inc]) =>
      compile(cxx, [...FLAGS, '-I', inc, '-o', exe[build], DRIVER, ...cpp.map((f) => path.join(inc, 'Box2D', f))], log, `the ${build} runner`),
    ),
  );
  return exe;
}
