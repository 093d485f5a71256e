// lpfg's Animate menu (manual 1.2.3, animation file 8.2): Step, Run, Forever,
// Stop, Rewind. Each step waits until its picture is on screen before the
// next, so a slow model never queues steps.
import { postJSON } from './api.js';

const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));

export class Animator {
  // waitForScene(version) resolves once that scene (or a later one) is displayed.
  constructor(store, waitForScene, onError) {
    this.store = store;
    this.waitForScene = waitForScene;
    this.onError = onError;
    this.mode = null; // null, 'step', 'run', 'forever', 'rewind'
    this.generation = 0;
    this.listeners = [];
  }

  onChange(listener) {
    this.listeners.push(listener);
  }

  setMode(mode) {
    this.mode = mode;
    for (const listener of this.listeners) listener(mode);
  }

  animation() {
    const state = this.store.state || {};
    const a = state.animation || {};
    return {
      first: a.first ?? 0,
      last: a.last ?? state.derivation_length ?? 0,
      step: Math.max(1, a.step ?? 1),
      interval: Math.max(0, a.swap_interval_ms ?? 0),
    };
  }

  atEnd(state) {
    return !!(state.finished || state.stopped || state.error || state.step >= this.animation().last);
  }

  async command(path, body) {
    const state = this.store.apply(await postJSON(path, body));
    await this.waitForScene(state.scene_version);
    return this.store.state;
  }

  // One user command at a time; Stop ends a Run or Forever between steps.
  async exclusive(mode, action) {
    if (this.mode) return;
    const generation = ++this.generation;
    this.setMode(mode);
    try {
      await action(() => generation === this.generation);
    } catch (e) {
      this.onError(e.message);
    } finally {
      if (generation === this.generation) this.setMode(null);
    }
  }

  step() {
    return this.exclusive('step', () => this.command('/api/step', { count: this.animation().step }));
  }

  run() {
    return this.exclusive('run', (going) => this.runToLast(going));
  }

  forever() {
    return this.exclusive('forever', async (going) => {
      while (going()) {
        await this.runToLast(going);
        if (!going() || this.store.state.error) return;
        await this.rewindToFirst();
        await sleep(this.animation().interval);
      }
    });
  }

  stop() {
    this.generation++;
    this.setMode(null);
  }

  rewind() {
    this.stop();
    return this.exclusive('rewind', () => this.rewindToFirst());
  }

  async rewindToFirst() {
    await this.command('/api/rewind');
    const { first } = this.animation();
    if (first > 0) await this.command('/api/run', { to: first });
  }

  async runToLast(going) {
    let state = this.store.state;
    while (going() && !this.atEnd(state)) {
      const before = state.step;
      state = await this.command('/api/step', { count: this.animation().step });
      if (state.step === before && !state.finished) return; // the model cannot go on
      if (!this.atEnd(state)) await sleep(this.animation().interval);
    }
  }
}
