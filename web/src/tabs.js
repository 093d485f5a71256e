// The side panel's tabs: one page shown at a time.
import { el } from './dom.js';

export class Tabs {
  constructor(root, names) {
    this.bar = el('nav.tab-bar');
    this.pages = {};
    this.buttons = {};
    this.listeners = [];
    for (const name of names) {
      this.buttons[name] = el('button.tab', { type: 'button', onclick: () => this.show(name) }, name);
      this.pages[name] = el('section.tab-page', { dataset: { tab: name } });
      this.bar.append(this.buttons[name]);
    }
    root.append(this.bar, ...Object.values(this.pages));
    this.show(names[0]);
  }

  page(name) {
    return this.pages[name];
  }

  show(name) {
    this.current = name;
    for (const [n, page] of Object.entries(this.pages)) {
      page.hidden = n !== name;
      this.buttons[n].classList.toggle('active', n === name);
    }
    for (const listener of this.listeners) listener(name);
  }

  onShow(listener) {
    this.listeners.push(listener);
  }
}
