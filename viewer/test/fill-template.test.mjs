// fillTemplate (what `cueball view` does on the C++ side) and the contract of
// the built page: one token, in its JSON <script>, no external URLs.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { test } from 'node:test';
import { checkPage } from '../scripts/build.mjs';
import { fillTemplate, RESULT_TOKEN, TEMPLATE_PATH } from '../scripts/fill-template.mjs';

const template = readFileSync(TEMPLATE_PATH, 'utf8');

test('the built page holds the token once, alone in its JSON script element', () => {
  assert.equal(template.split(RESULT_TOKEN).length, 2);
  assert.ok(template.includes(`<script type="application/json" id="cueball-result">${RESULT_TOKEN}</script>`));
  checkPage(template);
});

test('the built page loads nothing: no URLs, no external scripts, styles or fonts', () => {
  assert.doesNotMatch(template, /https?:\/\//i);
  assert.doesNotMatch(template, /<script[^>]*\ssrc=/i);
  assert.doesNotMatch(template, /<link[^>]*rel="?stylesheet/i);
  assert.doesNotMatch(template, /@import|@font-face/i);
  assert.equal((template.match(/<style>/g) || []).length, 1);
  assert.equal((template.match(/<script[ >]/g) || []).length, 2);
  assert.ok(Buffer.byteLength(template) < 60_000, `bundle ${Buffer.byteLength(template)} bytes`);
});

test('fillTemplate escapes "<" so the JSON cannot close its script element', () => {
  const result = JSON.stringify({ name: '</script><script>alert(1)</script>', n: 1.5, $: '$& $1' });
  const page = fillTemplate(template, result);
  assert.ok(!page.includes(RESULT_TOKEN));
  const open = '<script type="application/json" id="cueball-result">';
  const start = page.indexOf(open) + open.length;
  const body = page.slice(start, page.indexOf('</script>', start));
  assert.ok(!body.includes('<'));
  assert.deepEqual(JSON.parse(body), JSON.parse(result), 'still the same JSON ($ patterns untouched)');
});

test('fillTemplate refuses a template without exactly one token', () => {
  assert.throws(() => fillTemplate('<html></html>', '{}'), /exactly once/);
  assert.throws(() => fillTemplate(`${RESULT_TOKEN}${RESULT_TOKEN}`, '{}'), /exactly once/);
});
