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
