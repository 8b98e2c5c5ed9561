// The preview's size (editor/preview_size.js): the export's shape at the
// panel's long side, square where the export's size is not one, and the
// long side within its bounds whatever the panel's width.
//   node --test editor/tests/preview_size_test.mjs
import { test } from "node:test";
import assert from "node:assert/strict";
import { boundedSide, defaultPanelWidth, defaultPreviewSide, largestPreviewSide, panelForSide, shapedDims, sideForPanel,
         smallestPreviewSide } from "../preview_size.js";

test("a square export shows a square preview", () => {
  assert.deepEqual(shapedDims(256, 512, 512), [256, 256]);
});

test("a 16:9 export shows a 16:9 preview at the long side, either way round", () => {
  assert.deepEqual(shapedDims(256, 1920, 1080), [256, 144]);
  assert.deepEqual(shapedDims(256, 1080, 1920), [144, 256]);
});

test("a thin export keeps at least a pixel", () => {
  assert.deepEqual(shapedDims(256, 4096, 1), [256, 1]);
});

test("a size that is not one (an empty or negative field) shows a square preview", () => {
  assert.deepEqual(shapedDims(256, 0, 100), [256, 256]);
  assert.deepEqual(shapedDims(256, NaN, 100), [256, 256]);
  assert.deepEqual(shapedDims(256, -5, 100), [256, 256]);
});

test("the default panel shows the default side, and a wider panel a larger one", () => {
  assert.equal(sideForPanel(defaultPanelWidth), defaultPreviewSide);
  assert.equal(sideForPanel(defaultPanelWidth + 100), defaultPreviewSide + 100);
  assert.equal(sideForPanel(panelForSide(400)), 400);
});

test("the side stays within its bounds", () => {
  assert.equal(sideForPanel(0), smallestPreviewSide);
  assert.equal(sideForPanel(1e6), largestPreviewSide);
  assert.equal(boundedSide(Number("garbage")), defaultPreviewSide, "a side kept by an older page, say");
  assert.equal(boundedSide(300.4), 300);
});
