// Small helpers of the side panel's controls.

export function element(tag, properties = {}, children = []) {
  const result = Object.assign(document.createElement(tag), properties);
  result.append(...children);
  return result;
}

// Colours as <input type="color"> holds them ("#rrggbb") and as graph files
// do ([r, g, b] in [0, 1]; 4 decimals at most, so that files stay readable).
const clampUnit = (v) => Math.min(1, Math.max(0, v));
export const hexOf = (rgb) => "#" + rgb.map((v) => Math.round(clampUnit(v) * 255).toString(16).padStart(2, "0")).join("");
export const rgbOf = (hex) => [1, 3, 5].map((i) => Math.round((parseInt(hex.slice(i, i + 2), 16) / 255) * 1e4) / 1e4);
