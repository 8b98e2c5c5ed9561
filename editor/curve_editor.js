// Editors for the table attributes of spline-like nodes, shown in the side
// panel: a curve with draggable control points for spline, color_table
// and table1d (with a gradient strip and a colour picker per knot when the
// knots are colours), a paintable grid for table2d. Edits write into the
// document's node and call onEdit(interactive), interactive while a drag
// or typing goes on (the preview may then render coarser, and the whole
// drag makes one history step).

import { element, hexOf, rgbOf } from "./dom.js";

const channelColors = { 1: ["#e8e8e8"], 2: ["#ff9b6a", "#5ec8f8"], 3: ["#ff6060", "#5fd35f", "#6a94ff"] };
const width = 280;
const plotHeight = 150;
const stripHeight = 16;
const pad = { left: 30, right: 8, top: 8, bottom: 16 };
const hitRadius = 9;

// Table attributes hold 4 decimals at most, so that files stay readable.
const tidy = (value) => Math.round(value * 1e4) / 1e4;
const clamp = (value, lo, hi) => Math.min(hi, Math.max(lo, value));

// The spline of nodes/semantics/splines.h, over rows of components.
function splineAt(rows, basis, x) {
  const n = rows.length;
  x = clamp(x, 0, 1);
  if (basis === "step") return rows[Math.min(Math.floor(x * n), n - 1)];
  const segments = basis === "catmull-rom" ? n - 3 : n - 1;
  if (segments <= 0) return rows[0];
  const t = x * segments;
  const s = Math.min(Math.floor(t), segments - 1);
  const f = t - s;
  if (basis === "linear") return rows[s].map((k0, c) => k0 + (rows[s + 1][c] - k0) * f);
  const f2 = f * f, f3 = f2 * f;
  return rows[s].map((_, c) => 0.5 * ((2 * f2 - f3 - f) * rows[s][c] + (3 * f3 - 5 * f2 + 2) * rows[s + 1][c] +
                                      (4 * f2 - 3 * f3 + f) * rows[s + 2][c] + (f3 - f2) * rows[s + 3][c]));
}

// Where each op puts its equally spaced values along x in [0,1], what its
// curve is, and how few values it accepts (nodes/ops/splines.h). The end
// knots of a Catmull-Rom spline only steer its tangents: they are drawn
// just outside [0,1].
const endKnotX = 0.04;
const models = {
  spline: {
    attribute: "knots",
    basis: (node) => node.basis || "catmull-rom",
    minimum: (node) => ({ "catmull-rom": 4, linear: 2, step: 1 })[models.spline.basis(node)],
    xOf(node, i, n) {
      const basis = models.spline.basis(node);
      if (basis === "step") return (i + 0.5) / n;
      if (basis === "linear") return n > 1 ? i / (n - 1) : 0.5;
      if (i === 0) return -endKnotX;
      if (i === n - 1) return 1 + endKnotX;
      return (i - 1) / (n - 3);
    },
    at: (node, rows, x) => splineAt(rows, models.spline.basis(node), x),
  },
  color_table: {
    attribute: "entries",
    minimum: () => 1,
    xOf: (node, i, n) => (i + 0.5) / n,
    at: (node, rows, x) => splineAt(rows, "step", x),
  },
  table1d: {
    attribute: "values",
    minimum: () => 1,
    xOf: (node, i, n) => (n > 1 ? i / (n - 1) : 0.5),
    at: (node, rows, x) => splineAt(rows, "linear", x),
  },
};

function sizedCanvas(cssWidth, cssHeight) {
  const canvas = element("canvas");
  const ratio = window.devicePixelRatio || 1;
  canvas.width = Math.round(cssWidth * ratio);
  canvas.height = Math.round(cssHeight * ratio);
  canvas.style.width = `${cssWidth}px`;
  canvas.style.height = `${cssHeight}px`;
  const context = canvas.getContext("2d");
  context.scale(ratio, ratio);
  return [canvas, context];
}

// The editor of a node of op spline, color_table, table1d or table2d, or null.
export function attributeEditor(node, onEdit) {
  if (node.op === "table2d") return Array.isArray(node.values) ? new GridEditor(node, onEdit).element : null;
  const model = models[node.op];
  if (!model || !Array.isArray(node[model.attribute]) || node[model.attribute].length === 0) return null;
  return new CurveEditor(node, model, onEdit).element;
}

class CurveEditor {
  constructor(node, model, onEdit) {
    this.node = node;
    this.model = model;
    this.onEdit = onEdit;
    const values = node[model.attribute];
    this.scalar = !Array.isArray(values[0]);
    this.rows = values.map((v) => (this.scalar ? [Number(v)] : v.map(Number)));
    this.components = this.rows[0].length;
    this.selected = null;  // {index, component}
    this.drag = null;
    this.colour = this.components === 3;
    const height = plotHeight + (this.colour ? stripHeight + 4 : 0);
    [this.canvas, this.context] = sizedCanvas(width, height);
    this.canvas.className = "curve";
    this.canvas.title = "drag a point to change its value (shift: all channels), double-click to add one, right-click to delete one";
    this.canvas.curveEditor = this;  // for tests: pointOf(), valueAt()
    this.swatches = element("div", { className: "swatches" });
    this.fields = element("div", { className: "knot-fields" });
    this.element = element("div", { className: "curve-editor" }, [this.canvas, this.swatches, this.fields]);
    if (node.op === "spline") this.element.append(this.basisControl());
    if (node.op === "table1d") this.element.append(this.domainControl());
    this.listen();
    this.refresh();
  }

  get count() { return this.rows.length; }
  get plotTop() { return this.colour ? stripHeight + 4 : 0; }

  // Pixel <-> curve coordinates. The x axis shows [0,1] and a little
  // margin for Catmull-Rom end knots; the value axis spans the values and
  // [0,1], frozen during a drag so that the curve does not jump.
  valueRange() {
    if (this.drag) return this.drag.range;
    const all = this.rows.flat();
    const lo = Math.min(0, ...all), hi = Math.max(1, ...all);
    const margin = (hi - lo) * 0.05;
    return [lo - margin, hi + margin];
  }
  xToPixel(x) { return pad.left + ((x + 0.06) / 1.12) * (width - pad.left - pad.right); }
  pixelToX(px) { return ((px - pad.left) / (width - pad.left - pad.right)) * 1.12 - 0.06; }
  valueToPixel(v) {
    const [lo, hi] = this.valueRange();
    const top = this.plotTop + pad.top, bottom = this.plotTop + plotHeight - pad.bottom;
    return bottom - ((v - lo) / (hi - lo)) * (bottom - top);
  }
  pixelToValue(py) {
    const [lo, hi] = this.valueRange();
    const top = this.plotTop + pad.top, bottom = this.plotTop + plotHeight - pad.bottom;
    return lo + ((bottom - py) / (bottom - top)) * (hi - lo);
  }

  // The curve drawn, at x in [0,1]: one value per component.
  valueAt(x) { return this.model.at(this.node, this.rows, x); }

  // Where control point (index, component) is drawn, in CSS pixels of the canvas.
  pointOf(index, component = 0) {
    return [this.xToPixel(this.model.xOf(this.node, index, this.count)), this.valueToPixel(this.rows[index][component])];
  }

  hit(event) {
    const [px, py] = this.eventPoint(event);
    let best = null;
    for (let index = 0; index < this.count; ++index) {
      for (let component = 0; component < this.components; ++component) {
        const [x, y] = this.pointOf(index, component);
        const distance = Math.hypot(x - px, y - py);
        if (distance <= hitRadius && (!best || distance < best.distance)) best = { index, component, distance };
      }
    }
    return best;
  }

  eventPoint(event) {
    const box = this.canvas.getBoundingClientRect();
    return [event.clientX - box.left, event.clientY - box.top];
  }

  listen() {
    this.canvas.addEventListener("pointerdown", (event) => {
      if (event.button !== 0) return;
      const hit = this.hit(event);
      if (!hit) return;
      this.selected = { index: hit.index, component: hit.component };
      this.drag = { ...this.selected, all: event.shiftKey, start: [...this.rows[hit.index]],
                    startValue: this.pixelToValue(this.eventPoint(event)[1]), range: this.valueRange() };
      this.canvas.setPointerCapture(event.pointerId);
      this.refresh();
    });
    this.canvas.addEventListener("pointermove", (event) => {
      if (!this.drag) return;
      const value = this.pixelToValue(this.eventPoint(event)[1]);
      const { index, component, all, start, startValue } = this.drag;
      this.rows[index] = all ? start.map((v) => tidy(v + value - startValue))
                             : start.map((v, c) => (c === component ? tidy(value) : v));
      this.write(true);
    });
    const release = () => {
      if (!this.drag) return;
      this.drag = null;
      this.write(false);
    };
    this.canvas.addEventListener("pointerup", release);
    this.canvas.addEventListener("pointercancel", release);
    this.canvas.addEventListener("dblclick", (event) => {
      if (this.hit(event)) return;
      this.insertAt(clamp(this.pixelToX(this.eventPoint(event)[0]), 0, 1));
    });
    this.canvas.addEventListener("contextmenu", (event) => {
      event.preventDefault();
      const hit = this.hit(event);
      if (hit) this.remove(hit.index);
    });
  }

  // A new knot at x, on the curve as it is, so that the shape barely changes.
  insertAt(x) {
    const n = this.count;
    const value = this.valueAt(x).map(tidy);
    let index = 0;
    while (index < n && this.model.xOf(this.node, index, n) <= x) index += 1;
    if (this.node.op === "spline" && this.model.basis(this.node) === "catmull-rom") index = clamp(index, 1, n - 1);
    this.rows.splice(index, 0, value);
    this.selected = { index, component: 0 };
    this.write(false);
  }

  remove(index) {
    if (this.count <= this.model.minimum(this.node)) return;
    this.rows.splice(index, 1);
    this.selected = null;
    this.write(false);
  }

  write(interactive) {
    this.node[this.model.attribute] = this.rows.map((row) => (this.scalar ? row[0] : [...row]));
    this.refresh();
    this.onEdit(interactive);
  }

  refresh() {
    this.draw();
    this.showSwatches();
    this.showFields();
  }

  draw() {
    const g = this.context;
    const height = this.plotTop + plotHeight;
    g.clearRect(0, 0, width, height);
    g.fillStyle = "#17181b";
    g.fillRect(0, this.plotTop, width, plotHeight);
    if (this.colour) {
      for (let px = pad.left; px < width - pad.right; ++px) {
        g.fillStyle = hexOf(this.valueAt(clamp(this.pixelToX(px + 0.5), 0, 1)));
        g.fillRect(px, 0, 1, stripHeight);
      }
    }
    // Axes: x = 0, 1 and the values 0, 1.
    g.strokeStyle = "#3a3d42";
    g.lineWidth = 1;
    g.beginPath();
    for (const x of [0, 0.25, 0.5, 0.75, 1]) {
      g.moveTo(this.xToPixel(x), this.plotTop + pad.top);
      g.lineTo(this.xToPixel(x), this.plotTop + plotHeight - pad.bottom);
    }
    for (const v of [0, 1]) {
      g.moveTo(pad.left, this.valueToPixel(v));
      g.lineTo(width - pad.right, this.valueToPixel(v));
    }
    g.stroke();
    g.fillStyle = "#888";
    g.font = "10px sans-serif";
    g.textAlign = "right";
    for (const v of [0, 1]) g.fillText(String(v), pad.left - 4, this.valueToPixel(v) + 3);
    g.textAlign = "center";
    const [xLo, xHi] = this.node.op === "table1d" && Array.isArray(this.node.domain) ? this.node.domain : [0, 1];
    g.fillText(String(xLo), this.xToPixel(0), this.plotTop + plotHeight - 3);
    g.fillText(String(xHi), this.xToPixel(1), this.plotTop + plotHeight - 3);
    const colours = channelColors[this.components] || channelColors[1];
    for (let component = 0; component < this.components; ++component) {
      g.strokeStyle = colours[component];
      g.lineWidth = 1.5;
      g.beginPath();
      for (let px = this.xToPixel(0); px <= this.xToPixel(1); px += 1) {
        const y = this.valueToPixel(this.valueAt(clamp(this.pixelToX(px), 0, 1))[component]);
        if (px === this.xToPixel(0)) g.moveTo(px, y);
        else g.lineTo(px, y);
      }
      g.stroke();
      for (let index = 0; index < this.count; ++index) {
        const [x, y] = this.pointOf(index, component);
        const tangentOnly = this.node.op === "spline" && this.model.basis(this.node) === "catmull-rom" &&
                            (index === 0 || index === this.count - 1);
        g.beginPath();
        g.arc(x, y, 4, 0, Math.PI * 2);
        g.fillStyle = tangentOnly ? "#17181b" : colours[component];
        g.strokeStyle = colours[component];
        g.fill();
        g.stroke();
        if (this.selected && this.selected.index === index) {
          g.beginPath();
          g.arc(x, y, 6.5, 0, Math.PI * 2);
          g.strokeStyle = "#fff";
          g.stroke();
        }
      }
    }
  }

  // One colour picker per knot, under the gradient.
  showSwatches() {
    if (!this.colour) return;
    if (this.swatches.children.length !== this.count) {
      this.swatches.replaceChildren(...this.rows.map((_, index) => {
        const picker = element("input", { type: "color", title: `knot ${index}` });
        picker.addEventListener("input", () => {
          this.rows[index] = rgbOf(picker.value);
          this.selected = { index, component: 0 };
          this.write(true);
        });
        picker.addEventListener("change", () => this.onEdit(false));
        return picker;
      }));
    }
    this.rows.forEach((row, index) => {
      const picker = this.swatches.children[index];
      if (document.activeElement !== picker) picker.value = hexOf(row);
      picker.classList.toggle("selected", Boolean(this.selected && this.selected.index === index));
    });
  }

  // The selected knot's exact values, and a delete button.
  showFields() {
    if (this.fields.contains(document.activeElement)) return;
    const n = this.count;
    const minimum = this.model.minimum(this.node);
    const summary = element("span", { textContent: `${n} ${this.model.attribute}` + (minimum > 1 ? ` (at least ${minimum})` : "") });
    if (!this.selected || this.selected.index >= n) {
      this.fields.replaceChildren(summary);
      return;
    }
    const { index } = this.selected;
    const inputs = this.rows[index].map((value, component) => {
      const input = element("input", { type: "number", step: "0.01", value: String(value), title: `knot ${index}, component ${component}` });
      input.addEventListener("input", () => {
        if (input.value === "" || !Number.isFinite(Number(input.value))) return;
        this.rows[index][component] = tidy(Number(input.value));
        this.node[this.model.attribute] = this.rows.map((row) => (this.scalar ? row[0] : [...row]));
        this.draw();
        this.showSwatches();
        this.onEdit(true);
      });
      input.addEventListener("change", () => this.onEdit(false));
      return input;
    });
    const remove = element("button", { textContent: "Delete", disabled: n <= minimum, title: "delete this knot" });
    remove.addEventListener("click", () => this.remove(index));
    this.fields.replaceChildren(summary, element("span", { textContent: ` · #${index}` }), ...inputs, remove);
  }

  basisControl() {
    const select = element("select", { title: "spline basis" },
                           ["catmull-rom", "linear", "step"].map((basis) => new Option(basis, basis)));
    select.value = models.spline.basis(this.node);
    select.addEventListener("change", () => {
      this.node.basis = select.value;
      // A basis that needs more knots: repeat the end ones.
      while (this.count < models.spline.minimum(this.node)) this.rows.push([...this.rows[this.count - 1]]);
      this.write(false);
    });
    return element("label", { className: "inline" }, ["basis ", select]);
  }

  domainControl() {
    const [lo, hi] = Array.isArray(this.node.domain) ? this.node.domain : [0, 1];
    const field = (value) => element("input", { type: "number", step: "0.1", value: String(value) });
    const low = field(lo), high = field(hi);
    const apply = () => {
      const domain = [Number(low.value), Number(high.value)];
      if (!domain.every(Number.isFinite) || domain[0] === domain[1]) return;
      this.node.domain = domain;
      this.draw();
      this.onEdit(true);
    };
    for (const field of [low, high]) {
      field.addEventListener("input", apply);
      field.addEventListener("change", () => this.onEdit(false));
    }
    return element("label", { className: "inline" }, ["domain ", low, " to ", high]);
  }
}

// table2d: rows of values, row 0 at y = 0 (drawn at the bottom). Click or
// drag paints the brush value; right-click picks a cell's value.
class GridEditor {
  constructor(node, onEdit) {
    this.node = node;
    this.onEdit = onEdit;
    this.rows = node.values.map((row) => row.map(Number));
    this.brush = element("input", { type: "range", min: "0", max: "1", step: "0.01", value: "1", title: "the value painted" });
    this.brushValue = element("input", { type: "number", step: "0.01", value: "1" });
    this.brush.addEventListener("input", () => { this.brushValue.value = this.brush.value; });
    this.brushValue.addEventListener("input", () => { this.brush.value = this.brushValue.value; });
    const buttons = [["+ row", () => this.rows.push([...this.rows.at(-1)])],
                     ["− row", () => this.rows.length > 1 && this.rows.pop()],
                     ["+ column", () => this.rows.forEach((row) => row.push(row.at(-1)))],
                     ["− column", () => this.rows[0].length > 1 && this.rows.forEach((row) => row.pop())]]
      .map(([label, change]) => {
        const button = element("button", { textContent: label });
        button.addEventListener("click", () => {
          change();
          this.layout();
          this.write(false);
        });
        return button;
      });
    this.host = element("div");
    this.element = element("div", { className: "grid-editor" }, [
      this.host,
      element("label", { className: "inline" }, ["paint ", this.brush, this.brushValue]),
      element("div", { className: "grid-buttons" }, buttons),
    ]);
    this.layout();
  }

  layout() {
    const columns = this.rows[0].length, count = this.rows.length;
    this.cell = Math.max(6, Math.min(width / columns, 180 / count, 32));
    [this.canvas, this.context] = sizedCanvas(this.cell * columns, this.cell * count);
    this.canvas.className = "grid";
    this.canvas.title = "click or drag to paint the value below; right-click picks a cell's value";
    this.canvas.gridEditor = this;  // for tests: cellPoint()
    this.host.replaceChildren(this.canvas);
    this.listen();
    this.draw();
  }

  // The centre of cell (row, column), in CSS pixels of the canvas.
  cellPoint(row, column) { return [(column + 0.5) * this.cell, (this.rows.length - row - 0.5) * this.cell]; }

  cellAt(event) {
    const box = this.canvas.getBoundingClientRect();
    const column = Math.floor((event.clientX - box.left) / this.cell);
    const row = this.rows.length - 1 - Math.floor((event.clientY - box.top) / this.cell);
    if (row < 0 || row >= this.rows.length || column < 0 || column >= this.rows[0].length) return null;
    return [row, column];
  }

  listen() {
    let painting = false;
    const paint = (event) => {
      const cell = this.cellAt(event);
      const value = Number(this.brushValue.value);
      if (!cell || !Number.isFinite(value) || this.rows[cell[0]][cell[1]] === tidy(value)) return;
      this.rows[cell[0]][cell[1]] = tidy(value);
      this.write(true);
    };
    this.canvas.addEventListener("pointerdown", (event) => {
      if (event.button !== 0) return;
      painting = true;
      this.canvas.setPointerCapture(event.pointerId);
      paint(event);
    });
    this.canvas.addEventListener("pointermove", (event) => painting && paint(event));
    const release = () => {
      if (!painting) return;
      painting = false;
      this.write(false);
    };
    this.canvas.addEventListener("pointerup", release);
    this.canvas.addEventListener("pointercancel", release);
    this.canvas.addEventListener("contextmenu", (event) => {
      event.preventDefault();
      const cell = this.cellAt(event);
      if (!cell) return;
      this.brushValue.value = String(this.rows[cell[0]][cell[1]]);
      this.brush.value = this.brushValue.value;
    });
  }

  write(interactive) {
    this.node.values = this.rows.map((row) => [...row]);
    this.draw();
    this.onEdit(interactive);
  }

  draw() {
    const g = this.context;
    const all = this.rows.flat();
    const lo = Math.min(0, ...all), hi = Math.max(1, ...all);
    g.font = "9px sans-serif";
    g.textAlign = "center";
    this.rows.forEach((row, r) => row.forEach((value, c) => {
      const [x, y] = this.cellPoint(r, c);
      const shade = Math.round(((value - lo) / (hi - lo)) * 255);
      g.fillStyle = `rgb(${shade},${shade},${shade})`;
      g.fillRect(x - this.cell / 2, y - this.cell / 2, this.cell, this.cell);
      g.strokeStyle = "#2a2c30";
      g.strokeRect(x - this.cell / 2 + 0.5, y - this.cell / 2 + 0.5, this.cell - 1, this.cell - 1);
      if (this.cell >= 22) {
        g.fillStyle = shade > 128 ? "#000" : "#ddd";
        g.fillText(String(Math.round(value * 100) / 100), x, y + 3);
      }
    }));
  }
}
