// The Animate toolbar and its read-outs: step / derivation length, modules, time per step.
import { el, formatCount } from './dom.js';

export function animateToolbar(animator) {
  const button = (label, key, title, action) => el('button.anim', { type: 'button',
    dataset: { action: label.toLowerCase() }, title: `${title} (${key})`, onclick: action }, label);
  const buttons = {
    step: button('Step', 's', 'Advance by the animation step and redraw', () => animator.step()),
    run: button('Run', 'r', 'Step and redraw until the last frame', () => animator.run()),
    forever: button('Forever', 'f', 'Run, then rewind to the first frame and go on', () => animator.forever()),
    stop: button('Stop', 'Space', 'Stop the animation', () => animator.stop()),
    rewind: button('Rewind', 'w', 'Back to the axiom, then to the first frame', () => animator.rewind()),
  };
  animator.onChange((mode) => {
    for (const [name, node] of Object.entries(buttons)) node.classList.toggle('active', name === mode);
    buttons.stop.disabled = mode !== 'run' && mode !== 'forever';
  });
  buttons.stop.disabled = true;
  const step = el('span.readout.step', { title: 'Derivation step / derivation length' });
  const modules = el('span.readout.modules', { title: 'Modules in the string' });
  const time = el('span.readout.time', { title: 'Time of the last derivation step' });
  const node = el('div.animate', {}, Object.values(buttons), el('span.sep'), step, modules, time);
  return {
    node,
    update(state) {
      step.textContent = `step ${state.step ?? '–'} / ${state.derivation_length ?? '–'}${state.finished ? ' ✓' : ''}`;
      modules.textContent = `${formatCount(state.modules)} modules`;
      time.textContent = state.step_ms == null ? '' : `${state.step_ms < 10 ? state.step_ms.toFixed(2) : Math.round(state.step_ms)} ms/step`;
    },
  };
}
