// The node canvas (@comfyorg/litegraph) as a view of one scope of the
// document, the main graph or a function's body: its nodes and wires,
// with the scope's sources ("$name": params or function inputs) and
// outputs as two boundary nodes. show() builds the canvas from the
// document; document() reads the document back with the canvas's wires.
import { LGraph, LGraphCanvas, LGraphNode, LiteGraph } from "/assets/node_modules/@comfyorg/litegraph/dist/litegraph.es.js";
import { freshId, parseReference, scopeBody, sourcesOf } from "./graph_document.js";
import { thumbnailSide } from "./thumbnails.js";

const nodeWidth = 150;
const columnGap = 40;
const rowGap = 24;
const thumbnailRoom = thumbnailSide + 10;

// What a node made on the canvas starts with, for ops that need attributes.
const newNodeAttributes = {
  spline: { basis: "catmull-rom", knots: [[0, 0, 0], [0, 0, 0], [1, 1, 1], [1, 1, 1]] },
  color_table: { entries: [[0, 0, 0], [1, 1, 1]] },
  table1d: { values: [0, 1] },
  table2d: { values: [[0, 0], [1, 1]] },
};

const literalText = (value) => (Array.isArray(value) ? `[${value.join(", ")}]` : String(value));
// An input's label, "name: type", with " = value" when a constant feeds it.
function labelConstant(slot, value) {
  slot.label = slot.label.replace(/ ⚠$/, "").replace(/ = .*$/, "") + (value === undefined ? "" : ` = ${literalText(value)}`);
}
const titleOf = (id, op) => (id === op ? id : `${id} (${op})`);
const positionKey = (v) => v.shadetreeId ?? `#${v.boundary}`;

// A graph file's "layout" section (docs/graph-format.md) as the places
// the canvas keeps, scope -> key -> [x, y]; what is not a place is left out.
function placesOf(section) {
  const places = new Map();
  const isPlace = (xy) => Array.isArray(xy) && xy.length === 2 && xy.every(Number.isFinite);
  const add = (scope, entries) => {
    if (entries && typeof entries === "object")
      places.set(scope, new Map(Object.entries(entries).filter(([, xy]) => isPlace(xy))));
  };
  add("", section?.nodes);
  for (const [name, entries] of Object.entries(section?.functions || {})) add(name, entries);
  return places;
}

// A node of the library or of a function of the document, with room under
// its slots for a thumbnail of its output (in a function's body, as at the
// function's first call).
class ShadetreeNode extends LGraphNode {
  constructor(title) {
    super(title);
    this.clonable = false;  // litegraph's Clone drops attributes: Duplicate copies the document's node
  }
  onConnectionsChange() { this.graph?.view.edited(); }
  getMenuOptions() { return this.graph?.view.nodeMenu(this) ?? []; }
  // A deleted node takes its wires along: litegraph would join its first
  // input to its outputs, changing what other nodes read unasked.
  connectInputToOutput() {}
  onDrawBackground(ctx) {
    const view = this.graph?.view;
    if (this.flags.collapsed || !this.shadetreeId || !view) return;
    const entry = view.thumbnailOf(this.shadetreeId);
    const x = (this.size[0] - thumbnailSide) / 2, y = this.size[1] - thumbnailSide - 5;
    if (entry?.image) {
      ctx.imageSmoothingEnabled = false;
      ctx.drawImage(entry.image, x, y, thumbnailSide, thumbnailSide);
      view.thumbnailsDrawn += 1;
      return;
    }
    ctx.fillStyle = "rgba(0, 0, 0, 0.25)";
    ctx.fillRect(x, y, thumbnailSide, thumbnailSide);
    if (entry?.note) {
      ctx.fillStyle = "#888";
      ctx.font = "10px sans-serif";
      ctx.textAlign = "center";
      ctx.fillText(entry.note, this.size[0] / 2, y + thumbnailSide / 2 + 3);
    }
  }
}

// The ends of a scope. They are part of the view, not nodes of the
// document, and cannot be deleted or copied.
class BoundaryNode extends LGraphNode {
  constructor(title, boundary) {
    super(title);
    this.boundary = boundary;
    this.block_delete = true;
    this.clonable = false;
    this.color = "#2e4a3e";
    this.bgcolor = "#22332c";
  }
  onConnectionsChange() { this.graph?.view.edited(); }
  getMenuOptions() { return []; }
}

// Litegraph truncates a title to the node's width less a title height at
// each end.
const measure = document.createElement("canvas").getContext("2d");

export class GraphView {
  // state: the editor's {library, kinds, doc, scope, errors,
  // unreadErrors}, read here (and new nodes added to state.doc); onEdit():
  // the user changed the scope's nodes or wires; onPlace(): the user put
  // nodes in new places (a drag, a new node); thumbnailOf(id): the
  // thumbnail entry of a node, or null; nodeMenu(v): the items of node
  // v's context menu; canvasMenu(): those of the canvas's.
  constructor(canvasElement, { state, onEdit, onPlace, thumbnailOf, nodeMenu, canvasMenu }) {
    this.state = state;
    this.onEdit = onEdit;
    this.onPlace = onPlace;
    this.nodeMenu = nodeMenu;
    this.thumbnailOf = thumbnailOf;
    this.thumbnailsDrawn = 0;
    this.showing = false;  // while show() rebuilds the canvas: no edits
    this.positions = new Map();  // scope -> node id or #boundary -> [x, y], kept across shows
    this.graph = new LGraph();
    this.graph.view = this;
    this.element = canvasElement;
    this.canvas = new LGraphCanvas(canvasElement, this.graph);
    // Whole graphs are shown zoomed out: keep titles and slot names
    // readable there, and leave out litegraph's debugging overlay.
    this.canvas.low_quality_zoom_threshold = 0.4;
    this.canvas.show_info = false;
    this.canvas.render_canvas_border = false;
    // Menus offer what this document can keep: no groups, colours, pins,
    // titles or subgraphs, which graph files do not hold.
    this.canvas.getMenuOptions = canvasMenu;
    this.graph.onGetNodeMenuOptions = (options) => {
      const kept = options.filter((item) => !["Align Selected To", "Distribute Nodes"].includes(item?.content));
      options.splice(0, options.length, ...kept);
    };
    this.graph.onNodeAdded = (v) => {
      if (this.showing || !v.op || v.shadetreeId) return;
      this.adopt(v);
      this.edited();
      this.onPlace();
    };
    this.graph.onNodeRemoved = () => this.edited();
    this.canvas.onNodeMoved = () => onPlace();
    // Keys reach the canvas once it has the focus; a new node goes where
    // the canvas was last clicked.
    canvasElement.tabIndex = 0;
    canvasElement.addEventListener("pointerdown", (event) => {
      canvasElement.focus();
      this.clickedAt = this.canvas.convertEventToCanvasOffset(event);
    });
  }

  edited() {
    if (!this.showing) this.onEdit();
  }

  get scopeKey() { return this.state.scope ?? ""; }
  opViews() { return this.graph._nodes.filter((v) => v.shadetreeId); }
  boundaryView(boundary) { return this.graph._nodes.find((v) => v.boundary === boundary); }
  viewOf(id) { return this.graph._nodes.find((v) => v.shadetreeId === id); }
  docNode(id) { return scopeBody(this.state.doc, this.state.scope).nodes.find((n) => n.id === id); }
  selectedId() { return Object.values(this.canvas.selected_nodes || {}).find((v) => v.shadetreeId)?.shadetreeId ?? null; }
  selectedIds() { return Object.values(this.canvas.selected_nodes || {}).filter((v) => v.shadetreeId).map((v) => v.shadetreeId); }
  select(ids) { this.canvas.selectItems(ids.map((id) => this.viewOf(id)).filter(Boolean)); }

  // What to tell the user about canvas point [x, y] (canvas coordinates):
  // {title, text} of the input or output under it, else of the node's op
  // (a function's, the kind's outputs'), null over empty canvas.
  docAt([x, y]) {
    const v = this.graph.getNodeOnPos(x, y, this.canvas.visible_nodes);
    if (!v) return null;
    const input = v.getInputOnPos([x, y]), output = input ? null : v.getOutputOnPos([x, y]);
    if (v.boundary === "outputs") {
      const contract = this.state.kinds.get(this.state.doc.kind)?.outputs || [];
      const port = input && contract.find((o) => o.name === input.name);
      if (port) return { title: `${port.name}: ${port.type}${port.required ? "" : " (optional)"}`, text: port.doc };
      return { title: `outputs of a ${this.state.doc.kind} graph`, text: contract.map((o) => o.name).join(", ") };
    }
    if (v.boundary) return null;
    const entry = this.state.library.get(v.op);
    const fn = entry ? null : this.state.doc.functions?.[v.op];
    const slot = input ?? output;
    if (slot) {
      const port = (entry ? (input ? entry.inputs : entry.outputs) : []).find((p) => p.name === slot.name);
      const unset = input && !input.link && !/ = /.test(slot.label ?? "") && port && "default" in port;
      return { title: slot.label ?? slot.name, text: [port?.doc, unset && `default ${port.default}`].filter(Boolean).join("; ") };
    }
    return { title: v.shadetreeId ? `${v.shadetreeId} (${v.op})` : v.op, text: entry?.doc ?? fn?.doc ?? "" };
  }

  // Registered, so that litegraph's own search and copy-paste make nodes
  // of it too; a function's type is registered again when its signature
  // changes.
  registerType(name, inputs, outputs, doc, category) {
    const type = `${category}/${name}`;
    const signature = JSON.stringify([inputs, outputs]);
    if (LiteGraph.registered_node_types[type]?.signature === signature) return type;
    class OpNode extends ShadetreeNode {
      constructor() {
        super(name);
        // Any wire may be drawn ("*"): the checker judges it (floats
        // promote to vectors, T is inferred), and says what is wrong on
        // the input.
        for (const input of inputs) this.addInput(input.name, "*", { label: `${input.name}: ${input.type}`, nameLocked: true });
        for (const output of outputs) this.addOutput(output.name, "*", { label: `${output.name}: ${output.type}`, nameLocked: true });
        this.op = name;
      }
    }
    OpNode.title = name;
    OpNode.desc = doc;
    OpNode.signature = signature;
    LiteGraph.registerNodeType(type, OpNode);
    return type;
  }

  typeForOp(op) {
    const entry = this.state.library.get(op);
    if (entry) return this.registerType(op, entry.inputs, entry.outputs, entry.doc, `shadetree/${entry.family}`);
    const fn = this.state.doc.functions?.[op];
    if (!fn) return null;
    const outputs = Object.keys(fn.outputs || {}).map((name) => ({ name, type: "*" }));
    return this.registerType(op, sourcesOf(this.state.doc, op), outputs, fn.doc || "", "functions");
  }

  // Litegraph's Add Node menu and search list the registered types: the
  // functions listed are this document's.
  registerFunctions() {
    const names = Object.keys(this.state.doc.functions || {});
    for (const type of Object.keys(LiteGraph.registered_node_types))
      if (type.startsWith("functions/") && !names.includes(type.slice("functions/".length))) LiteGraph.unregisterNodeType(type);
    for (const name of names) this.typeForOp(name);
  }

  // Wide enough for the title, tall enough for a thumbnail.
  fitSize(v) {
    measure.font = this.canvas.title_text_font;
    const title = Math.ceil(measure.measureText(v.title).width) + 2 * LiteGraph.NODE_TITLE_HEIGHT + 4;
    const [width, height] = v.computeSize();
    v.size = [Math.max(width, nodeWidth, title), height + (v.op ? thumbnailRoom : 0)];
  }

  // A node made by the palette, litegraph's search or a paste gets a
  // fresh id, and a place in the document with the attributes its op needs.
  adopt(v) {
    v.shadetreeId = freshId(scopeBody(this.state.doc, this.state.scope), v.op, (id) => this.viewOf(id));
    v.title = titleOf(v.shadetreeId, v.op);
    this.fitSize(v);
    scopeBody(this.state.doc, this.state.scope).nodes.push(
      { id: v.shadetreeId, op: v.op, ...structuredClone(newNodeAttributes[v.op] || {}) });
  }

  // A node of op `op`, right of the selected node, or where the canvas was
  // last clicked, or in the middle of the view; below any node it would
  // cover. It is selected.
  addNode(op) {
    const type = this.typeForOp(op);
    if (!type) return null;
    const v = LiteGraph.createNode(type);
    this.fitSize(v);
    const selected = this.viewOf(this.selectedId());
    const [width, height] = this.viewSize();
    v.pos = selected ? [selected.pos[0] + selected.size[0] + columnGap, selected.pos[1]]
          : this.clickedAt ? [...this.clickedAt]
          : this.canvas.ds.convertCanvasToOffset([width / 2 - v.size[0] / 2, height / 3]);
    this.makeRoom(v);
    this.graph.add(v);
    this.canvas.selectNode(v);  // the next one goes right of it
    return v;
  }

  // Moves v down until it covers no other node.
  makeRoom(v) {
    const title = LiteGraph.NODE_TITLE_HEIGHT;
    const covers = (other) => other !== v && v.pos[0] < other.pos[0] + other.size[0] && other.pos[0] < v.pos[0] + v.size[0] &&
                              v.pos[1] - title < other.pos[1] + other.size[1] && other.pos[1] - title < v.pos[1] + v.size[1];
    for (let other = this.graph._nodes.find(covers); other; other = this.graph._nodes.find(covers))
      v.pos[1] = other.pos[1] + other.size[1] + title + rowGap;
  }

  viewSize() {
    const ratio = window.devicePixelRatio || 1;
    return [this.element.width / ratio, this.element.height / ratio];
  }

  // Wires output `output` of node `from` into input `input` of node `to`
  // (ids; "$" for the params or function inputs, "#outputs" for the outputs).
  connect(from, output, to, input) {
    const source = from === "$" ? this.boundaryView("sources") : this.viewOf(from);
    const target = to === "#outputs" ? this.boundaryView("outputs") : this.viewOf(to);
    source.connect(source.findOutputSlot(output), target, target.findInputSlot(input));
  }

  rememberPositions() {
    this.positions.set(this.scopeKey, new Map(this.graph._nodes.map((v) => [positionKey(v), [...v.pos]])));
  }

  // The places of the nodes of every scope shown so far, as text (for the
  // history), and back: the scopes it has replace the remembered ones.
  layout() {
    this.rememberPositions();
    return JSON.stringify([...this.positions].map(([scope, places]) => [scope, [...places]]));
  }

  restoreLayout(text) {
    for (const [scope, places] of JSON.parse(text)) this.positions.set(scope, new Map(places));
  }

  // The places of a file's "layout" section replace all those kept.
  loadLayout(section) {
    this.positions = placesOf(section);
  }

  // The "layout" section of `doc`: the places of its nodes in each scope
  // shown or read from its file, in whole units.
  layoutSection(doc) {
    this.rememberPositions();
    const section = (scope) => {
      const body = scopeBody(doc, scope || null);
      const ids = new Set([...body.nodes.map((node) => node.id), "#sources", "#outputs"]);
      const places = [...(this.positions.get(scope) || [])].filter(([key]) => ids.has(key));
      return Object.fromEntries(places.map(([key, xy]) => [key, xy.map(Math.round)]));
    };
    const functions = Object.keys(doc.functions || {}).filter((name) => this.positions.has(name));
    const layout = { nodes: section("") };
    if (functions.length > 0) layout.functions = Object.fromEntries(functions.map((name) => [name, section(name)]));
    return layout;
  }

  // Rebuilds the canvas from state.doc's scope state.scope; nodes keep the
  // places they had when this scope was last shown.
  show({ fit = false } = {}) {
    const { doc, scope } = this.state;
    this.showing = true;
    this.registerFunctions();
    this.canvas.deselectAll();
    this.graph.clear();
    const body = scopeBody(doc, scope);
    const views = new Map();
    const sources = new BoundaryNode(scope ? "inputs" : "params", "sources");
    for (const source of sourcesOf(doc, scope)) sources.addOutput(source.name, "*", { label: `$${source.name}: ${source.type}` });
    const outputs = new BoundaryNode("outputs", "outputs");
    for (const output of this.outputSlots(body)) outputs.addInput(output.name, "*", { label: output.label, nameLocked: true });
    // Columns by depth: a node one right of its deepest input; the
    // sources in the first column, the outputs in the last.
    const depth = new Map();
    const columns = [];
    const place = (v, column) => (columns[column] ??= []).push(v);
    if (sources.outputs?.length) place(sources, 0);
    for (const node of body.nodes) {
      const type = this.typeForOp(node.op);
      const v = type ? LiteGraph.createNode(type) : new ShadetreeNode(node.op);
      v.title = titleOf(node.id, node.op);
      v.shadetreeId = node.id;
      v.op = node.op;
      this.fitSize(v);
      let level = 1;
      for (const value of Object.values(node.in || {})) {
        const reference = parseReference(value);
        if (reference && depth.has(reference.id)) level = Math.max(level, depth.get(reference.id) + 1);
      }
      depth.set(node.id, level);
      place(v, level);
      views.set(node.id, v);
    }
    place(outputs, columns.length);
    this.layOut(columns.filter(Boolean));
    this.wire(views, sources, outputs);
    this.showing = false;
    if (fit) this.fit();
    this.markErrors();
  }

  // The main graph's outputs node offers every output of its kind's
  // contract, so one whose wire is cut can be wired again; the outputs
  // a file has beyond it stay, for the checker to name.
  outputSlots(body) {
    const given = Object.keys(body.outputs || {});
    if (this.state.scope) return given.map((name) => ({ name, label: name }));
    const contract = this.state.kinds.get(this.state.doc.kind)?.outputs || [];
    return [...contract.map((output) => ({ name: output.name, label: `${output.name}: ${output.type}${output.required ? " (required)" : ""}` })),
            ...given.filter((name) => !contract.some((output) => output.name === name)).map((name) => ({ name, label: name }))];
  }

  // Columns left to right, each centred on one line as wires mostly run
  // along it; remembered places win. A column taller than the view and
  // than the layout would be with the view's proportions is wrapped into
  // columns side by side: ocean's longest would not fit at the least zoom.
  layOut(columns) {
    const remembered = this.positions.get(this.scopeKey) || new Map();
    const rowOf = (v) => v.size[1] + LiteGraph.NODE_TITLE_HEIGHT + rowGap;
    const [width, height] = this.viewSize();
    const area = columns.flat().reduce((sum, v) => sum + (v.size[0] + columnGap) * rowOf(v), 0);
    const wrapAt = Math.max(height, Math.sqrt(area * height / width));
    const wrapped = columns.flatMap((column) => {
      const parts = [[]];
      let used = 0;
      for (const v of column) {
        if (used + rowOf(v) > wrapAt && parts.at(-1).length > 0) {
          parts.push([]);
          used = 0;
        }
        parts.at(-1).push(v);
        used += rowOf(v);
      }
      return parts;
    });
    const heightOf = (column) => column.reduce((sum, v) => sum + rowOf(v), 0);
    const tallest = Math.max(...wrapped.map(heightOf));
    let x = 30;
    for (const column of wrapped) {
      let y = 40 + (tallest - heightOf(column)) / 2;
      for (const v of column) {
        v.pos = remembered.get(positionKey(v)) || [x, y];
        y += rowOf(v);
        this.graph.add(v);
      }
      x += Math.max(...column.map((v) => v.size[0])) + columnGap;
    }
  }

  // Literals are shown on their input's label, and references the canvas
  // cannot draw (an unknown node or input) are kept as written.
  wire(views, sources, outputs) {
    const sourceOf = (value) => {
      if (value.startsWith("$")) {
        const slot = sources.findOutputSlot(value.slice(1));
        return slot < 0 ? null : [sources, slot];
      }
      const reference = parseReference(value);
      const source = views.get(reference.id);
      if (!source?.outputs?.length) return null;
      const slot = reference.output ? source.findOutputSlot(reference.output) : 0;
      return slot < 0 ? null : [source, slot];
    };
    const wireInto = (target, values) => {
      target.unresolved = {};
      for (const [input, value] of Object.entries(values || {})) {
        const slot = target.findInputSlot(input);
        const source = typeof value === "string" ? sourceOf(value) : null;
        if (typeof value !== "string") {
          if (slot >= 0) labelConstant(target.inputs[slot], value);
        } else if (source && slot >= 0) {
          source[0].connect(source[1], target, slot);
        } else {
          target.unresolved[input] = value;
        }
      }
    };
    const body = scopeBody(this.state.doc, this.state.scope);
    for (const node of body.nodes) wireInto(views.get(node.id), node.in);
    wireInto(outputs, body.outputs);
  }

  // Zoom and scroll so that the whole scope is in sight, not magnified.
  // [x0, y0, x1, y1] holding every node, titles included; null with none.
  bounds() {
    const nodes = this.graph._nodes;
    if (nodes.length === 0) return null;
    const title = LiteGraph.NODE_TITLE_HEIGHT;
    return [Math.min(...nodes.map((v) => v.pos[0])), Math.min(...nodes.map((v) => v.pos[1] - title)),
            Math.max(...nodes.map((v) => v.pos[0] + v.size[0])), Math.max(...nodes.map((v) => v.pos[1] + v.size[1]))];
  }

  // The view's centre on graph point [x, y], at the same zoom.
  centreOn([x, y]) {
    const [width, height] = this.viewSize();
    const { scale } = this.canvas.ds;
    this.canvas.ds.offset = [width / (2 * scale) - x, height / (2 * scale) - y];
    this.canvas.setDirty(true, true);
  }

  fit() {
    const box = this.bounds();
    if (!box) return;
    const [x0, y0, x1, y1] = box;
    const [width, height] = this.viewSize();
    const scale = Math.max(this.canvas.ds.min_scale, Math.min(1, (width - 40) / (x1 - x0), (height - 40) / (y1 - y0)));
    this.canvas.ds.scale = scale;
    this.canvas.ds.offset = [Math.max(20 / scale, (width / scale - (x1 - x0)) / 2) - x0,
                             Math.max(20 / scale, (height / scale - (y1 - y0)) / 2) - y0];
    this.canvas.setDirty(true, true);
  }

  // A wire's value in the document.
  static referenceTo(source, slot) {
    if (source.boundary === "sources") return `$${source.outputs[slot].name}`;
    return source.outputs.length > 1 ? `${source.shadetreeId}.${source.outputs[slot].name}` : source.shadetreeId;
  }

  // The values of a node's inputs (or of the outputs) as the canvas has
  // them, in the file's order: wires where there are wires, literals and
  // references the canvas could not draw where there are none.
  valuesFromCanvas(target, values) {
    const linked = new Map();
    target.inputs.forEach((slot, index) => {
      const link = target.getInputLink(index);
      if (link) linked.set(slot.name, GraphView.referenceTo(this.graph.getNodeById(link.origin_id), link.origin_slot));
    });
    const result = {};
    for (const [input, value] of Object.entries(values || {})) {
      if (linked.has(input)) result[input] = linked.get(input);
      else if (typeof value !== "string" || target.unresolved?.[input] === value) result[input] = value;
    }
    for (const [input, reference] of linked) result[input] ??= reference;
    return result;
  }

  // A copy of state.doc with the shown scope's wires as the canvas has
  // them. Nodes keep their place in the file and every field they had
  // (attributes, docs); new nodes go last.
  document() {
    const doc = structuredClone(this.state.doc);
    const body = scopeBody(doc, this.state.scope);
    const views = new Map(this.opViews().map((v) => [v.shadetreeId, v]));
    body.nodes = body.nodes.filter((node) => views.has(node.id));
    for (const [id, v] of views) {
      let node = body.nodes.find((n) => n.id === id);
      if (!node) {
        node = { id, op: v.op };
        body.nodes.push(node);
      }
      const values = this.valuesFromCanvas(v, node.in);
      if (Object.keys(values).length > 0) node.in = values;
      else delete node.in;
    }
    const outputs = this.boundaryView("outputs");
    if (outputs) body.outputs = this.valuesFromCanvas(outputs, body.outputs);
    return doc;
  }

  // Input `input` of node `id` is fed the constant `value` (undefined: none).
  showConstant(id, input, value) {
    const v = this.viewOf(id);
    const slot = v?.findInputSlot(input) ?? -1;
    if (slot < 0) return;
    labelConstant(v.inputs[slot], value);
    this.markErrors();
  }

  // Whether a wire feeds input `input` of node `id` on the canvas.
  isWired(id, input) {
    const v = this.viewOf(id);
    const slot = v?.findInputSlot(input) ?? -1;
    return slot >= 0 && v.inputs[slot].link != null;
  }

  // The checker's diagnostics on the nodes and inputs they name: red
  // when they stop the preview, amber on nodes no output reads, which do
  // not.
  markErrors() {
    const of = (diagnostics, v) => v.shadetreeId ? diagnostics.filter((diagnostic) => diagnostic.node === v.shadetreeId) : [];
    for (const v of this.graph._nodes) {
      const stopping = of(this.state.errors, v);
      const faults = stopping.length ? stopping : of(this.state.unreadErrors, v);
      const wrong = faults.length > 0;
      const [color, bgcolor] = stopping.length ? ["#8a2c2c", "#4a1f1f"] : ["#8a6a2c", "#4a3a1f"];
      if (!v.boundary) {
        v.color = wrong ? color : undefined;
        v.bgcolor = wrong ? bgcolor : undefined;
      }
      for (const slot of v.inputs || []) {
        const wrongInput = faults.some((diagnostic) => slot.name === diagnostic.input);
        slot.color_on = wrongInput ? "#ff5555" : undefined;
        slot.color_off = wrongInput ? "#ff5555" : undefined;
        slot.label = slot.label.replace(/ ⚠$/, "") + (wrongInput ? " ⚠" : "");
      }
    }
    this.canvas.setDirty(true, true);
  }
}
