// Fills the viewer template with a result, as `cueball view` does on the C++
// side: the token is replaced by the result JSON with every "<" written as
// \u003c (still valid JSON, and it cannot close the <script> element).
//
//   node scripts/fill-template.mjs RESULT.json OUT.html [TEMPLATE]
import { readFileSync, writeFileSync } from 'node:fs';
import { dirname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

export const RESULT_TOKEN = '__CUEBALL_RESULT__';

/** The page for one result: templateText with the token replaced by the escaped JSON. */
export function fillTemplate(templateText, resultJsonText) {
  const parts = templateText.split(RESULT_TOKEN);
  if (parts.length !== 2) throw new Error(`the template must contain ${RESULT_TOKEN} exactly once`);
  return parts[0] + resultJsonText.trim().replaceAll('<', '\\u003c') + parts[1];
}

const here = dirname(fileURLToPath(import.meta.url));
export const TEMPLATE_PATH = resolve(here, '../dist/cueball-viewer.html');

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const [result, out, template = TEMPLATE_PATH] = process.argv.slice(2);
  if (!result || !out) {
    console.error('usage: node scripts/fill-template.mjs RESULT.json OUT.html [TEMPLATE]');
    process.exit(2);
  }
  writeFileSync(out, fillTemplate(readFileSync(template, 'utf8'), readFileSync(result, 'utf8')));
  console.log(`wrote ${out}`);
}
