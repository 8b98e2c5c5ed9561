// The preview's size: its long side follows the width of the panel it
// sits in (the splitter left of the panel), its shape the export's width
// and height, so that the preview frames what Export renders.
export const defaultPreviewSide = 256;
export const smallestPreviewSide = 128;
export const largestPreviewSide = 1024;
// The panel's width at the default side: the preview, its padding and room
// for the panel's scroll bar.
export const defaultPanelWidth = 320;

// [width, height] of a picture whose long side is `side` and whose shape
// is width:height; a shape that is not two positive numbers is square.
export function shapedDims(side, width, height) {
  if (!(width > 0 && height > 0)) return [side, side];
  const long = Math.max(width, height);
  return [Math.max(1, Math.round((side * width) / long)), Math.max(1, Math.round((side * height) / long))];
}

// `side` within the bounds, or the default where it is not a number.
export function boundedSide(side) {
  if (!Number.isFinite(side)) return defaultPreviewSide;
  return Math.min(Math.max(Math.round(side), smallestPreviewSide), largestPreviewSide);
}

// The preview's long side for a panel `panelWidth` pixels wide.
export const sideForPanel = (panelWidth) => boundedSide(defaultPreviewSide + panelWidth - defaultPanelWidth);

// The panel's width that shows a preview of long side `side`.
export const panelForSide = (side) => side - defaultPreviewSide + defaultPanelWidth;
