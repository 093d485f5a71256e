// Export: a download link per format the server offers (at the canvas size),
// and a PNG snapshot of the view as it is on screen.
import { el } from './dom.js';

const LABELS = { png: 'PNG image', svg: 'SVG drawing', pdf: 'PDF drawing', ps: 'PostScript', eps: 'EPS',
  obj: 'OBJ mesh', mtl: 'MTL materials', ply: 'PLY mesh', glb: 'glTF binary', string: 'String (text)' };

export function exportMenu(viewer, viewId) {
  const list = el('div.menu-list', { hidden: true });
  const toggle = el('button', { type: 'button', title: 'Save the current state in a file', 'aria-haspopup': 'true' }, 'Export ▾');
  const node = el('div.menu', {}, toggle, list);
  let formats = [];
  const stem = () => (document.title.replace(/ — Sylva Studio$/, '') || 'sylva').replace(/\.[^.]*$/, '');
  const snapshot = () => {
    const link = el('a', { href: viewer.snapshot(), download: `${stem()}-view.png` });
    link.click();
    close();
  };
  const fill = () => {
    const width = Math.round(viewer.canvas.clientWidth);
    const height = Math.round(viewer.canvas.clientHeight);
    list.replaceChildren(
      el('button.menu-item', { type: 'button', onclick: snapshot, title: 'The view as shown, from the canvas' }, 'Snapshot PNG (view)'),
      el('hr'),
      ...formats.map((f) => el('a.menu-item', {
        href: `/api/export?${new URLSearchParams({ format: f, view: viewId(), width, height })}`,
        download: '', dataset: { format: f }, onclick: () => close(),
      }, LABELS[f] || f, el('span.dim', {}, ` .${f === 'string' ? 'str' : f}`))),
    );
  };
  const close = () => { list.hidden = true; };
  toggle.addEventListener('click', (e) => {
    e.stopPropagation();
    if (list.hidden) fill();
    list.hidden = !list.hidden;
  });
  document.addEventListener('click', (e) => { if (!node.contains(e.target)) close(); });
  return {
    node,
    snapshot,
    update(state) {
      formats = state.formats || [];
    },
  };
}
