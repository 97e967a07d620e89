// Asks before the page fetches anything from another host: a link may name a model on any https
// server, and opening a link must not make requests the person did not agree to.
import { byId, h } from './dom';

export class HostPrompt {
  private readonly root = byId('host-prompt');

  /** Shows `what` on `host` with Load / Keep buttons; resolves true when the person chose Load. */
  ask(host: string, what: string): Promise<boolean> {
    return new Promise((resolve) => {
      const answer = (load: boolean) => {
        this.root.hidden = true;
        this.root.replaceChildren();
        resolve(load);
      };
      const load = h('button', { class: 'button primary', type: 'button', 'data-testid': 'host-load' }, 'Load it');
      const keep = h('button', { class: 'button', type: 'button', 'data-testid': 'host-keep' }, 'Keep the demo model');
      load.addEventListener('click', () => answer(true));
      keep.addEventListener('click', () => answer(false));
      this.root.replaceChildren(
        h('span', { class: 'host-text', 'data-testid': 'host-text' }, `This link's ${what} is on another host: `, h('strong', { 'data-testid': 'host-name' }, host), '. Nothing has been downloaded from it. Load it from there?'),
        load,
        keep,
      );
      this.root.hidden = false;
    });
  }
}
