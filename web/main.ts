// Wires the page: the core client, the viewer, the panels, and file drops / picks.
import './style.css';
import { AlignStep } from './app/align-step';
import { Batch } from './app/batch';
import { startBatch } from './app/batch-view';
import { LandmarkStep, type Shown } from './app/landmark-step';
import { Session, type SavedScanWork } from './app/session';
import { TemplateView } from './app/template-view';
import { WarpStep } from './app/warp-step';
import { readFiles } from './app/read-files';
import { SessionStore, type SavedScan } from './app/session-store';
import { ShapeSpace } from './app/shape-space';
import { CoreClient } from './client/core-client';
import { classifyFile } from './shared/file-kind';
import { METRES_PER_UNIT, type ParsedLandmarks, type ParsedScan, type Units } from './shared/results';
import { acceptDrops } from './ui/drop-overlay';
import { byId } from './ui/dom';
import { ErrorBanner } from './ui/error-banner';
import { ScanPanel } from './ui/scan-panel';
import { TopBar } from './ui/top-bar';
import { Viewer } from './view/viewer';

const client = new CoreClient('core');
// Long jobs that Cancel may stop (the RBF warp and alignment) run in a worker of their own:
// cancelling or losing it never touches the template, the scan read or the shape model, which live
// in the main core worker.
const alignClient = new CoreClient('align');
// The landmark estimate and its checks run in a third worker: cancelling an estimate stops only it.
const landmarkClient = new CoreClient('landmarks');
// Population work (measurement distributions, boundary manikins) runs in a fourth: cancelling it
// never touches the body shown.
const populationClient = new CoreClient('population');
let caesarNames: string[] = [];
const session = new Session(() => caesarNames);
const viewer = new Viewer(byId('viewport'));
const banner = new ErrorBanner();
const topBar = new TopBar((files) => void open(files));
const scanPanel = new ScanPanel(changeUnits);
const emptyHint = byId('empty-hint');
const body = document.body;
const showError = (message: string) => banner.show([message]);
const templateView = new TemplateView(client, viewer, showError);
const warpStep = new WarpStep(alignClient, viewer, session, templateView, showError);
const alignStep = new AlignStep(alignClient, viewer, session, templateView, warpStep, showError);
// An edited landmark set invalidates the warp and the fit as a new landmark file does, but keeps the view.
const landmarkStep = new LandmarkStep(client, landmarkClient, viewer, session, () => caesarNames, (keepView) => {
  session.changed(keepView ? 'edited' : 'estimated');
}, showError);
// Picking a landmark to place on a hidden scan (after Align) shows the scan, so the click lands.
landmarkStep.onPick = () => warpStep.show('scan', true);
// A landmark shown up close is placed on the scan: the warped template would cover it.
landmarkStep.onCloseUp = () => warpStep.show('warped', false);
// "Back to" work put aside: it comes back with its landmarks as they were shown.
landmarkStep.onBringBack = (index) => {
  const before = session.scan;
  session.bringBack(index);
  refresh(session.scan !== before);
  landmarkStep.afterBringBack();
  const name = session.scan?.fileName ?? '';
  topBar.setStatus(session.scan === before ? `Back to the other set of landmarks of ${name}.` : `Back to ${name}; ${before?.fileName ?? ''} is put aside.`);
};
// One change of the session, one reset of what was made from it: the picked landmark (new files),
// then the fit (before the warp: both run in the align worker, which a running fit's cancel stops),
// then the warp, which runs again (not under a batch fit, which takes only the fit's place).
session.onChange((change) => {
  if (change === 'aside') return;
  if (change === 'files') landmarkStep.reset();
  alignStep.reset();
  if (change !== 'batchFit') warpStep.reset(change === 'edited');
});
templateView.onLoaded((data) => landmarkStep.setTemplate(data));
templateView.onLoaded(() => {
  if (warpStep.ready) session.changed('template');
});
// The single scan's work kept in the browser, so a reload loses nothing.
const work = new SessionStore<Shown>(session, (edits) => landmarkStep.shownOf(edits));
session.onChange(() => work.saveSoon());
landmarkStep.onOriented = () => work.saveSoon();
let lastReadMs = 0;
let loads = 0;

const shapeSpace = new ShapeSpace(client, viewer, banner, populationClient);

// The batch aligns in a pool of workers of its own.
const batch = startBatch({ client, viewer, session, templateView, warpStep, shapeSpace, banner });

// `?debug` lets the crash-recovery tests trap a worker's core as a bug would: the main or align
// worker now, or the next batch job's worker when it starts.
if (new URLSearchParams(location.search).has('debug')) {
  const trap = (which: 'core' | 'align' | 'batch') => {
    if (which === 'batch') batch.trapNext = true;
    else void (which === 'core' ? client.call({ type: 'trap' }) : alignClient.call({ type: 'trap' })).catch(() => undefined);
  };
  const setBatchWorkers = (n: number | null) => (batch.workerLimit = n);
  // Where a point of the scan's frame (metres) is drawn, so a test can click where a landmark truly is.
  const canvasPoint = (point: [number, number, number]) => viewer.canvasPoint('scan', point);
  (window as unknown as { bodyspaceDebug: unknown }).bodyspaceDebug = { trap, setBatchWorkers, canvasPoint };
}
void shapeSpace.start(location.hash);

acceptDrops((files) => void open(files));

Promise.all([client.call({ type: 'version' }), client.call({ type: 'caesarNames' }), alignClient.call({ type: 'alignDefaults' })])
  .then(([version, names, defaults]) => {
    warpStep.panel.setDefaults(defaults);
    landmarkStep.nearlyFull = defaults.subject.nearly_full;
    caesarNames = names;
    landmarkStep.show(null);
    topBar.setStatus(`Core ${version} ready. Drop a scan and its landmarks anywhere on the page.`);
    body.dataset.coreReady = 'true';
    // A shared link brings its own camera: the template must not re-frame over it.
    return templateView.load('base', !location.hash);
  })
  .then(() => {
    // A shared link shows its model; the work saved stays for the next plain visit.
    if (!location.hash) void restoreWork().catch((error: Error) => banner.show([`The work saved before the reload could not be opened again: ${error.message}`]));
  })
  .catch((error: Error) => {
    topBar.setStatus('The core did not start.');
    banner.show([`The BodySpace core could not start: ${error.message}`]);
  });

/** Reads `files` and shows whatever was read; failures leave what was shown before in place. */
async function open(all: File[]): Promise<void> {
  const models = all.filter((f) => ShapeSpace.isModelFile(f.name));
  if (models.length) await shapeSpace.openModelFiles(models);
  const files = all.filter((f) => !ShapeSpace.isModelFile(f.name));
  if (files.length === 0) return;
  if (Batch.wants(files, (name) => classifyFile(name) === 'scan')) {
    await batch.add(files);
    topBar.setStatus(`Added ${files.length} files to the batch.`);
    body.dataset.loads = String(++loads);
    return;
  }
  body.dataset.busy = 'true';
  const outcome = await readFiles(client, files, (text) => topBar.setStatus(text));
  for (const s of outcome.scans) work.remember(s.scan, s.file);
  for (const l of outcome.landmarks) work.remember(l.landmarks, l.file);
  const scan = outcome.scans.at(-1);
  const landmarks = outcome.landmarks.at(-1)?.landmarks;
  if (scan) {
    lastReadMs = scan.roundTripMs;
    body.dataset.lastScanRoundTripMs = scan.roundTripMs.toFixed(2);
    body.dataset.lastScanCoreMs = scan.scan.timings.coreMs.toFixed(2);
    body.dataset.lastScanCopyMs = scan.scan.timings.copyMs.toFixed(2);
  }
  if (scan || landmarks) {
    const shownFile = session.landmarks;
    // A scan opened alone takes the landmark file shown when the core pairs their names (`a.ply`, `a.csv`).
    const namesPair = Boolean(scan && !landmarks && shownFile) && (await namesPairUp(scan!.scan.fileName, shownFile!.fileName));
    // Before the refresh, so the camera frames the new data, not the template beside it.
    session.open(scan?.scan ?? null, landmarks ?? null, namesPair);
    // The scan and the shape body would stand in the same place: the scan takes the view.
    shapeSpace.hide();
    refresh(Boolean(scan) || !session.scan);
    landmarkStep.afterLoad();
  }

  if (outcome.errors.length > 0) banner.show(outcome.errors);
  else if (scan || landmarks) banner.dismiss();
  const read = [...outcome.scans.map((s) => s.scan.fileName), ...outcome.landmarks.map((l) => l.landmarks.fileName)];
  topBar.setStatus(
    read.length ? `Opened ${read.join(', ')}` : outcome.errors.length ? 'Not opened: see the message above. What was open stays as it was.' : '',
  );
  body.dataset.busy = 'false';
  body.dataset.loads = String(++loads);
}

/**
 * Opens the work saved before the page was reloaded, if any and nothing was opened since: the
 * scan and its landmark file read again, the set and what the editor showed of it as they were,
 * and the work put aside with its own. Work put aside whose scan cannot be read again is named,
 * and the rest opens without it.
 */
async function restoreWork(): Promise<void> {
  const saved = await work.load();
  if (!saved || session.scan) return;
  const errors: string[] = [];
  const scans = new Map<number, ParsedScan | null>();
  const read = async (w: SavedScan<Shown>): Promise<SavedScanWork | null> => {
    if (!scans.has(w.scan)) scans.set(w.scan, (await readSaved(saved.scans[w.scan]!, saved.keys.get(saved.scans[w.scan]!), errors)) as ParsedScan | null);
    const scan = scans.get(w.scan);
    const landmarks = w.landmarks && ((await readSaved(w.landmarks, saved.keys.get(w.landmarks), errors)) as ParsedLandmarks | null);
    return scan ? { scan, landmarks, saved: w.saved } : null;
  };
  const [first, ...rest] = saved.works;
  const shown = await read(first!);
  if (!shown || session.scan) {
    if (errors.length) banner.show([`The scan saved before the reload could not be read again: ${errors.join(' ')}`]);
    return;
  }
  const asides: { work: SavedScanWork; view: Shown | null }[] = [];
  for (const w of rest) {
    const a = await read(w);
    if (a) asides.push({ work: a, view: w.view });
  }
  if (session.scan) return;
  if (errors.length) banner.show([`Not all the work saved before the reload could be read again; what could not is left out. ${errors.join(' ')}`]);
  session.restore(shown, asides.map((a) => a.work));
  session.putAside.forEach((w, i) => landmarkStep.keepShown(w.edits, asides[i]!.view));
  shapeSpace.hide();
  refresh(true);
  // An estimate the reload cut short, with nothing placed: estimated again, as after a load.
  landmarkStep.showAgain(session.edits?.placed().names.length ? first!.view : null);
  const aside = session.putAside.length ? `; ${session.putAside.length} put aside` : '';
  topBar.setStatus(`Restored ${shown.scan.fileName}${shown.landmarks ? ` and ${shown.landmarks.fileName}` : ''} with the landmarks as they were before the page was reloaded${aside}.`);
  body.dataset.restored = 'true';
}

/** Reads a file saved before a reload again (a scan or a landmark file), remembered with its record `key` for the next save; null, with the reason in `errors`, when it cannot be. */
async function readSaved(file: File, key: string | undefined, errors: string[]): Promise<ParsedScan | ParsedLandmarks | null> {
  const outcome = await readFiles(client, [file], (text) => topBar.setStatus(text));
  errors.push(...outcome.errors);
  const parsed = outcome.scans[0]?.scan ?? outcome.landmarks[0]?.landmarks ?? null;
  if (parsed) work.remember(parsed, file, key);
  return parsed;
}

/** Whether the core's rule for a batch's files (`pairSubjectFiles`) makes `landmarks` the landmark file of `scan`. */
async function namesPairUp(scan: string, landmarks: string): Promise<boolean> {
  const pairing = await client.call({ type: 'pairSubjectFiles', fileNames: [scan, landmarks] }).catch(() => null);
  return pairing?.subjects.some((s) => s.scan === 0 && s.landmarks === 1) ?? false;
}

function changeUnits(units: Units): void {
  session.setScanUnits(units);
  refresh(true);
}

/** Pushes the session into the view and the panels; `frame` re-aims the camera. */
function refresh(frame: boolean): void {
  const scan = session.scan;
  const set = session.landmarks;
  viewer.showBody('scan', { mesh: scan, triangleFacing: scan?.triangleFacing ?? null, meshScale: session.scanScale, landmarks: landmarkStep.markers() }, frame);
  emptyHint.hidden = Boolean(scan || set) || body.dataset.shapeShown === 'true';
  const summary = session.scanSummary;
  scanPanel.render(
    scan && summary ? { fileName: scan.fileName, summary, units: session.scanUnits, readMs: lastReadMs } : null,
  );
  landmarkStep.show(set ? { fileName: set.fileName, report: set.report, unitsNote: landmarkUnitsNote(set.units) } : null);
  body.dataset.scanLoaded = String(Boolean(scan));
  body.dataset.landmarksLoaded = String(Boolean(set));
  body.dataset.scanUnits = session.scanUnits;
}

function landmarkUnitsNote(fixed: Units | null): string {
  const units = session.landmarkUnits ?? 'metres';
  const why = fixed ? 'as the file format says' : session.scan ? 'following the scan' : 'guessed from their spread';
  return `Coordinates read in ${units} (${why}); 1 unit = ${METRES_PER_UNIT[units]} m.`;
}
