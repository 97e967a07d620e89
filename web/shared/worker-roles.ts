// The page's core workers by role, and the messages each is sent: the one list. A client's type
// is built from it (`CoreClient<'align'>` takes only the align worker's messages), and the worker,
// named by its role, refuses any other. No DOM here: shared by both threads.
import type { CoreRequestBody } from './messages';

/** Every role's messages (request types of `CoreRequestBody`). */
export const ROLE_MESSAGES = {
  /** The main worker: files read, the template, the shape model shown and its exports, the batch's pairing. */
  core: [
    'version',
    'caesarNames',
    'parseScan',
    'parseLandmarks',
    'pairSubjectFiles',
    'loadTemplate',
    'writeLandmarks',
    'exportMesh',
    'loadModel',
    'buildModel',
    'morph',
    'reconstruct',
    'shapeResolution',
    'bodyFromMeasurements',
    'modelCsv',
    'modelGlb',
    'modelFile',
    'modelStatismo',
    'trap',
  ],
  /** The single scan's warp and fit, which Cancel stops; its fit's export. */
  align: ['alignDefaults', 'rbfWarp', 'align', 'exportMesh', 'trap'],
  /** The landmark estimate and the check of an edited set. */
  landmarks: ['estimateLandmarks', 'checkLandmarks'],
  /** Population work on its own copy of the model: distributions and manikins, which Cancel stops. */
  population: ['loadModel', 'manikinDefaults', 'measurementDistribution', 'boundaryManikins', 'reconstruct', 'exportMesh'],
  /** One worker of the batch's pool: one subject's files to a checked fit. */
  batch: ['alignFiles', 'trap'],
} as const satisfies Record<string, readonly CoreRequestBody['type'][]>;

export type WorkerRole = keyof typeof ROLE_MESSAGES;

/** The requests a worker of role `W` is sent (without their `id`). */
export type RoleRequest<W extends WorkerRole> = Extract<CoreRequestBody, { type: (typeof ROLE_MESSAGES)[W][number] }>;

/** Whether `name` is a role (the worker's name is its role). */
export function isWorkerRole(name: string): name is WorkerRole {
  return Object.hasOwn(ROLE_MESSAGES, name);
}

/** Whether a worker of `role` handles requests of `type`. */
export function roleHandles(role: WorkerRole, type: CoreRequestBody['type']): boolean {
  return (ROLE_MESSAGES[role] as readonly string[]).includes(type);
}
