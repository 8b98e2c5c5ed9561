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
