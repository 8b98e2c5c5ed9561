// Value fields for the inputs of a node that no wire feeds, in the node
// panel: the constant the file gives the input ("radius": 1.05), or an
// empty field whose placeholder is the op's default, which an emptied
// field goes back to. Numbers (a whole one for an int), a checkbox for a
// bool, a colour picker, a field per component of a vector. Edits write
// the node's "in" and call onEdit(interactive) as param edits do, so they
// are undone and previewed the same way; a constant is part of the
// program, so unlike a param's value it is compiled anew.
import { element, hexOf, rgbOf } from "./dom.js";
import { paramTypes } from "./params_panel.js";

const components = { vec2: 2, vec3: 3, color: 3 };

function setConstant(node, name, value) {
  if (value !== undefined) {
    node.in ??= {};
    node.in[name] = value;
    return;
  }
  if (node.in) delete node.in[name];
  if (node.in && Object.keys(node.in).length === 0) delete node.in;
}

const numberOrNull = (field) => (field.value !== "" && Number.isFinite(Number(field.value)) ? Number(field.value) : null);

// The fields of one input; changed(value, interactive) with the new
// constant, or undefined for none (the default).
function fieldsOf(id, input, value, changed) {
  const name = `${id}.${input.name}`;
  const fallback = input.default;
  const count = components[input.type] ?? (Array.isArray(value) ? value.length : 1);
  if (input.type === "bool") {
    const box = element("input", { type: "checkbox", name, checked: Boolean(value ?? fallback) });
    box.addEventListener("change", () => changed(box.checked, false));
    return [box];
  }
  if (input.type === "color") {
    const picker = element("input", { type: "color", name, value: hexOf(value ?? Array(3).fill(fallback ?? 0)) });
    picker.addEventListener("input", () => changed(rgbOf(picker.value), true));
    picker.addEventListener("change", () => changed(rgbOf(picker.value), false));
    return [picker];
  }
  const integral = input.type === "int";
  const fields = Array.from({ length: count }, (_, i) => {
    const shown = count === 1 ? value : value?.[i];
    const placeholder = Array.isArray(fallback) ? fallback[i] : fallback;
    return element("input", { type: "number", step: integral ? "1" : "any", name: count === 1 ? name : `${name}.${i}`,
                              value: shown ?? "", placeholder: placeholder ?? "", title: `${input.name}: ${input.type}` });
  });
  // Every field a number, or every field empty (the default); else the
  // typing is not done yet.
  const read = (interactive) => {
    const numbers = fields.map(numberOrNull);
    if (fields.every((field) => field.value === "")) changed(undefined, interactive);
    else if (numbers.every((n) => n !== null && (!integral || Number.isInteger(n))))
      changed(count === 1 ? numbers[0] : numbers, interactive);
  };
  for (const field of fields) {
    field.addEventListener("input", () => read(true));
    field.addEventListener("change", () => read(false));
  }
  return fields;
}

// The rows for `node`'s unwired inputs ([{name, type, default, doc}]);
// wired(name) says whether a wire feeds the input; onConstant(name, value)
// after node.in changed, then onEdit(interactive); onPromote(input), if
// given, behind each row's "$" button.
export function inputValueRows(node, inputs, { wired, onConstant, onEdit, onPromote }) {
  return inputs
    .filter((input) => !wired(input.name) && typeof node.in?.[input.name] !== "string")
    .map((input) => {
      const row = element("label", { className: "inline", title: input.doc ?? "" }, [
        `${input.name} `,
        ...fieldsOf(node.id, input, node.in?.[input.name], (value, interactive) => {
          setConstant(node, input.name, value);
          onConstant(input.name, value);
          onEdit(interactive);
        }),
      ]);
      if (onPromote && promotedType(input.type, node.in?.[input.name] ?? input.default)) {
        const promote = element("button", { type: "button", textContent: "$", name: `promote ${node.id}.${input.name}`,
                                             title: "promote to a param: the input reads a new param of this value, " +
                                                    "which the Params panel edits without a compile" });
        promote.addEventListener("click", (event) => {
          event.preventDefault();
          onPromote(input);
        });
        row.append(promote);
      }
      return row;
    });
}

// The param type an input of `type` holding `value` is promoted to (a
// generic T from the value's shape), or null for one no param can feed.
export function promotedType(type, value) {
  if (paramTypes.includes(type)) return type;
  if (type !== "T") return null;
  if (typeof value === "number" || value === undefined) return "float";
  return Array.isArray(value) && value.length === 2 ? "vec2" : Array.isArray(value) && value.length === 3 ? "vec3" : null;
}
