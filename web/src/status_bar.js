// The status line: what the server is busy with, the warnings and the model's
// printed messages (both collapsible), and whether the server answers.
import { el } from './dom.js';

const BUSY = { compiling: 'compiling…', deriving: 'deriving…' };

export function statusBar() {
  const busy = el('span.busy');
  const connection = el('span.connection', { hidden: true }, 'server not answering');
  const note = el('span.note');
  const warningsButton = el('button.status-toggle', { type: 'button', hidden: true });
  const consoleButton = el('button.status-toggle', { type: 'button', title: "The model's printed output" }, 'Console');
  const drawer = el('div.drawer', { hidden: true });
  const warningsList = el('ul.warnings');
  const messages = el('pre.console');
  let open = null;
  const show = (which) => {
    open = open === which ? null : which;
    drawer.hidden = !open;
    drawer.replaceChildren(open === 'warnings' ? warningsList : open === 'console' ? messages : '');
    warningsButton.classList.toggle('active', open === 'warnings');
    consoleButton.classList.toggle('active', open === 'console');
    if (open === 'console') messages.scrollTop = messages.scrollHeight;
  };
  warningsButton.addEventListener('click', () => show('warnings'));
  consoleButton.addEventListener('click', () => show('console'));
  const bar = el('div.status-bar', {}, busy, connection, note, el('span.spacer'), warningsButton, consoleButton);
  let lastMessages = null;
  return {
    node: el('footer.status', {}, drawer, bar),
    setConnected(connected) {
      connection.hidden = connected;
    },
    setNote(text) {
      note.textContent = text || '';
    },
    update(state) {
      busy.textContent = BUSY[state.busy] || state.busy || (state.error ? 'error' : 'ready');
      busy.className = `busy ${state.busy ? 'working' : state.error ? 'failed' : 'idle'}`;
      const warnings = state.warnings || [];
      warningsButton.hidden = warnings.length === 0;
      warningsButton.textContent = `⚠ ${warnings.length} warning${warnings.length === 1 ? '' : 's'}`;
      warningsList.replaceChildren(...warnings.map((w) => el('li', {}, w)));
      if (!warnings.length && open === 'warnings') show('warnings');
      const text = state.messages || '';
      if (text !== lastMessages) {
        lastMessages = text;
        const atBottom = messages.scrollTop + messages.clientHeight >= messages.scrollHeight - 4;
        messages.textContent = text || '(the model has printed nothing)';
        if (atBottom) messages.scrollTop = messages.scrollHeight;
        consoleButton.classList.toggle('has-output', !!text);
      }
    },
  };
}
