// "Keep as aligned subject": a fit without a quality flag is kept at a click; a flagged fit's
// button says it is flagged, and a click asks first, naming the flags in words (`qualityText`), so
// a fit the core doubts never joins the subjects as if it were good.
import type { QualityReport } from '../shared/align-types';
import { button, h } from './dom';
import { flagName, qualityText } from './format';

/** The Keep control of a finished fit of `quality` (null: not checked); `kept` once it is kept. */
export function keepControl(quality: QualityReport | null, kept: boolean, onKeep: () => void): HTMLElement {
  const box = h('div', { class: 'keep' });
  const flags = quality?.flags ?? [];
  if (kept || !quality || flags.length === 0) {
    const keep = button('align-keep', kept ? 'Kept ✓' : 'Keep as aligned subject', 'button', onKeep);
    keep.disabled = kept;
    box.append(h('div', { class: 'actions' }, keep));
    return box;
  }
  const offer = (): HTMLElement => {
    const keep = button('align-keep', `Keep as aligned subject — flagged: ${flags.map(flagName).join(', ')}…`, 'button', ask);
    keep.dataset.flags = flags.join(' ');
    return h('div', { class: 'actions' }, keep);
  };
  function ask(): void {
    box.replaceChildren(
      h(
        'p',
        { class: 'warn-note', 'data-testid': 'align-keep-question', 'data-flags': flags.join(' ') },
        `This fit is flagged: ${qualityText(quality!)}. A kept subject joins those a shape model is built from. Keep it all the same?`,
      ),
      h(
        'div',
        { class: 'actions' },
        button('align-keep-confirm', 'Keep it all the same', 'button', onKeep),
        button('align-keep-cancel', 'Do not keep it', 'button', () => box.replaceChildren(offer())),
      ),
    );
  }
  box.append(offer());
  return box;
}
