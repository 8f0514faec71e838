// The page's state in its URL, so that a link reproduces a run exactly: the built-in sample, the
// method (panel), seed, output size, and every input and select of the method's options, keyed
// by its id (radio buttons by their name; a tablist inside the options, such as the design
// stages, by its id). An uploaded exemplar has no name a link could carry, so it is left out.

const FIXED = { sample: 'sample', method: 'method', seed: 'seed', width: 'w', height: 'h' };

/** The state a URL's query names: `{ sample, method, seed, width, height, options }`, where
 * `options` is a Map from control key to its value as written; absent parts are undefined. */
export function readUrlState(search) {
  const params = new URLSearchParams(search);
  const state = { options: new Map() };
  for (const [field, key] of Object.entries(FIXED)) state[field] = params.get(key) ?? undefined;
  const fixedKeys = new Set(Object.values(FIXED));
  for (const [key, value] of params) if (!fixedKeys.has(key)) state.options.set(key, value);
  return state;
}

/** The query string for `state` (the same shape `readUrlState` gives). */
export function urlQuery(state) {
  const params = new URLSearchParams();
  for (const [field, key] of Object.entries(FIXED)) if (state[field] != null) params.set(key, String(state[field]));
  for (const [key, value] of state.options) params.set(key, value);
  return `?${params}`;
}

/** The tablists inside `root`, keyed by id, with the selected tab's value. */
function tablists(root) {
  return [...root.querySelectorAll('[role="tablist"][id]')].map((list) => {
    const tabs = [...list.querySelectorAll('[role="tab"]')];
    const valueOf = (tab) => tab.dataset.stage ?? tab.dataset.panel ?? tab.id;
    return {
      key: list.id,
      read: () => {
        const selected = tabs.find((t) => t.getAttribute('aria-selected') === 'true');
        return selected ? valueOf(selected) : null;
      },
      write: (value) => tabs.find((t) => valueOf(t) === value)?.click(),
    };
  });
}

/** Every input and select inside `root` that has a key, with a reader and a writer. */
function controls(root) {
  const seen = new Set();
  const list = [];
  for (const el of root.querySelectorAll('input, select')) {
    if (el.type === 'file' || el.type === 'button') continue;
    if (el.type === 'radio') {
      if (!el.name || seen.has(el.name)) continue;
      seen.add(el.name);
      const group = [...root.querySelectorAll(`input[type="radio"][name="${CSS.escape(el.name)}"]`)];
      list.push({
        key: el.name,
        read: () => group.find((r) => r.checked)?.value ?? null,
        write: (value) => {
          const radio = group.find((r) => r.value === value);
          if (radio && !radio.checked) {
            radio.checked = true;
            notify(radio);
          }
        },
      });
    } else if (el.id) {
      list.push({
        key: el.id,
        read: () => (el.type === 'checkbox' ? (el.checked ? '1' : '0') : el.value),
        write: (value) => {
          if (el.type === 'checkbox') {
            if (el.checked === (value === '1')) return;
            el.checked = value === '1';
          } else {
            if (el.value === value) return;
            if (el.tagName === 'SELECT' && ![...el.options].some((o) => o.value === value)) return;
            el.value = value;
          }
          notify(el);
        },
      });
    }
  }
  return list;
}

/** Tells the page's own listeners that a control changed, as a user's edit would. */
function notify(el) {
  el.dispatchEvent(new Event('input', { bubbles: true }));
  el.dispatchEvent(new Event('change', { bubbles: true }));
}

/** The keyed values of the tablists and controls inside `root`, as a Map. */
export function readOptions(root) {
  const values = new Map();
  for (const { key, read } of [...tablists(root), ...controls(root)]) {
    const value = read();
    if (value != null) values.set(key, value);
  }
  return values;
}

/** Writes `values` (a Map) into the controls inside `root`: tablists first (a stage tab
 * replaces the options under it), then the controls, each once. */
export function writeOptions(root, values) {
  for (const { key, write } of tablists(root)) if (values.has(key)) write(values.get(key));
  for (const { key, write } of controls(root)) if (values.has(key)) write(values.get(key));
}
