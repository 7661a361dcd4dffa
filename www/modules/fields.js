// The Settings panel's tables of numbers (offsets, tools): each field is
// checked as it is typed, its reason shown beside it and announced, and a
// valid value applied at once; an "Add …" form refuses a bad number the
// same way. One place, so the tables cannot drift apart.

/**
 * A text field checked as it is typed: `check(text)` gives `{ value }` or
 * `{ reason }`; `apply(value)` runs for a valid value. Returns the input
 * and its reason, for the caller to label and place.
 */
export function checkedField({ value, numeric = false, check, apply }) {
  const input = document.createElement('input');
  input.type = 'text';
  input.inputMode = numeric ? 'numeric' : 'decimal';
  input.autocomplete = 'off';
  input.spellcheck = false;
  input.value = String(value);
  const reason = document.createElement('span');
  reason.className = 'reason';
  reason.setAttribute('aria-live', 'polite');
  input.addEventListener('input', () => {
    const checked = check(input.value);
    reason.textContent = checked.reason ?? '';
    if (checked.reason) {
      input.setAttribute('aria-invalid', 'true');
      return;
    }
    input.removeAttribute('aria-invalid');
    apply(checked.value);
  });
  return { input, reason };
}

/**
 * Wires an "Add …" form: its submit calls `add(text)`, which returns a
 * reason to refuse it (shown beside the field) or nothing; typing clears
 * the reason.
 */
export function addForm(form, input, reasonOut, add) {
  form.addEventListener('submit', (event) => {
    event.preventDefault();
    const reason = add(input.value);
    if (reason) {
      reasonOut.textContent = reason;
      input.setAttribute('aria-invalid', 'true');
    }
  });
  input.addEventListener('input', () => {
    reasonOut.textContent = '';
    input.removeAttribute('aria-invalid');
  });
}
