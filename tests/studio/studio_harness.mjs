// What the studio's browser tests and benchmarks share: starting `sylva studio`
// on a copy of a model, a headless Chromium with software WebGL, and reading
// the page's picture.
import { spawn } from 'node:child_process';
import { cpSync, mkdirSync, rmSync } from 'node:fs';
import { createRequire } from 'node:module';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';

const repository = fileURLToPath(new URL('../..', import.meta.url));
// playwright-core is one of the page's npm packages (web/node_modules).
const require = createRequire(join(repository, 'web', 'package.json'));
const { chromium } = require('playwright-core');

export const modelsDir = fileURLToPath(new URL('models', import.meta.url));
export { repository };

export function parseArgs(argv, defaults) {
  const options = { ...defaults };
  for (let i = 0; i < argv.length; i++) {
    const name = argv[i].replace(/^--/, '');
    if (!(name in options)) throw new Error(`unknown option ${argv[i]}`);
    options[name] = typeof options[name] === 'boolean' ? true : argv[++i];
  }
  return options;
}

// A fresh copy of models/NAME (or any folder) in work/NAME.
export function copyModel(source, work, name) {
  const folder = join(work, name);
  rmSync(folder, { recursive: true, force: true });
  mkdirSync(work, { recursive: true });
  cpSync(source, folder, { recursive: true });
  return folder;
}

// Starts `sylva studio ARGS --port 0` in `cwd`; resolves with {url, process, output(), stop()}
// once it prints its address.
export function startStudio(sylva, args, { cwd, env = {}, timeoutMs = 60000 } = {}) {
  return new Promise((resolve, reject) => {
    const child = spawn(sylva, ['studio', ...args, '--port', '0'], { cwd, env: { ...process.env, ...env },
      stdio: ['ignore', 'pipe', 'pipe'] });
    let output = '';
    let started = false;
    const timer = setTimeout(() => fail(new Error(`sylva studio printed no address in ${timeoutMs} ms:\n${output}`)), timeoutMs);
    const fail = (error) => {
      clearTimeout(timer);
      child.kill('SIGKILL');
      reject(error);
    };
    const read = (chunk) => {
      output += chunk;
      const match = !started && output.match(/Sylva Studio: (https?:\/\/\S+)/);
      if (!match) return;
      started = true;
      clearTimeout(timer);
      resolve({
        url: match[1],
        process: child,
        output: () => output,
        alive: () => child.exitCode === null && child.signalCode === null,
        stop: () => new Promise((done) => {
          if (child.exitCode !== null || child.signalCode !== null) return done();
          child.once('exit', done);
          child.kill('SIGTERM');
          setTimeout(() => child.kill('SIGKILL'), 3000).unref();
        }),
      });
    };
    child.stdout.on('data', read);
    child.stderr.on('data', read);
    child.once('exit', (code, signal) => { if (!started) fail(new Error(`sylva studio exited (${code ?? signal}):\n${output}`)); });
  });
}

export async function launchBrowser(executablePath = '/usr/bin/chromium') {
  return chromium.launch({
    executablePath,
    // Software WebGL: SwiftShader through ANGLE, no GPU needed.
    args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist'],
  });
}

// Waits until the page holds a state satisfying `predicate` (a function of
// state, evaluated in the page) with its scene on screen.
export async function waitForStudio(page, predicate = 'true', timeout = 60000) {
  await page.waitForFunction((source) => {
    const studio = window.sylvaStudio;
    const state = studio?.state;
    if (!state || state.busy) return false;
    // eslint-disable-next-line no-new-func
    const ok = new Function('state', 'studio', `return (${source});`)(state, studio);
    return ok && studio.sceneVersion >= state.scene_version && studio.animating === null;
  }, typeof predicate === 'function' ? `(${predicate})(state, studio)` : predicate, { timeout });
  return page.evaluate(() => window.sylvaStudio.state);
}

// The view's pixels as a grid of cells, each the count of pixels differing
// from the background: {cells, columns, rows, total}.
export async function pictureCells(page, columns = 32, rows = 32) {
  return page.evaluate(({ columns, rows }) => {
    const source = document.querySelector('canvas.view');
    const studio = window.sylvaStudio;
    studio.viewer.renderNow();
    const width = source.width;
    const height = source.height;
    const copy = document.createElement('canvas');
    copy.width = width;
    copy.height = height;
    const context = copy.getContext('2d', { willReadFrequently: true });
    context.drawImage(source, 0, 0);
    const data = context.getImageData(0, 0, width, height).data;
    const background = (studio.state.view?.background || [0, 0, 0]).map((c) => Math.round(c * 255));
    const cells = new Array(columns * rows).fill(0);
    let total = 0;
    for (let y = 0; y < height; y++) {
      const row = Math.min(rows - 1, Math.floor((y * rows) / height));
      for (let x = 0; x < width; x++) {
        const at = (y * width + x) * 4;
        const differs = Math.abs(data[at] - background[0]) > 12 || Math.abs(data[at + 1] - background[1]) > 12
          || Math.abs(data[at + 2] - background[2]) > 12;
        if (!differs) continue;
        cells[row * columns + Math.min(columns - 1, Math.floor((x * columns) / width))]++;
        total++;
      }
    }
    return { cells, columns, rows, total };
  }, { columns, rows });
}

// How much two pictures differ: the sum of the cells' count differences.
export function pictureDifference(a, b) {
  return a.cells.reduce((sum, count, i) => sum + Math.abs(count - b.cells[i]), 0);
}
