// Regenerates the unit-test fixtures in test/fixtures/ from the cueball
// binary ($CUEBALL_BIN): simulation results with `samples` (--sample HZ), the
// C++ states that test/motion.test.mjs compares the page's evaluation with.
// Written as compact JSON (numbers unchanged: JSON round-trips doubles).
//
//   npm run fixtures
import { readFileSync, writeFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { cueball, tempDir, VIEWER_DIR } from './cueball.mjs';

const scenarios = resolve(VIEWER_DIR, 'test/fixtures/scenarios');
export const FIXTURES = [
  { name: 'nine-ball-break', scenario: null, hz: 50 }, // the built-in break
  { name: 'snooker-break', scenario: join(scenarios, 'snooker-break.json'), hz: 10 },
  { name: 'cut-shot', scenario: join(scenarios, 'cut-shot.json'), hz: 50 }, // docs/example-cut-shot.json: pockets the 1
  { name: 'carom-side-spin', scenario: join(scenarios, 'carom-side-spin.json'), hz: 20 }, // no pockets
];

const dir = tempDir();
for (const f of FIXTURES) {
  const raw = join(dir, `${f.name}.json`);
  cueball(['simulate', ...(f.scenario ? [f.scenario] : []), '-o', raw, '--sample', String(f.hz)]);
  const out = resolve(VIEWER_DIR, 'test/fixtures', `${f.name}.json`);
  writeFileSync(out, `${JSON.stringify(JSON.parse(readFileSync(raw, 'utf8')))}\n`);
  console.log(`wrote ${out}`);
}
