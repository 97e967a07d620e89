// Property tests of the link decoder (fast-check): whatever a link carries, decoding never throws,
// never accepts a model location that is neither a same-origin path nor https, and every link the
// app writes decodes to the same body. Runs in Node.
import { test } from '@playwright/test';
import fc from 'fast-check';
import { decodeShapeLink, encodeShapeLink, quantiseSigma, type ShapeLink } from '../../web/shared/shape-link';
import { SEGMENTS } from '../../web/shared/shape-results';

const RUNS = 10_000;

test('any hash decodes to a link or to problems, without throwing', () => {
  const part = fc.oneof(
    fc.string(),
    fc.constantFrom('m=models/demo.bsm', 'w=AAAA', 'w=', 'v=torso', 'r=fine', 'c=1,2,3,4,5,6', 's=torso.AQA', 'm=https%3A%2F%2Fa.b%2Fc'),
  );
  fc.assert(
    fc.property(fc.array(part, { maxLength: 8 }), (parts) => {
      const decoded = decodeShapeLink(`#${parts.join('&')}`);
      if (decoded === null) return true;
      if (!decoded.link) return decoded.problems.length > 0;
      const m = decoded.link.model;
      return (m === '' || m.startsWith('https://') || !/^[a-z]+:/i.test(m)) && !m.includes('..');
    }),
    { numRuns: RUNS },
  );
});

test('every link the app writes decodes to the same body', () => {
  const sigma = fc.double({ min: -40, max: 40, noNaN: true }).map(quantiseSigma);
  const coords = fc.tuple(fc.double({ min: -999, max: 999, noNaN: true }), fc.double({ min: -999, max: 999, noNaN: true }), fc.double({ min: -999, max: 999, noNaN: true }));
  const link: fc.Arbitrary<ShapeLink> = fc.record({
    model: fc.oneof(fc.constant('models/demo.bsm'), fc.webUrl({ validSchemes: ['https'] }).filter((u) => !/\s/.test(u))),
    coefficients: fc.record({
      whole: fc.array(sigma, { maxLength: 40 }),
      segments: fc.tuple(...SEGMENTS.map(() => fc.option(fc.array(sigma, { maxLength: 20 }), { nil: null }))),
    }),
    view: fc.constantFrom('whole' as const, ...SEGMENTS),
    camera: fc.option(fc.record({ position: coords, target: coords }), { nil: null }),
    resolution: fc.constantFrom('base' as const, 'fine' as const),
  });
  fc.assert(
    fc.property(link, (original) => {
      const back = decodeShapeLink(encodeShapeLink(original))?.link;
      if (!back) return false;
      const same = (a: number[] | null, b: number[] | null) =>
        a === null || b === null ? a === b : a.length === b.length && a.every((t, i) => Math.abs(t - b[i]!) < 1e-9);
      const camera = original.camera
        ? back.camera !== null && [...original.camera.position, ...original.camera.target].every((x, i) => Math.abs(x - [...back.camera!.position, ...back.camera!.target][i]!) < 1e-4)
        : back.camera === null;
      return (
        back.model === original.model &&
        back.view === original.view &&
        back.resolution === original.resolution &&
        same(back.coefficients.whole, original.coefficients.whole) &&
        back.coefficients.segments.every((v, i) => same(v, original.coefficients.segments[i] ?? null)) &&
        camera
      );
    }),
    { numRuns: 2_000 },
  );
});
