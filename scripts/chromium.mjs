// Headless Chromium for the browser tests and bench/compare-browser.mjs, through puppeteer-core
// (which never downloads a browser): the executable is $CHROME_PATH, else Debian's /usr/bin/chromium
// (installed by `npm run setup`), else another usual location; and the flags that run it offline,
// without a display, with WebGPU on SwiftShader when asked.
import { existsSync } from 'node:fs';

const kCandidates = [
  '/usr/bin/chromium',
  '/usr/bin/chromium-browser',
  '/usr/bin/google-chrome-stable',
  '/usr/bin/google-chrome',
  '/Applications/Google Chrome.app/Contents/MacOS/Google Chrome',
  '/Applications/Chromium.app/Contents/MacOS/Chromium',
];

/** The Chromium or Chrome executable; throws, saying how to get one, when there is none. */
export function chromiumPath() {
  const fromEnv = process.env.CHROME_PATH;
  if (fromEnv !== undefined && fromEnv !== '') {
    if (existsSync(fromEnv)) return fromEnv;
    throw new Error(`CHROME_PATH is ${fromEnv}, which does not exist. Point it at a Chromium or Chrome executable.`);
  }
  const found = kCandidates.find((candidate) => existsSync(candidate));
  if (found !== undefined) return found;
  throw new Error(
    'The browser tests need Chromium and found none (looked at $CHROME_PATH, ' +
      kCandidates.join(', ') +
      '). On Debian or Ubuntu run `npm run setup` (it runs `apt-get install chromium`); elsewhere ' +
      'install Chromium or Google Chrome and set CHROME_PATH to its executable.',
  );
}

/** The flags that make Chromium run offline, without a display, in a fresh profile. */
export function chromiumArgs({ webgpu = false } = {}) {
  const args = [
    '--headless',
    '--no-sandbox',
    '--disable-background-networking',
    '--disable-component-update',
    '--disable-sync',
    '--no-first-run',
    '--hide-scrollbars',
    '--disable-dev-shm-usage', // containers often have a small /dev/shm
    '--window-size=1000,700',
  ];
  // WebGPU on SwiftShader (the CPU Vulkan driver Chromium ships) needs the GPU process. Without
  // ANGLE and Vulkan both on SwiftShader, a page that draws into a WebGPU canvas loses its
  // queue's callbacks: mapAsync and onSubmittedWorkDone then fail with "A valid external
  // Instance reference no longer exists".
  if (webgpu)
    args.push('--enable-unsafe-webgpu', '--enable-features=Vulkan', '--use-webgpu-adapter=swiftshader', '--use-angle=swiftshader', '--use-vulkan=swiftshader');
  else args.push('--disable-gpu');
  return args;
}
