// Helpers shared by the tests and scripts: the cueball binary, headless
// Chromium, and pages made from simulation results.
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { fillTemplate, TEMPLATE_PATH } from './fill-template.mjs';

export const VIEWER_DIR = resolve(dirname(fileURLToPath(import.meta.url)), '..');

/** The cueball binary: $CUEBALL_BIN, or ../build/release/cueball relative to viewer/. */
export function cueballBinary() {
  return resolve(VIEWER_DIR, process.env.CUEBALL_BIN || '../build/release/cueball');
}

/** Path to Chromium: $CHROMIUM, or Debian's /usr/bin/chromium. */
export function chromiumPath() {
  return process.env.CHROMIUM || '/usr/bin/chromium';
}

export const CHROMIUM_ARGS = [
  '--headless',
  '--no-sandbox',
  '--disable-gpu',
  '--disable-quic',
  '--no-first-run',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
];

/** Launches headless Chromium through playwright-core. */
export async function launchChromium() {
  const { chromium } = await import('playwright-core');
  return chromium.launch({ executablePath: chromiumPath(), args: CHROMIUM_ARGS });
}

export function tempDir(prefix = 'cueball-viewer-') {
  return mkdtempSync(join(tmpdir(), prefix));
}

/** Runs `cueball ARGS...`; returns stdout. */
export function cueball(args) {
  return execFileSync(cueballBinary(), args, { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
}

/**
 * Simulates a scenario (null: the built-in 9-ball break) into dir and writes
 * the page from the template with fillTemplate(). Returns the paths and the
 * parsed result.
 */
export function simulateToPage(dir, name, scenario = null, template = TEMPLATE_PATH) {
  const json = join(dir, `${name}.json`);
  cueball(['simulate', ...(scenario ? [scenario] : []), '-o', json]);
  const text = readFileSync(json, 'utf8');
  const html = join(dir, `${name}.html`);
  writeFileSync(html, fillTemplate(readFileSync(template, 'utf8'), text));
  return { json, html, result: JSON.parse(text) };
}
