// npm run setup: install the npm dependencies, then the system packages that the browser and
// WebGPU tests need (Chromium for headless browser tests, and its SwiftShader Vulkan driver that
// Dawn uses as a software adapter; libvulkan1 is the Vulkan loader; Firefox ESR for SpiderMonkey).
// Safe to run repeatedly.
import { execFileSync, spawnSync } from 'node:child_process';
import { existsSync, readFileSync } from 'node:fs';

function run(cmd, args) {
  console.log(`> ${[cmd, ...args].join(' ')}`);
  execFileSync(cmd, args, { stdio: 'inherit' });
}

function has(cmd) {
  return spawnSync('sh', ['-c', `command -v ${cmd}`], { stdio: 'ignore' }).status === 0;
}

run('npm', ['ci']);

const systemPackages = ['chromium', 'libvulkan1', 'firefox-esr'];
const isDebianLike =
  process.platform === 'linux' &&
  existsSync('/etc/os-release') &&
  /^(ID|ID_LIKE)=.*\b(debian|ubuntu)\b/m.test(readFileSync('/etc/os-release', 'utf8')) &&
  has('dpkg-query') &&
  has('apt-get');

if (!isDebianLike) {
  console.log(
    `\nNot a Debian/Ubuntu system: install these yourself for the browser and WebGPU tests:\n` +
      `  - Chromium or Chrome (headless browser tests, and its SwiftShader Vulkan driver)\n` +
      `  - the Vulkan loader (libvulkan1 or your distribution's vulkan-loader)\n` +
      `  - Firefox (the golden suite and the testbed in SpiderMonkey; set FIREFOX_PATH if it is not found)\n` +
      `Set WEBPHYSICS_VK_ICD to a SwiftShader ICD json if it is not in a standard location.`,
  );
  process.exit(0);
}

const installed = (pkg) => spawnSync('dpkg-query', ['-W', '-f=${Status}', pkg], { encoding: 'utf8' }).stdout?.includes('install ok installed');
const missing = systemPackages.filter((pkg) => !installed(pkg));
if (missing.length === 0) {
  console.log(`System packages present: ${systemPackages.join(', ')}`);
  process.exit(0);
}

const isRoot = typeof process.getuid === 'function' && process.getuid() === 0;
const prefix = isRoot ? [] : has('sudo') ? ['sudo'] : null;
if (prefix === null) {
  console.error(`Missing ${missing.join(', ')}; run as root or install sudo, then: apt-get install ${missing.join(' ')}`);
  process.exit(1);
}
const apt = (args) => (prefix.length ? run('sudo', ['apt-get', ...args]) : run('apt-get', args));
process.env.DEBIAN_FRONTEND = 'noninteractive';
apt(['update']);
apt(['install', '-y', '--no-install-recommends', ...missing]);
