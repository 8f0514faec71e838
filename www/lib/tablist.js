// Keyboard behaviour for the page's groups of buttons, after the WAI-ARIA authoring practices:
// a group is one Tab stop (roving tabindex: only the current item has tabindex 0), and the arrow
// keys, Home and End move focus inside it. Tabs activate with Enter or Space (manual activation:
// selecting a method resets its run, so passing over a tab with the arrows must not).

/** Gives the item that should be the group's Tab stop tabindex 0 and the others -1. */
export function syncRoving(container, selector, isCurrent) {
  const items = [...container.querySelectorAll(selector)];
  const current = items.find(isCurrent) ?? items[0];
  for (const item of items) item.tabIndex = item === current ? 0 : -1;
}

/** How many items share the first item's row (the grid's columns as the CSS laid them out). */
function columnsOf(items) {
  const top = items[0]?.getBoundingClientRect().top;
  const n = items.findIndex((item) => Math.abs(item.getBoundingClientRect().top - top) > 1);
  return n < 0 ? items.length : n;
}

/**
 * Arrow keys move focus among `container`'s items (`selector`). With `grid`, Up and Down move by
 * a row of the grid as laid out (the samples show 4 or 8 to a row with the viewport's width).
 * Focus moves, and the moved-to item becomes the Tab stop.
 */
export function rovingFocus(container, selector, { grid = false } = {}) {
  container.addEventListener('keydown', (event) => {
    const items = [...container.querySelectorAll(selector)];
    const at = items.indexOf(document.activeElement);
    if (at < 0) return;
    const columns = grid ? columnsOf(items) : 1;
    const moves = {
      ArrowRight: 1, ArrowLeft: -1, Home: -at, End: items.length - 1 - at,
      ArrowDown: columns > 1 ? columns : 1, ArrowUp: columns > 1 ? -columns : -1,
    };
    if (!(event.key in moves)) return;
    event.preventDefault();
    let next = at + moves[event.key];
    // Left and right wrap around (as in a tablist); up and down stop at the edge of the grid.
    if (columns === 1 || event.key === 'ArrowLeft' || event.key === 'ArrowRight') next = (next + items.length) % items.length;
    next = Math.min(items.length - 1, Math.max(0, next));
    for (const item of items) item.tabIndex = -1;
    items[next].tabIndex = 0;
    items[next].focus();
  });
}

/** A tablist whose tabs are buttons with aria-selected: roving focus plus tabindex kept in step
 * with the selection. Call the returned function after the selection changes. */
export function setupTablist(tablist) {
  rovingFocus(tablist, '[role="tab"]');
  const sync = () => syncRoving(tablist, '[role="tab"]', (tab) => tab.getAttribute('aria-selected') === 'true');
  sync();
  return sync;
}
