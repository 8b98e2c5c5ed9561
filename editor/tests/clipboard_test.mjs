// Copy and paste on the document (editor/clipboard.js): fresh ids, wires
// between copied nodes kept, wires from outside kept only where their
// source exists in the scope pasted into, attributes and places kept.
//   node --test editor/tests/clipboard_test.mjs
import { test } from "node:test";
import assert from "node:assert/strict";
import { copyNodes, pasteNodes } from "../clipboard.js";

function document() {
  return {
    params: { octaves: "int" },
    nodes: [
      { id: "p", op: "mul", in: { a: "P", b: 2 } },
      { id: "turbulence1", op: "turbulence", in: { p: "p", octaves: "$octaves" } },
      { id: "spline1", op: "spline", in: { x: "turbulence1" }, attributes: { knots: [0, 0.2, 0.5, 0.8, 1, 1, 0.3, 0.1] } },
    ],
    outputs: { color: "spline1" },
    functions: { f: { inputs: { t: "float" }, nodes: [], outputs: {} } },
  };
}
const places = { p: [0, 0], turbulence1: [200, 0], spline1: [400, 10] };

test("a copy is the file's nodes, in the file's order, with their places", () => {
  const doc = document();
  const copy = copyNodes(doc, ["spline1", "turbulence1"], (id) => places[id]);
  assert.deepEqual(copy.nodes.map((node) => node.id), ["turbulence1", "spline1"]);
  assert.deepEqual(copy.places, [[200, 0], [400, 10]]);
  copy.nodes[1].attributes.knots[0] = 9;
  assert.equal(doc.nodes[2].attributes.knots[0], 0, "a copy shares nothing with the document");
});

test("a paste renames, keeps inner wires, outer wires whose source is there, and attributes", () => {
  const doc = document();
  const copy = copyNodes(doc, ["turbulence1", "spline1"], (id) => places[id]);
  const pasted = pasteNodes(doc, null, doc, copy, [30, 40]);
  assert.deepEqual(pasted, [["turbulence2", [230, 40]], ["spline2", [430, 50]]]);
  const [turbulence, spline] = doc.nodes.slice(3);
  assert.deepEqual(turbulence.in, { p: "p", octaves: "$octaves" });
  assert.deepEqual(spline.in, { x: "turbulence2" });
  assert.equal(spline.attributes.knots.length, 8);
});

test("pasted into a function, wires and params it lacks are dropped", () => {
  const doc = document();
  const copy = copyNodes(doc, ["turbulence1", "spline1"], (id) => places[id]);
  const body = doc.functions.f;
  const pasted = pasteNodes(doc, "f", body, copy, [0, 0]);
  assert.deepEqual(pasted.map(([id]) => id), ["turbulence1", "spline1"]);
  assert.equal(body.nodes[0].in, undefined, "neither p nor $octaves exists in f");
  assert.deepEqual(body.nodes[1].in, { x: "turbulence1" });
});

test("two pastes of one copy take different ids", () => {
  const doc = document();
  const copy = copyNodes(doc, ["p"], (id) => places[id]);
  pasteNodes(doc, null, doc, copy, [0, 0]);
  pasteNodes(doc, null, doc, copy, [0, 0]);
  assert.deepEqual(doc.nodes.map((node) => node.id), ["p", "turbulence1", "spline1", "mul1", "mul2"]);
});
