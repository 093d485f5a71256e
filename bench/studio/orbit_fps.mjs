// The studio's page on a big plant: frames per second while the camera is
// orbited by mouse drags, and the time from saving the model to its new
// picture on screen. Run by hand (bench/README.md):
//   node bench/studio/orbit_fps.mjs --sylva build/src/sylva [--model bench/models/plant_1m.l,bench/models/plant_1m.v]
//        [--seconds 10] [--work /tmp/sylva-orbit] [--chromium /usr/bin/chromium] [--width 1280 --height 800]
import { copyFileSync, mkdirSync, rmSync, utimesSync } from 'node:fs';
import { basename, join, resolve } from 'node:path';
import { launchBrowser, parseArgs, repository, startStudio, waitForStudio } from '../../tests/studio/studio_harness.mjs';

const options = parseArgs(process.argv.slice(2), {
  sylva: join(repository, 'build/src/sylva'),
  model: 'bench/models/plant_1m.l,bench/models/plant_1m.v',
  seconds: '10',
  work: '/tmp/sylva-orbit',
  chromium: '/usr/bin/chromium',
  width: '1280',
  height: '800',
});
const files = options.model.split(',').map((f) => resolve(repository, f));
const folder = join(resolve(options.work), basename(files[0]).replace(/\.[^.]*$/, ''));
rmSync(folder, { recursive: true, force: true });
mkdirSync(folder, { recursive: true });
for (const file of files) copyFileSync(file, join(folder, basename(file)));

const seconds = (ms) => `${(ms / 1000).toFixed(2)} s`;
const studio = await startStudio(resolve(options.sylva), files.map((f) => basename(f)), {
  cwd: folder, env: { SYLVA_CACHE_DIR: join(resolve(options.work), 'model-cache') }, timeoutMs: 600000 });
const browser = await launchBrowser(options.chromium);
try {
  const page = await browser.newPage({ viewport: { width: Number(options.width), height: Number(options.height) } });
  await page.goto(studio.url);
  await waitForStudio(page, 'true', 600000);

  // The whole derivation, then its picture.
  let started = Date.now();
  await page.evaluate(() => fetch('/api/run', { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: '{}' }));
  let state = await waitForStudio(page, 'state.finished || state.step >= state.derivation_length', 900000);
  const runToPicture = Date.now() - started;
  const firstLoadMs = await page.evaluate(() => window.sylvaStudio.sceneLoadMs);
  const { triangles, lines } = await page.evaluate(() => window.sylvaStudio.viewer.renderer.info.render);
  console.log(`${basename(files[0])}: step ${state.step}, ${state.modules.toLocaleString('en-US')} modules, `
    + `${triangles.toLocaleString('en-US')} triangles and ${lines.toLocaleString('en-US')} lines drawn; run to the end and show it: ${seconds(runToPicture)} `
    + `(the page's fetch, parse and first frame: ${seconds(firstLoadMs)})`);

  // Orbit: left drags around the view's middle for the given time.
  const box = await page.locator('canvas.view').boundingBox();
  const cx = box.x + box.width / 2;
  const cy = box.y + box.height / 2;
  const frames = () => page.evaluate(() => window.sylvaStudio.framesRendered);
  // The first picture drawn to the end first (readPixels waits for the GPU):
  // the orbit's frames are not to queue behind it.
  await page.evaluate(() => {
    const gl = window.sylvaStudio.viewer.renderer.getContext();
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
  });
  const framesBefore = await frames();
  started = Date.now();
  let moves = 0;
  await page.mouse.move(cx, cy);
  await page.mouse.down();
  while (Date.now() - started < Number(options.seconds) * 1000) {
    const angle = moves * 0.05;
    await page.mouse.move(cx + 200 * Math.sin(angle), cy + 60 * Math.sin(angle * 0.7));
    moves++;
  }
  await page.mouse.up();
  await page.evaluate(() => window.sylvaStudio.viewer.nextFrame());
  const elapsed = Date.now() - started;
  const rendered = (await frames()) - framesBefore;
  console.log(`orbit: ${rendered} frames in ${seconds(elapsed)} = ${((1000 * rendered) / elapsed).toFixed(1)} frames/s `
    + `(${moves} mouse moves)`);

  // One frame drawn to the end (readPixels waits for the GPU), the model still.
  const frameMs = await page.evaluate(() => {
    const { viewer } = window.sylvaStudio;
    const gl = viewer.renderer.getContext();
    const pixel = new Uint8Array(4);
    const times = [];
    for (let i = 0; i < 3; i++) {
      const t = performance.now();
      viewer.renderNow();
      gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
      times.push(performance.now() - t);
    }
    return Math.min(...times);
  });
  console.log(`one frame, finished: ${frameMs.toFixed(1)} ms (best of 3)`);

  // Save to picture: the model file touched, until the new scene is on screen.
  const sceneBefore = state.scene_version;
  const now = new Date();
  started = Date.now();
  utimesSync(join(folder, basename(files[0])), now, now);
  state = await waitForStudio(page, `state.scene_version > ${sceneBefore}`, 900000);
  const pageMs = await page.evaluate(() => window.sylvaStudio.sceneLoadMs);
  console.log(`save to picture: ${seconds(Date.now() - started)}, of which the page's fetch, parse and first frame `
    + `${seconds(pageMs)} (now at step ${state.step}, ${state.modules.toLocaleString('en-US')} modules)`);
  await page.screenshot({ path: join(resolve(options.work), `${basename(folder)}.png`), timeout: 600000 });
} finally {
  await browser.close();
  await studio.stop();
}
