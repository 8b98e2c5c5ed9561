// documentText (editor/document_text.js): a graph file saved after an
// edit differs from the file opened only where the document does.
//   node --test editor/tests/document_text_test.mjs
import { readdirSync, readFileSync } from "node:fs";
import { join } from "node:path";
import { test } from "node:test";
import assert from "node:assert/strict";
import { documentText } from "../document_text.js";

const gallery = join(import.meta.dirname, "..", "..", "graphs");
const fireball = readFileSync(join(gallery, "fireball.json"), "utf8");

// The lines of `after` that are not those of `before`, and the reverse.
function changedLines(before, after) {
  const a = before.split("\n"), b = after.split("\n");
  let head = 0;
  while (head < a.length && head < b.length && a[head] === b[head]) ++head;
  let tail = 0;
  while (tail < a.length - head && tail < b.length - head && a[a.length - 1 - tail] === b[b.length - 1 - tail]) ++tail;
  return { removed: a.slice(head, a.length - tail), added: b.slice(head, b.length - tail) };
}

const edited = (text, edit) => {
  const doc = JSON.parse(text);
  edit(doc);
  const result = documentText(text, doc);
  assert.deepEqual(JSON.parse(result), doc, "the text holds the document");
  return result;
};

test("every gallery file unedited is written back byte for byte", () => {
  const files = readdirSync(gallery).filter((name) => name.endsWith(".json"));
  assert.ok(files.length > 40);
  for (const name of files) {
    const text = readFileSync(join(gallery, name), "utf8");
    assert.equal(documentText(text, JSON.parse(text)), text, name);
  }
});

test("a changed param default changes that one line only", () => {
  const result = edited(fireball, (doc) => { doc.params.scale.default = 3.25; });
  assert.deepEqual(changedLines(fireball, result), {
    removed: ['    "scale": {"type": "float", "default": 2.5, "min": 0.1, "max": 64, "doc": "frequency of the turbulence"},'],
    added: ['    "scale": {"type": "float", "default": 3.25, "min": 0.1, "max": 64, "doc": "frequency of the turbulence"},'],
  });
});

test("a number written as a float stays written as one", () => {
  const result = edited(fireball, (doc) => { doc.nodes.find((n) => n.id === "flame").knots[0][1] = 1; });
  assert.match(result, /"knots": \[\[0\.4, 1\.0, 0\.0\], \[0\.5,/);
  assert.equal(changedLines(fireball, result).added.length, 1);
});

test("a new node is a line of its own, as its neighbours are written", () => {
  const result = edited(fireball, (doc) => { doc.nodes.push({ id: "noise1", op: "noise", in: { p: "x" } }); });
  assert.deepEqual(changedLines(fireball, result), {
    removed: ['    {"id": "opacity", "op": "mul", "in": {"a": "density", "b": 0.35}}'],
    added: ['    {"id": "opacity", "op": "mul", "in": {"a": "density", "b": 0.35}},',
            '    {"id": "noise1", "op": "noise", "in": {"p": "x"}}'],
  });
});

test("a deleted node takes its line with it, first, middle or last", () => {
  for (const id of ["x", "push", "opacity"]) {
    const result = edited(fireball, (doc) => { doc.nodes = doc.nodes.filter((n) => n.id !== id); });
    const { removed, added } = changedLines(fireball, result);
    assert.ok(removed.some((line) => line.includes(`"id": "${id}"`)), id);
    assert.ok(removed.length <= 2 && added.length <= 1, `${id}: ${JSON.stringify({ removed, added })}`);
  }
});

test("a rewired input and a new input change the node's line only", () => {
  const result = edited(fireball, (doc) => {
    const ball = doc.nodes.find((n) => n.id === "ball");
    ball.in.radius = "push";
    ball.in.extra = [1, 2];
  });
  assert.deepEqual(changedLines(fireball, result).added,
                   ['    {"id": "ball", "op": "sphere", "in": {"p": "scaled", "radius": "push", "softness": 0.9, "extra": [1, 2]}},']);
});

test("a renamed param keeps its place", () => {
  const result = edited(fireball, (doc) => {
    doc.params = Object.fromEntries(Object.entries(doc.params).map(([name, spec]) => [name === "drift" ? "rise" : name, spec]));
  });
  const lines = result.split("\n");
  assert.ok(lines.findIndex((line) => line.includes('"rise"')) < lines.findIndex((line) => line.includes('"evolve"')));
  assert.equal(changedLines(fireball, result).added.length, 1);
});

test("inline arrays and objects lose and gain members with their separators", () => {
  const text = '{"a": [1, 2, 3], "b": {"x": 1, "y": 2}, "c": [], "d": {}}\n';
  const cases = [
    [(doc) => doc.a.pop(), '{"a": [1, 2], "b": {"x": 1, "y": 2}, "c": [], "d": {}}\n'],
    [(doc) => doc.a.shift(), '{"a": [2, 3], "b": {"x": 1, "y": 2}, "c": [], "d": {}}\n'],
    [(doc) => { doc.a = [1]; }, '{"a": [1], "b": {"x": 1, "y": 2}, "c": [], "d": {}}\n'],
    [(doc) => delete doc.b.y, '{"a": [1, 2, 3], "b": {"x": 1}, "c": [], "d": {}}\n'],
    [(doc) => delete doc.b.x, '{"a": [1, 2, 3], "b": {"y": 2}, "c": [], "d": {}}\n'],
    [(doc) => { doc.c.push(4, 5); doc.d.z = "w"; }, '{"a": [1, 2, 3], "b": {"x": 1, "y": 2}, "c": [4, 5], "d": {"z": "w"}}\n'],
    [(doc) => { doc.b = { y: 2, x: 1 }; }, text],
    [(doc) => { doc.a = "a"; }, '{"a": "a", "b": {"x": 1, "y": 2}, "c": [], "d": {}}\n'],
  ];
  for (const [edit, expected] of cases) assert.equal(edited(text, edit), expected);
});

test("a field set to undefined is left out, as JSON.stringify leaves it", () => {
  const text = '{"a": 1, "b": 2}';
  assert.equal(documentText(text, { a: 1, b: undefined }), '{"a": 1}');
});

// A small seeded generator, so that a failure names its seed.
function random(seed) {
  let state = seed;
  return (n) => {
    state = (state * 1103515245 + 12345) % 2147483648;
    return Math.floor((state / 2147483648) * n);
  };
}

// Random edits anywhere in a document: numbers changed, keys and elements
// deleted, added and replaced, values retyped.
function mutate(value, pick) {
  if (Array.isArray(value)) {
    const action = pick(6);
    if (action === 0 && value.length > 0) value.splice(pick(value.length), 1);
    else if (action === 1) value.splice(pick(value.length + 1), 0, pick(2) ? pick(100) / 8 : { id: `n${pick(1000)}`, op: "add" });
    else if (value.length > 0) {
      const i = pick(value.length);
      value[i] = mutate(value[i], pick);
    }
    return value;
  }
  if (value && typeof value === "object") {
    const keys = Object.keys(value);
    const action = pick(6);
    if (action === 0 && keys.length > 0) delete value[keys[pick(keys.length)]];
    else if (action === 1) value[`k${pick(50)}`] = pick(2) ? [pick(9), 0.5] : "text";
    else if (keys.length > 0) {
      const key = keys[pick(keys.length)];
      value[key] = mutate(value[key], pick);
    }
    return value;
  }
  return pick(4) === 0 ? [value] : typeof value === "number" ? value + pick(7) - 3 : value;
}

test("random edits of every gallery file: the text holds the edited document", () => {
  const files = readdirSync(gallery).filter((name) => name.endsWith(".json"));
  for (const [index, name] of files.entries()) {
    const text = readFileSync(join(gallery, name), "utf8");
    for (let round = 0; round < 20; ++round) {
      const seed = index * 100 + round;
      const pick = random(seed);
      const doc = JSON.parse(text);
      for (let edits = 1 + pick(5); edits > 0; --edits) mutate(doc, pick);
      assert.deepEqual(JSON.parse(documentText(text, doc)), doc, `${name}, seed ${seed}`);
    }
  }
});
