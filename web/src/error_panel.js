// The model's error over the view (the last good picture stays visible under it):
// kind, file:line:column, the message, the source line with the column marked.
import { el } from './dom.js';

const KINDS = { model: 'Model error', crash: 'The model crashed', timeout: 'Time limit exceeded', memory: 'Memory limit exceeded' };

export function errorPanel() {
  const node = el('div.error-panel', { hidden: true, role: 'alert' });
  let shown = null;
  return {
    node,
    update(state) {
      const error = state.error;
      const key = JSON.stringify(error);
      if (key === shown) return;
      shown = key;
      node.hidden = !error;
      if (!error) return node.replaceChildren();
      const where = error.file ? [error.file, error.line, error.column].filter((x) => x != null && x !== 0).join(':') : '';
      const source = error.source_line != null && error.source_line !== ''
        ? el('pre.source', {},
          el('span.line-number', {}, error.line != null ? `${error.line} | ` : ''), error.source_line,
          error.column ? el('span.caret', {}, `\n${' '.repeat(String(error.line ?? '').length + 3 + Math.max(0, error.column - 1))}^`) : null)
        : null;
      node.replaceChildren(...[
        el('div.error-head', {},
          el('span.error-kind', {}, KINDS[error.kind] || error.kind || 'Error'),
          where ? el('span.error-where', {}, where) : null,
          error.step != null ? el('span.dim', {}, `at step ${error.step}`) : null),
        el('pre.error-message', {}, error.message || ''),
        source,
        el('div.dim.error-note', {}, 'Showing the last good picture. Save the file to try again.'),
      ].filter(Boolean));
    },
  };
}
