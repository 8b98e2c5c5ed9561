// The shadetree graph editor: the graph file (JSON) is the document; the
// node canvas (@comfyorg/litegraph) is a view of the nodes and wires of
// one scope of it, the main graph or one function, and every edit writes
// back into the document, which the server checks and renders
// (server/editor_server.h). The params panel edits the document's params:
// a change of a value or range reaches only the uniform block, so a
// slider drag re-renders without recompiling.
import { LGraphCanvas } from "/assets/node_modules/@comfyorg/litegraph/dist/litegraph.es.js";
import { api, errorOf, imageOf, readTiles } from "./api.js";
import { attributeEditor } from "./curve_editor.js";
import { copyNodes, pasteNodes } from "./clipboard.js";
import { documentText } from "./document_text.js";
import { scopeBody, sourcesOf, upstreamOf, withoutUnreadNodes } from "./graph_document.js";
import { GpuPreview, gpuKinds, shaderKey } from "./gpu_preview.js";
import { GraphView } from "./graph_view.js";
import { FunctionInputs } from "./function_inputs.js";
import { History } from "./history.js";
import { element } from "./dom.js";
import { installHoverDocs } from "./hover_docs.js";
import { inputValueRows, promotedType } from "./input_values.js";
import { Minimap } from "./minimap.js";
import { newParams, ParamsPanel } from "./params_panel.js";
import { PreviewView } from "./preview_view.js";
import { boundedSide, panelForSide, shapedDims, sideForPanel } from "./preview_size.js";
import { Thumbnails, thumbnailSide } from "./thumbnails.js";

// How long after the last interactive edit a volume preview is refined to
// full size; until then it renders at a fraction of it.
const refineDelayMs = 250;
// A 60 Hz frame: a texture slower than this to preview at full size (from
// the request to the picture) is drawn at half size while dragged.
const slowTextureMs = 16;
// A volume's draft is half the full side, or a quarter when the full
// preview takes over 150 ms (or has not been drawn yet), and smaller still
// (down to 32, in steps of 16) where that would take longer than this:
// judged by what its last draft on a compiled kernel cost per pixel or,
// before it has one, its full preview over draftSaving (drafts march at
// 4x the step, render/graph_preview.h: 5.5 to 11 times cheaper per pixel
// on the gallery).
const draftBudgetMs = 30;
const draftSaving = 6;
const framesPerSecond = 24;  // nodes/globals.h: time = frame / 24

const state = {
  library: new Map(),   // op name -> its entry of /api/nodes
  kinds: new Map(),     // graph kind -> its entry of /api/nodes: output contract, render fields
  path: null,           // the graph file open, relative to the served folder (null: a new graph)
  doc: null,            // the graph file's JSON
  scope: null,          // the function shown on the canvas, or null: the main graph
  previews: 0,          // previews drawn
  errors: [],           // the checker's diagnostics of the current document, the one to mend first first
  unreadErrors: [],     // or of nodes no output reads, which do not stop the preview
  keepLayout: false,    // whether saves write the nodes' places (the file had them, or the user placed nodes)
  sequence: 0,          // of the latest update; older previews are dropped
  opened: 0,            // files opened: a preview of an earlier one is never drawn
  frame: 0,             // sent with previews of graphs that use frame or time
  playing: false,
  lastInteraction: -Infinity,
  fullPreviewMs: null,  // how long the last full-size preview of this graph took
  draftMsPerPixel: null, // what the last draft of this graph took per pixel
  drawnKey: null,       // what the preview shows: size, frame and the document sent
  drawnSide: null,      // and its long side
  previewSide: boundedSide(Number(localStorage.getItem("shadetree.previewSide") ?? NaN)), // the full preview's long side
  savedText: null,      // the document as last opened or saved
  fileText: null,       // the file's text as last opened or saved, which a save patches
  lastExport: null,     // {url, name, type, size} of the last exported image
  checked: null,        // {key, check, whole}: the last document that checked, its params' values aside
  fileTag: null,        // the ETag of the file as last opened or saved: a save over a file changed since asks first
  previewNode: null,    // {id, scope}: the node whose value the preview shows instead of the outputs
  edits: 0,             // edits of the document so far
  undrawnEdits: [],     // {edit, at}: edits no preview shows yet, with when they were made
  latencies: [],        // {ms, gpu, structural}: from an edit to the first preview showing it (the last 1000)
  drawTimes: [],        // when previews were drawn (the last 1000)
};

const byId = (id) => document.getElementById(id);
const pathQuery = () => (state.path ? `path=${encodeURIComponent(state.path)}&` : "");

const graphView = new GraphView(byId("graph-canvas"), {
  state,
  // A wire drawn or cut may free or take an input the node panel shows.
  onEdit: () => {
    edited();
    showNodePanel(graphView.viewOf(graphView.selectedId()));
  },
  onPlace: () => {
    state.keepLayout = true;
    history.touch(snapshot);
  },
  thumbnailOf: (id) => thumbnails.cache.get(thumbnailCacheKey(id)),
  nodeMenu: (v) => [
    state.previewNode?.id === v.shadetreeId && state.previewNode.scope === state.scope
      ? { content: "Show the outputs in the preview", callback: () => previewNode(null) }
      : { content: "Show in the preview", callback: () => previewNode({ id: v.shadetreeId, scope: state.scope }) },
    { content: "Duplicate (Ctrl+D)", callback: () => duplicate() },
    { content: "Copy (Ctrl+C)", callback: () => copy() },
    ...(state.doc.functions?.[v.op] ? [{ content: `Edit ${v.op}`, callback: () => showScope(v.op) }] : []),
  ],
  canvasMenu: () => [
    { content: "Add Node", has_submenu: true, callback: LGraphCanvas.onMenuAdd },
    { content: "Paste (Ctrl+V)", disabled: !clipboard, callback: () => paste() },
    { content: "Select all (Ctrl+A)", callback: () => canvas.selectItems() },
    { content: "Frame all (F)", callback: () => graphView.fit() },
  ],
});
const { graph, canvas } = graphView;
const status = document.getElementById("status");
const previewCanvas = document.getElementById("preview");
const view = new PreviewView(previewCanvas, { documentOf: () => state.doc, onChange: (interactive) => scheduleUpdate({ interactive }) });
const history = new History({ onChange: showHistoryState });
const gpu = new GpuPreview();
const thumbnails = new Thumbnails({ onDrawn: () => canvas.setDirty(true, false) });
const paramsPanel = new ParamsPanel(byId("params"), {
  state,
  documentOf: () => graphView.document(),
  onEdit: (interactive) => edited({ interactive }),
  onRestructure: restructure,
});
const functionInputs = new FunctionInputs(byId("function-inputs"), {
  documentOf: () => graphView.document(),
  onRestructure: restructure,
});

function setStatus(text, isError) {
  status.textContent = text;
  status.title = text;
  status.classList.toggle("error", Boolean(isError));
}

function functionSignature(doc, name) {
  const inputs = sourcesOf(doc, name).map((input) => `${input.name}: ${input.type}`).join(", ");
  return `${name}(${inputs}) → ${Object.keys(doc.functions[name].outputs || {}).join(", ")}`;
}

// --- edits and history ---

// The document as a save writes it: with the nodes' places once the file
// has them or the user placed a node, so that other edits of a file
// without places change only what they change.
function fileDocument() {
  const doc = graphView.document();
  if (state.keepLayout) doc.layout = graphView.layoutSection(doc);
  return doc;
}

// The document, and where the nodes of every scope shown are on the
// canvas: a move is a step too.
const snapshot = () => ({ text: JSON.stringify(fileDocument()), layout: graphView.layout(), scope: state.scope });

// The places of a document's "layout" section go to the canvas, which
// keeps them while the document is edited.
function takeLayout(doc) {
  state.keepLayout = Boolean(doc.layout);
  delete doc.layout;
  return doc;
}

// Every change of the document: into the history and the preview.
// interactive: part of a drag (or of typing), whose edits make one step
// and whose previews may render coarser.
function edited({ interactive = false } = {}) {
  if (!state.doc) return;
  state.undrawnEdits.push({ edit: ++state.edits, at: performance.now() });
  history.touch(snapshot, { dragging: interactive });
  // Any edit of a volume is drawn coarse first and refined on a pause.
  scheduleUpdate({ interactive: interactive || state.doc.kind === "volume" });
}

function restore(step) {
  if (!step) return;
  graphView.rememberPositions();
  graphView.restoreLayout(step.snapshot.layout);
  const selected = graphView.selectedId();
  state.doc = takeLayout(JSON.parse(step.snapshot.text));
  state.scope = step.scope && state.doc.functions?.[step.scope] ? step.scope : null;
  showScopes();
  graphView.show();
  paramsPanel.show();
  showFrameControls();
  const v = selected && graphView.viewOf(selected);
  if (v) canvas.selectNode(v);
  else showNodePanel(null);
  scheduleUpdate();
}

const undo = () => restore(history.undo());
const redo = () => restore(history.redo());

// Edited since opened or saved: the history's current step is not the file.
const unsaved = () => Boolean(state.doc) && history.steps[history.index]?.text !== state.savedText;

function showHistoryState() {
  byId("undo").disabled = !history.canUndo;
  byId("redo").disabled = !history.canRedo;
  byId("save").textContent = unsaved() ? "Save •" : "Save";
}

// --- params ---

// Adding, renaming or deleting a param changes the main graph's sources
// (and a rename its references): the canvas's wires are read back into
// the document first, and the canvas is built again from it.
// A change of a scope's sources (params, function inputs): applied to the
// whole document, then the canvas and panels drawn anew.
function restructure(change) {
  // Typing just before (a constant, say) stays a step of its own.
  history.flush();
  graphView.rememberPositions();
  state.doc = graphView.document();
  change(state.doc);
  graphView.show();
  paramsPanel.show();
  showScopes();
  edited();
}

// --- the selected node: its doc and attribute editors ---

function showNodePanel(v) {
  const panel = byId("node-panel");
  const node = v?.shadetreeId && graphView.docNode(v.shadetreeId);
  if (!node) {
    panel.replaceChildren(...(state.doc ? graphFields() : []));
    return;
  }
  const entry = state.library.get(node.op);
  const fn = state.doc.functions?.[node.op];
  const heading = document.createElement("h3");
  heading.textContent = `${node.id}: ${node.op}`;
  const doc = document.createElement("p");
  doc.className = "doc";
  doc.textContent = node.doc || entry?.doc || fn?.doc || "";
  panel.replaceChildren(heading, doc);
  const thumbnail = thumbnails.cache.get(thumbnailCacheKey(node.id));
  if (thumbnail?.why) {
    const why = document.createElement("p");
    why.className = "doc";
    why.textContent = `No thumbnail: ${thumbnail.why}`;
    panel.append(why);
  }
  if (fn) {
    const open = document.createElement("button");
    open.textContent = `Edit ${node.op}`;
    open.addEventListener("click", () => showScope(node.op));
    panel.append(open);
  }
  const editor = attributeEditor(node, (interactive) => edited({ interactive }));
  if (editor) panel.append(editor);
  for (const attribute of entry?.attributes || []) panel.append(...simpleAttributeField(node, attribute));
  const declared = fn?.inputs || {};
  const inputs = entry ? entry.inputs
                       : fn ? sourcesOf(state.doc, node.op).map((input) => ({ ...input, default: declared[input.name]?.default })) : [];
  panel.append(...inputValueRows(node, inputs, {
    wired: (input) => graphView.isWired(node.id, input),
    onConstant: (input, value) => graphView.showConstant(node.id, input, value),
    onEdit: (interactive) => edited({ interactive }),
    // Params are the main graph's: a function's body reads its inputs.
    onPromote: state.scope ? null : (input) => promoteToParam(node.id, input),
  }));
}

// The input's constant (or its default) becomes a new param of that value,
// which the input reads: the Params panel then edits it live, without a
// compile. A number's range reaches twice its size.
function promoteToParam(id, input) {
  const value = graphView.docNode(id).in?.[input.name] ?? input.default;
  const type = promotedType(input.type, value);
  const param = structuredClone(newParams[type]);
  const components = Array.isArray(param.default) ? param.default.length : 0;
  if (value !== undefined) param.default = components && !Array.isArray(value) ? Array(components).fill(value) : value;
  if (type === "float" || type === "int") {
    param.min = Math.min(param.min, 2 * param.default);
    param.max = Math.max(param.max, 2 * param.default);
  }
  const taken = new Set(Object.keys(state.doc.params || {}));
  const base = `${id}_${input.name}`.replace(/[^A-Za-z0-9_]/g, "_").replace(/^(?=[0-9])/, "p");
  let name = base;
  for (let n = 2; taken.has(name); ++n) name = `${base}${n}`;
  restructure((doc) => {
    doc.params = { ...doc.params, [name]: param };
    const node = doc.nodes.find((n) => n.id === id);
    node.in = { ...node.in, [input.name]: `$${name}` };
  });
  const v = graphView.viewOf(id);
  if (v) canvas.selectNode(v);
  setStatus(`${id}.${input.name} reads the new param $${name}`);
}

// With no node selected: the graph's name, doc and kind. A new kind keeps
// the nodes and outputs (the checker names what it refuses) and drops the
// render fields it does not take; a volume is given bounds, which it needs.
function graphFields() {
  const heading = element("h3", { textContent: "Graph" });
  const name = element("input", { name: "graph name", value: state.doc.name ?? "", size: 24 });
  name.addEventListener("input", () => {
    state.doc.name = name.value;
    edited({ interactive: true });
  });
  const doc = element("textarea", { name: "graph doc", value: state.doc.doc ?? "", rows: 2 });
  doc.addEventListener("input", () => {
    if (doc.value) state.doc.doc = doc.value;
    else delete state.doc.doc;
    edited({ interactive: true });
  });
  const kind = element("select", { name: "graph kind" }, [...state.kinds.keys()].map((k) => new Option(k, k)));
  kind.value = state.doc.kind;
  kind.title = state.kinds.get(state.doc.kind)?.doc ?? "";
  kind.addEventListener("change", () => restructure((changed) => setKind(changed, kind.value)));
  const outputs = element("ul", { className: "doc" }, (state.kinds.get(state.doc.kind)?.outputs || []).map((output) =>
    element("li", { textContent: `${output.name}${output.required ? " (required)" : ""}: ${output.doc}` })));
  return [heading,
          element("label", { className: "inline" }, ["name ", name]),
          element("label", { className: "inline" }, ["doc ", doc]),
          element("label", { className: "inline" }, ["kind ", kind]),
          element("p", { className: "doc", textContent: "Outputs (wire them into the outputs node):" }), outputs];
}

const defaultVolume = { bounds: { min: [-1, -1, -1], max: [1, 1, 1] } };

function setKind(doc, kind) {
  doc.kind = kind;
  const fields = state.kinds.get(kind).render;
  for (const field of Object.keys(doc.render || {})) if (!fields.includes(field)) delete doc.render[field];
  if (kind === "volume" && !doc.render?.volume) doc.render = { ...doc.render, volume: structuredClone(defaultVolume) };
  if (doc.render && Object.keys(doc.render).length === 0) delete doc.render;
}

// Integer and choice attributes (a noise seed, an image's wrap) as fields.
function simpleAttributeField(node, attribute) {
  if (attribute.kind !== "integer" && attribute.kind !== "choice") return [];
  if (attribute.kind === "choice" && attribute.name === "basis" && node.op === "spline") return [];
  const label = document.createElement("label");
  label.className = "inline";
  label.title = attribute.doc;
  let field;
  if (attribute.kind === "integer") {
    field = Object.assign(document.createElement("input"), { type: "number", step: "1", value: node[attribute.name] ?? "", placeholder: "default" });
    field.addEventListener("input", () => {
      if (field.value === "") delete node[attribute.name];
      else if (Number.isInteger(Number(field.value))) node[attribute.name] = Number(field.value);
      else return;
      edited({ interactive: true });
    });
    field.addEventListener("change", () => edited());
  } else {
    field = document.createElement("select");
    field.append(new Option("(default)", ""), ...attribute.choices.map((choice) => new Option(choice, choice)));
    field.value = node[attribute.name] ?? "";
    field.addEventListener("change", () => {
      if (field.value === "") delete node[attribute.name];
      else node[attribute.name] = field.value;
      edited();
    });
  }
  label.append(`${attribute.name} `, field);
  return [label];
}

// --- scopes on the canvas ---

function showScopes() {
  const select = byId("scope");
  const names = Object.keys(state.doc.functions || {});
  select.replaceChildren(new Option("main graph", ""), ...names.map((name) => new Option(`function ${name}`, name)));
  select.value = graphView.scopeKey;
  select.disabled = names.length === 0;
  byId("scope-signature").textContent = state.scope ? functionSignature(state.doc, state.scope) : "";
  functionInputs.show(state.scope);
}

function showScope(scope) {
  if ((scope || null) === state.scope) return;
  history.flush();
  graphView.rememberPositions();
  state.doc = graphView.document();
  state.scope = scope || null;
  showScopes();
  graphView.show({ fit: !graphView.positions.has(graphView.scopeKey) });
  showNodePanel(null);
  scheduleUpdate();
}

// --- check and preview after every edit, the latest one winning ---

let pending = null;
let refine = null;
let inflight = null;       // the main preview request under way: {controller, started, done}
let previewRequests = 0;   // main preview requests made
let previewDrawn = 0;      // the latest of them drawn
const patienceMs = 150;
const checks = new Map();  // the last few checks' answers, by path and body

// The server's check of `body` (the document's text) as the file open.
async function checkOf(body) {
  const key = `${state.path}\n${body}`;
  if (!checks.has(key)) {
    const response = await api("POST", `/api/check?${pathQuery().slice(0, -1)}`, body);
    let result;
    if (response.ok) result = await response.json();
    else {
      const error = { text: await errorOf(response) };
      result = { ok: false, error, errors: [error] };
    }
    if (checks.size >= 4) checks.delete(checks.keys().next().value);
    checks.set(key, result);
  }
  return checks.get(key);
}

// Edits within 15 ms of the first one not yet drawn are drawn together.
// The timer is not restarted by the next edit, so a drag whose events come
// faster than that (a 120 Hz mouse) still draws as it goes.
function scheduleUpdate({ interactive = false } = {}) {
  if (!state.doc) return;
  if (interactive) state.lastInteraction = performance.now();
  pending ??= setTimeout(() => {
    pending = null;
    update();
  }, 15);
}

// Volume previews are slow: a graph's first picture, the pictures just
// after an edit and those of a playing animation are drafts, smaller and
// marched at a coarser step. On a pause they are refined step by step: a
// small draft doubles up to the largest draft, then the preview is drawn
// at full size and step. A texture whose full preview took longer than
// slowTextureMs is drawn at half its side while dragged, and refined on a
// pause.
function previewSide() {
  const full = state.previewSide;
  if (state.doc.kind !== "volume") {
    const dragging = !state.playing && performance.now() - state.lastInteraction < refineDelayMs;
    return dragging && state.fullPreviewMs > slowTextureMs ? full / 2 : full;
  }
  const largest = state.fullPreviewMs === null || state.fullPreviewMs > 150 ? full / 4 : full / 2;
  const paused = !state.playing && performance.now() - state.lastInteraction >= refineDelayMs;
  if (paused && state.drawnSide !== null)
    return state.drawnSide < largest ? Math.min(2 * state.drawnSide, largest) : full;
  // Pixels per side squared: 1 for a square preview, less for another shape.
  const fill = pixelsOf(full) / (full * full);
  const msPerPixel = state.draftMsPerPixel ?? (state.fullPreviewMs ?? 0) / pixelsOf(full) / draftSaving;
  const side = 16 * Math.floor(Math.sqrt(draftBudgetMs / msPerPixel / fill) / 16);
  return Math.min(Math.max(side, 32), largest);
}

async function update() {
  const sequence = ++state.sequence;
  const covers = state.edits;
  thumbnails.cancel();
  clearTimeout(refine);
  const doc = graphView.document();
  // A node no output reads (one just added, say) must not stop the
  // preview: when the document fails the check, what its outputs read is
  // checked and previewed, and the first error is shown on its node as a
  // warning. The page chooses what to send, as it does for the preview's
  // view, so that the server's check stays the command line's (which
  // refuses the file as saved until the node is mended or deleted).
  // A change of params' values alone (a slider drag) checks as the
  // document did before it, so the server is not asked again.
  let check, previewed = doc;
  const checkKey = `${state.path}\n${shaderKey(doc)}`;
  const structural = state.checked?.key !== checkKey;
  if (!structural) {
    check = state.checked.check;
    if (!state.checked.whole) previewed = withoutUnreadNodes(doc);
  } else {
    try {
      check = await checkOf(JSON.stringify(doc, null, 2));
      if (!check.ok && check.parsed) {
        const read = withoutUnreadNodes(doc);
        const readCheck = await checkOf(JSON.stringify(read, null, 2));
        // Else the errors that stop what the outputs read are the ones to
        // mend; those of unread nodes are shown beside them.
        const unread = readCheck.ok ? check.errors
                     : check.errors.filter((error) => !readCheck.errors.some((e) => e.text === error.text));
        [check, previewed] = readCheck.ok ? [{ ok: true, unread }, read] : [{ ...readCheck, unread }, doc];
      }
      if (sequence !== state.sequence) return;
    } catch (error) {
      if (sequence === state.sequence) setStatus(String(error), true);
      return;
    }
    state.checked = check.ok ? { key: checkKey, check, whole: previewed === doc } : null;
  }
  state.errors = check.ok ? [] : check.errors;
  state.unreadErrors = check.unread ?? [];
  graphView.markErrors();
  byId("diagnostic").textContent = [...state.errors.map((error) => error.text),
                                    ...state.unreadErrors.map((error) => `No output reads ${error.node}: ${error.text}`)].join("\n");
  if (!check.ok) {
    setStatus(check.error.text, true);
    recordLatency(covers, false, structural);  // the error is what the edit shows
    return;
  }
  const previewDoc = view.apply(previewed);
  const previewBody = JSON.stringify(previewDoc);
  const probe = nodeProbeQuery(previewed);
  if (!probe && gpu.accepts(previewDoc)) {
    const drawn = await drawOnGpu(previewDoc, covers, structural, sequence);
    if (sequence !== state.sequence) return;
    if (drawn) {
      if (state.playing) nextFrame();
      else refreshThumbnailsWhenStill(doc, previewBody, previewed === doc);
      return;
    }
  }
  const side = probe ? state.previewSide : previewSide();
  const previewKey = `${previewDims(side).join("x")} ${state.frame}${probe}\n${previewBody}`;
  // Unless this very picture is shown and no other is on its way.
  const needed = () => inflight || previewKey !== state.drawnKey;
  if (needed()) {
    // A preview started moments ago may finish, so that a drag keeps
    // showing pictures; one that takes longer is superseded.
    const age = inflight ? performance.now() - inflight.started : Infinity;
    if (age < patienceMs) {
      await Promise.race([inflight.done, new Promise((resolve) => setTimeout(resolve, patienceMs - age))]);
      if (sequence !== state.sequence) return;
    }
    if (needed() && (!(await requestPreview(previewBody, side, previewKey, covers, structural, probe)) ||
                     sequence !== state.sequence))
      return;
  } else {
    recordLatency(covers, false, structural);  // the picture shown is already this one
  }
  if (state.playing) {
    nextFrame();
  } else if (side < state.previewSide) {
    const paused = performance.now() - state.lastInteraction;
    refine = setTimeout(() => scheduleUpdate(), Math.max(0, refineDelayMs - paused));
  } else {
    refreshThumbnailsWhenStill(doc, previewBody, previewed === doc);
  }
}

// Thumbnails wait for a pause in a drag, which then redraws the preview
// (from the kernel or the shader it has) and asks for them.
function refreshThumbnailsWhenStill(doc, previewBody, whole) {
  const since = performance.now() - state.lastInteraction;
  if (since < refineDelayMs) refine = setTimeout(() => scheduleUpdate(), refineDelayMs - since);
  else refreshThumbnails(doc, previewBody, whole);
}

function showOk() {
  const unread = state.unreadErrors.map((error) => error.node);
  setStatus(`${state.path || "untitled"}: ok` +
            (unread.length ? ` (no output reads ${unread.join(", ")}, which ${unread.length > 1 ? "have errors" : "has an error"})` : ""),
            false);
}

// Draws the preview on the page's GPU, from drafts where it is slow;
// false where it cannot (the server draws it then), or where a newer edit
// or file came meanwhile.
async function drawOnGpu(doc, covers, structural, sequence) {
  const started = performance.now();
  const opened = state.opened;
  const stale = () => sequence !== state.sequence || opened !== state.opened;
  const show = (canvas) => {
    inflight?.controller.abort();  // a server preview under way would draw over this one
    const context = previewCanvas.getContext("2d");
    context.clearRect(0, 0, previewCanvas.width, previewCanvas.height);
    context.drawImage(canvas, 0, 0, previewCanvas.width, previewCanvas.height);
  };
  let drawn = null;
  try {
    drawn = await gpu.draw(doc, state.previewSide, state.frame, pathQuery(), {
      dimsOf: previewDims,
      stale,
      show: (canvas) => {
        show(canvas);
        byId("preview-info").textContent = `${canvas.width}x${canvas.height} draft, refining (GPU: WebGL 2)`;
      },
    });
  } catch (error) {
    gpu.error = String(error);
  }
  if (!drawn || stale()) return false;
  show(drawn);
  state.drawnKey = null;
  state.drawnSide = state.previewSide;
  state.previews += 1;
  recordLatency(covers, true, structural);
  byId("preview-info").textContent = `${previewDims().join("x")} in ${(performance.now() - started).toFixed(1)} ms (GPU: WebGL 2)` +
    (view.changed ? ", view moved" : "");
  byId("reset-view").disabled = !view.changed;
  showOk();
  return true;
}

// Draws the preview, unless a newer one was drawn already; false if it
// was superseded or refused. Requests of slot "main" supersede the one
// in flight: the server stops it and answers 409. A volume's full-size
// preview is streamed: its tiles are drawn over the draft as they are
// marched, so that a slow one shows something new every few tiles.
async function requestPreview(body, side, key, covers, structural, probe = "") {
  inflight?.controller.abort();
  const id = ++previewRequests;
  const opened = state.opened;
  const controller = new AbortController();
  let finished;
  inflight = { controller, started: performance.now(), done: new Promise((resolve) => { finished = resolve; }) };
  const started = inflight.started;
  try {
    const draft = side < state.previewSide ? "&draft=1" : "";
    const streamed = side === state.previewSide && !probe && state.doc.kind === "volume";
    const [width, height] = previewDims(side);
    const response = await api("POST", `/api/preview?${pathQuery()}width=${width}&height=${height}&frame=${state.frame}&slot=main${draft}${probe}` +
                               (streamed ? "&stream=1" : ""), body, controller.signal);
    if (response.status === 409) return false;
    if (!response.ok) {
      const error = await errorOf(response);
      if (opened === state.opened) setStatus(error, true);
      return false;
    }
    const kernel = response.headers.get("X-Kernel");
    let milliseconds;
    if (streamed) {
      let marched = 0;
      await readTiles(response, (x, y, tile) => {
        if (opened !== state.opened) return;
        previewCanvas.getContext("2d").putImageData(tile, x, y);
        marched += tile.width * tile.height;
        byId("preview-info").textContent = `${width}x${height}, ${Math.floor((100 * marched) / (width * height))}% marched (CPU, kernel: ${kernel})`;
      });
      if (id < previewDrawn || opened !== state.opened) return false;
      milliseconds = performance.now() - started;
    } else {
      const image = await imageOf(response);
      if (id < previewDrawn || opened !== state.opened) return false;
      drawPreview(image);
      milliseconds = Number(response.headers.get("X-Milliseconds"));
    }
    previewDrawn = id;
    state.drawnKey = key;
    state.drawnSide = side;
    recordLatency(covers, false, structural);
    const took = performance.now() - started;
    // A draft that waited for a compile says little of the next one.
    if (side === state.previewSide) state.fullPreviewMs = took;
    else if (kernel !== "compiling") state.draftMsPerPixel = took / pixelsOf(side);
    state.previews += 1;
    const gpuRefusal = gpu.enabled && gpuKinds.includes(state.doc.kind) && gpu.error ? `; GPU: ${gpu.error}` : "";
    byId("preview-info").textContent = `${width}x${height} in ${milliseconds.toFixed(1)} ms (CPU, kernel: ${kernel}${gpuRefusal})` +
      (side < state.previewSide ? (state.playing ? ", coarse while playing" : ", refining") : "") + (view.changed ? ", view moved" : "") +
      (probe ? `, node "${state.previewNode.id}"${state.previewNode.scope ? ` of ${state.previewNode.scope}` : ""}` : "");
    byId("reset-view").disabled = !view.changed;
    showOk();
    return true;
  } catch (error) {
    // A stream's end record says "superseded" where a newer preview stopped it.
    if (error.name !== "AbortError" && error.message !== "superseded" && opened === state.opened) setStatus(String(error), true);
    return false;
  } finally {
    finished();
    if (inflight?.controller === controller) inflight = null;
  }
}

// The preview shows `node` ({id, scope}) instead of the outputs, or the
// outputs again (null); drawn by the server, as its thumbnail is.
function previewNode(node) {
  state.previewNode = node;
  state.drawnKey = null;
  scheduleUpdate();
}

// "&node=ID[&function=SCOPE]" of the node the preview shows, if it is
// still in `doc`; else "" (and the preview shows the outputs again).
function nodeProbeQuery(doc) {
  const node = state.previewNode;
  if (!node) return "";
  const nodes = node.scope ? doc.functions?.[node.scope]?.nodes : doc.nodes;
  if (!nodes?.some((n) => n.id === node.id)) {
    state.previewNode = null;
    return "";
  }
  return `&node=${encodeURIComponent(node.id)}` + (node.scope ? `&function=${encodeURIComponent(node.scope)}` : "");
}

// Latency from the user's hand: what every edit up to `covers` looks like
// is shown now (a preview drawn, or a check's error, or the picture
// already shown); the first of those edits waited this long. What the
// browser test reports (docs/architecture.md, "From the user's hand").
function recordLatency(covers, gpuDrawn, structural) {
  const now = performance.now();
  const keep = (list, entry) => {
    list.push(entry);
    if (list.length > 1000) list.shift();
  };
  keep(state.drawTimes, now);
  const shown = state.undrawnEdits.filter((entry) => entry.edit <= covers);
  if (shown.length === 0) return;
  state.undrawnEdits = state.undrawnEdits.filter((entry) => entry.edit > covers);
  keep(state.latencies, { ms: now - shown[0].at, gpu: gpuDrawn, structural });
}

// A coarse preview is scaled up, smoothly, to the preview's size.
// --- the preview's size (editor/preview_size.js) ---

// [width, height] of a preview of long side `side`, shaped as the export.
function previewDims(side = state.previewSide) {
  return shapedDims(side, Number(byId("export-width").value), Number(byId("export-height").value));
}

const pixelsOf = (side) => previewDims(side).reduce((a, b) => a * b);

// Sizes the panel and the preview's canvas to the full preview, keeping
// the picture shown (stretched) until the next one is drawn.
function fitPreview() {
  byId("panel").style.width = `${panelForSide(state.previewSide)}px`;
  const [width, height] = previewDims();
  previewCanvas.style.width = `${width}px`;
  previewCanvas.style.height = `${height}px`;
  if (previewCanvas.width === width && previewCanvas.height === height) return;
  const shown = document.createElement("canvas");
  shown.width = previewCanvas.width;
  shown.height = previewCanvas.height;
  shown.getContext("2d").drawImage(previewCanvas, 0, 0);
  previewCanvas.width = width;
  previewCanvas.height = height;
  previewCanvas.getContext("2d").drawImage(shown, 0, 0, width, height);
  state.drawnKey = null;
}

// The splitter left of the panel sets the preview's long side: a drag of
// it by some pixels widens the panel and the preview as much. The graph
// keeps at least minimumGraphWidth pixels.
const minimumGraphWidth = 320;
function installPanelSplitter(splitter) {
  let start = null;  // {x, side} where the drag began
  splitter.addEventListener("pointerdown", (event) => {
    start = { x: event.clientX, side: state.previewSide };
    splitter.setPointerCapture(event.pointerId);
  });
  splitter.addEventListener("pointermove", (event) => {
    if (!start) return;
    const widest = sideForPanel(window.innerWidth - minimumGraphWidth);
    state.previewSide = Math.min(boundedSide(start.side + start.x - event.clientX), widest);
    fitPreview();
    scheduleUpdate({ interactive: true });
  });
  const release = () => {
    if (!start) return;
    start = null;
    localStorage.setItem("shadetree.previewSide", String(state.previewSide));
    scheduleUpdate();
  };
  splitter.addEventListener("pointerup", release);
  splitter.addEventListener("pointercancel", release);
}

function drawPreview(image) {
  const context = previewCanvas.getContext("2d");
  if (image.width === previewCanvas.width && image.height === previewCanvas.height) {
    context.putImageData(image, 0, 0);
    return;
  }
  const scratch = document.createElement("canvas");
  scratch.width = image.width;
  scratch.height = image.height;
  scratch.getContext("2d").putImageData(image, 0, 0);
  context.imageSmoothingEnabled = true;
  context.drawImage(scratch, 0, 0, previewCanvas.width, previewCanvas.height);
}

// --- thumbnails ---

const thumbnailCacheKey = (id) => `${graphView.scopeKey}/${id}`;

// What the output of node `id` depends on: the nodes upstream of it, the
// params they read, the functions they call, the frame if time is read,
// and the render settings.
function thumbnailKey(doc, id, render) {
  const upstream = upstreamOf(scopeBody(doc, state.scope), [id]);
  const dollars = new Set([...upstream.values()].flatMap((node) => Object.values(node.in || {}))
                                                .filter((value) => typeof value === "string" && value.startsWith("$"))
                                                .map((value) => value.slice(1)));
  const calls = [...upstream.values()].some((n) => doc.functions?.[n.op]);
  const params = [...dollars].map((name) => [name, doc.params?.[name]?.default]);
  const timed = usesTime([...upstream.values()], calls ? doc.functions : {});
  // A function's node is shown at the function's first call in the main
  // graph, so it depends on the whole main graph too.
  const context = state.scope ? [doc.nodes, doc.params] : null;
  return JSON.stringify([[...upstream.values()], calls ? doc.functions : null, params, timed ? state.frame : 0, doc.kind,
                         render, context]);
}

// previewBody: the preview's text; whole: whether it is all of `doc`.
function refreshThumbnails(doc, previewBody, whole) {
  // A volume graph's thumbnails are slices through its bounds: the camera
  // does not change them.
  const render = doc.kind === "volume" ? doc.render?.volume : JSON.parse(previewBody).render;
  // The server probes a node only in a document that checks as a whole.
  // When only what the outputs read checks, a node is probed in that and
  // what the node reads: its picture, or its error, then depends on
  // nothing outside its key, under which it is kept.
  const bodyOf = (id) => whole ? () => previewBody
                               : () => JSON.stringify(view.apply(withoutUnreadNodes(doc, state.scope, [id])));
  const jobs = graphView.opViews().map((v) => ({
    cacheKey: thumbnailCacheKey(v.shadetreeId),
    key: thumbnailKey(doc, v.shadetreeId, render),
    url: `/api/preview?${pathQuery()}node=${encodeURIComponent(v.shadetreeId)}&width=${thumbnailSide}&height=${thumbnailSide}` +
         `&frame=${state.frame}&slot=thumb-${encodeURIComponent(thumbnailCacheKey(v.shadetreeId))}` +
         (state.scope ? `&function=${encodeURIComponent(state.scope)}` : ""),
    body: bodyOf(v.shadetreeId),
  }));
  thumbnails.refresh(jobs).catch((error) => setStatus(`thumbnails: ${error}`, true));
}

// --- frames ---

function usesTime(nodes, functions) {
  const timed = (list) => list.some((n) => n.op === "frame" || n.op === "time");
  return timed(nodes) || Object.values(functions || {}).some((fn) => timed(fn.nodes || []));
}

// The graph's render.frames, or four seconds from 0 (docs/graph-format.md).
const frameRange = () => state.doc.render?.frames ?? [0, 95];

function showFrameControls() {
  const shown = usesTime(state.doc.nodes, state.doc.functions);
  byId("frame-row").hidden = !shown;
  if (!shown) setPlaying(false);
  const [first, last] = frameRange();
  Object.assign(byId("frame"), { min: first, max: last });
  byId("frame").value = state.frame;
  byId("frame-value").textContent = frameText();
}

const frameText = () => `frame ${state.frame} (${(state.frame / framesPerSecond).toFixed(2)} s)`;

function setFrame(frame, interactive) {
  state.frame = frame;
  byId("frame").value = frame;
  byId("frame-value").textContent = frameText();
  scheduleUpdate({ interactive });
}

function setPlaying(playing) {
  state.playing = playing;
  byId("play").textContent = playing ? "❚❚" : "▶";
  if (playing) setFrame(state.frame, true);
  else scheduleUpdate();
}

let lastFrameAt = 0;

// The next frame once this one is drawn, at 24 frames a second at most.
function nextFrame() {
  const wait = Math.max(0, 1000 / framesPerSecond - (performance.now() - lastFrameAt));
  setTimeout(() => {
    if (!state.playing) return;
    lastFrameAt = performance.now();
    const [first, last] = frameRange();
    setFrame(state.frame >= first && state.frame < last ? state.frame + 1 : first, true);
  }, wait);
}

// --- files ---

// Selects `path` in the list of graphs, adding it (in order) if the file
// is newer than the list.
function selectInGraphList(path) {
  const list = byId("graph-list");
  if (![...list.options].some((option) => option.value === path)) {
    const later = [...list.options].find((option) => option.value.localeCompare(path) > 0);
    list.insertBefore(new Option(path, path), later || null);
  }
  list.value = path;
}

// The document changes only once the server has read the file as a graph
// (graph/parse.h: its JSON, fields and their types), so a file the canvas
// cannot show leaves the open one open, and Save cannot write over it. A
// graph with a check error (a type, a missing node) opens, with the error
// on its node. Of two opens under way, the later one wins.
let opening = 0;
async function open(path) {
  const attempt = ++opening;
  const keepOpen = (message) => {
    if (attempt !== opening) return;
    setStatus(message, true);
    byId("graph-list").value = state.path ?? "";
  };
  const response = await api("GET", `/api/graph?path=${encodeURIComponent(path)}`);
  if (!response.ok) return keepOpen(await errorOf(response));
  const text = await response.text();
  const refuse = (why) => keepOpen(`${path} is not a graph file (${why}); ${state.path ?? "nothing"} stays open`);
  let doc;
  try {
    doc = JSON.parse(text);
  } catch (error) {
    return refuse(error.message);
  }
  const checked = await api("POST", `/api/check?path=${encodeURIComponent(path)}`, text);
  if (!checked.ok) return keepOpen(await errorOf(checked));
  const check = await checked.json();
  if (!check.ok && !check.parsed) return refuse(check.error.message);
  if (attempt !== opening) return;
  await showDocument(path, doc, text, response.headers.get("ETag"));
}

// A new graph of `kind`, with no nodes and no file until saved as one.
async function newGraph(kind) {
  const doc = { format: "shadetree-graph", version: 1, name: "untitled", kind, nodes: [], outputs: {} };
  setKind(doc, kind);
  ++opening;
  await showDocument(null, doc, null);
}

// `doc`, read from `text` of file `path` (null: new) whose ETag is `tag`,
// becomes the document. The path and its tag change together, before
// anything is awaited: a save made meanwhile keeps the tag it got.
async function showDocument(path, doc, text, tag = null) {
  setPlaying(false);
  state.opened += 1;
  inflight?.controller.abort();
  previewCanvas.getContext("2d").clearRect(0, 0, previewCanvas.width, previewCanvas.height);
  state.path = path;
  graphView.loadLayout(doc.layout);
  state.doc = takeLayout(doc);
  state.fileText = text;
  state.fileTag = tag;
  state.previewNode = null;
  state.scope = null;
  state.frame = state.doc.render?.frame ?? frameRange()[0];
  state.drawnKey = null;
  state.drawnSide = null;
  state.fullPreviewMs = null;
  state.draftMsPerPixel = null;
  state.errors = [];
  state.unreadErrors = [];
  thumbnails.cancel();
  thumbnails.cache.clear();
  view.clear();
  const size = state.doc.render?.size || [512, 512];
  byId("export-width").value = size[0];
  byId("export-height").value = size[1];
  fitPreview();
  if (path) selectInGraphList(path);
  else byId("graph-list").value = "";
  showPalette();
  showScopes();
  graphView.show({ fit: true });
  paramsPanel.show();
  showFrameControls();
  showNodePanel(null);
  const opened = snapshot();
  state.savedText = opened.text;
  history.reset(opened);
  await update();
}

// A new graph is saved as a file named first.
async function save() {
  if (state.doc && !state.path) return showSaveAs(true);
  return write(state.path, false);
}

// PUT the document, written in the style of the file it was opened from
// (editor/document_text.js), to `path`, which then is the file open;
// isNew: the server refuses (409) to overwrite a file. Nothing of it is
// remembered if another file was opened meanwhile.
async function write(path, isNew) {
  if (!state.doc) return false;
  history.flush();
  const opened = state.opened;
  const doc = fileDocument();
  const text = documentText(state.fileText, doc);
  const url = `/api/graph?path=${encodeURIComponent(path)}${isNew ? "&new=1" : ""}`;
  // The file open is written only as it was read or written here: if
  // another program changed it since, the user says whether to overwrite.
  const guarded = !isNew && path === state.path && state.fileTag;
  let response = await api("PUT", url, text, undefined, guarded ? { "If-Match": state.fileTag } : {});
  let error = response.ok ? null : await errorOf(response);
  if (response.status === 412 && opened === state.opened && confirm(`${error}. Overwrite it with the graph shown here?`)) {
    response = await api("PUT", url, text);
    error = response.ok ? null : await errorOf(response);
  }
  if (opened !== state.opened) return false;
  if (error) {
    setStatus(`not saved: ${error}`, true);
    // A refused Save as keeps its form open, and the refusal beside the
    // name to change: a preview that ends meanwhile rewrites the status.
    if (isNew) byId("save-as-error").value = error;
    return false;
  }
  state.path = path;
  state.fileText = text;
  state.fileTag = response.headers.get("ETag");
  state.savedText = JSON.stringify(doc);
  state.keepLayout = Boolean(doc.layout);
  setStatus(`saved ${path}`, false);
  showHistoryState();
  return true;
}

// Save as NAME(.json): a new file of the served folder, then the one open.
async function saveAs(name) {
  const path = name.trim().endsWith(".json") ? name.trim() : `${name.trim()}.json`;
  if (path === ".json") return false;
  if (!(await write(path, true))) return false;
  selectInGraphList(path);
  scheduleUpdate();
  return true;
}

function showSaveAs(shown) {
  byId("save-as-form").hidden = !shown;
  byId("save-as-error").value = "";
  byId("save-as").hidden = shown;
  if (shown) {
    const input = byId("save-as-name");
    input.value = state.path ? state.path.replace(/\.json$/, "_copy.json") : "untitled.json";
    input.focus();
    input.select();
  }
}

// Renders what the preview shows (its panned, zoomed or orbited view) at
// the size asked, and offers the image as a download.
async function exportImage() {
  const width = Number(byId("export-width").value), height = Number(byId("export-height").value);
  const format = byId("export-format").value;
  if (!(width >= 1 && height >= 1)) {
    setStatus("export: width and height must be positive", true);
    return null;
  }
  setStatus(`exporting ${width}x${height} ${format}…`, false);
  const response = await api("POST", `/api/export?${pathQuery()}width=${width}&height=${height}&frame=${state.frame}&format=${format}`,
                             JSON.stringify(view.apply(graphView.document())));
  if (!response.ok) {
    setStatus(`export: ${await errorOf(response)}`, true);
    return null;
  }
  const blob = await response.blob();
  if (state.lastExport) URL.revokeObjectURL(state.lastExport.url);
  const name = `${(state.path || "untitled").replace(/^.*\//, "").replace(/\.json$/, "")}.${format}`;
  state.lastExport = { url: URL.createObjectURL(blob), name, type: blob.type, size: blob.size };
  const link = byId("export-link");
  link.href = state.lastExport.url;
  link.download = name;
  link.textContent = name;
  link.hidden = false;
  link.click();
  setStatus(`exported ${name} (${Math.ceil(blob.size / 1024)} KB)`, false);
  return state.lastExport;
}

// --- copy, paste and duplicate (editor/clipboard.js) ---

let clipboard = null;  // {nodes, places} of the last copy

// The selected nodes as a copy, or null.
function selection() {
  const ids = graphView.selectedIds();
  if (ids.length === 0) return null;
  graphView.rememberPositions();
  const places = graphView.positions.get(graphView.scopeKey);
  return copyNodes(scopeBody(graphView.document(), state.scope), ids, (id) => places.get(id));
}

function copy() {
  clipboard = selection() ?? clipboard;
  if (clipboard) setStatus(`copied ${clipboard.nodes.length} node${clipboard.nodes.length > 1 ? "s" : ""}`, false);
}

const topLeft = (copied) => [Math.min(...copied.places.map((xy) => xy[0])), Math.min(...copied.places.map((xy) => xy[1]))];

// The copy's nodes, their top left corner at `at` (canvas units), selected.
function insert(copied, at) {
  const [left, top] = topLeft(copied);
  let added = [];
  restructure((doc) => {
    added = pasteNodes(doc, state.scope, scopeBody(doc, state.scope), copied, [at[0] - left, at[1] - top]);
    for (const [id, xy] of added) graphView.positions.get(graphView.scopeKey).set(id, xy);
    state.keepLayout = true;
  });
  graphView.select(added.map(([id]) => id));
}

// Where the pointer is on the canvas, or past the copied nodes.
function paste() {
  if (!clipboard) return;
  const pointer = graphView.canvas.graph_mouse;
  insert(clipboard, pointer && Number.isFinite(pointer[0]) ? [...pointer] : topLeft(clipboard).map((v) => v + 40));
}

// The selected nodes again, a little down and right of them.
function duplicate() {
  const copied = selection();
  if (copied) insert(copied, topLeft(copied).map((v) => v + 40));
}

// Undo and redo everywhere but in text fields, which have their own; on
// the canvas, when it has the focus, the node keys (Delete, Backspace and
// Ctrl+A are litegraph's own).
function onKey(event) {
  const control = event.ctrlKey || event.metaKey;
  const key = event.key.toLowerCase();
  if (event.target === canvas.canvas && !event.altKey) {
    const action = control ? { c: copy, v: paste, d: duplicate }[key] : !event.shiftKey && { f: () => graphView.fit() }[key];
    if (action) {
      action();
      event.preventDefault();
      event.stopPropagation();
      return;
    }
  }
  if (!control || event.target.matches("textarea, input:not([type=range]):not([type=color]):not([type=checkbox]):not([type=button])")) return;
  if (key === "z" && !event.shiftKey) undo();
  else if ((key === "z" && event.shiftKey) || key === "y") redo();
  else if (key === "s") save();
  else return;
  event.preventDefault();
  event.stopPropagation();
}

// The palette offers the ops a graph of this kind may use.
function showPalette() {
  const palette = byId("palette");
  for (const option of palette.options) option.hidden = !state.library.get(option.value).kinds?.includes(state.doc.kind);
  if (palette.selectedOptions[0]?.hidden) palette.value = [...palette.options].find((option) => !option.hidden)?.value ?? "";
}

async function start() {
  const nodes = await (await api("GET", "/api/nodes")).json();
  for (const kind of nodes.kinds) state.kinds.set(kind.name, kind);
  const newGraphKind = byId("new-graph");
  newGraphKind.append(...nodes.kinds.map((kind) => Object.assign(new Option(kind.name, kind.name), { title: kind.doc })));
  newGraphKind.addEventListener("change", () => {
    history.flush();
    const kind = newGraphKind.value;
    newGraphKind.value = "";
    if (!unsaved() || confirm(`Discard the unsaved changes to ${state.path ?? "the new graph"}?`)) newGraph(kind);
  });
  const palette = byId("palette");
  for (const op of nodes.ops) {
    state.library.set(op.name, op);
    const option = new Option(`${op.family}: ${op.name}`, op.name);
    option.title = op.doc;
    palette.append(option);
  }
  const graphs = (await (await api("GET", "/api/graphs")).json()).graphs;
  const list = byId("graph-list");
  for (const path of graphs) list.append(new Option(path, path));
  list.addEventListener("change", () => {
    history.flush();
    if (unsaved() && !confirm(`Discard the unsaved changes to ${state.path ?? "the new graph"}?`)) list.value = state.path ?? "";
    else open(list.value);
  });
  byId("save").addEventListener("click", save);
  byId("save-as").addEventListener("click", () => showSaveAs(true));
  byId("save-as-cancel").addEventListener("click", () => showSaveAs(false));
  byId("save-as-form").addEventListener("submit", async (event) => {
    event.preventDefault();
    if (await saveAs(byId("save-as-name").value)) showSaveAs(false);
  });
  byId("save-as-name").addEventListener("keydown", (event) => event.key === "Escape" && showSaveAs(false));
  byId("undo").addEventListener("click", undo);
  byId("redo").addEventListener("click", redo);
  byId("export").addEventListener("click", exportImage);
  for (const field of [byId("export-width"), byId("export-height")])
    field.addEventListener("input", () => {
      fitPreview();
      scheduleUpdate();
    });
  installPanelSplitter(byId("panel-splitter"));
  fitPreview();
  byId("add-node").addEventListener("click", () => graphView.addNode(palette.value));
  byId("scope").addEventListener("change", (event) => showScope(event.target.value));
  byId("reset-view").addEventListener("click", () => view.reset());
  byId("gpu-label").hidden = !gpu.available;
  byId("gpu").addEventListener("change", (event) => {
    gpu.enabled = event.target.checked;
    state.drawnKey = null;
    scheduleUpdate();
  });
  byId("frame-all").addEventListener("click", () => graphView.fit());
  const minimap = new Minimap(byId("minimap"), graphView);
  canvas.onDrawForeground = (ctx, area) => minimap.draw(area);
  installHoverDocs(byId("graph-canvas"), byId("hover-doc"),
                   (event) => graphView.docAt(graphView.canvas.convertEventToCanvasOffset(event)));
  byId("frame").addEventListener("input", (event) => setFrame(Number(event.target.value), true));
  byId("frame").addEventListener("change", (event) => setFrame(Number(event.target.value), false));
  byId("play").addEventListener("click", () => setPlaying(!state.playing));
  document.addEventListener("keydown", onKey, true);
  // Closing or reloading the page asks first when edits are unsaved.
  window.addEventListener("beforeunload", (event) => {
    history.flush();
    if (!unsaved()) return;
    event.preventDefault();
    event.returnValue = "";
  });
  canvas.onNodeSelected = showNodePanel;
  canvas.onNodeDblClicked = (v) => state.doc.functions?.[v.op] && showScope(v.op);
  canvas.onNodeDeselected = () => {
    if (!graphView.selectedId()) showNodePanel(null);
  };
  new ResizeObserver(() => canvas.resize()).observe(byId("graph-host"));
  canvas.resize();
  graph.start();
  showHistoryState();
  if (graphs.length > 0) await open(graphs[0]);
}

// For tests and the console.
window.shadetreeEditor = {
  state, graph, canvas, graphView, history, view, thumbnails, gpu,
  open, newGraph, save, saveAs, exportImage, showScope, undo, redo,
  addNode: (op) => graphView.addNode(op),
  connect: (...ends) => graphView.connect(...ends),
  documentFromCanvas: () => graphView.document(),
  viewOf: (id) => graphView.viewOf(id),
  ready: start(),
};
