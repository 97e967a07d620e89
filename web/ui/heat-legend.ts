// The colour legend of the distance heat map: the gradient, its end values in millimetres and
// what it measures.
import { heatGradientCss } from '../view/heat-colours';
import { h, withBackground } from './dom';

/** A legend for distances from `minMm` to `maxMm` (values beyond are drawn in the end colours). */
export function heatLegend(minMm: number, maxMm: number, what: string): HTMLElement {
  const ticks = [0, 0.25, 0.5, 0.75, 1].map((t) => h('span', {}, (minMm + t * (maxMm - minMm)).toFixed(1)));
  return h(
    'div',
    { class: 'heat-legend', 'data-testid': 'heat-legend', 'data-min-mm': minMm.toFixed(2), 'data-max-mm': maxMm.toFixed(2) },
    h('div', { class: 'heat-title' }, what),
    withBackground(h('div', { class: 'heat-bar' }), heatGradientCss()),
    h('div', { class: 'heat-ticks' }, ...ticks),
    h('div', { class: 'heat-unit' }, 'millimetres'),
  );
}
