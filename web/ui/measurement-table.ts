// The measurements of the body shown, one row each, with a target entry beside each value: "Find
// body" asks for the most likely body with the targets entered (any subset), and each row with a
// target then says what the body on screen achieves and whether that meets it. Rows are built once
// per set of measurements and updated in place, so typing in a target survives slider moves.
import { meets, parseTarget, targetUnit, type FoundBody, type Targets, type TargetTolerances } from '../shared/anthropometry';
import type { Measurements, PartName, Reading } from '../shared/shape-results';
import { button, h } from './dom';
import { formatReading } from './format';

interface Row {
  reading: Reading;
  value: HTMLElement;
  input: HTMLInputElement;
  /** Target, achieved and met, under the row once a body was found for a target of it. */
  result: HTMLTableRowElement;
  resultCell: HTMLElement;
  /** The population column (the current body's percentile), for the distribution view. */
  population: HTMLElement;
}

export class MeasurementTable {
  readonly element = h('div', { class: 'measurement-table' });
  private readonly body = h('tbody', {});
  private readonly status = h('p', { class: 'note', 'data-testid': 'find-body-status' });
  private readonly rows = new Map<string, Row>();
  private names = '';
  /** The targets of the last body found and the tolerances that say "met". */
  private found: { targets: Targets; tolerances: TargetTolerances } | null = null;
  private last: Measurements = [];
  /** The part in view and the measurements its targets may name (others' entries are disabled). */
  private part: PartName = 'whole';
  private targetable: ReadonlySet<string> | null = null;
  private readonly scope = h('p', { class: 'note', 'data-testid': 'target-scope' });

  constructor(private readonly onFind: (targets: Targets) => void) {
    this.element.append(
      h('table', { class: 'measurements', 'data-testid': 'shape-readings' }, h('thead', {}, h('tr', {}, h('th', {}, 'Measurement'), h('th', {}, 'Value'), h('th', {}, 'Target'), h('th', {}, 'Population'))), this.body),
      this.scope,
      h('div', { class: 'row' }, button('find-body', 'Find body', 'button primary', () => this.find()), button('clear-targets', 'Clear targets', 'button', () => this.clear())),
      this.status,
    );
  }

  /** The readings of the body on screen; the met / not met of every target follows them. */
  show(measurements: Measurements): void {
    const names = measurements.map((r) => r.name).join(' ');
    if (names !== this.names) this.build(measurements, names);
    this.last = measurements;
    for (const r of measurements) {
      const row = this.rows.get(r.name)!;
      row.value.textContent = formatReading(r.kind, r.value);
    }
    this.showAchieved();
  }

  /** The population cell of `name` (the distribution view fills it). */
  populationCell(name: string): HTMLElement | undefined {
    return this.rows.get(name)?.population;
  }

  /** The label of measurement `name` (its name when unknown). */
  label(name: string): string {
    return this.rows.get(name)?.reading.label ?? name;
  }

  /** The part in view: in a segment's view only its own measurements take targets. */
  setTargetable(part: PartName, names: readonly string[]): void {
    this.part = part;
    this.targetable = new Set(names);
    this.applyTargetable();
  }

  private applyTargetable(): void {
    const labels: string[] = [];
    for (const [name, row] of this.rows) {
      const ok = !this.targetable || this.targetable.has(name);
      row.input.disabled = !ok;
      row.input.title = ok ? '' : `Not a target of the ${this.part.replace('_', ' ')} model: it is measured on another part of the body.`;
      if (ok) labels.push(row.reading.label);
    }
    this.scope.textContent =
      this.part === 'whole'
        ? ''
        : labels.length
          ? `In this segment's view, targets act on the ${this.part.replace('_', ' ')} model (the rest of the body held): ${labels.join(', ')}.`
          : `No measurement acts on the ${this.part.replace('_', ' ')} model alone: pick the whole body to enter targets.`;
  }

  /** A body was found for `targets` and is being shown. */
  showFound(targets: Targets, found: FoundBody): void {
    this.found = { targets, tolerances: found.tolerances };
    const met = found.achieved.filter((a) => a.met).length;
    this.status.classList.remove('error-note');
    this.status.textContent = `Found in ${found.workerMs.toFixed(0)} ms (${found.iterations} Gauss–Newton step${found.iterations === 1 ? '' : 's'}): ${met} of ${found.achieved.length} target${found.achieved.length === 1 ? '' : 's'} met; the body is ${found.mahalanobis.toFixed(2)}σ from the mean (Mahalanobis).`;
    this.showAchieved();
  }

  showError(text: string): void {
    this.status.classList.add('error-note');
    this.status.textContent = text;
  }

  showStatus(text: string): void {
    this.status.classList.remove('error-note');
    this.status.textContent = text;
  }

  private build(measurements: Measurements, names: string): void {
    this.names = names;
    this.rows.clear();
    this.found = null;
    const rows: HTMLTableRowElement[] = [];
    for (const reading of measurements) {
      const unit = targetUnit(reading.kind);
      const input = h('input', { type: 'text', inputmode: 'decimal', class: 'target-input', placeholder: unit, 'data-testid': `target-${reading.name}`, 'aria-label': `Target ${reading.label} (${unit})` });
      input.addEventListener('keydown', (e) => {
        if (e.key === 'Enter') this.find();
      });
      const value = h('td', { class: 'reading', 'data-testid': `measure-${reading.name}` });
      const population = h('td', { class: 'population', 'data-testid': `population-${reading.name}` });
      const resultCell = h('td', { colspan: '4', class: 'achieved', 'data-testid': `achieved-${reading.name}` });
      const result = h('tr', { class: 'achieved-row' }, resultCell);
      result.hidden = true;
      rows.push(h('tr', {}, h('th', { scope: 'row' }, reading.label), value, h('td', {}, input), population), result);
      this.rows.set(reading.name, { reading, value, input, result, resultCell, population });
    }
    this.body.replaceChildren(...rows);
    this.applyTargetable();
  }

  /** The targets entered, or what is wrong with them. */
  private entered(): { targets: Targets; errors: string[] } {
    const targets: Targets = {};
    const errors: string[] = [];
    for (const [name, row] of this.rows) {
      if (row.input.disabled) continue;
      const parsed = parseTarget(row.reading, row.input.value);
      row.input.classList.toggle('invalid', Boolean(parsed.error));
      if (parsed.error) errors.push(parsed.error);
      else if (parsed.value != null) targets[name] = parsed.value;
    }
    if (!errors.length && !Object.keys(targets).length) errors.push('Enter a target beside at least one measurement (lengths and girths in cm, volume in L, area in m²).');
    return { targets, errors };
  }

  private find(): void {
    const { targets, errors } = this.entered();
    if (errors.length) {
      this.showError(errors.join('\n'));
      return;
    }
    this.showStatus('Finding the body…');
    this.onFind(targets);
  }

  /** Empties every target and forgets the last body found (a new model's body was never found for them). */
  clear(): void {
    for (const row of this.rows.values()) {
      row.input.value = '';
      row.input.classList.remove('invalid');
    }
    this.found = null;
    this.showStatus('');
    this.showAchieved();
  }

  /** Each target of the last body found against the value on screen now. */
  private showAchieved(): void {
    for (const [name, row] of this.rows) {
      const target = this.found?.targets[name];
      row.result.hidden = target == null;
      if (target == null || !this.found) continue;
      const kind = row.reading.kind;
      const value = this.last.find((r) => r.name === name)?.value ?? null;
      const ok = meets(kind, value, target, this.found.tolerances);
      row.resultCell.dataset.met = String(ok);
      row.resultCell.dataset.target = String(target);
      row.resultCell.dataset.achieved = String(value ?? NaN);
      row.resultCell.textContent = `target ${formatReading(kind, target)} → ${formatReading(kind, value)}: ${ok ? 'met' : 'not met'} (±${formatReading(kind, this.found.tolerances[kind])})`;
      row.resultCell.classList.toggle('met', ok);
      row.resultCell.classList.toggle('not-met', !ok);
    }
  }
}
