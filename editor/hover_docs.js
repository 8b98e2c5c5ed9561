// Hover docs on the canvas: resting the pointer on a node, an input or an
// output shows what the op table (/api/nodes) or the document says of it,
// by the pointer. Text only: a function's doc is the user's own text.

// How long the pointer rests before the doc shows, as a desktop tooltip.
const restMilliseconds = 350;

// docAt(event): {title, text} of what lies under the pointer, or null.
export function installHoverDocs(canvasElement, tooltip, docAt) {
  let timer = null;
  const hide = () => {
    clearTimeout(timer);
    tooltip.hidden = true;
  };
  const show = (event) => {
    const doc = docAt(event);
    if (!doc) return;
    tooltip.querySelector("strong").textContent = doc.title;
    tooltip.querySelector("span").textContent = doc.text;
    tooltip.hidden = false;
    // Below and right of the pointer, kept inside the window.
    const margin = 12, box = tooltip.getBoundingClientRect();
    tooltip.style.left = `${Math.max(0, Math.min(event.clientX + margin, innerWidth - box.width - 4))}px`;
    tooltip.style.top = `${event.clientY + margin + box.height > innerHeight ? event.clientY - margin - box.height : event.clientY + margin}px`;
  };
  canvasElement.addEventListener("pointermove", (event) => {
    hide();
    if (event.buttons === 0) timer = setTimeout(() => show(event), restMilliseconds);
  });
  for (const type of ["pointerdown", "pointerleave", "wheel", "keydown"]) canvasElement.addEventListener(type, hide);
}
