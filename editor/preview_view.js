// Navigation of the preview: the wheel zooms and a drag pans a texture's
// domain, or orbits (shift: pans, wheel: dollies) the camera of a surface
// or volume graph. The view changes only the document sent for previews
// (apply()); the document itself, and so the saved file, keeps its own
// render domain and camera.
const defaultDomain = { min: [0, 0], max: [1, 1] };
const defaultCamera = { position: [0, 0, 4], target: [0, 0, 0], up: [0, 1, 0], fov: 40 };

const add = (a, b) => a.map((v, i) => v + b[i]);
const sub = (a, b) => a.map((v, i) => v - b[i]);
const scale = (a, s) => a.map((v) => v * s);
const dot = (a, b) => a.reduce((sum, v, i) => sum + v * b[i], 0);
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const normalize = (a) => scale(a, 1 / Math.hypot(...a));

// Rodrigues: v rotated by `angle` about the unit axis.
function rotate(v, axis, angle) {
  const c = Math.cos(angle), s = Math.sin(angle);
  return add(add(scale(v, c), scale(cross(axis, v), s)), scale(axis, dot(axis, v) * (1 - c)));
}

export class PreviewView {
  // documentOf(): the document shown; onChange(interactive): the view
  // changed, interactive while dragging.
  constructor(element, { documentOf, onChange }) {
    this.element = element;
    this.documentOf = documentOf;
    this.onChange = onChange;
    this.domain = null;  // texture: {min, max}, or null for the document's
    this.camera = null;  // surface, volume: {position, target, up, fov, orthographic?}, or null
    this.listen();
  }

  get doc() { return this.documentOf(); }

  // A new document: its own framing, with no change to tell.
  clear() {
    this.domain = null;
    this.camera = null;
  }

  get texture() { return this.doc && this.doc.kind === "texture"; }
  get navigable() {
    // A surface graph's scene has objects; without a scene there is no
    // camera to move (the server's default one is not in the document).
    return Boolean(this.doc && (this.texture || this.doc.kind === "volume" || this.doc.render?.scene));
  }
  get changed() { return this.domain !== null || this.camera !== null; }

  reset() {
    if (!this.changed) return;
    this.domain = null;
    this.camera = null;
    this.onChange(false);
  }

  // `doc` (a copy made for one request) with the view's domain or camera.
  apply(doc) {
    if (!this.changed) return doc;
    const result = structuredClone(doc);
    result.render = result.render || {};
    if (this.domain) result.render.domain = structuredClone(this.domain);
    if (this.camera) {
      result.render.scene = result.render.scene || {};
      result.render.scene.camera = structuredClone(this.camera);
    }
    return result;
  }

  currentDomain() {
    return structuredClone(this.domain || this.doc.render?.domain || defaultDomain);
  }

  currentCamera() {
    return { ...structuredClone(defaultCamera), ...structuredClone(this.camera || this.doc.render?.scene?.camera || {}) };
  }

  listen() {
    this.element.addEventListener("wheel", (event) => {
      if (!this.navigable) return;
      event.preventDefault();
      // A wheel notch (deltaY 100) moves the camera 5% of its distance.
      const factor = Math.exp(event.deltaY * 0.0005);
      if (this.texture) this.zoomDomain(factor, this.unitPoint(event));
      else this.dolly(factor);
      this.onChange(true);
    }, { passive: false });
    let last = null;
    this.element.addEventListener("pointerdown", (event) => {
      if (!this.navigable || event.button !== 0) return;
      last = [event.clientX, event.clientY];
      this.element.setPointerCapture(event.pointerId);
    });
    this.element.addEventListener("pointermove", (event) => {
      if (!last) return;
      const box = this.element.getBoundingClientRect();
      const dx = (event.clientX - last[0]) / box.width, dy = (event.clientY - last[1]) / box.height;
      last = [event.clientX, event.clientY];
      if (this.texture) this.panDomain(dx, dy);
      else if (event.shiftKey) this.panCamera(dx, dy);
      else this.orbit(dx, dy);
      this.onChange(true);
    });
    const release = () => {
      if (!last) return;
      last = null;
      this.onChange(false);
    };
    this.element.addEventListener("pointerup", release);
    this.element.addEventListener("pointercancel", release);
    this.element.addEventListener("dblclick", () => this.reset());
  }

  // The pointer in [0,1]^2 over the preview, y up (the domain's way).
  unitPoint(event) {
    const box = this.element.getBoundingClientRect();
    return [(event.clientX - box.left) / box.width, 1 - (event.clientY - box.top) / box.height];
  }

  // Zoom about the point under the pointer, which stays where it is.
  zoomDomain(factor, [u, v]) {
    const { min, max } = this.currentDomain();
    const pivot = [min[0] + (max[0] - min[0]) * u, min[1] + (max[1] - min[1]) * v];
    this.domain = { min: add(pivot, scale(sub(min, pivot), factor)), max: add(pivot, scale(sub(max, pivot), factor)) };
  }

  panDomain(dx, dy) {
    const { min, max } = this.currentDomain();
    const shift = [-dx * (max[0] - min[0]), dy * (max[1] - min[1])];
    this.domain = { min: add(min, shift), max: add(max, shift) };
  }

  // Turn the camera about its target: left-right about its up axis (half
  // a turn across the preview's width), up-down about its right axis (a
  // quarter turn across its height), stopping short of looking along up.
  orbit(dx, dy) {
    const camera = this.currentCamera();
    const up = normalize(camera.up);
    let offset = rotate(sub(camera.position, camera.target), up, -dx * Math.PI);
    const right = normalize(cross(up, offset));
    const pitched = rotate(offset, right, -dy * Math.PI / 2);
    if (Math.abs(dot(normalize(pitched), up)) < 0.995) offset = pitched;
    camera.position = add(camera.target, offset);
    this.camera = camera;
  }

  dolly(factor) {
    const camera = this.currentCamera();
    if (typeof camera.orthographic === "number") camera.orthographic *= factor;
    else camera.position = add(camera.target, scale(sub(camera.position, camera.target), factor));
    this.camera = camera;
  }

  // Move position and target together across the view, by as much as the
  // pointer moved over the image at the target's distance.
  panCamera(dx, dy) {
    const camera = this.currentCamera();
    const offset = sub(camera.position, camera.target);
    const right = normalize(cross(camera.up, offset));
    const up = normalize(cross(offset, right));
    const span = typeof camera.orthographic === "number" ? camera.orthographic
      : 2 * Math.hypot(...offset) * Math.tan((camera.fov * Math.PI) / 360);
    const shift = add(scale(right, -dx * span), scale(up, dy * span));
    camera.position = add(camera.position, shift);
    camera.target = add(camera.target, shift);
    this.camera = camera;
  }
}
