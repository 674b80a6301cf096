// The lesson in the page: opens URL (luz.html?lesson=N&lang=..., served), waits for luz.ready,
// then walks the lesson from step N to its last with `lesson next` through window.luz.run, each
// step's move done (its scene loaded, its solver's shots taken; its traces start and the next
// step cancels them) before the next, with no page error. Screenshots of the first and last
// steps (caption, buttons) go to SHOT_PREFIX-first.png and SHOT_PREFIX-last.png.
// Usage: node tests/web/page_lesson.mjs URL LESSON.json SHOT_PREFIX   (NODE_PATH=build-web/npm/node_modules)
import { readFileSync } from 'node:fs';
import { openLuz, openPage } from './browser.mjs';

const [url, lessonFile, shots] = process.argv.slice(2);
if (!url || !lessonFile || !shots) {
  console.error('usage: page_lesson.mjs URL LESSON.json SHOT_PREFIX');
  process.exit(2);
}
const steps = JSON.parse(readFileSync(lessonFile, 'utf8')).steps.length;
const first = Number(new URL(url).searchParams.get('lesson'));

let failed = false;
const check = (ok, what) => {
  if (!ok) console.log(`FAILED: ${what}`);
  if (!ok) failed = true;
};
const { browser, page } = await openPage(() => { failed = true; });
const began = Date.now();
try {
  const outcome = await openLuz(page, url);
  check(outcome.ok, `ready: ${outcome.message}`);
  if (outcome.ok) {
    await page.screenshot({ path: `${shots}-first.png` });
    for (let step = first + 1; step <= steps && !failed; ++step) {
      const result = await page.evaluate(() => window.luz.run('lesson next').then(() => 'done', (e) => 'rejected: ' + e.message));
      check(result === 'done', `step ${step}: run("lesson next"): ${result}`);
    }
    // The last step's move is on screen, and its work (a trace) is cancelled by going back.
    const back = await page.evaluate(() => window.luz.run('lesson prev').then(() => 'done', (e) => 'rejected: ' + e.message));
    check(back === 'done', `run("lesson prev") at the end: ${back}`);
    const again = await page.evaluate(() => window.luz.run('lesson next').then(() => 'done', (e) => 'rejected: ' + e.message));
    check(again === 'done', `run("lesson next") back to the last step: ${again}`);
    await page.screenshot({ path: `${shots}-last.png` });
  }
} finally {
  await browser.close();
}
console.log(`lesson ${url}: steps ${first} to ${steps} in ${((Date.now() - began) / 1000).toFixed(1)} s: ${failed ? 'FAILED' : 'ok'}`);
process.exit(failed ? 1 : 0);
