// The page's banners: one for messages (a link, an example or a file
// opened with a way back, a broken link, the worker stopped) and one of its
// own for storage problems, so that no other message can hide that the
// work is not being saved. Text only.

const $ = (id) => document.getElementById(id);

/**
 * Shows `message` in the banner as a message of `kind`, with an optional
 * action button; no message hides the banner if it shows a message of that kind.
 */
export function showBanner(message, { kind, action, onAction } = {}) {
  const banner = $('banner');
  if (!message) {
    if (banner.dataset.kind === kind) banner.hidden = true;
    return;
  }
  banner.dataset.kind = kind;
  banner.querySelector('.text').textContent = message;
  const button = $('banner-action');
  button.hidden = !action;
  button.textContent = action ?? '';
  button.onclick = onAction ?? null;
  banner.hidden = false;
}

/** Storage problems have their own banner: no other message may hide that the work is not saved. */
export function showStorageProblem(message) {
  const banner = $('storage-banner');
  banner.querySelector('.text').textContent = message ?? '';
  banner.hidden = !message;
}

export function initBanners() {
  $('banner-close').addEventListener('click', () => {
    $('banner').hidden = true;
  });
  $('storage-banner-close').addEventListener('click', () => {
    $('storage-banner').hidden = true;
  });
}
