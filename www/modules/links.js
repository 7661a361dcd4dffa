// Links (issue 5): a link in the fragment — compact `#v1.…` or plain
// `#program=…` — is decoded by the worker (the Rust codec) on load and on
// `hashchange` and opened without destroying the user's own work, which is
// kept one click away (modules/documents.js). A broken link is said in the
// banner, as text, and the work stays as it was. The address bar follows
// the document (modules/address.js) with its compact link; `embed=1` shows
// the drawing, the step controls and a read-only editor only.

import { initAddress, ownFragment, writtenFragment } from './address.js';
import { showBanner } from './banner.js';
import {
  loadDocument, openWork, sameDocument, viewOf, workOf,
} from './documents.js';
import { EMBED, base } from './page.js';
import {
  call, flushRun, isParked, requestRun, setPendingView,
} from './runner.js';
import { currentWork } from './work.js';

/** Programs longer than this are not put in the address bar (their link would be too long to be of use there). */
const ADDRESS_MAX_PROGRAM = 256 * 1024;
/** Links longer than this leave the address bar without a fragment. */
const ADDRESS_MAX_LINK = 32 * 1024;

let editor = null;

/**
 * "Open in playground": the codec's link to this page (never a `javascript:`
 * or other URL a link could smuggle in); anything but an http(s) link of
 * this page's own address falls back to the plain page.
 */
function playgroundHref(link) {
  try {
    const url = new URL(link, base);
    const page = new URL(base);
    if (['http:', 'https:'].includes(url.protocol) && url.origin === page.origin && url.pathname === page.pathname) {
      return url.href;
    }
  } catch {
    // not a URL: the plain page
  }
  return './';
}

/** Says in the banner why a link (or file: `what`) could not be opened. */
export function showLinkError(error, what = 'This link') {
  const kept = EMBED ? '' : ' Your own work is unchanged.';
  showBanner(`${what} could not be opened: ${error.message} (${error.code}).${kept}`, { kind: 'link-error' });
  document.body.dataset.linkError = error.code;
}

/**
 * Opens the link in the fragment. `initial`: on page load (the saved work is
 * in the editor and has not run yet). Resolves when the page shows the result.
 */
export async function openLink(fragment, { initial = false } = {}) {
  document.body.dataset.link = 'opening';
  let answer;
  try {
    answer = await call('decode', { text: fragment, base });
  } catch (error) {
    answer = { error: { code: 'link-internal', message: error.message } };
  }
  if (answer.error) {
    showLinkError(answer.error);
    if (initial) requestRun();
    document.body.dataset.link = 'error';
    return;
  }
  delete document.body.dataset.linkError;
  showBanner(null, { kind: 'link-error' });
  const w = workOf(answer.document);
  if (answer.embed !== EMBED && !initial) {
    // A link of the other mode pasted into this tab: load the page afresh in its mode.
    location.reload();
    return;
  }
  if (EMBED) {
    document.getElementById('open-playground').href = playgroundHref(answer.playground);
    loadDocument(w);
  } else if (await sameDocument(w, currentWork())) {
    // The work shown already (say, a reload of an opened link): only its view and step.
    setPendingView(viewOf(w));
    requestRun();
  } else {
    openWork(w, 'Opened the program of a shared link, with its offsets and settings.');
  }
  document.body.dataset.link = 'opened';
}

/**
 * The current document's compact fragment (no `#`); '' for none (a program
 * too long for the address bar); null to leave the address as it is (the
 * setup is refused).
 */
async function currentFragment() {
  if (isParked()) return null; // not run: the worker has no document to make the link of
  if (editor.length() > ADDRESS_MAX_PROGRAM) return '';
  flushRun();
  const answer = await call('document', { base, forms: ['link'] });
  if (answer.setupFailed) return null;
  if (answer.link.length > ADDRESS_MAX_LINK) return '';
  return answer.link.slice(answer.link.indexOf('#') + 1);
}

/** Links pasted into the address bar open too. */
export function initLinks(theEditor) {
  editor = theEditor;
  addEventListener('hashchange', () => {
    const fragment = location.hash.slice(1);
    if (!fragment || fragment === writtenFragment()) return;
    openLink(fragment);
  });
}

/**
 * Opens the page's first document: the link in the fragment, unless it is
 * the tab's own address (a reload: the autosave, `saved`, is at least as
 * new); then the address bar follows the document.
 */
export async function openFirst(saved) {
  const fragment = location.hash.slice(1);
  const own = ownFragment(fragment) && saved;
  if (fragment && !own) await openLink(fragment, { initial: true });
  else requestRun();
  if (!EMBED) initAddress(currentFragment);
}
