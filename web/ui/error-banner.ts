// The dismissable banner that names the file and the problem. Shows the latest messages.
import { byId } from './dom';

export class ErrorBanner {
  private readonly root = byId('error-banner');
  private readonly text = this.root.querySelector<HTMLElement>('.error-text')!;

  constructor() {
    this.root.querySelector('.error-close')!.addEventListener('click', () => this.dismiss());
  }

  /** Shows `messages` (one per line), replacing what the banner showed. */
  show(messages: string[]): void {
    this.text.textContent = messages.join('\n');
    this.root.hidden = false;
  }

  dismiss(): void {
    this.root.hidden = true;
    this.text.textContent = '';
  }
}
