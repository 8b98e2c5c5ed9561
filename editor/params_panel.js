// The side panel's params (graph/parse.cpp): a control per param for its
// default (a slider and a field for float and int, logarithmic over a wide
// positive range; a checkbox for bool; a colour picker; number fields for
// vec2 and vec3), a ⚙ toggle per param revealing its name, type, range,
// doc and a delete button, and a row to add a param. Value edits write into the
// document's params and call onEdit(interactive), interactive while a drag
// or typing goes on, so they reach the uniform block only. Adding,
// renaming and deleting change the main graph's sources: they go through
// onRestructure(change), which applies change(doc) to the whole document.

import { element, hexOf, rgbOf } from "./dom.js";

export const paramTypes = ["float", "int", "bool", "color", "vec2", "vec3"];
// What a param added in the panel starts with.
export const newParams = {
  float: { type: "float", default: 0.5, min: 0, max: 1 },
  int: { type: "int", default: 1, min: 0, max: 10 },
  bool: { type: "bool", default: false },
  color: { type: "color", default: [0.5, 0.5, 0.5] },
  vec2: { type: "vec2", default: [0, 0] },
  vec3: { type: "vec3", default: [0, 0, 0] },
};
// A positive range this wide (max / min) gets a logarithmic slider.
const logarithmicRatio = 1000;
const logSteps = 1000;
export const namePattern = /^[A-Za-z_][A-Za-z0-9_]*$/;

const headingOf = (name, param) => name + (param.doc ? ` — ${param.doc}` : "");
const ranged = (param) => param.type !== "bool";  // min and max bound each component

// The nodes (and outputs) of a body that read "$name": the main graph's
// for a param (function bodies' "$name" are their own inputs), a
// function's for one of its inputs.
export function paramUsers(doc, name) {
  const reference = `$${name}`;
  const users = (doc.nodes || []).filter((node) => Object.values(node.in || {}).includes(reference)).map((node) => node.id);
  for (const [output, value] of Object.entries(doc.outputs || {})) if (value === reference) users.push(`output ${output}`);
  return users;
}

// Renames param `from` in place, keeping its place in the file, and every
// main-graph reference to it.
export function renameParam(doc, from, to) {
  doc.params = Object.fromEntries(Object.entries(doc.params).map(([name, spec]) => [name === from ? to : name, spec]));
  const rewrite = (values) => {
    for (const [key, value] of Object.entries(values || {})) if (value === `$${from}`) values[key] = `$${to}`;
  };
  for (const node of doc.nodes || []) rewrite(node.in);
  rewrite(doc.outputs);
}

// `param` retyped as `to`: its default converted (a vector's first
// component for a scalar, a scalar repeated for a vector, a bool as 0 or
// 1 and back), its range kept where the new type has one.
export function retypeParam(param, to) {
  const values = (Array.isArray(param.default) ? param.default : [param.default]).map(Number);
  const components = { vec2: 2, vec3: 3, color: 3 }[to] ?? 1;
  param.type = to;
  if (to === "bool") {
    param.default = values[0] !== 0;
    delete param.min;
    delete param.max;
  } else if (components === 1) {
    param.default = to === "int" ? Math.round(values[0]) : values[0];
    for (const key of ["min", "max"]) if (to === "int" && param[key] !== undefined) param[key] = Math.round(param[key]);
  } else {
    param.default = Array.from({ length: components }, (_, i) => values[Math.min(i, values.length - 1)]);
  }
}

// The slider of a float or int param: its own min and max, or positions
// 0..logSteps on a logarithmic scale.
function sliderScale(param) {
  const lo = param.min ?? 0;
  const hi = param.max ?? Math.max(1, Number(param.default) * 4);
  const round = (v) => (param.type === "int" ? Math.round(v) : Number(v.toPrecision(4)));
  if (lo > 0 && hi / lo >= logarithmicRatio) {
    return { min: 0, max: logSteps, step: 1, logarithmic: true,
             toValue: (position) => round(lo * (hi / lo) ** (position / logSteps)),
             toPosition: (value) => (Math.log(value / lo) / Math.log(hi / lo)) * logSteps };
  }
  return { min: lo, max: hi, step: param.type === "int" ? 1 : (hi - lo) / 1000, logarithmic: false,
           toValue: (position) => (param.type === "int" ? Math.round(position) : position),
           toPosition: (value) => value };
}

export class ParamsPanel {
  // state: the editor's {doc, scope}; documentOf(): the document with the
  // canvas's wires, to find a param's users; onEdit(interactive): a value
  // changed; onRestructure(change): apply change(doc) and show the panel again.
  constructor(host, { state, documentOf, onEdit, onRestructure }) {
    this.host = host;
    this.state = state;
    this.documentOf = documentOf;
    this.onEdit = onEdit;
    this.onRestructure = onRestructure;
    this.opened = new Set();  // names of the params whose settings are shown
  }

  show() {
    const params = this.state.doc.params || {};
    this.host.replaceChildren(...Object.entries(params).map(([name, param]) => this.row(name, param)), this.adder());
  }

  row(name, param) {
    const label = element("span", { className: "param-name", textContent: headingOf(name, param) });
    const toggle = element("button", { className: "param-toggle", textContent: "⚙", title: `edit param ${name}` });
    const control = element("div", { className: "param-control" }, this.controls(name, param));
    const settings = this.settings(name, param, () => {
      label.textContent = headingOf(name, param);
      control.replaceChildren(...this.controls(name, param));
    });
    settings.hidden = !this.opened.has(name);
    toggle.addEventListener("click", () => {
      settings.hidden = !settings.hidden;
      if (settings.hidden) this.opened.delete(name);
      else this.opened.add(name);
    });
    return element("div", { className: "param" }, [element("div", { className: "param-head" }, [label, toggle]), control, settings]);
  }

  // The controls of a param's default.
  controls(name, param) {
    const edit = (interactive) => this.onEdit(interactive);
    if (param.type === "float" || param.type === "int") {
      const scale = sliderScale(param);
      const slider = element("input", { type: "range", name, min: scale.min, max: scale.max, step: scale.step,
                                        title: `${param.min ?? scale.min} to ${param.max ?? scale.max}` +
                                               (scale.logarithmic ? ", logarithmic" : "") });
      slider.value = scale.toPosition(Number(param.default));
      const field = element("input", { type: "number", className: "param-value", step: param.type === "int" ? "1" : "any",
                                       value: String(param.default), title: `${name}: exact value` });
      slider.addEventListener("input", () => {
        param.default = scale.toValue(Number(slider.value));
        field.value = String(param.default);
        edit(true);
      });
      field.addEventListener("input", () => {
        const value = Number(field.value);
        if (field.value === "" || !Number.isFinite(value) || (param.type === "int" && !Number.isInteger(value))) return;
        param.default = value;
        slider.value = scale.toPosition(value);
        edit(true);
      });
      for (const input of [slider, field]) input.addEventListener("change", () => edit(false));
      return [slider, field];
    }
    if (param.type === "bool") {
      const box = element("input", { type: "checkbox", name, checked: Boolean(param.default) });
      box.addEventListener("change", () => {
        param.default = box.checked;
        edit(false);
      });
      return [box];
    }
    if (param.type === "color") {
      const picker = element("input", { type: "color", name, value: hexOf(param.default) });
      picker.addEventListener("input", () => {
        param.default = rgbOf(picker.value);
        edit(true);
      });
      picker.addEventListener("change", () => edit(false));
      return [picker];
    }
    return param.default.map((value, component) => {
      const field = element("input", { type: "number", step: "any", name: `${name}.${component}`, value: String(value),
                                       title: `${name}, component ${component}` });
      field.addEventListener("input", () => {
        if (field.value === "" || !Number.isFinite(Number(field.value))) return;
        param.default[component] = Number(field.value);
        edit(true);
      });
      field.addEventListener("change", () => edit(false));
      return field;
    });
  }

  // Name, type, min, max, doc and delete; `changed()` redraws the row's label
  // and controls after a range or doc edit.
  settings(name, param, changed) {
    const message = element("p", { className: "param-message" });
    const rename = element("input", { name: `${name}.name`, value: name, size: 10,
                                      title: "rename: rewrites the main graph's references" });
    rename.addEventListener("change", () => {
      const to = rename.value.trim();
      if (to === name) return;
      const why = this.invalidName(to);
      if (why) {
        message.textContent = why;
        rename.value = name;
        return;
      }
      this.opened.delete(name);
      this.opened.add(to);
      this.onRestructure((doc) => renameParam(doc, name, to));
    });
    const type = element("select", { name: `${name}.type`, title: "retype: the nodes reading it are checked anew" },
                         paramTypes.map((t) => new Option(t, t, false, t === param.type)));
    type.addEventListener("change", () => this.onRestructure((doc) => retypeParam(doc.params[name], type.value)));
    const fields = [element("label", {}, ["name ", rename]), element("label", {}, ["type ", type])];
    if (ranged(param)) {
      const bound = (key) => {
        const field = element("input", { type: "number", step: "any", name: `${name}.${key}`, value: param[key] ?? "",
                                         placeholder: "none" });
        field.addEventListener("change", () => {
          const value = Number(field.value);
          if (field.value !== "" && !Number.isFinite(value)) return;
          // A range must stay a range: min above max is refused here, as the checker would.
          const [min, max] = key === "min" ? [value, param.max] : [param.min, value];
          if (field.value !== "" && min !== undefined && max !== undefined && min > max) {
            message.textContent = `min (${min}) must not be above max (${max})`;
            field.value = param[key] ?? "";
            return;
          }
          message.textContent = "";
          if (field.value === "") delete param[key];
          else param[key] = value;
          this.clampDefault(param);
          changed();
          this.onEdit(false);
        });
        return element("label", {}, [`${key} `, field]);
      };
      fields.push(bound("min"), bound("max"));
    }
    const doc = element("input", { name: `${name}.doc`, value: param.doc ?? "", placeholder: "what it does", size: 24 });
    doc.addEventListener("input", () => {
      if (doc.value === "") delete param.doc;
      else param.doc = doc.value;
      changed();
      this.onEdit(true);
    });
    doc.addEventListener("change", () => this.onEdit(false));
    const remove = element("button", { textContent: "Delete", title: `delete param ${name}` });
    remove.addEventListener("click", () => {
      const users = paramUsers(this.documentOf(), name);
      if (users.length > 0) {
        message.textContent = `"${name}" is used by ${users.join(", ")}: rewire ${users.length > 1 ? "them" : "it"} first`;
        return;
      }
      this.opened.delete(name);
      this.onRestructure((doc) => delete doc.params[name]);
    });
    fields.push(element("label", {}, ["doc ", doc]), remove, message);
    return element("div", { className: "param-settings" }, fields);
  }

  // A new range keeps the default inside it, as its slider shows it (an
  // int's among the integers of the range).
  clampDefault(param) {
    if (param.min !== undefined && param.max !== undefined && param.min > param.max) return;
    const integral = param.type === "int";
    const lo = integral ? Math.ceil(param.min ?? -Infinity) : param.min ?? -Infinity;
    const hi = integral ? Math.floor(param.max ?? Infinity) : param.max ?? Infinity;
    const clamp = (v) => Math.min(hi, Math.max(lo, v));
    param.default = Array.isArray(param.default) ? param.default.map(clamp) : clamp(param.default);
  }

  invalidName(name) {
    if (!namePattern.test(name)) return `"${name}": a name is letters, digits and _, not starting with a digit`;
    if (Object.hasOwn(this.state.doc.params || {}, name)) return `there is a param "${name}" already`;
    return null;
  }

  adder() {
    const name = element("input", { name: "new-param-name", placeholder: "new param", size: 12 });
    const type = element("select", { name: "new-param-type" }, paramTypes.map((t) => new Option(t, t)));
    const add = element("button", { textContent: "Add param" });
    const message = element("p", { className: "param-message" });
    add.addEventListener("click", () => {
      const why = this.invalidName(name.value.trim());
      if (why) {
        message.textContent = why;
        return;
      }
      this.onRestructure((doc) => {
        doc.params = { ...doc.params, [name.value.trim()]: structuredClone(newParams[type.value]) };
      });
    });
    return element("div", { className: "param-adder" }, [name, type, add, message]);
  }
}
