/*
 * Headless Firefox (SpiderMonkey) for the browser tests, through puppeteer-core and WebDriver
 * BiDi: the executable is scripts/firefox.mjs's. Like Chromium, a missing browser is an error that
 * says how to install one.
 */

import puppeteer from 'puppeteer-core';
import { firefoxPath } from '../../scripts/firefox.mjs';
import type { LaunchedBrowser } from './chromium';

export async function launchFirefox(): Promise<LaunchedBrowser> {
  const browser = await puppeteer.launch({
    browser: 'firefox',
    executablePath: firefoxPath(),
    headless: true,
    defaultViewport: { width: 1000, height: 700, deviceScaleFactor: 1 },
    protocolTimeout: 300_000,
  });
  return {
    browser,
    close: () => browser.close(),
  };
}
