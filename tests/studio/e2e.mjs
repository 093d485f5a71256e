// Browser end-to-end tests of `sylva studio`: each test starts the studio on a
// copy of a small model (models/), drives the page in headless Chromium and
// looks at what it draws. Screenshots are left in the work folder.
//   node tests/studio/e2e.mjs --sylva build/src/sylva --work DIR [--chromium PATH] [--only NAME]
import assert from 'node:assert/strict';
import { readFileSync, symlinkSync, writeFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import {
  copyModel, launchBrowser, modelsDir, parseArgs, pictureCells, pictureDifference, startStudio, waitForStudio,
} from './studio_harness.mjs';

const options = parseArgs(process.argv.slice(2), { sylva: '', work: '', chromium: '/usr/bin/chromium', only: '' });
if (!options.sylva || !options.work) {
  console.error('usage: node tests/studio/e2e.mjs --sylva PATH --work DIR [--chromium PATH] [--only NAME]');
  process.exit(2);
}
const sylva = resolve(options.sylva);
const work = resolve(options.work);
const cacheDir = join(work, 'model-cache');

// The picture must change by more than this many pixels to count as another picture.
const CHANGED = 50;

let browser;
let shot = 0;

// Opens the studio on a fresh copy of models/NAME and the page on it.
async function open(name, files) {
  const folder = copyModel(join(modelsDir, name.split('+')[0]), work, name.replace('+', '-'));
  const studio = await startStudio(sylva, files, { cwd: folder, env: { SYLVA_CACHE_DIR: cacheDir } });
  const page = await browser.newPage({ viewport: { width: 960, height: 640 } });
  const problems = [];
  page.on('pageerror', (error) => problems.push(error.message));
  await page.goto(studio.url);
  const close = async () => {
    await page.close();
    await studio.stop();
  };
  return { folder, studio, page, problems, close };
}

async function screenshot(page, label) {
  const path = join(work, `${String(++shot).padStart(2, '0')}-${label}.png`);
  await page.screenshot({ path });
  return path;
}

// Clicks the trunk of a tree standing in the middle: the lowest drawn cell of
// the picture's middle column (a 64 x 64 pictureCells), a little above its foot.
async function clickTrunk(page, picture) {
  const box = await page.locator('canvas.view').boundingBox();
  const column = 32;
  let row = 63;
  while (row > 0 && picture.cells[row * 64 + column] + picture.cells[row * 64 + column - 1] === 0) row--;
  row -= 2;
  await page.mouse.click(box.x + (box.width * column) / 64 - 1, box.y + (box.height * (row + 0.5)) / 64);
}

function assertPlantDrawn(picture, what) {
  const { cells, columns, rows } = picture;
  const at = (c, r) => cells[r * columns + c];
  const corners = [at(0, 0), at(columns - 1, 0), at(0, rows - 1), at(columns - 1, rows - 1)];
  assert.deepEqual(corners, [0, 0, 0, 0], `${what}: the corners are background`);
  let centre = 0;
  for (let r = rows / 4; r < (3 * rows) / 4; r++) for (let c = columns / 4; c < (3 * columns) / 4; c++) centre += at(c, r);
  assert.ok(centre > 100, `${what}: the plant is drawn in the middle (${centre} pixels)`);
}

async function click(page, action) {
  await page.click(`button[data-action="${action}"]`);
}

// Each test's model (a folder of models/) and the files the studio opens.
// The command line of each model; its folder under models/ is the name up to a '+'.
const MODELS = {
  branching2d: ['branching.l', 'branching.v'],
  tree3d: ['tree.l', 'tree.v'],
  // Its spheres and cylinders sent as instances, as a big plant's are.
  'tree3d+instanced': ['tree.l', 'tree.v', '--instances-above', '0'],
  crash: ['crash.l'],
};

// [name, model, test]
const tests = [
  ['the picture; Step and Run advance it', 'branching2d', async ({ page }) => {
    let state = await waitForStudio(page, 'state.scene_version > 0');
    assert.equal(state.error, null);
    await click(page, 'rewind');
    state = await waitForStudio(page, `state.step === ${state.animation?.first ?? 0}`);
    const first = await pictureCells(page);
    await screenshot(page, 'branching-first-frame');
    const before = state.step;
    await click(page, 'step');
    state = await waitForStudio(page, `state.step > ${before}`);
    const stepped = await pictureCells(page);
    assert.ok(pictureDifference(first, stepped) > CHANGED, 'Step changes the picture');
    assert.match(await page.textContent('.readout.step'), new RegExp(`step ${state.step} /`));
    await click(page, 'run');
    state = await waitForStudio(page, 'state.finished || state.step >= (state.animation?.last ?? state.derivation_length)');
    const ran = await pictureCells(page);
    assertPlantDrawn(ran, 'after Run');
    assert.ok(pictureDifference(stepped, ran) > CHANGED, 'Run changes the picture');
    await screenshot(page, 'branching-after-run');
  }],

  ['a slider changes the picture, not the file', 'branching2d', async ({ page, folder }) => {
    const model = join(folder, 'branching.l');
    const text = readFileSync(model, 'utf8');
    let state = await waitForStudio(page, 'state.scene_version > 0');
    assert.ok(state.params.some((p) => p.define === 'ANGLE'), 'the ANGLE define is offered as a parameter');
    await click(page, 'run');
    state = await waitForStudio(page, 'state.finished');
    const shown = await pictureCells(page);
    const slider = page.locator('.slider-param', { hasText: /Branching angle|ANGLE/ }).locator('input');
    await slider.evaluate((input) => {
      input.value = 70;
      input.dispatchEvent(new Event('input', { bubbles: true }));
    });
    state = await waitForStudio(page, `state.scene_version > ${state.scene_version} && state.params.some((p) => p.modified)`);
    assert.ok(pictureDifference(shown, await pictureCells(page)) > CHANGED, 'the slider changes the picture');
    assert.equal(readFileSync(model, 'utf8'), text, 'the slider leaves the file as it is');
    assert.ok(await page.isEnabled('text=Write to files'));
    await screenshot(page, 'branching-slider-70');
    await page.click('.button-row >> text=Reset');
    await waitForStudio(page, '!state.params_modified && state.params.every((p) => !p.modified)');
  }],

  ['an edit reloads the picture; a translation error keeps it', 'branching2d', async ({ page, folder }) => {
    const model = join(folder, 'branching.l');
    const text = readFileSync(model, 'utf8');
    let state = await waitForStudio(page, 'state.scene_version > 0');
    await click(page, 'run');
    state = await waitForStudio(page, 'state.finished');
    const shown = await pictureCells(page);
    writeFileSync(model, text.replace('#define ANGLE 30', '#define ANGLE 12'));
    state = await waitForStudio(page, `state.scene_version > ${state.scene_version}`);
    assert.equal(state.error, null);
    if (!state.finished) {
      await click(page, 'run');
      state = await waitForStudio(page, 'state.finished');
    }
    const edited = await pictureCells(page);
    assert.ok(pictureDifference(shown, edited) > CHANGED, 'the edit changes the picture');
    await screenshot(page, 'branching-edited');

    const broken = text.replace('F(x) : {', 'F(x) :: {');
    const errorLine = broken.split('\n').findIndex((line) => line.includes('F(x) ::')) + 1;
    writeFileSync(model, broken);
    state = await waitForStudio(page, 'state.error !== null');
    await page.waitForSelector('.error-panel:not([hidden])');
    const panel = await page.textContent('.error-panel');
    assert.ok(panel.includes(`branching.l:${errorLine}`), `the error panel names branching.l:${errorLine}: ${panel}`);
    assert.ok(panel.includes('F(x) :: {'), 'the error panel shows the source line');
    assert.ok(pictureDifference(edited, await pictureCells(page)) <= CHANGED, 'the last good picture stays');
    await screenshot(page, 'branching-translation-error');
    writeFileSync(model, text);
    await waitForStudio(page, 'state.error === null');
    await page.waitForSelector('.error-panel', { state: 'hidden' });
  }],

  ['files outside the model folder are refused', 'branching2d', async ({ studio, folder }) => {
    const base = new URL(studio.url);
    const get = async (path) => (await fetch(new URL(path, base), { redirect: 'manual' })).status;
    assert.equal(await get('/files/branching.l'), 200);
    writeFileSync(join(work, 'outside.txt'), 'not the model\'s');
    symlinkSync(join(work, 'outside.txt'), join(folder, 'outside-link.txt'));
    for (const path of ['/files/../outside.txt', '/files/%2e%2e/outside.txt', '/files/..%2foutside.txt',
      '/files/outside-link.txt', '/files//etc/passwd']) {
      const status = await get(path);
      assert.ok(status === 403 || status === 404, `${path} is refused (${status})`);
    }
  }],

  ['3D picture and picking a module', 'tree3d', async ({ page }) => {
    await waitForStudio(page, 'state.scene_version > 0');
    await page.click('button[data-action="run"]');
    const state = await waitForStudio(page, 'state.finished || state.step >= state.derivation_length');
    assertPlantDrawn(await pictureCells(page), '3D tree');
    assert.equal(state.view.perspective, true);
    await screenshot(page, 'tree3d');
    // Clicking the trunk inspects the F there.
    await clickTrunk(page, await pictureCells(page, 64, 64));
    await page.waitForSelector('.module-name');
    assert.equal(await page.textContent('.module-name'), 'F');
    await screenshot(page, 'tree3d-picked');
  }],

  ['a big scene as instances: drawn, picked', 'tree3d+instanced', async ({ page }) => {
    await waitForStudio(page, 'state.scene_version > 0');
    await page.click('button[data-action="run"]');
    const state = await waitForStudio(page, 'state.finished || state.step >= state.derivation_length');
    assert.equal(state.instances, true, 'the scene came as instances');
    await page.waitForFunction(() => window.sylvaStudio.sceneVersion >= window.sylvaStudio.state.scene_version);
    const picture = await pictureCells(page, 64, 64);
    assertPlantDrawn(picture, 'instanced 3D tree');
    await screenshot(page, 'tree3d-instanced');
    // The trunk, as in the test above: an instanced cylinder of module F.
    await clickTrunk(page, picture);
    await page.waitForSelector('.module-name');
    assert.equal(await page.textContent('.module-name'), 'F');
    await screenshot(page, 'tree3d-instanced-picked');
  }],

  ['a crashing model is reported and a fixed save recovers', 'crash', async ({ page, studio, folder }) => {
    await waitForStudio(page, 'state.scene_version > 0');
    await page.click('button[data-action="run"]');
    const state = await waitForStudio(page, 'state.error !== null', 90000);
    assert.equal(state.error.kind, 'crash');
    await page.waitForSelector('.error-panel:not([hidden])');
    assert.match(await page.textContent('.error-panel'), /crash/i);
    await screenshot(page, 'crash-reported');
    assert.ok(studio.alive(), 'the server is still up');
    const model = join(folder, 'crash.l');
    writeFileSync(model, readFileSync(model, 'utf8').replace('if (steps > 2) *nowhere = steps;', ''));
    await waitForStudio(page, 'state.error === null');
    await page.click('button[data-action="run"]');
    await waitForStudio(page, 'state.error === null && (state.finished || state.step >= state.derivation_length)');
    assertPlantDrawn(await pictureCells(page), 'after the fix');
    await screenshot(page, 'crash-fixed');
  }],
];

browser = await launchBrowser(options.chromium);
let failed = 0;
for (const [name, model, test] of tests) {
  if (options.only && !name.includes(options.only)) continue;
  const started = Date.now();
  let opened = null;
  try {
    opened = await open(model, MODELS[model]);
    await test(opened);
    assert.deepEqual(opened.problems, [], 'the page threw');
    console.log(`ok   ${name} (${((Date.now() - started) / 1000).toFixed(1)} s)`);
  } catch (error) {
    failed++;
    const seen = opened ? await opened.page.evaluate(() => {
      const s = window.sylvaStudio;
      return s && JSON.stringify({ step: s.state?.step, scene: s.state?.scene_version, shown: s.sceneVersion,
        busy: s.state?.busy, animating: s.animating, error: s.state?.error?.message });
    }).catch(() => null) : null;
    if (opened) await screenshot(opened.page, 'failed').catch(() => {});
    console.log(`FAIL ${name} (${((Date.now() - started) / 1000).toFixed(1)} s)\n${error.stack || error}`
      + `${seen ? `\n  page: ${seen}` : ''}${opened ? `\n  studio output:\n${opened.studio.output()}` : ''}`);
  } finally {
    await opened?.close();
  }
}
await browser.close();
console.log(`screenshots in ${work}`);
process.exit(failed ? 1 : 0);
