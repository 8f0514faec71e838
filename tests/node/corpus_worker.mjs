// Runs the corpus rows from `workerData.start` on, in a worker thread so that the test can stop a
// row that hangs. Posts one result per row; after a trap it stops, because a trapped wasm
// instance may be left in a broken state, and the test starts a fresh worker at the next row.
import { parentPort, workerData } from 'node:worker_threads';
import { corpusRows, runRow } from './corpus.mjs';

const rows = corpusRows();
parentPort.postMessage({ count: rows.length });
for (let i = workerData.start; i < rows.length; i++) {
  parentPort.postMessage({ started: i, name: rows[i][0] });
  const result = runRow(rows[i]);
  parentPort.postMessage({ index: i, name: rows[i][0], ...result });
  if (result.outcome === 'trap') break;
}
parentPort.postMessage({ finished: true });
