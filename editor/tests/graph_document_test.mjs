// The graph document apart from any view (editor/graph_document.js):
// references, fresh ids, what the outputs read, unread nodes pruned.
//   node --test editor/tests/graph_document_test.mjs
import { test } from "node:test";
import assert from "node:assert/strict";
import { freshId, parseReference, sourcesOf, upstreamOf, withoutUnreadNodes } from "../graph_document.js";

const doc = {
  params: { scale: { type: "float", default: 4 }, tint: "color" },
  nodes: [
    { id: "p", op: "mul", in: { a: "P", b: "$scale" } },
    { id: "n", op: "noise", in: { p: "p" } },
    { id: "stray", op: "mul", in: { a: "n" } },
    { id: "loose", op: "add" },
  ],
  outputs: { color: "n.value" },
  functions: {
    f: { inputs: { x: "float" }, nodes: [{ id: "s", op: "sin", in: { x: "$x" } }, { id: "u", op: "cos" }], outputs: { y: "s" } },
  },
};

test("references name a node and an optional output; $names are not wires", () => {
  assert.deepEqual(parseReference("n"), { id: "n", output: null });
  assert.deepEqual(parseReference("cell.distance"), { id: "cell", output: "distance" });
  assert.equal(parseReference("$scale"), null);
  assert.equal(parseReference(3), null);
});

test("sources are the params, or a function's inputs, with their types", () => {
  assert.deepEqual(sourcesOf(doc, null), [{ name: "scale", type: "float" }, { name: "tint", type: "color" }]);
  assert.deepEqual(sourcesOf(doc, "f"), [{ name: "x", type: "float" }]);
});

test("a fresh id skips the ids the body and the caller have taken", () => {
  assert.equal(freshId(doc, "noise"), "noise1");
  const body = { nodes: [{ id: "mul1" }, { id: "mul2" }] };
  assert.equal(freshId(body, "mul"), "mul3");
  assert.equal(freshId(body, "mul", (id) => id === "mul3"), "mul4");
});

test("upstream follows wires through nodes and ignores params and unknown ids", () => {
  assert.deepEqual([...upstreamOf(doc, ["n.value"]).keys()].sort(), ["n", "p"]);
  assert.deepEqual([...upstreamOf(doc, ["stray", "nothing"]).keys()].sort(), ["n", "p", "stray"]);
  assert.equal(upstreamOf(doc, ["$scale"]).size, 0);
});

test("unread nodes go from every body, the document itself is untouched", () => {
  const pruned = withoutUnreadNodes(doc);
  assert.deepEqual(pruned.nodes.map((node) => node.id), ["p", "n"]);
  assert.deepEqual(pruned.functions.f.nodes.map((node) => node.id), ["s"]);
  assert.equal(doc.nodes.length, 4);
  const kept = withoutUnreadNodes(doc, null, ["stray"]);
  assert.deepEqual(kept.nodes.map((node) => node.id), ["p", "n", "stray"]);
  assert.deepEqual(withoutUnreadNodes(doc, "f", ["u"]).functions.f.nodes.map((node) => node.id), ["s", "u"]);
});
