// A graph file's text after an edit of its document, in the file's own
// style: the text as opened with only what changed rewritten, so that key
// order, number spellings ("0.0") and line layout stay, a file saved
// unedited is byte for byte what was opened, and one changed value is a
// one-line diff in a graph kept in git.
//
// The page does this rather than the server: it holds both the text it
// opened and the document it edited, so the server's save stays a plain
// write of the bytes the page shows it will write, and JSON with source
// positions (momoa, the parser of ESLint's JSON support) is at hand in
// JavaScript, where nlohmann::json keeps none.
import { evaluate, parse } from "@humanwhocodes/momoa";
import stringify from "json-stringify-pretty-compact";

// New values are written as the gallery writes nodes: on one line where
// they fit, with a space after ":" and ",".
const lineWidth = 120;

// Equal as JSON values, whatever the order of object keys.
function sameValue(a, b) {
  if (a === b) return true;
  if (typeof a !== "object" || typeof b !== "object" || a === null || b === null) return false;
  if (Array.isArray(a) !== Array.isArray(b)) return false;
  const keys = Object.keys(a);
  if (keys.length !== Object.keys(b).length) return false;
  return keys.every((key) => Object.hasOwn(b, key) && sameValue(a[key], b[key]));
}

// What pairs an old array element with a new one: a node's id, else the
// whole value.
const identity = (value) =>
  value && typeof value === "object" && !Array.isArray(value) && typeof value.id === "string" ? `id ${value.id}` : JSON.stringify(value);

// Old index -> new index of the longest common subsequence of identities.
function matchElements(before, after) {
  const a = before.map(identity), b = after.map(identity);
  const longest = Array.from({ length: a.length + 1 }, () => new Array(b.length + 1).fill(0));
  for (let i = a.length - 1; i >= 0; --i)
    for (let j = b.length - 1; j >= 0; --j)
      longest[i][j] = a[i] === b[j] ? longest[i + 1][j + 1] + 1 : Math.max(longest[i + 1][j], longest[i][j + 1]);
  const matched = new Map();
  for (let i = 0, j = 0; i < a.length && j < b.length;) {
    if (a[i] === b[j]) matched.set(i++, j++);
    else if (longest[i + 1][j] >= longest[i][j + 1]) ++i;
    else ++j;
  }
  return matched;
}

class Writer {
  constructor(text) {
    this.text = text;
    const indented = text.match(/\n([ \t]+)\S/);
    this.indentUnit = indented ? indented[1] : "  ";
  }

  slice(node) { return this.text.slice(node.range[0], node.range[1]); }

  // A new value, its later lines indented from `indentation`.
  fresh(value, indentation) {
    return stringify(value, { indent: this.indentUnit, maxLength: lineWidth - indentation.length })
      .replaceAll("\n", `\n${indentation}`);
  }

  // The indentation of the line `offset` of the text is on.
  indentationAt(offset) {
    return this.text.slice(this.text.lastIndexOf("\n", offset - 1) + 1).match(/^[ \t]*/)[0];
  }

  // `node`'s text for `value`: the old text where the value is the same.
  render(node, value) {
    if (sameValue(evaluate(node), value)) return this.slice(node);
    if (node.type === "Number" && Number.isInteger(value) && Math.abs(value) < 1e15 && /^-?\d+\.0+$/.test(this.slice(node)))
      return `${value}.0`;  // a float written "1.0" stays written as one
    const isObject = value !== null && typeof value === "object" && !Array.isArray(value);
    if (node.type === "Object" && isObject) return this.object(node, value);
    if (node.type === "Array" && Array.isArray(value)) return this.array(node, value);
    return this.fresh(value, this.indentationAt(node.range[0]));
  }

  // Members keep their order; a new key goes after the key the document
  // has before it (so a renamed param keeps its place).
  object(node, value) {
    const items = node.members.filter((member) => Object.hasOwn(value, member.name.value)).map((member) => ({
      key: member.name.value,
      old: node.members.indexOf(member),
      text: this.text.slice(member.range[0], member.value.range[0]) + this.render(member.value, value[member.name.value]),
    }));
    const colon = node.members.length > 0 ? this.text.slice(node.members[0].name.range[1], node.members[0].value.range[0]) : ": ";
    const keys = Object.keys(value);
    keys.forEach((key, index) => {
      if (items.some((item) => item.key === key)) return;
      const before = keys.slice(0, index).findLast((k) => items.some((item) => item.key === k));
      items.splice(items.findIndex((item) => item.key === before) + 1, 0, { key, old: null, text: null });
    });
    return this.container(node, node.members, items,
                          (item, indentation) => `${JSON.stringify(item.key)}${colon}${this.fresh(value[item.key], indentation)}`);
  }

  // Elements are paired by identity; the unpaired ones between two pairs
  // are paired in order, so that a changed element keeps its place.
  array(node, value) {
    const elements = node.elements.map((element) => element.value);
    const matched = matchElements(elements.map(evaluate), value);
    const oldOf = new Map([...matched].map(([i, k]) => [k, i]));
    let next = 0;
    elements.forEach((_, i) => {
      if (matched.has(i)) {
        next = matched.get(i) + 1;
        return;
      }
      const bound = [...matched].find(([later]) => later > i)?.[1] ?? value.length;
      if (next < bound) oldOf.set(next++, i);
    });
    const items = value.map((v, k) => (oldOf.has(k) ? { old: oldOf.get(k), text: this.render(elements[oldOf.get(k)], v) }
                                                    : { old: null, value: v, text: null }));
    return this.container(node, elements, items, (item, indentation) => this.fresh(item.value, indentation));
  }

  // The container's text with `items` (each an old child rendered anew,
  // or new) between its brackets: an old child with the separator that
  // came before it, a new one with the one before the last child (or
  // ", " between brackets on one line).
  container(node, children, items, freshText) {
    const [start, end] = node.range;
    const open = this.text[start], close = this.text[end - 1];
    if (items.length === 0) return open + close;
    const separatorBefore = (i) => this.text.slice(children[i - 1].range[1], children[i].range[0]);
    const opening = children.length > 0 ? this.text.slice(start, children[0].range[0]) : open;
    const closing = children.length > 0 ? this.text.slice(children.at(-1).range[1], end) : close;
    const usual = children.length > 1 ? separatorBefore(children.length - 1)
                : opening.includes("\n") ? `,${opening.slice(1)}` : ", ";
    let text = opening;
    items.forEach((item, k) => {
      if (k > 0) text += item.old > 0 ? separatorBefore(item.old) : usual;
      const indentation = text.includes("\n") ? text.slice(text.lastIndexOf("\n") + 1).match(/^[ \t]*/)[0]
                                              : this.indentationAt(start);
      text += item.text ?? freshText(item, indentation);
    });
    return text + closing;
  }
}

// `text` (a graph file) rewritten to hold `doc`: only what differs is new;
// with no text (a new graph), `doc` written as the gallery writes graphs.
export function documentText(text, doc) {
  // As it will be read back: keys whose value is undefined are not written.
  const value = JSON.parse(JSON.stringify(doc));
  if (text === null) return `${stringify(value, { indent: "  ", maxLength: lineWidth })}\n`;
  const ast = parse(text, { mode: "json", ranges: true });
  return text.slice(0, ast.body.range[0]) + new Writer(text).render(ast.body, value) + text.slice(ast.body.range[1]);
}
