// The Chromium every browser benchmark drives: Debian's (CHROMIUM_PATH to override), headless,
// software WebGL (SwiftShader), nothing running in the background that could skew a timing.
import { chromium } from '@playwright/test';

/** Launches the benchmark browser and opens one page of the usual viewport. */
export async function launchBenchPage() {
  const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM_PATH ?? '/usr/bin/chromium',
    args: [
      '--no-sandbox',
      '--disable-gpu',
      '--disable-background-networking',
      '--disable-component-update',
      '--no-first-run',
      '--use-angle=swiftshader',
      '--enable-unsafe-swiftshader',
    ],
  });
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  return { browser, page };
}
