// The graph document itself, apart from any view of it: its scopes (the
// main graph, each function's body), the references of its inputs, and
// which nodes its outputs read.

// The node list and outputs of a scope (null: the main graph).
export function scopeBody(doc, scope) {
  return scope ? doc.functions[scope] : doc;
}

// What "$name" refers to in a scope: the params, or the function's inputs.
export function sourcesOf(doc, scope) {
  const declared = (scope ? doc.functions[scope].inputs : doc.params) || {};
  return Object.entries(declared).map(([name, spec]) => ({ name, type: typeof spec === "string" ? spec : spec.type }));
}

// "id" or "id.output": a wire from a node; "$name": a param or function input.
export function parseReference(value) {
  if (typeof value !== "string" || value.startsWith("$")) return null;
  const dot = value.indexOf(".");
  return dot < 0 ? { id: value, output: null } : { id: value.slice(0, dot), output: value.slice(dot + 1) };
}

// A node id not yet taken in `body`: the op's name and a number.
export function freshId(body, op, taken = () => false) {
  let n = 1;
  while (body.nodes.some((node) => node.id === `${op}${n}`) || taken(`${op}${n}`)) n += 1;
  return `${op}${n}`;
}

// The nodes of `body` that `references` ("id", "id.output") read, directly
// or through other nodes, by id.
export function upstreamOf(body, references) {
  const nodes = new Map(body.nodes.map((node) => [node.id, node]));
  const upstream = new Map();
  const stack = [...references];
  while (stack.length > 0) {
    const reference = parseReference(stack.pop());
    const node = reference && nodes.get(reference.id);
    if (!node || upstream.has(node.id)) continue;
    upstream.set(node.id, node);
    stack.push(...Object.values(node.in || {}));
  }
  return upstream;
}

// The document without the nodes no output reads, in every body; in the
// body of `scope` (null: the main graph), the nodes `alsoRead` reads stay.
export function withoutUnreadNodes(doc, scope = null, alsoRead = []) {
  const pruned = structuredClone(doc);
  for (const [name, body] of [[null, pruned], ...Object.entries(pruned.functions || {})]) {
    const read = upstreamOf(body, [...Object.values(body.outputs || {}), ...(name === scope ? alsoRead : [])]);
    body.nodes = body.nodes.filter((node) => read.has(node.id));
  }
  return pruned;
}
