// A tiny element builder, so panels read as the markup they produce.

type Attributes = Record<string, string | undefined>;

/** `<tag attrs>children</tag>`; `data-*` and other attributes go through setAttribute. */
export function h<K extends keyof HTMLElementTagNameMap>(
  tag: K,
  attributes: Attributes = {},
  ...children: (Node | string)[]
): HTMLElementTagNameMap[K] {
  const element = document.createElement(tag);
  for (const [name, value] of Object.entries(attributes)) {
    if (value !== undefined) element.setAttribute(name, value);
  }
  element.append(...children);
  return element;
}

/** A `<button>` of class `cls` that runs `onClick`. */
export function button(testid: string, label: string, cls: string, onClick: () => void): HTMLButtonElement {
  const b = h('button', { class: cls, type: 'button', 'data-testid': testid }, label);
  b.addEventListener('click', onClick);
  return b;
}

/**
 * `element` with its background set through the CSS object model: the page's
 * Content-Security-Policy allows no inline `style` attributes, but script-set styles are fine.
 */
export function withBackground<E extends HTMLElement>(element: E, background: string): E {
  element.style.background = background;
  return element;
}

/** Finds a required element of the page. */
export function byId<T extends HTMLElement = HTMLElement>(id: string): T {
  const element = document.getElementById(id);
  if (!element) throw new Error(`the page has no #${id}`);
  return element as T;
}

/** What makes a live element the same as the one a redraw puts in its place. */
const IDENTITY = ['data-testid', 'data-subject'];

function same(live: Node, next: Node): boolean {
  if (live.nodeType !== next.nodeType || live.nodeName !== next.nodeName) return false;
  if (!(live instanceof Element) || !(next instanceof Element)) return true;
  if (IDENTITY.some((name) => live.getAttribute(name) !== next.getAttribute(name))) return false;
  // A button's listener acts on what its label says ("Exclude" / "Include"): another label, another button.
  return live.tagName !== 'BUTTON' || live.textContent === next.textContent;
}

function syncAttributes(live: Element, next: Element): void {
  for (const { name } of [...live.attributes]) if (!next.hasAttribute(name)) live.removeAttribute(name);
  for (const { name, value } of [...next.attributes]) {
    if (live.getAttribute(name) === value) continue;
    // Styles through the CSS object model, as `withBackground` sets them (the page's policy).
    if (name === 'style' && live instanceof HTMLElement && next instanceof HTMLElement) live.style.cssText = next.style.cssText;
    else live.setAttribute(name, value);
  }
}

/**
 * Makes `live`'s children those of `next`'s, keeping each live node that a redraw puts back in the
 * same place (same tag, test id, subject and, for a button, label) and changing only its attributes
 * and text. A panel redrawn every frame while workers report progress so keeps its buttons and
 * lists: a click whose press and release fall on either side of a redraw still lands, and an open
 * list stays open. A kept element keeps its first listeners, so they must read what they act on
 * when they run, not when they were made.
 */
export function morphChildren(live: Element, next: Element): void {
  const wanted = [...next.childNodes];
  wanted.forEach((want, i) => {
    const have = live.childNodes[i];
    if (!have) live.appendChild(want);
    else if (!same(have, want)) live.replaceChild(want, have);
    else if (have instanceof Element) {
      // A select's choice is a property, not an attribute; read it before its options move.
      const value = want instanceof HTMLSelectElement ? want.value : null;
      syncAttributes(have, want as Element);
      morphChildren(have, want as Element);
      if (have instanceof HTMLSelectElement && value !== null && have.value !== value) have.value = value;
    } else if (have.nodeValue !== want.nodeValue) have.nodeValue = want.nodeValue;
  });
  while (live.childNodes.length > wanted.length) live.lastChild!.remove();
}
