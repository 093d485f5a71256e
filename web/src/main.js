// Sylva Studio's page: a large 3D view with lpfg's mouse and Animate menu,
// side panels (parameters, inspection, the string, module counts), the
// model's errors over the view and a status line. It follows the server's
// state (GET /api/state) and shows each new scene when it is ready.
import { el } from './dom.js';
import { Store } from './store.js';
import { Viewer } from './viewer.js';
import { LpfgControls } from './controls.js';
import { SceneSync } from './scene_sync.js';
import { Animator } from './animator.js';
import { animateToolbar } from './toolbar.js';
import { exportMenu } from './export_menu.js';
import { errorPanel } from './error_panel.js';
import { statusBar } from './status_bar.js';
import { Tabs } from './tabs.js';
import { ParamsPanel } from './params_panel.js';
import { Inspector } from './inspector.js';
import { StringTab } from './string_tab.js';
import { CountsTab } from './counts_tab.js';
import { bindKeys } from './keyboard.js';

const store = new Store();
let viewId = 0;
const currentView = () => viewId;

// Layout.
const canvas = el('canvas.view');
const errors = errorPanel();
const status = statusBar();
const mouseHelp = el('div.mouse-help', {},
  'drag: rotate · shift+drag: pan · ctrl+drag, middle, wheel: zoom · shift+middle: roll · click: inspect');
const viewport = el('div.viewport', {}, canvas, errors.node, mouseHelp);
const side = el('aside.side');
const brand = el('div.brand', {}, el('span.logo', {}, 'Sylva'), el('span.model-name'));
const viewSelect = el('select.view-select', { hidden: true, title: 'Which view (UseView window) to show' });
const resetViewButton = el('button', { type: 'button', title: "Back to the view file's camera (0)" }, 'Reset view');
const toolbarRight = el('div.toolbar-right', {}, viewSelect, resetViewButton);
const header = el('header.toolbar', {}, brand);
document.body.replaceChildren(header, el('main.workspace', {}, viewport, side), status.node);

// The view and its scene.
const viewer = new Viewer(canvas);
const tabs = new Tabs(side, ['Parameters', 'Inspect', 'String', 'Counts']);
const inspector = new Inspector(tabs.page('Inspect'), viewer, currentView, () => tabs.show('Inspect'));
const scenes = new SceneSync(viewer, currentView, (version, ms) => {
  inspector.clear();
  status.setNote(`scene ${version} loaded in ${Math.round(ms)} ms`);
});
new LpfgControls(viewer, (x, y) => inspector.pickAt(x, y));
resetViewButton.addEventListener('click', () => viewer.resetView());

// Commands.
const reportError = (message) => status.setNote(`⚠ ${message}`);
const animator = new Animator(store, (version) => scenes.waitFor(version), reportError);
const toolbar = animateToolbar(animator);
const exports = exportMenu(viewer, currentView);
toolbarRight.append(exports.node);
header.append(toolbar.node, el('span.spacer'), toolbarRight);
const params = new ParamsPanel(tabs.page('Parameters'), store, reportError);
const strings = new StringTab(tabs.page('String'), (item) => inspector.showModule(item.index));
const counts = new CountsTab(tabs.page('Counts'));
tabs.onShow((name) => {
  strings.setVisible(name === 'String');
  counts.setVisible(name === 'Counts');
});
bindKeys({
  step: () => animator.step(),
  run: () => animator.run(),
  forever: () => animator.forever(),
  stop: () => animator.stop(),
  rewind: () => animator.rewind(),
  resetView: () => viewer.resetView(),
});
viewSelect.addEventListener('change', () => {
  viewId = Number(viewSelect.value);
  scenes.reload();
});

// Following the server's state.
store.onConnection = (connected) => status.setConnected(connected);
store.subscribe((state, previous) => {
  document.title = `${state.model || 'model'} — Sylva Studio`;
  brand.querySelector('.model-name').textContent = state.model || '';
  brand.title = state.folder ? `${state.folder}\n${(state.files || []).join(', ')}` : '';
  if (state.view && JSON.stringify(state.view) !== JSON.stringify(previous?.view)) viewer.setView(state.view);
  const views = state.views || [];
  viewSelect.hidden = views.length < 2;
  if (views.length > 1 && viewSelect.options.length !== views.length) {
    viewSelect.replaceChildren(...views.map((v) => el('option', { value: v.id }, v.name || `view ${v.id}`)));
    viewSelect.value = viewId;
  }
  scenes.want(state.scene_version || 0);
  toolbar.update(state);
  exports.update(state);
  errors.update(state);
  status.update(state);
  params.update(state);
  strings.update(state);
  counts.update(state);
});
store.startPolling();

// What tests and benchmarks read.
window.sylvaStudio = {
  get state() { return store.state; },
  get stateVersion() { return store.state?.version ?? 0; },
  get sceneVersion() { return scenes.displayed; },
  get sceneLoadMs() { return scenes.lastLoadMs; },
  get framesRendered() { return viewer.framesRendered; },
  get animating() { return animator.mode; },
  get camera() { return viewer.cam; },
  get triangles() { return viewer.renderer.info.render.triangles; },
  viewer,
};
