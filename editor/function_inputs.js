// The inputs of the function shown on the canvas, beside its signature:
// each input's type (a select) and a delete button, refused while the body
// reads the input, and a row to add one. A new input has a default (the
// same as a new param's), so that every call stays valid; a deleted input
// leaves every call's "in". Changes go through onRestructure(change),
// which applies change(doc) to the whole document.
import { element } from "./dom.js";
import { namePattern, newParams, paramTypes, paramUsers, retypeParam } from "./params_panel.js";

const typeOf = (spec) => (typeof spec === "string" ? spec : spec.type);

// Every node that calls function `name`, in the main graph and in functions.
function callsOf(doc, name) {
  const bodies = [doc, ...Object.values(doc.functions || {})];
  return bodies.flatMap((body) => (body.nodes || []).filter((node) => node.op === name));
}

function typeSelect(name, selected, title) {
  const select = element("select", { name, title });
  select.append(...paramTypes.map((type) => new Option(type, type)));
  select.value = selected;
  return select;
}

export class FunctionInputs {
  constructor(host, { documentOf, onRestructure }) {
    this.host = host;
    this.documentOf = documentOf;
    this.onRestructure = onRestructure;
  }

  // Shows function `scope`'s inputs, or nothing for the main graph.
  show(scope) {
    this.host.replaceChildren();
    this.host.hidden = !scope;
    if (!scope) return;
    const inputs = this.documentOf().functions[scope].inputs || {};
    const message = element("span", { className: "input-message" });
    for (const [name, spec] of Object.entries(inputs)) {
      const type = typeSelect(`input ${name}.type`, typeOf(spec), `the type of input ${name}`);
      type.addEventListener("change", () => this.onRestructure((doc) => {
        const declared = doc.functions[scope].inputs;
        if (typeof declared[name] === "string") declared[name] = type.value;
        else retypeParam(declared[name], type.value);
      }));
      const remove = element("button", { textContent: "✕", title: `delete input ${name}` });
      remove.addEventListener("click", () => {
        const users = paramUsers(this.documentOf().functions[scope], name);
        if (users.length) {
          message.textContent = `input ${name} is read by ${users.join(", ")}`;
          return;
        }
        this.onRestructure((doc) => {
          delete doc.functions[scope].inputs[name];
          for (const call of callsOf(doc, scope)) if (call.in) delete call.in[name];
        });
      });
      this.host.append(element("span", { className: "function-input" }, [`${name}: `, type, remove]));
    }
    const newName = element("input", { name: "new input name", placeholder: "new input", size: 8 });
    const newType = typeSelect("new input type", "float", "the new input's type");
    const add = element("button", { textContent: "Add input", title: "add an input (with a default, so calls stay valid)" });
    add.addEventListener("click", () => {
      const name = newName.value.trim();
      if (!namePattern.test(name)) {
        message.textContent = "an input name is a letter or _ then letters, digits or _";
        return;
      }
      if (name in inputs) {
        message.textContent = `${scope} has an input ${name} already`;
        return;
      }
      this.onRestructure((doc) => {
        const fn = doc.functions[scope];
        fn.inputs = { ...(fn.inputs || {}), [name]: { type: newType.value, default: structuredClone(newParams[newType.value].default) } };
      });
    });
    this.host.append(newName, newType, add, message);
  }
}
