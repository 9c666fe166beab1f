// The checked-in dist/cueball-viewer.html is what `npm run build` makes from
// the sources (rebuilt to a temporary path and compared byte for byte), and
// the build is deterministic.
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { test } from 'node:test';
import { DEFAULT_OUT } from '../scripts/build.mjs';
import { tempDir, VIEWER_DIR } from '../scripts/cueball.mjs';

test('dist/cueball-viewer.html is up to date with the sources (run `npm run build`)', () => {
  const dir = tempDir();
  const outputs = ['a.html', 'b.html'].map((name) => {
    const out = join(dir, name);
    execFileSync(process.execPath, ['scripts/build.mjs', '--out', out], { cwd: VIEWER_DIR, stdio: 'pipe' });
    return readFileSync(out);
  });
  assert.ok(outputs[0].equals(outputs[1]), 'two builds give the same bytes');
  const checkedIn = readFileSync(DEFAULT_OUT);
  assert.ok(
    outputs[0].equals(checkedIn),
    'dist/cueball-viewer.html differs from a fresh build: run `npm run build` and commit the result',
  );
});
