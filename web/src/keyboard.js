// lpfg's Animate shortcuts as plain keys (the browser keeps Ctrl+R, Ctrl+F):
// s step, r run, f forever, space stop, w rewind, 0 reset view.
export function bindKeys(actions) {
  document.addEventListener('keydown', (event) => {
    if (event.ctrlKey || event.metaKey || event.altKey) return;
    const target = event.target;
    if (target.closest?.('input, textarea, select, [contenteditable]')) return;
    const action = { s: actions.step, r: actions.run, f: actions.forever, ' ': actions.stop, w: actions.rewind,
      0: actions.resetView }[event.key];
    if (!action) return;
    event.preventDefault();
    action();
  });
}
