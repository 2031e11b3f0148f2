// Charts exist only while their card is on screen (or near it): an IntersectionObserver makes a card's
// chart when it comes within a screen of the viewport and destroys it when it leaves, so 500 series
// cost 500 cards of DOM but only a handful of canvases.

/**
 * Watches `cards` ({element, mount(), unmount()}); returns a promise that resolves after the first
 * round of mounts (the first screen drawn).
 */
export function lazyCharts(cards) {
  const byElement = new Map(cards.map((c) => [c.element, c]));
  let firstRound;
  const drawn = new Promise((resolve) => { firstRound = resolve; });
  if (cards.length === 0) firstRound();
  const observer = new IntersectionObserver((entries) => {
    for (const entry of entries) {
      const card = byElement.get(entry.target);
      if (entry.isIntersecting) card.mount();
      else card.unmount();
    }
    firstRound();
  }, { rootMargin: "100% 0px 100% 0px" });
  for (const c of cards) observer.observe(c.element);
  return drawn;
}
