// What every part of the page needs to know about this page load: its
// address (the base of the links it makes), whether it is embedded in a
// lesson (`embed=1`), the hooks of the end-to-end tests and the time budgets
// of the interpreter's worker (modules/supervisor.js).

/** The page's address without the fragment: the base of the links it makes. */
export const base = location.href.split('#')[0];

/** Embed mode (`embed=1` in the link): known before the link is decoded, so the page never flashes the full layout. */
export const EMBED = /(?:^#|&)embed=(?:1|true)(?:&|$)/.test(location.hash);

/**
 * Hooks of the end-to-end tests, set by an init script before the page loads
 * (never by a link or a document): `{ budgetMs, startupMs, progressAfterMs, hooks }`; `hooks`
 * lets a program ask the worker for a test fault (see worker.js fault()).
 * Only a plain object counts (an element with that id is not one).
 */
export const TEST = Object.getPrototypeOf(window.offsetlabTest ?? 0) === Object.prototype ? window.offsetlabTest : null;
const positive = (v) => (Number.isFinite(v) && v > 0 ? v : null);
const nonNegative = (v) => (Number.isFinite(v) && v >= 0 ? v : null);

/**
 * The time budget of one task the page waits for (a run, a link, an
 * export). The core stops every run at 5,000,000 blocks or moves, so every
 * run is bounded; the budget leaves a slow machine ten times what the
 * longest such run takes on the project's 2-core machine (the slowest file
 * of tests/data/hostile, which the hostile corpus test opens); past it the
 * task is stopped as a runaway.
 */
export const BUDGET_MS = positive(TEST?.budgetMs) ?? 30_000;
/** The worker must have loaded the core within this. */
export const STARTUP_MS = positive(TEST?.startupMs) ?? 60_000;
/**
 * A run longer than this shows its progress in the summary line. The tests
 * may show it from the start (0): how long a program runs depends on the
 * machine, and on a quick one a program the tests can afford ends sooner.
 */
export const PROGRESS_AFTER_MS = nonNegative(TEST?.progressAfterMs) ?? 200;
