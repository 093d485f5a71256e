// The String tab: the derived string as a virtual list (only the rows in
// sight exist, fetched a page at a time), with a search that jumps from match
// to match.
import { getJSON } from './api.js';
import { debounce, el, formatCount } from './dom.js';

const ROW = 20;
const PAGE = 500;
// Browsers cap an element's height (~33 M px in Chromium, less elsewhere): past
// this the scroll bar maps onto the rows proportionally.
const MAX_HEIGHT = 8e6;

export class StringTab {
  constructor(page, onPick) {
    this.onPick = onPick;
    this.pages = new Map();
    this.modules = 0;
    this.key = null;
    this.matches = [];
    this.matchCount = 0;
    this.current = -1;
    this.selected = -1;
    this.visible = false;
    this.search = el('input.search', { type: 'search', placeholder: 'Search modules (e.g. F( )', spellcheck: false,
      oninput: debounce(() => this.runSearch(), 300),
      onkeydown: (e) => { if (e.key === 'Enter') { e.preventDefault(); this.jump(e.shiftKey ? -1 : 1); } } });
    this.matchLabel = el('span.match-count');
    this.summary = el('div.list-summary');
    this.spacer = el('div.list-spacer');
    this.rows = el('div.list-rows');
    this.scroller = el('div.list-scroller', { onscroll: () => this.draw() }, this.spacer, this.rows);
    page.append(
      el('div.search-bar', {}, this.search,
        el('button.icon', { type: 'button', title: 'Previous match (Shift+Enter)', onclick: () => this.jump(-1) }, '▲'),
        el('button.icon', { type: 'button', title: 'Next match (Enter)', onclick: () => this.jump(1) }, '▼'),
        this.matchLabel),
      this.summary,
      this.scroller,
    );
  }

  setVisible(visible) {
    this.visible = visible;
    if (visible) this.refresh();
  }

  // A new string (another step or another scene) empties the page cache.
  update(state) {
    const key = `${state.scene_version}/${state.step}/${state.modules}`;
    if (key === this.key) return;
    this.key = key;
    this.pages.clear();
    this.modules = state.modules || 0;
    this.stale = true;
    if (this.visible) this.refresh();
  }

  refresh() {
    if (!this.stale) return this.draw();
    this.stale = false;
    this.setHeight();
    this.summary.textContent = `${formatCount(this.modules)} modules`;
    if (this.search.value) this.runSearch();
    this.draw();
  }

  async fetchPage(number) {
    if (this.pages.has(number)) return;
    const key = this.key;
    this.pages.set(number, null);
    try {
      const answer = await getJSON('/api/string', { offset: number * PAGE, limit: PAGE });
      if (key !== this.key) return;
      this.pages.set(number, answer.items);
      if (answer.modules !== this.modules) {
        this.modules = answer.modules;
        this.setHeight();
      }
      this.draw();
    } catch {
      this.pages.delete(number);
    }
  }

  item(index) {
    const page = this.pages.get(Math.floor(index / PAGE));
    return page ? page[index % PAGE] : undefined;
  }

  setHeight() {
    this.spacer.style.height = `${Math.min(this.modules * ROW, MAX_HEIGHT)}px`;
  }

  // How many list pixels one scroll pixel stands for (1 unless the list is very long).
  scrollRatio() {
    const view = this.scroller.clientHeight;
    const total = this.modules * ROW;
    const height = Math.min(total, MAX_HEIGHT);
    return height > view ? Math.max(1, (total - view) / (height - view)) : 1;
  }

  draw() {
    if (!this.visible) return;
    const scrollTop = this.scroller.scrollTop;
    const top = scrollTop * this.scrollRatio();
    const first = Math.max(0, Math.floor(top / ROW) - 5);
    const last = Math.min(this.modules, Math.ceil((top + this.scroller.clientHeight) / ROW) + 5);
    const matchSet = new Set(this.matches);
    const rows = [];
    for (let i = first; i < last; i++) {
      const item = this.item(i);
      if (item === undefined) this.fetchPage(Math.floor(i / PAGE));
      const classes = ['list-row'];
      if (matchSet.has(i)) classes.push('match');
      if (this.matches[this.current] === i) classes.push('current');
      if (i === this.selected) classes.push('selected');
      rows.push(el(`div.${classes.join('.')}`, { style: `top:${scrollTop + i * ROW - top}px`, onclick: () => item && this.pick(item) },
        el('span.row-index', {}, i), el('span.row-text', {}, item ? item.text : '…')));
    }
    this.rows.replaceChildren(...rows);
  }

  pick(item) {
    this.selected = item.index;
    this.draw();
    this.onPick(item);
  }

  async runSearch() {
    const text = this.search.value;
    if (!text) {
      this.matches = [];
      this.matchCount = 0;
      this.current = -1;
      this.matchLabel.textContent = '';
      return this.draw();
    }
    try {
      const answer = await getJSON('/api/string', { offset: 0, limit: 1, search: text });
      if (text !== this.search.value) return;
      this.matches = answer.matches || [];
      this.matchCount = answer.match_count ?? this.matches.length;
      this.current = -1;
      this.updateMatchLabel();
      this.draw();
    } catch (e) {
      this.matchLabel.textContent = e.message;
    }
  }

  updateMatchLabel() {
    const shown = this.matches.length < this.matchCount ? ` (first ${this.matches.length})` : '';
    this.matchLabel.textContent = this.matchCount === 0 ? 'no match'
      : `${this.current >= 0 ? this.current + 1 : '–'} / ${formatCount(this.matchCount)}${shown}`;
  }

  jump(direction) {
    if (!this.matches.length) return;
    const n = this.matches.length;
    this.current = this.current < 0 ? (direction > 0 ? 0 : n - 1) : (this.current + direction + n) % n;
    const index = this.matches[this.current];
    this.scroller.scrollTop = Math.max(0, (index * ROW - this.scroller.clientHeight / 2) / this.scrollRatio());
    this.updateMatchLabel();
    this.draw();
  }
}
