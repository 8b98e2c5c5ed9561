// Copy, paste and duplicate of nodes, done on the document rather than by
// litegraph (whose copies are its own nodes, without the attributes,
// constants and docs a graph file gives them): a copy is the nodes as the
// file has them and their places; a paste gives each a fresh id, keeps
// the wires between the copied nodes, and keeps a wire from outside the
// copy where the scope pasted into has its source (so a duplicate keeps
// its inputs, as Ctrl+Shift+V does in ComfyUI).
import { freshId, parseReference, sourcesOf } from "./graph_document.js";

// The nodes of `body` with ids `ids`, in the file's order, and their places.
export function copyNodes(body, ids, placeOf) {
  const nodes = body.nodes.filter((node) => ids.includes(node.id)).map((node) => structuredClone(node));
  return { nodes, places: nodes.map((node) => placeOf(node.id)) };
}

// Adds `copy`'s nodes to `body` (a scope of `doc`, null: the main graph),
// their places moved by `offset`; returns [id, place] of each new node.
export function pasteNodes(doc, scope, body, copy, offset) {
  const renamed = new Map();
  for (const node of copy.nodes) renamed.set(node.id, freshId(body, node.op, (id) => [...renamed.values()].includes(id)));
  const sources = new Set(sourcesOf(doc, scope).map((source) => source.name));
  const outside = new Set(body.nodes.map((node) => node.id));
  const rewired = (value) => {
    if (typeof value !== "string") return value;
    if (value.startsWith("$")) return sources.has(value.slice(1)) ? value : undefined;
    const { id, output } = parseReference(value);
    if (renamed.has(id)) return output === null ? renamed.get(id) : `${renamed.get(id)}.${output}`;
    return outside.has(id) ? value : undefined;
  };
  return copy.nodes.map((original, i) => {
    const node = { ...structuredClone(original), id: renamed.get(original.id) };
    if (node.in) {
      node.in = Object.fromEntries(Object.entries(node.in).map(([input, value]) => [input, rewired(value)])
                                                          .filter(([, value]) => value !== undefined));
      if (Object.keys(node.in).length === 0) delete node.in;
    }
    body.nodes.push(node);
    const place = copy.places[i];
    return [node.id, place && [place[0] + offset[0], place[1] + offset[1]]];
  });
}
