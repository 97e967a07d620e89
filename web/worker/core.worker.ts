// The only code that imports the WASM core. Runs every core call off the UI thread; arrays come
// out of WASM memory as copies and go back to the UI thread transferred, never copied again.
import init, { caesarLandmarkNames, coreVersion, pairSubjectFiles, parseLandmarks, parseScan, trapForTest, writeLandmarks } from '../pkg/bodyspace.js';
import type { AlignResult } from '../shared/align-types';
import type { CoreReply, CoreRequest } from '../shared/messages';
import type { MeshSummary, ParsedLandmarks, ParsedScan, SubjectPairing } from '../shared/results';
import { runAlign, runAlignDefaults, runAlignFiles, runExport, runRbfWarp } from './align-handlers';
import { runCheck, runEstimate } from './landmark-handlers';
import { templateData, templateTransfer } from './template-handlers';
import * as models from './model-handlers';
import { isWorkerRole, roleHandles } from '../shared/worker-roles';

const ready = init();
/** This worker's role: the name its client started it with (`client/core-client.ts`). */
const role = (self as unknown as DedicatedWorkerGlobalScope).name;

function post(reply: CoreReply, transfer: Transferable[] = []): void {
  (self as unknown as Worker).postMessage(reply, transfer);
}

/** Reads a scan with the core and returns its arrays with positions scaled to metres. */
function readScan(bytes: ArrayBuffer, fileName: string): ParsedScan {
  const t0 = performance.now();
  const scan = parseScan(new Uint8Array(bytes), fileName);
  const t1 = performance.now();
  try {
    const summary = JSON.parse(scan.summaryJson()) as MeshSummary;
    const positions = scan.positions();
    const scale = summary.scale_to_metres;
    if (scale !== 1) for (let i = 0; i < positions.length; i++) positions[i] = positions[i]! * scale;
    const result: ParsedScan = {
      fileName,
      positions,
      triangles: scan.triangles(),
      normals: scan.normals(),
      triangleFacing: scan.triangleFacing(),
      summary,
      timings: { coreMs: t1 - t0, copyMs: performance.now() - t1 },
    };
    return result;
  } finally {
    scan.free();
  }
}

function readLandmarks(bytes: ArrayBuffer, fileName: string): ParsedLandmarks {
  const parsed = JSON.parse(parseLandmarks(new Uint8Array(bytes), fileName)) as Omit<ParsedLandmarks, 'fileName'>;
  return { fileName, ...parsed };
}

self.onmessage = async (event: MessageEvent<CoreRequest>) => {
  const request = event.data;
  try {
    if (!isWorkerRole(role) || !roleHandles(role, request.type)) throw new Error(`the ${role || 'unnamed'} worker is not sent '${request.type}' requests`);
    await ready;
    switch (request.type) {
      case 'version':
        post({ id: request.id, type: 'result', result: coreVersion() });
        break;
      case 'caesarNames':
        post({ id: request.id, type: 'result', result: caesarLandmarkNames() });
        break;
      case 'parseScan': {
        post({ id: request.id, type: 'progress', fraction: 0, label: `Reading ${request.fileName}` });
        const scan = readScan(request.bytes, request.fileName);
        post({ id: request.id, type: 'result', result: scan }, [
          scan.positions.buffer,
          scan.triangles.buffer,
          scan.normals.buffer,
          scan.triangleFacing.buffer,
        ]);
        break;
      }
      case 'parseLandmarks':
        post({ id: request.id, type: 'result', result: readLandmarks(request.bytes, request.fileName) });
        break;
      case 'pairSubjectFiles':
        post({ id: request.id, type: 'result', result: JSON.parse(pairSubjectFiles(request.fileNames)) as SubjectPairing });
        break;
      case 'loadTemplate': {
        post({ id: request.id, type: 'progress', fraction: 0, label: `Loading the ${request.resolution} template` });
        const data = templateData(request.resolution);
        post({ id: request.id, type: 'result', result: data }, templateTransfer(data));
        break;
      }
      case 'alignDefaults':
        post({ id: request.id, type: 'result', result: runAlignDefaults() });
        break;
      case 'rbfWarp': {
        const warp = runRbfWarp(request.scan, request.params);
        post({ id: request.id, type: 'result', result: warp }, [warp.positions.buffer, warp.normals.buffer]);
        break;
      }
      case 'align': {
        const id = request.id;
        const aligned = runAlign(request.subject, request.options, (event, transfer) =>
          post({ id, type: 'event', event }, transfer),
        );
        const result: AlignResult = { ...aligned, wasmMemoryBytes: (await ready).memory.buffer.byteLength };
        post({ id, type: 'result', result }, [result.positions.buffer, result.normals.buffer, result.distances.buffer, result.heat.colours.buffer]);
        break;
      }
      case 'alignFiles': {
        const id = request.id;
        const aligned = runAlignFiles(request.scan, request.landmarks, request.resolution, request.options, (event) => post({ id, type: 'event', event }));
        const result: AlignResult = { ...aligned, wasmMemoryBytes: (await ready).memory.buffer.byteLength };
        post({ id, type: 'result', result }, [result.positions.buffer, result.normals.buffer, result.distances.buffer, result.heat.colours.buffer]);
        break;
      }
      case 'estimateLandmarks': {
        const id = request.id;
        post({ id, type: 'progress', fraction: 0, label: 'Estimating the landmarks: finding the frame' });
        const estimate = runEstimate(request.scan, request.orientation, (fraction, label) => post({ id, type: 'progress', fraction, label }));
        const transfer = [estimate.positions.buffer, estimate.confidence.buffer, estimate.given.buffer, estimate.prediction.positions.buffer, estimate.prediction.parts.buffer];
        post({ id, type: 'result', result: estimate }, transfer);
        break;
      }
      case 'checkLandmarks':
        post({ id: request.id, type: 'result', result: runCheck(request.names, request.positions, request.prediction) });
        break;
      case 'exportMesh': {
        const bytes = runExport(request.positions, request.triangles, request.format);
        post({ id: request.id, type: 'result', result: bytes }, [bytes.buffer]);
        break;
      }
      case 'writeLandmarks': {
        const bytes = writeLandmarks(request.names.join('\n'), request.positions, request.format, request.subjectId);
        post({ id: request.id, type: 'result', result: bytes }, [bytes.buffer]);
        break;
      }
      case 'loadModel': {
        post({ id: request.id, type: 'progress', fraction: 0, label: `Reading ${request.fileName}` });
        const loaded = await models.loadModel(request.bytes, request.fileName);
        post({ id: request.id, type: 'result', result: loaded }, [loaded.triangles.buffer]);
        break;
      }
      case 'buildModel': {
        const n = request.names.length;
        post({ id: request.id, type: 'progress', fraction: 0.05, label: `Building a model of ${n} subjects (PCA and quality curves)` });
        const built = models.buildModel(request.positions, request.names, request.variance);
        post({ id: request.id, type: 'progress', fraction: 1, label: 'Model built' });
        post({ id: request.id, type: 'result', result: built }, [built.triangles.buffer]);
        break;
      }
      case 'morph': {
        const body = models.morph(request.coefficients, request.rebuild);
        post({ id: request.id, type: 'result', result: body }, [body.positions.buffer, body.normals.buffer]);
        break;
      }
      case 'reconstruct': {
        const body = models.reconstruct(request.coefficients);
        post({ id: request.id, type: 'result', result: body }, [body.positions.buffer, body.normals.buffer]);
        break;
      }
      case 'shapeResolution': {
        const id = request.id;
        const shown = models.useResolution(request.resolution, (fraction, label) => post({ id, type: 'progress', fraction, label }));
        post({ id, type: 'result', result: shown }, [shown.triangles.buffer]);
        break;
      }
      case 'bodyFromMeasurements':
        post({ id: request.id, type: 'result', result: models.bodyFromMeasurements(request.targets, request.part) });
        break;
      case 'measurementDistribution': {
        const id = request.id;
        const d = models.measurementDistribution((fraction, label) => post({ id, type: 'progress', fraction, label }));
        post({ id, type: 'result', result: d });
        break;
      }
      case 'boundaryManikins': {
        const id = request.id;
        const set = models.boundaryManikins(request.names, request.coverage, (fraction, label) => post({ id, type: 'progress', fraction, label }));
        post({ id, type: 'result', result: set });
        break;
      }
      case 'manikinDefaults':
        post({ id: request.id, type: 'result', result: models.manikinDefaults() });
        break;
      case 'modelCsv':
        post({ id: request.id, type: 'result', result: models.modelCsv(request.kind) });
        break;
      case 'modelGlb': {
        const glb = models.modelGlb(request.modes, request.parts);
        post({ id: request.id, type: 'result', result: glb }, [glb.buffer]);
        break;
      }
      case 'trap':
        trapForTest();
        break;
      case 'modelStatismo': {
        post({ id: request.id, type: 'progress', fraction: 0, label: 'Writing the statismo file' });
        const file = await models.modelStatismo(request.part);
        post({ id: request.id, type: 'result', result: file }, [file.buffer]);
        break;
      }
      case 'modelFile': {
        const file = models.modelFile();
        post({ id: request.id, type: 'result', result: file }, [file.buffer]);
        break;
      }
    }
  } catch (error) {
    // A trap leaves the WASM instance unusable; every other error is the core's message.
    const fatal = error instanceof WebAssembly.RuntimeError;
    const message = error instanceof Error ? error.message : String(error);
    post({
      id: request.id,
      type: 'error',
      message: fatal ? `the core stopped unexpectedly (${message}); it has been restarted` : message,
      fatal,
    });
  }
};
