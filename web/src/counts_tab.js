// The Counts tab: how many modules of each name the string holds, largest first, with bars.
import { getJSON } from './api.js';
import { el, formatCount } from './dom.js';

export class CountsTab {
  constructor(page) {
    this.page = page;
    this.key = null;
    this.shownKey = undefined;
    this.visible = false;
  }

  setVisible(visible) {
    this.visible = visible;
    if (visible) this.refresh();
  }

  update(state) {
    this.key = `${state.scene_version}/${state.step}/${state.modules}`;
    if (this.visible) this.refresh();
  }

  async refresh() {
    if (this.shownKey === this.key) return;
    const key = this.key;
    this.shownKey = key;
    try {
      const { counts } = await getJSON('/api/counts');
      if (key !== this.key) return;
      this.show(counts || []);
    } catch (e) {
      this.shownKey = undefined;
      this.page.replaceChildren(el('p.error-text', {}, e.message));
    }
  }

  show(counts) {
    const sorted = [...counts].sort((a, b) => b.count - a.count || a.name.localeCompare(b.name));
    const total = sorted.reduce((sum, c) => sum + c.count, 0);
    const largest = sorted[0]?.count || 1;
    this.page.replaceChildren(
      el('div.list-summary', {}, `${formatCount(total)} modules, ${sorted.length} kinds`),
      el('table.counts', {},
        el('thead', {}, el('tr', {}, el('th', {}, 'Module'), el('th.num', {}, 'Count'), el('th.num', {}, '%'), el('th', {}))),
        el('tbody', {}, sorted.map((c) => el('tr', {},
          el('td.mono', {}, c.name),
          el('td.num', {}, formatCount(c.count)),
          el('td.num', {}, total ? ((100 * c.count) / total).toFixed(1) : '0'),
          el('td.bar-cell', {}, el('div.bar', { style: `width:${(100 * c.count) / largest}%` })))))),
    );
  }
}
