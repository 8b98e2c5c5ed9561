// Undo and redo over snapshots of the document and of its nodes' places
// on the canvas ({text, layout, scope}). A burst of edits becomes one
// step: a snapshot is taken only once the edits have been quiet for a
// moment (a slider or control-point drag), or at the end of the current
// task (a wire replaced: one removed, one added; a node moved), or when
// undo/redo needs it now.
export class History {
  constructor({ limit = 200, quietMs = 400, onChange = () => {} } = {}) {
    this.limit = limit;
    this.quietMs = quietMs;
    this.onChange = onChange;
    this.steps = [];
    this.index = -1;
    this.take = null;
  }

  // A new document: its only step is `snapshot`.
  reset(snapshot) {
    clearTimeout(this.timer);
    this.take = null;
    this.steps = [snapshot];
    this.index = 0;
    this.onChange();
  }

  // An edit happened: `take()` makes its snapshot once edits are quiet;
  // a drag's edits are quiet after quietMs, others right after this task.
  touch(take, { dragging = false } = {}) {
    clearTimeout(this.timer);
    this.take = take;
    this.timer = setTimeout(() => this.flush(), dragging ? this.quietMs : 0);
  }

  flush() {
    clearTimeout(this.timer);
    const take = this.take;
    this.take = null;
    if (take) this.record(take());
  }

  // Edits that end where they started (a drag and back) are no step.
  record(snapshot) {
    const last = this.steps[this.index];
    if (last && last.text === snapshot.text && last.layout === snapshot.layout) return;
    this.steps.splice(this.index + 1);
    this.steps.push(snapshot);
    if (this.steps.length > this.limit) this.steps.shift();
    this.index = this.steps.length - 1;
    this.onChange();
  }

  get canUndo() { return this.index > 0 || this.take !== null; }
  get canRedo() { return this.index < this.steps.length - 1; }

  // Each returns the snapshot to show, and the scope the step was edited
  // in (where the user expects to see it undone), or null.
  undo() {
    this.flush();
    if (this.index <= 0) return null;
    const undone = this.steps[this.index];
    this.index -= 1;
    this.onChange();
    return { snapshot: this.steps[this.index], scope: undone.scope };
  }

  redo() {
    this.flush();
    if (this.index >= this.steps.length - 1) return null;
    this.index += 1;
    this.onChange();
    const redone = this.steps[this.index];
    return { snapshot: redone, scope: redone.scope };
  }
}
