// The Parameters tab: the model's panels (or its numeric #defines) as sliders
// and toggle buttons. A change re-runs the model with the value (files are
// untouched) until "Write to files".
import { postJSON } from './api.js';
import { el, everyAtMost } from './dom.js';

const SEND_DELAY_MS = 150;

function defineValue(param, value) {
  const scale = param.scale || 1;
  const v = value / scale;
  return scale === 1 ? String(v) : String(Number(v.toPrecision(6)));
}

export class ParamsPanel {
  constructor(page, store, onError) {
    this.page = page;
    this.store = store;
    this.onError = onError;
    this.shape = null;
    this.controls = new Map();
    this.resetButton = el('button', { type: 'button', title: 'Every parameter back to its file value',
      onclick: () => this.post('/api/param/reset') }, 'Reset');
    this.saveButton = el('button.primary', { type: 'button', title: 'Write the changed values into their files',
      onclick: () => this.post('/api/param/save') }, 'Write to files');
    this.groups = el('div.param-groups');
    this.empty = el('p.hint', {}, 'This model has no panel and no numeric #define.');
    page.append(this.groups, el('div.button-row', {}, this.resetButton, this.saveButton));
  }

  async post(path, body) {
    try {
      this.store.apply(await postJSON(path, body));
    } catch (e) {
      this.onError(e.message);
    }
  }

  update(state) {
    const params = state.params || [];
    const shape = JSON.stringify(params.map((p) => [p.id, p.panel, p.kind, p.name, p.min, p.max, p.step, p.scale]));
    if (shape !== this.shape) {
      this.shape = shape;
      this.build(params);
    }
    for (const param of params) this.controls.get(param.id)?.update(param);
    this.saveButton.disabled = !state.params_modified;
    this.resetButton.disabled = !state.params_modified && !params.some((p) => p.modified);
  }

  build(params) {
    this.controls.clear();
    if (!params.length) {
      this.groups.replaceChildren(this.empty);
      return;
    }
    const panels = new Map();
    for (const param of params) {
      const name = param.panel || 'Parameters';
      if (!panels.has(name)) panels.set(name, []);
      panels.get(name).push(param);
    }
    this.groups.replaceChildren(...[...panels].map(([name, list]) => el('fieldset.param-group', {},
      el('legend', {}, name),
      list.map((param) => {
        const control = param.kind === 'button' ? this.button(param) : this.slider(param);
        this.controls.set(param.id, control);
        return control.node;
      }))));
  }

  slider(param) {
    const input = el('input.slider', { type: 'range', min: param.min ?? 0, max: param.max ?? 100, step: param.step || 1 });
    const shown = el('span.param-value');
    const label = el('span.param-name', { title: param.define ? `#define ${param.define}` : '' }, param.name || param.define);
    const node = el('div.param.slider-param', { dataset: { id: param.id } }, el('div.param-head', {}, label, shown), input);
    let sending = 0;
    const send = everyAtMost(async (value) => {
      sending++;
      await this.post('/api/param', { id: param.id, value });
      sending--;
    }, SEND_DELAY_MS);
    let dragging = false;
    input.addEventListener('pointerdown', () => { dragging = true; });
    input.addEventListener('pointerup', () => { dragging = false; });
    input.addEventListener('input', () => {
      shown.textContent = defineValue(param, Number(input.value));
      node.classList.add('modified');
      send(Number(input.value));
    });
    return {
      node,
      update(p) {
        Object.assign(param, p);
        node.classList.toggle('modified', !!p.modified);
        // The user's value wins while it is being dragged or not yet sent.
        if (dragging || sending || send.pending()) return;
        input.value = p.value;
        shown.textContent = defineValue(p, p.value);
        shown.title = (p.scale || 1) === 1 ? '' : `slider ${p.value} / ${p.scale}`;
      },
    };
  }

  button(param) {
    const toggle = el('button.toggle', { type: 'button', dataset: { id: param.id },
      onclick: () => this.post('/api/param', { id: param.id, value: param.value ? 0 : 1 }) }, param.name || param.define);
    return {
      node: el('div.param.button-param', {}, toggle),
      update(p) {
        Object.assign(param, p);
        toggle.classList.toggle('on', !!p.value);
        toggle.classList.toggle('modified', !!p.modified);
        toggle.title = `${p.define ? `#define ${p.define} ` : ''}${p.value ? 'on' : 'off'}`;
      },
    };
  }
}
