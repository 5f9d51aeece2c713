// Types for scripts/firefox.mjs.

/** The Firefox executable; throws, saying how to get one, when there is none. */
export function firefoxPath(): string;
