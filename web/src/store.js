// The server's state (GET /api/state), polled ~4x/s and also taken from every
// POST's answer; listeners hear each newer version once.
import { getJSON } from './api.js';

const POLL_MS = 250;

export class Store {
  constructor() {
    this.state = null;
    this.listeners = [];
    this.connected = true;
    this.onConnection = () => {};
  }

  subscribe(listener) {
    this.listeners.push(listener);
    if (this.state) listener(this.state, null);
  }

  // A state from a poll or a POST answer; older versions than the one held are dropped.
  apply(state) {
    if (!state || typeof state.version !== 'number') return this.state;
    if (this.state && state.version < this.state.version) return this.state;
    const previous = this.state;
    if (previous && state.version === previous.version) return previous;
    this.state = state;
    for (const listener of this.listeners) listener(state, previous);
    return state;
  }

  async refresh() {
    try {
      const state = this.apply(await getJSON('/api/state'));
      this.setConnected(true);
      return state;
    } catch (error) {
      this.setConnected(false);
      return this.state;
    }
  }

  setConnected(connected) {
    if (connected === this.connected) return;
    this.connected = connected;
    this.onConnection(connected);
  }

  startPolling() {
    const tick = async () => {
      await this.refresh();
      setTimeout(tick, document.hidden ? POLL_MS * 4 : POLL_MS);
    };
    tick();
  }
}
