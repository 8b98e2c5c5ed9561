// The shadetree graph editor: the graph file (JSON) is the document; the
// node canvas (@comfyorg/litegraph) is a view of its nodes and wires, and
// every edit writes back into the document, which the server checks and
// renders (server/editor_server.h). Params are sliders that change only
// the document's param values, so a drag re-renders without recompiling.
import { LGraph, LGraphCanvas, LGraphNode, LiteGraph } from "/assets/node_modules/@comfyorg/litegraph/dist/litegraph.es.js";

const token = new URLSearchParams(location.search).get("token") || "";
const previewSize = 256;

// Requests carry the session token (the cookie would do too, but not for
// a page opened from a file:// URL in tests).
async function api(method, url, body) {
  const response = await fetch(url, { method, body, headers: { "X-Shadetree-Token": token } });
  return response;
}

const state = {
  library: new Map(),   // op name -> its entry of /api/nodes
  path: null,           // the graph file open, relative to the served folder
  doc: null,            // the graph file's JSON
  previews: 0,          // previews drawn
  lastError: null,      // the checker's diagnostic of the current document, or null
  sequence: 0,          // of the latest edit; older previews are dropped
};

const graph = new LGraph();
const canvas = new LGraphCanvas(document.getElementById("graph-canvas"), graph);
const status = document.getElementById("status");

function setStatus(text, isError) {
  status.textContent = text;
  status.classList.toggle("error", Boolean(isError));
}

// --- node types, one per library op and per function of the document ---

function registerType(name, inputs, outputs, doc, category) {
  const type = `${category}/${name}`;
  if (LiteGraph.registered_node_types[type]) return type;
  class OpNode extends LGraphNode {
    constructor() {
      super(name);
      // Any wire may be drawn ("*"): the checker judges it (floats promote
      // to vectors, T is inferred), and says what is wrong on the input.
      for (const input of inputs) this.addInput(input.name, "*", { label: `${input.name}: ${input.type}` });
      for (const output of outputs) this.addOutput(output.name, "*", { label: `${output.name}: ${output.type}` });
      this.op = name;
    }
    onConnectionsChange() { scheduleUpdate(); }
  }
  OpNode.title = name;
  OpNode.desc = doc;
  LiteGraph.registerNodeType(type, OpNode);
  return type;
}

function typeForOp(op) {
  const entry = state.library.get(op);
  if (entry) return registerType(op, entry.inputs, entry.outputs, entry.doc, `shadetree/${entry.family}`);
  const fn = state.doc.functions && state.doc.functions[op];
  if (!fn) return null;
  const inputs = Object.entries(fn.inputs || {}).map(([name, type]) => ({ name, type: typeof type === "string" ? type : type.type }));
  const outputs = Object.keys(fn.outputs || {}).map((name) => ({ name, type: "*" }));
  return registerType(op, inputs, outputs, fn.doc || "", "functions");
}

// --- the document as nodes and wires ---

// "id" or "id.output": a wire from a node; "$name": a param; otherwise a literal.
function parseReference(value) {
  if (typeof value !== "string" || value.startsWith("$")) return null;
  const dot = value.indexOf(".");
  return dot < 0 ? { id: value, output: null } : { id: value.slice(0, dot), output: value.slice(dot + 1) };
}

function showDocument() {
  graph.clear();
  const byId = new Map();
  const depth = new Map();
  for (const node of state.doc.nodes) {
    const type = typeForOp(node.op);
    const view = type ? LiteGraph.createNode(type) : new LGraphNode(node.op);
    view.title = node.id;
    view.shadetreeId = node.id;
    let level = 0;
    for (const value of Object.values(node.in || {})) {
      const reference = parseReference(value);
      if (reference && depth.has(reference.id)) level = Math.max(level, depth.get(reference.id) + 1);
    }
    depth.set(node.id, level);
    const row = [...depth.values()].filter((d) => d === level).length - 1;
    view.pos = [30 + level * 230, 30 + row * 130];
    graph.add(view);
    byId.set(node.id, view);
  }
  for (const node of state.doc.nodes) {
    const target = byId.get(node.id);
    for (const [input, value] of Object.entries(node.in || {})) {
      const reference = parseReference(value);
      const source = reference && byId.get(reference.id);
      const slot = target.findInputSlot(input);
      if (!source || slot < 0) continue;
      const output = reference.output ? source.findOutputSlot(reference.output) : 0;
      source.connect(Math.max(output, 0), target, slot);
    }
  }
  canvas.setDirty(true, true);
}

// The document with its wires as the canvas has them. Nodes keep their
// place in the file and every field they had (attributes, docs); new
// nodes go last.
function documentFromCanvas() {
  const doc = structuredClone(state.doc);
  const views = new Map();
  for (const view of graph._nodes) if (view.shadetreeId) views.set(view.shadetreeId, view);
  doc.nodes = doc.nodes.filter((node) => views.has(node.id));
  for (const view of graph._nodes) {
    if (!view.shadetreeId) continue;
    let node = doc.nodes.find((n) => n.id === view.shadetreeId);
    if (!node) {
      node = { id: view.shadetreeId, op: view.op };
      doc.nodes.push(node);
    }
    const wires = {};
    for (const [input, value] of Object.entries(node.in || {})) if (!parseReference(value)) wires[input] = value;
    view.inputs.forEach((slot, index) => {
      const link = view.getInputLink(index);
      if (!link) return;
      const source = graph.getNodeById(link.origin_id);
      const outputs = source.outputs || [];
      wires[slot.name] = outputs.length > 1 ? `${source.shadetreeId}.${outputs[link.origin_slot].name}` : source.shadetreeId;
    });
    if (Object.keys(wires).length > 0) node.in = wires;
    else delete node.in;
  }
  return doc;
}

// --- params as sliders ---

function showParams() {
  const panel = document.getElementById("params");
  panel.replaceChildren();
  for (const [name, param] of Object.entries(state.doc.params || {})) {
    const label = document.createElement("label");
    label.textContent = name + (param.doc ? ` — ${param.doc}` : "");
    panel.append(label);
    if (param.type === "float" || param.type === "int") {
      const slider = document.createElement("input");
      slider.type = "range";
      slider.name = name;
      slider.min = param.min ?? 0;
      slider.max = param.max ?? Math.max(1, Number(param.default) * 4);
      slider.step = param.type === "int" ? 1 : (slider.max - slider.min) / 1000;
      slider.value = param.default;
      const value = document.createElement("span");
      value.textContent = ` ${param.default}`;
      slider.addEventListener("input", () => {
        param.default = param.type === "int" ? Math.round(Number(slider.value)) : Number(slider.value);
        value.textContent = ` ${param.default}`;
        scheduleUpdate();
      });
      panel.append(slider, value);
    } else if (param.type === "color") {
      const picker = document.createElement("input");
      picker.type = "color";
      picker.name = name;
      const hex = (v) => Math.round(Math.min(1, Math.max(0, v)) * 255).toString(16).padStart(2, "0");
      picker.value = "#" + param.default.map(hex).join("");
      picker.addEventListener("input", () => {
        param.default = [1, 3, 5].map((i) => parseInt(picker.value.slice(i, i + 2), 16) / 255);
        scheduleUpdate();
      });
      panel.append(picker);
    }
  }
}

// --- check and preview after every edit, the latest one winning ---

let pending = null;
let inflight = null;

function scheduleUpdate() {
  if (!state.doc) return;
  clearTimeout(pending);
  pending = setTimeout(update, 15);
}

function markError(diagnostic) {
  for (const view of graph._nodes) {
    const wrong = diagnostic && view.shadetreeId === diagnostic.node;
    view.color = wrong ? "#8a2c2c" : undefined;
    view.bgcolor = wrong ? "#4a1f1f" : undefined;
    for (const slot of view.inputs || []) {
      const wrongInput = wrong && slot.name === diagnostic.input;
      slot.color_on = wrongInput ? "#ff5555" : undefined;
      slot.color_off = wrongInput ? "#ff5555" : undefined;
      slot.label = slot.label.replace(/ ⚠$/, "") + (wrongInput ? " ⚠" : "");
    }
  }
  document.getElementById("diagnostic").textContent = diagnostic ? diagnostic.text : "";
  canvas.setDirty(true, true);
}

async function update() {
  const sequence = ++state.sequence;
  const body = JSON.stringify(documentFromCanvas(), null, 2);
  const query = state.path ? `path=${encodeURIComponent(state.path)}&` : "";
  const check = await (await api("POST", `/api/check?${query.slice(0, -1)}`, body)).json();
  if (sequence !== state.sequence) return;
  state.lastError = check.ok ? null : check.error;
  markError(state.lastError);
  if (!check.ok) {
    setStatus(check.error.text, true);
    return;
  }
  if (inflight) inflight.abort();
  inflight = new AbortController();
  try {
    const response = await fetch(`/api/preview?${query}width=${previewSize}&height=${previewSize}`, {
      method: "POST", body, signal: inflight.signal, headers: { "X-Shadetree-Token": token } });
    if (sequence !== state.sequence) return;
    if (!response.ok) {
      setStatus((await response.json()).error, true);
      return;
    }
    const pixels = new Uint8ClampedArray(await response.arrayBuffer());
    const width = Number(response.headers.get("X-Width"));
    const height = Number(response.headers.get("X-Height"));
    const preview = document.getElementById("preview");
    preview.getContext("2d").putImageData(new ImageData(pixels, width, height), 0, 0);
    state.previews += 1;
    document.getElementById("preview-info").textContent =
      `${width}x${height} in ${Number(response.headers.get("X-Milliseconds")).toFixed(1)} ms (kernel: ${response.headers.get("X-Kernel")})`;
    setStatus(`${state.path || "untitled"}: ok`, false);
  } catch (error) {
    if (error.name !== "AbortError") setStatus(String(error), true);
  }
}

// --- files ---

async function open(path) {
  const response = await api("GET", `/api/graph?path=${encodeURIComponent(path)}`);
  if (!response.ok) {
    setStatus((await response.json()).error, true);
    return;
  }
  state.path = path;
  state.doc = await response.json();
  showDocument();
  showParams();
  await update();
}

async function save() {
  const body = JSON.stringify(documentFromCanvas(), null, 2) + "\n";
  const response = await api("PUT", `/api/graph?path=${encodeURIComponent(state.path)}`, body);
  const result = await response.json();
  setStatus(response.ok ? `saved ${result.saved}` : result.error, !response.ok);
  return response.ok;
}

function addNode(op) {
  const type = typeForOp(op);
  if (!type) return null;
  const view = LiteGraph.createNode(type);
  let n = 1;
  while (state.doc.nodes.some((node) => node.id === `${op}${n}`) || graph._nodes.some((v) => v.shadetreeId === `${op}${n}`)) n += 1;
  view.shadetreeId = `${op}${n}`;
  view.title = view.shadetreeId;
  view.op = op;
  view.pos = [40, 40];
  graph.add(view);
  scheduleUpdate();
  return view;
}

// Wires output `output` of node `from` into input `input` of node `to` (ids).
function connect(from, output, to, input) {
  const source = graph._nodes.find((v) => v.shadetreeId === from);
  const target = graph._nodes.find((v) => v.shadetreeId === to);
  source.connect(source.findOutputSlot(output), target, target.findInputSlot(input));
  scheduleUpdate();
}

async function start() {
  const nodes = await (await api("GET", "/api/nodes")).json();
  const palette = document.getElementById("palette");
  for (const op of nodes.ops) {
    state.library.set(op.name, op);
    const option = document.createElement("option");
    option.value = op.name;
    option.textContent = `${op.family}: ${op.name}`;
    option.title = op.doc;
    palette.append(option);
  }
  const graphs = (await (await api("GET", "/api/graphs")).json()).graphs;
  const list = document.getElementById("graph-list");
  for (const path of graphs) list.append(new Option(path, path));
  list.addEventListener("change", () => open(list.value));
  document.getElementById("save").addEventListener("click", save);
  document.getElementById("add-node").addEventListener("click", () => addNode(palette.value));
  graph.onNodeRemoved = scheduleUpdate;
  const resize = () => canvas.resize();
  window.addEventListener("resize", resize);
  resize();
  graph.start();
  if (graphs.length > 0) await open(graphs[0]);
}

window.shadetreeEditor = { state, graph, canvas, open, save, addNode, connect, documentFromCanvas, ready: start() };
