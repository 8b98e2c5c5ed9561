// Requests to `shadetree serve` (server/editor_server.h). They carry the
// session token in a header: the server takes the cookie alone for GET
// requests only, since other local pages' requests carry it too; previews,
// checks, exports and saves need the header. So the page needs the token
// in its URL: one opened without it (by the cookie) can only read.
const token = new URLSearchParams(location.search).get("token") || "";

export function api(method, url, body, signal, headers = {}) {
  return fetch(url, { method, body, signal, headers: { ...headers, "X-Shadetree-Token": token } });
}

// The server's one-line JSON error of a refused request, or its status line.
export async function errorOf(response) {
  try {
    return (await response.json()).error || `${response.status} ${response.statusText}`;
  } catch {
    return `${response.status} ${response.statusText}`;
  }
}

// A preview response (W x H RGBA bytes, rows from the top) as ImageData.
export async function imageOf(response) {
  const pixels = new Uint8ClampedArray(await response.arrayBuffer());
  return new ImageData(pixels, Number(response.headers.get("X-Width")), Number(response.headers.get("X-Height")));
}

// A streamed preview's records (stream=1, server/preview_stream.h): calls
// onTile(x, y, ImageData) for each tile as it arrives; resolves at the end
// record, or throws its error, or that the stream was cut before it.
export async function readTiles(response, onTile) {
  const reader = response.body.getReader();
  let bytes = new Uint8Array(0);
  for (;;) {
    while (bytes.length >= 16) {
      const head = new DataView(bytes.buffer, bytes.byteOffset, 16);
      const [x, y, width, height] = [0, 4, 8, 12].map((at) => head.getUint32(at, true));
      const size = width === 0 ? height : width * height * 4;
      if (bytes.length < 16 + size) break;
      const body = bytes.slice(16, 16 + size);
      bytes = bytes.subarray(16 + size);
      if (width === 0) {
        if (size > 0) throw new Error(new TextDecoder().decode(body));
        return;
      }
      onTile(x, y, new ImageData(new Uint8ClampedArray(body.buffer), width, height));
    }
    const { done, value } = await reader.read();
    if (done) throw new Error("the preview's stream ended early");
    const joined = new Uint8Array(bytes.length + value.length);
    joined.set(bytes);
    joined.set(value, bytes.length);
    bytes = joined;
  }
}
