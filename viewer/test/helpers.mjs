import { readFileSync } from 'node:fs';
import { dirname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

export const FIXTURE_DIR = resolve(dirname(fileURLToPath(import.meta.url)), 'fixtures');
export const FIXTURE_NAMES = ['nine-ball-break', 'snooker-break', 'cut-shot', 'carom-side-spin'];

export function readFixture(name) {
  return JSON.parse(readFileSync(resolve(FIXTURE_DIR, `${name}.json`), 'utf8'));
}
