// The picture in the README: the built-in 9-ball break in the viewer, mid-
// break with trails, at 1200 x 800 (docs/viewer.png).
//
//   npm run screenshot [-- --time 1.2 --out ../docs/viewer.png]
//   npm run screenshot -- --result RESULT.json --time 2 --out shot.png
import { readFileSync, writeFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { launchChromium, simulateToPage, tempDir, VIEWER_DIR } from './cueball.mjs';
import { fillTemplate, TEMPLATE_PATH } from './fill-template.mjs';

const args = process.argv.slice(2);
const option = (name, fallback) => {
  const at = args.indexOf(name);
  return at >= 0 ? args[at + 1] : fallback;
};
const time = Number(option('--time', '1.2'));
const out = resolve(option('--out', resolve(VIEWER_DIR, '../docs/viewer.png')));

const result = option('--result', null);
let html;
if (result) {
  html = join(tempDir(), 'shot.html');
  writeFileSync(html, fillTemplate(readFileSync(TEMPLATE_PATH, 'utf8'), readFileSync(result, 'utf8')));
} else {
  html = simulateToPage(tempDir(), 'break').html;
}
const browser = await launchChromium();
try {
  const page = await browser.newPage({ viewport: { width: 1200, height: 800 }, deviceScaleFactor: 1 });
  await page.goto(pathToFileURL(html).href);
  await page.waitForFunction(() => window.cueballViewer && window.cueballViewer.ready);
  await page.evaluate((t) => window.cueballViewer.seek(t), time);
  await page.screenshot({ path: out });
  console.log(`wrote ${out} (t = ${time} s)`);
} finally {
  await browser.close();
}
