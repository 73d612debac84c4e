// The style menu and parameter panel of <inkwire-scene>, built from the module's own style list
// (what `inkwire-render --style list` prints: names, ranges, defaults), so every parameter the
// native client has is here. A change calls back with the style and every setting that differs
// from its default; styles this build cannot draw are listed, disabled, with why.
export class ScenePanel {
  constructor(root, changed) {
    this.root = root;
    this.changed = changed;
  }

  // The server refuses this member style changes (it said so on joining): every control off and
  // `reason` shown above them; null turns them on again.
  lock(reason) {
    this.locked = reason;
    this.applyLock();
  }

  applyLock() {
    if (!this.menu) return;
    for (const control of this.root.querySelectorAll('select, input')) control.disabled = Boolean(this.locked) || 'file' in control.dataset;
    this.lockNote.textContent = this.locked ?? '';
    this.lockNote.hidden = !this.locked;
  }

  setStyles(list, paramsOf) {
    this.paramsOf = paramsOf;
    this.root.innerHTML = '';
    this.lockNote = document.createElement('div');
    this.lockNote.className = 'note';
    this.lockNote.setAttribute('part', 'locked');
    this.root.append(this.lockNote);
    this.menu = document.createElement('select');
    this.menu.setAttribute('aria-label', 'Style');
    for (const style of list.styles) {
      const option = new Option(style.name, style.name);
      option.title = style.summary;
      this.menu.add(option);
    }
    this.menu.addEventListener('change', () => this.changed(this.menu.value, {}));
    this.root.append(this.menu);
    this.fields = document.createElement('div');
    this.root.append(this.fields);
    this.applyLock();
  }

  // The session's style and settings; the fields are rebuilt only when the style changes, so a
  // slider being dragged keeps its place.
  show(name, settings) {
    if (!this.menu) return;
    this.settings = { ...settings };
    if ([...this.menu.options].some((o) => o.value === name)) this.menu.value = name;
    const params = this.paramsOf(name);
    if (params.error) {
      this.fields.textContent = params.error;
      return;
    }
    if (this.shown !== name) {
      this.shown = name;
      this.fields.innerHTML = '';
      this.inputs = new Map();
      for (const p of params) this.fields.append(this.field(p));
      this.applyLock();
    }
    for (const p of params) {
      const input = this.inputs.get(p.name);
      const value = this.settings[p.name] ?? p.default;
      if (input.type === 'checkbox') input.checked = ['1', 'true', 'on', 'yes'].includes(value);
      else if (document.activeElement !== input) input.value = value;
    }
  }

  field(p) {
    const label = document.createElement('label');
    label.title = p.help;
    label.append(p.name);
    let input;
    if (p.type === 'choice') {
      input = document.createElement('select');
      for (const c of p.choices) input.add(new Option(c, c));
    } else {
      input = document.createElement('input');
      if (p.type === 'float' || p.type === 'int') {
        input.type = 'range';
        input.min = p.min;
        input.max = p.max;
        input.step = p.type === 'int' ? 1 : (p.max - p.min) / 200;
      } else if (p.type === 'bool') {
        input.type = 'checkbox';
      } else if (p.type === 'colour') {
        input.type = 'color';
      } else {
        input.type = 'text';
        input.size = 10;
        if (p.file) {
          // A file on the machine that draws (a shade map, a painting style): a browser cannot
          // read it. Shown, not editable; a native client can set it.
          input.dataset.file = '';
          input.disabled = true;
          label.title = `${p.help} (a file: set it from the native client)`;
        }
      }
    }
    input.name = p.name;
    input.addEventListener(input.type === 'text' ? 'change' : 'input', () => {
      const value = input.type === 'checkbox' ? String(input.checked) : input.value;
      this.settings[p.name] = value;
      this.changed(this.menu.value, this.settings);
    });
    this.inputs.set(p.name, input);
    label.append(input);
    return label;
  }
}
