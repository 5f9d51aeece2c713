// Headless Firefox for the browser tests that check SpiderMonkey, through puppeteer-core (which
// never downloads a browser): the executable is $FIREFOX_PATH, else Debian's /usr/bin/firefox-esr
// (installed by `npm run setup`), else another usual location.
import { existsSync } from 'node:fs';

const kCandidates = ['/usr/bin/firefox-esr', '/usr/bin/firefox', '/Applications/Firefox.app/Contents/MacOS/firefox'];

/** The Firefox executable; throws, saying how to get one, when there is none. */
export function firefoxPath() {
  const fromEnv = process.env.FIREFOX_PATH;
  if (fromEnv !== undefined && fromEnv !== '') {
    if (existsSync(fromEnv)) return fromEnv;
    throw new Error(`FIREFOX_PATH is ${fromEnv}, which does not exist. Point it at a Firefox executable.`);
  }
  const found = kCandidates.find((candidate) => existsSync(candidate));
  if (found !== undefined) return found;
  throw new Error(
    'The SpiderMonkey tests need Firefox and found none (looked at $FIREFOX_PATH, ' +
      kCandidates.join(', ') +
      '). On Debian or Ubuntu run `npm run setup` (it runs `apt-get install firefox-esr`); elsewhere ' +
      'install Firefox and set FIREFOX_PATH to its executable.',
  );
}
