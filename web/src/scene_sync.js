// Keeps the view showing the server's newest scene: loads /api/scene.glb when
// scene_version grows (one load at a time, the last good scene staying up
// meanwhile and when a load fails) and tells waiters when a version is on screen.
import { getInstances, getScene } from './api.js';
import { parseScene } from './scene_loader.js';

export class SceneSync {
  constructor(viewer, viewId, onDisplayed) {
    this.viewer = viewer;
    this.viewId = viewId;
    this.onDisplayed = onDisplayed;
    this.wanted = 0;
    this.displayed = 0;
    this.loading = false;
    this.waiters = [];
    this.lastError = null;
    this.lastLoadMs = null; // fetch, parse and first frame of the last scene
  }

  want(version) {
    if (version > this.wanted) this.wanted = version;
    this.pump();
  }

  // Another view: the same version must be fetched again.
  reload() {
    this.displayed = 0;
    this.pump();
  }

  // Resolves when `version` or a newer one is displayed, or loading it failed.
  waitFor(version) {
    if (this.displayed >= version || version == null) return Promise.resolve();
    return new Promise((resolve) => this.waiters.push({ version, resolve }));
  }

  settle(failedUpTo = 0) {
    this.waiters = this.waiters.filter((w) => {
      if (w.version > this.displayed && w.version > failedUpTo) return true;
      w.resolve();
      return false;
    });
  }

  async pump() {
    if (this.loading) return;
    this.loading = true;
    try {
      while (this.displayed < this.wanted) {
        const target = this.wanted;
        const started = performance.now();
        try {
          const answer = await getScene(this.viewId());
          if (answer) {
            const instances = await getInstances(this.viewId());
            const model = await parseScene(answer.buffer, instances, this.viewer.renderMode);
            this.viewer.setModel(model);
            await this.viewer.nextFrame();
          }
          this.displayed = Math.max(answer?.version ?? target, target);
          this.lastError = null;
          this.lastLoadMs = performance.now() - started;
          this.onDisplayed(this.displayed, this.lastLoadMs);
          this.settle();
        } catch (error) {
          // Keep the last good scene; try again when the server has a newer one.
          this.lastError = error;
          console.warn('scene load failed:', error);
          this.settle(target);
          if (this.wanted === target) break;
        }
      }
    } finally {
      this.loading = false;
    }
  }
}
