// The top bar: the "Open files…" button (a hidden file input) and the status line.
import { ACCEPTED_EXTENSIONS } from '../shared/file-kind';
import { byId } from './dom';

export class TopBar {
  private readonly status = byId('status');

  /** Calls `onFiles` with the files picked in the dialog. */
  constructor(onFiles: (files: File[]) => void) {
    const input = byId<HTMLInputElement>('file-input');
    input.accept = ACCEPTED_EXTENSIONS.join(',');
    byId('open-files').addEventListener('click', () => input.click());
    input.addEventListener('change', () => {
      const files = [...(input.files ?? [])];
      input.value = '';
      if (files.length > 0) onFiles(files);
    });
  }

  setStatus(text: string): void {
    this.status.textContent = text;
  }
}
