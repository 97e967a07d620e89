// Which way is up: the person's word on the scan's frame for the landmark estimate (and the fit
// that estimates on its own). Up = auto or one of the six axes; Facing = auto or an axis across
// Up (auto while Up is auto). A change is only remembered: the next Estimate (in the landmark
// panel) or the next alignment (in the Batch panel) sends it.
import { AXES, axesAcross, axisLabel, type Axis, type Orientation } from '../shared/orientation';
import { h } from './dom';

const AUTO = 'auto';

function select(testid: string, label: string, values: readonly Axis[], value: Axis | null, disabled: boolean): HTMLSelectElement {
  const s = h('select', { 'data-testid': testid, 'aria-label': label });
  s.append(h('option', { value: AUTO }, 'auto'), ...values.map((a) => h('option', { value: a }, axisLabel(a))));
  s.value = value ?? AUTO;
  s.disabled = disabled;
  return s;
}

/** Where the control stands: its test ids' prefix (`estimate-up`, `batch-up`, …) and its tooltip. */
export interface OrientationPlace {
  id: 'estimate' | 'batch';
  title: string;
}

const ESTIMATE: OrientationPlace = {
  id: 'estimate',
  title: 'Which way the body stands in the scan: auto lets the estimate find it; Estimate uses what is chosen here',
};

/**
 * The Up and Facing selects for `orientation` (null: both auto); `onChange` gets the new
 * orientation (a facing that is not across the new up goes back to auto).
 */
export function orientationControl(
  orientation: Orientation | null,
  disabled: boolean,
  onChange: (orientation: Orientation | null) => void,
  place: OrientationPlace = ESTIMATE,
): HTMLElement {
  const up = select(`${place.id}-up`, 'Which scan axis points up, from the feet to the head', AXES, orientation?.up ?? null, disabled);
  const facing = select(`${place.id}-facing`, 'Which scan axis the body faces', orientation ? axesAcross(orientation.up) : [], orientation?.facing ?? null, disabled || !orientation);
  const changed = () => {
    if (up.value === AUTO) return onChange(null);
    const axis = up.value as Axis;
    const across = axesAcross(axis);
    const faces = facing.value === AUTO ? null : (facing.value as Axis);
    onChange({ up: axis, facing: faces && across.includes(faces) ? faces : null });
  };
  up.addEventListener('change', changed);
  facing.addEventListener('change', changed);
  return h(
    'div',
    { class: 'actions orientation', 'data-testid': `${place.id}-orientation`, title: place.title },
    h('label', {}, 'Up ', up),
    h('label', {}, 'Facing ', facing),
  );
}
