// Builds the self-contained viewer page: bundles src/main.js (esbuild),
// minifies src/styles.css and inlines both into src/template.html.
//
//   node scripts/build.mjs [--out PATH]     default: dist/cueball-viewer.html
//
// The output is deterministic (same bytes on every run) and has no external
// URLs; it contains the result token exactly once, inside
// <script type="application/json" id="cueball-result">, for `cueball view`
// and `cueball simulate --html` to replace with the result JSON.
import { build, transform } from 'esbuild';
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { RESULT_TOKEN } from './fill-template.mjs';

const root = resolve(dirname(fileURLToPath(import.meta.url)), '..');
export const DEFAULT_OUT = resolve(root, 'dist/cueball-viewer.html');

/** Returns the page's text. */
export async function buildPage() {
  const bundle = await build({
    entryPoints: [resolve(root, 'src/main.js')],
    bundle: true,
    format: 'iife',
    minify: true,
    target: 'es2020',
    charset: 'utf8',
    legalComments: 'none',
    write: false,
    logLevel: 'silent',
  });
  const script = bundle.outputFiles[0].text.trim();
  const css = await transform(readFileSync(resolve(root, 'src/styles.css'), 'utf8'), {
    loader: 'css',
    minify: true,
    charset: 'utf8',
  });
  const style = css.code.trim();
  const template = readFileSync(resolve(root, 'src/template.html'), 'utf8');

  for (const [what, text] of [['script', script], ['style', style]]) {
    if (/<\/(script|style)|<!--|<script/i.test(text)) throw new Error(`the ${what} would end its element early`);
    if (text.includes(RESULT_TOKEN)) throw new Error(`the ${what} contains the result token`);
  }
  const page = replaceOnce(replaceOnce(template, '/*STYLE*/', style), '/*SCRIPT*/', script);
  checkPage(page);
  return page;
}

function replaceOnce(text, placeholder, value) {
  const parts = text.split(placeholder);
  if (parts.length !== 2) throw new Error(`the template must contain ${placeholder} exactly once`);
  return parts[0] + value + parts[1];
}

/** The contract of the page (README): one token in its element, no URLs. */
export function checkPage(page) {
  const count = page.split(RESULT_TOKEN).length - 1;
  if (count !== 1) throw new Error(`the page contains the result token ${count} times, not once`);
  if (!page.includes(`<script type="application/json" id="cueball-result">${RESULT_TOKEN}</script>`)) {
    throw new Error('the result token is not alone in <script type="application/json" id="cueball-result">');
  }
  const url = /(https?|ftp|wss?):\/\/|@import|url\(\s*["']?(?!data:)/i.exec(page);
  if (url) throw new Error(`the page refers to an external resource: ${page.slice(url.index, url.index + 40)}`);
}

async function main() {
  const args = process.argv.slice(2);
  const at = args.indexOf('--out');
  const out = at >= 0 ? resolve(args[at + 1]) : DEFAULT_OUT;
  const page = await buildPage();
  mkdirSync(dirname(out), { recursive: true });
  writeFileSync(out, page);
  console.log(`wrote ${out} (${Buffer.byteLength(page)} bytes)`);
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  main().catch((err) => {
    console.error(`build failed: ${err.message}`);
    process.exit(1);
  });
}
