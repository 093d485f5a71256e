// The Inspect tab: what a click on the model hit (through the glTF's
// provenance), the module the server says it is, and its elements marked.
import { getJSON } from './api.js';
import { el } from './dom.js';
import { elementOfHit, rangesOfModule, recordOfElement, recordsOf } from './provenance.js';
import { Highlight } from './highlight.js';

export class Inspector {
  constructor(page, viewer, viewId, showTab) {
    this.page = page;
    this.viewer = viewer;
    this.viewId = viewId;
    this.showTab = showTab;
    this.highlight = new Highlight(viewer);
    this.request = 0;
    this.clear();
  }

  // A new scene: the old module indices mean nothing any more.
  clear() {
    this.highlight.clear();
    this.page.replaceChildren(el('p.hint', {}, 'Click on the model to inspect the module that drew it.'));
  }

  async pickAt(x, y) {
    const model = this.viewer.model;
    const hit = this.viewer.pick(x, y)[0];
    if (!model || !hit) {
      this.clear();
      return;
    }
    if (hit.object.isInstancedMesh) {
      await this.showModule(hit.object.userData.moduleIndices[hit.instanceId], { fromPick: true });
      return;
    }
    const records = await recordsOf(model, hit.object);
    const record = records && recordOfElement(records, elementOfHit(hit));
    if (!record) {
      this.highlight.clear();
      this.page.replaceChildren(el('p.hint', {}, 'No module recorded for this element.'));
      return;
    }
    await this.showModule(record.module, { fromPick: true });
  }

  // Shows module `index` of the string: the glTF's provenance numbers what
  // it drew by the module of the string that drew it (through interpretation
  // rules, if any), as the String tab numbers the string.
  async showModule(index, { fromPick = false } = {}) {
    const request = ++this.request;
    const model = this.viewer.model;
    let module = null;
    let error = null;
    try {
      module = await getJSON('/api/module', { view: this.viewId(), index });
    } catch (e) {
      error = e.message;
    }
    if (request !== this.request) return;
    const ranges = model && module ? await rangesOfModule(model, index) : [];
    if (request !== this.request) return;
    if (ranges.length) this.highlight.show(ranges);
    else this.highlight.clear();
    this.render(module, error, ranges, fromPick);
    this.showTab();
  }

  render(module, error, ranges, fromPick) {
    if (!module) {
      this.page.replaceChildren(el('p.error-text', {}, `Module not found: ${error}`));
      return;
    }
    const row = (label, value) => el('tr', {}, el('th', {}, label), el('td', {}, value ?? '–'));
    const parameters = module.parameters?.length
      ? el('ol.parameters', {}, module.parameters.map((p) => el('li', {}, p)))
      : el('span.dim', {}, module.parameters ? 'none' : '–');
    const elements = ranges.reduce((sum, r) => sum + r.count, 0);
    this.page.replaceChildren(
      el('h2.module-name', {}, module.name),
      el('pre.module-text', {}, module.text),
      el('table.props', {},
        row('Parameters', parameters),
        row('Index in the string', module.string_index),
        row('Made at step', module.step),
        row('Drawn', ranges.length ? `${elementCount(elements)} in ${ranges.length} part${ranges.length > 1 ? 's' : ''}` : 'nothing'),
      ),
    );
    if (!fromPick) this.page.append(el('p.hint', {}, 'Picked from the string.'));
  }
}

function elementCount(n) {
  return `${n.toLocaleString('en-US')} element${n === 1 ? '' : 's'}`;
}
