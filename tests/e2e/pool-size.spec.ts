// The batch's pool size: the machine's cores, capped by the memory the browser reports.
import { expect, test } from '@playwright/test';
import { JOB_MEMORY_MIB, poolSize } from '../../web/shared/pool-size';

test('the pool takes every core when memory allows, fewer when it does not, never none', () => {
  expect(poolSize(8, undefined, JOB_MEMORY_MIB.base)).toBe(8);
  expect(poolSize(8, 8, JOB_MEMORY_MIB.base)).toBe(8);
  // Half of 2 GiB at 500 MiB a job: 2 workers of 8 cores.
  expect(poolSize(8, 2, JOB_MEMORY_MIB.fine)).toBe(2);
  expect(poolSize(16, 0.5, JOB_MEMORY_MIB.fine)).toBe(1);
  expect(poolSize(undefined, undefined, JOB_MEMORY_MIB.base)).toBe(1);
  expect(poolSize(0, 4, JOB_MEMORY_MIB.base)).toBe(1);
});
