// Requests to `shadetree serve` (server/editor_server.h). They carry the
// session token in a header: the cookie would do too, but not for a page
// opened from a file:// URL in tests.
const token = new URLSearchParams(location.search).get("token") || "";

export function api(method, url, body, signal) {
  return fetch(url, { method, body, signal, headers: { "X-Shadetree-Token": token } });
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
