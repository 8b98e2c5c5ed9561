// Node thumbnails: a small picture, on each node, of what that node
// outputs. They are fetched one at a time after the main preview, so that
// they never delay it; a new edit cancels the round under way. A
// thumbnail is fetched again only when its key (what the node's output
// depends on) has changed.
import { api, imageOf } from "./api.js";

export const thumbnailSide = 64;

export class Thumbnails {
  // onDrawn(cacheKey): a thumbnail arrived.
  constructor({ onDrawn }) {
    this.onDrawn = onDrawn;
    this.cache = new Map();  // "scope/id" -> the entry of its latest thumbnail
    this.round = 0;
    this.controller = null;
    this.pending = 0;
  }

  cancel() {
    this.round += 1;
    this.controller?.abort();
    this.controller = null;
    this.pending = 0;
  }

  // The thumbnail of a node, if one was drawn for that key.
  lookup(cacheKey, key) {
    const entry = this.cache.get(cacheKey);
    return entry && entry.key === key ? entry : null;
  }

  // jobs: [{cacheKey, key, url, body: () => the text to send}], in the
  // order to fetch them (a body is made only for a thumbnail fetched). An
  // entry is {key, image: a canvas} or {key, image: null, note, why}.
  async refresh(jobs) {
    this.cancel();
    const round = this.round;
    const stale = jobs.filter((job) => !this.lookup(job.cacheKey, job.key));
    this.pending = stale.length;
    for (const job of stale) {
      this.controller = new AbortController();
      let entry;
      try {
        const response = await api("POST", job.url, job.body(), this.controller.signal);
        if (round !== this.round) return;
        // 409: superseded by a newer request of this slot, which will draw.
        if (response.status === 409) return;
        // 422: this node's output cannot be pictured; the reason goes to its panel.
        entry = response.ok ? { key: job.key, image: toCanvas(await imageOf(response)) }
                            : { key: job.key, image: null, note: "no preview", why: await reasonOf(response) };
      } catch (error) {
        if (error.name === "AbortError") return;
        throw error;
      }
      if (round !== this.round) return;
      this.cache.set(job.cacheKey, entry);
      this.pending -= 1;
      this.onDrawn(job.cacheKey);
    }
  }
}

async function reasonOf(response) {
  try {
    const body = await response.json();
    return body.diagnostic?.message || body.error || "";
  } catch {
    return `${response.status} ${response.statusText}`;
  }
}

function toCanvas(image) {
  const canvas = document.createElement("canvas");
  canvas.width = image.width;
  canvas.height = image.height;
  canvas.getContext("2d").putImageData(image, 0, 0);
  return canvas;
}
