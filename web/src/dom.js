// Small DOM helpers: the page is built from plain elements.

// el('div.a.b', {title: 'x', onclick: f}, child, 'text', ...)
export function el(spec, props = {}, ...children) {
  const [tag, ...classes] = spec.split('.');
  const node = document.createElement(tag || 'div');
  if (classes.length) node.className = classes.join(' ');
  for (const [key, value] of Object.entries(props)) {
    if (key.startsWith('on')) node.addEventListener(key.slice(2), value);
    else if (key === 'dataset') Object.assign(node.dataset, value);
    else if (key in node && key !== 'list') node[key] = value;
    else node.setAttribute(key, value);
  }
  for (const child of children.flat()) {
    if (child == null || child === false) continue;
    node.append(child instanceof Node ? child : String(child));
  }
  return node;
}


export function formatCount(n) {
  return n == null ? '–' : Number(n).toLocaleString('en-US');
}

// The function runs `ms` after the last of a burst of calls.
export function debounce(fn, ms) {
  let timer = null;
  return (...args) => {
    clearTimeout(timer);
    timer = setTimeout(() => fn(...args), ms);
  };
}

// Runs fn with the latest arguments at most once every `ms` (the first call
// waits `ms` too): a dragged slider sends its value as it goes, not only when it stops.
export function everyAtMost(fn, ms) {
  let timer = null;
  let latest = null;
  const call = (...args) => {
    latest = args;
    if (timer !== null) return;
    timer = setTimeout(() => {
      timer = null;
      fn(...latest);
    }, ms);
  };
  call.pending = () => timer !== null;
  return call;
}
