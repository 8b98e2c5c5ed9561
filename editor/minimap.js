// A map of the whole graph in a corner of the canvas, shown while some
// nodes lie outside the view (ocean's 129 nodes do at any readable zoom):
// each node a rectangle, the view a frame. A click or a drag on it brings
// the view's centre there.

// The map's longer side, in CSS pixels.
const mapSide = 160;

export class Minimap {
  // element: a <canvas> over the graph's; graphView: its GraphView.
  constructor(element, graphView) {
    this.element = element;
    this.graphView = graphView;
    this.mapping = null;  // {x0, y0, scale}: graph point -> map pixel, as last drawn
    element.addEventListener("pointerdown", (event) => {
      element.setPointerCapture(event.pointerId);
      this.centreAt(event);
    });
    element.addEventListener("pointermove", (event) => {
      if (event.buttons) this.centreAt(event);
    });
  }

  // Called after each draw of the canvas: `area` is its visible part [x, y, w, h].
  draw(area) {
    const box = this.graphView.bounds();
    const inView = box && box[0] >= area[0] && box[1] >= area[1] && box[2] <= area[0] + area[2] && box[3] <= area[1] + area[3];
    this.element.hidden = !box || inView;
    if (this.element.hidden) return;
    const x0 = Math.min(box[0], area[0]), y0 = Math.min(box[1], area[1]);
    const x1 = Math.max(box[2], area[0] + area[2]), y1 = Math.max(box[3], area[1] + area[3]);
    const scale = mapSide / Math.max(x1 - x0, y1 - y0);
    const width = Math.ceil((x1 - x0) * scale), height = Math.ceil((y1 - y0) * scale);
    if (this.element.width !== width || this.element.height !== height) Object.assign(this.element, { width, height });
    this.mapping = { x0, y0, scale };
    const ctx = this.element.getContext("2d");
    ctx.clearRect(0, 0, width, height);
    ctx.fillStyle = "rgba(20, 21, 24, 0.85)";
    ctx.fillRect(0, 0, width, height);
    const selected = new Set(this.graphView.selectedIds());
    for (const v of this.graphView.graph._nodes) {
      ctx.fillStyle = selected.has(v.shadetreeId) ? "#ddd" : v.boundary ? "#4a7a64" : "#777";
      ctx.fillRect((v.pos[0] - x0) * scale, (v.pos[1] - y0) * scale, Math.max(1, v.size[0] * scale), Math.max(1, v.size[1] * scale));
    }
    ctx.strokeStyle = "#8ab4f8";
    ctx.strokeRect((area[0] - x0) * scale + 0.5, (area[1] - y0) * scale + 0.5, area[2] * scale - 1, area[3] * scale - 1);
  }

  // The view's centre to the graph point under the pointer.
  centreAt(event) {
    if (!this.mapping) return;
    const { x0, y0, scale } = this.mapping;
    const box = this.element.getBoundingClientRect();
    const point = [x0 + (event.clientX - box.left) / scale, y0 + (event.clientY - box.top) / scale];
    this.graphView.centreOn(point);
  }
}
