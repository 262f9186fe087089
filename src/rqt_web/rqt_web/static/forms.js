'use strict';
// Forms generated from an interface's fields (GET /api/interface), checked in the page
// before anything is sent: each field's type and range, named in one clear line.

rqt.forms = {};

rqt.forms.build = (fields, prefix = '') => {
  const container = rqt.el('div', {class: 'form'});
  for (const field of fields) {
    const path = prefix + field.name;
    if (field.kind === 'message') {
      const set = rqt.el('fieldset', {}, rqt.el('legend', {text: `${field.name} (${field.type})`}));
      set.append(rqt.forms.build(field.fields, `${path}.`));
      container.append(set);
      continue;
    }
    let input;
    if (field.kind === 'bool') {
      input = rqt.el('input', {type: 'checkbox'});
      input.checked = Boolean(field.default);
    } else {
      const shown = field.kind === 'array' ? JSON.stringify(field.default) : String(field.default ?? '');
      input = rqt.el('input', {type: 'text', value: shown});
    }
    input.dataset.path = path;
    input.dataset.kind = field.kind;
    input.name = path;
    if (field.min !== undefined) input.dataset.min = field.min;
    if (field.max !== undefined) input.dataset.max = field.max;
    if (field.max_length !== undefined) input.dataset.maxLength = field.max_length;
    const range = field.kind === 'int' ? ` [${field.min}, ${field.max}]` : '';
    container.append(rqt.el('label', {class: 'field'},
      rqt.el('span', {text: field.name}), input,
      rqt.el('span', {class: 'type', text: field.type + range})));
  }
  return container;
};

// One field's value from its input, or an Error naming the field and what is allowed.
rqt.forms.read = (input) => {
  const {path, kind} = input.dataset;
  const text = input.value.trim();
  if (kind === 'bool') return input.checked;
  if (kind === 'int') {
    if (!/^[+-]?\d+$/.test(text)) {
      throw new Error(`'${path}' must be an integer in [${input.dataset.min}, ${input.dataset.max}], got ${JSON.stringify(input.value)}`);
    }
    const value = BigInt(text);
    if (value < BigInt(input.dataset.min) || value > BigInt(input.dataset.max)) {
      throw new Error(`'${path}' must be an integer in [${input.dataset.min}, ${input.dataset.max}], got ${text}`);
    }
    return Number(value);
  }
  if (kind === 'float') {
    const value = Number(text);
    if (text === '' || Number.isNaN(value) || !Number.isFinite(value)) {
      throw new Error(`'${path}' must be a finite number, got ${JSON.stringify(input.value)}`);
    }
    if (input.dataset.max !== undefined && Math.abs(value) > Number(input.dataset.max)) {
      throw new Error(`'${path}' must be a float32 in [-${input.dataset.max}, ${input.dataset.max}], got ${text}`);
    }
    return value;
  }
  if (kind === 'array') {
    let value;
    try { value = JSON.parse(text); } catch (error) { value = undefined; }
    if (!Array.isArray(value)) throw new Error(`'${path}' must be a list such as [1, 2], got ${JSON.stringify(input.value)}`);
    return value;
  }
  const limit = input.dataset.maxLength;
  if (limit !== undefined && input.value.length > Number(limit)) {
    throw new Error(`'${path}' can hold at most ${limit} characters, got ${input.value.length}`);
  }
  return input.value;
};

// {values} of the whole form, or {error} for the first bad field (which is marked).
rqt.forms.collect = (container) => {
  const values = {};
  for (const input of container.querySelectorAll('input[data-path]')) input.classList.remove('invalid');
  for (const input of container.querySelectorAll('input[data-path]')) {
    let value;
    try {
      value = rqt.forms.read(input);
    } catch (error) {
      input.classList.add('invalid');
      return {error: error.message};
    }
    const parts = input.dataset.path.split('.');
    let target = values;
    for (const part of parts.slice(0, -1)) target = (target[part] ??= {});
    target[parts.at(-1)] = value;
  }
  return {values};
};

rqt.forms.yaml = (value, indent = '') => {
  if (value === null || typeof value !== 'object') return JSON.stringify(value);
  if (Array.isArray(value)) return JSON.stringify(value);
  return Object.entries(value).map(([key, inner]) => (inner !== null && typeof inner === 'object' && !Array.isArray(inner))
    ? `${indent}${key}:\n${rqt.forms.yaml(inner, indent + '  ')}`
    : `${indent}${key}: ${rqt.forms.yaml(inner)}`).join('\n');
};
