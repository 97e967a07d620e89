// The top bar: the "Open files…" and "Open folder…" buttons (hidden file inputs) and the status line.
import { ACCEPTED_EXTENSIONS } from '../shared/file-kind';
import { byId } from './dom';

export class TopBar {
  private readonly status = byId('status');

  /** Calls `onFiles` with the files picked in the dialog. */
  constructor(onFiles: (files: File[]) => void) {
    const input = byId<HTMLInputElement>('file-input');
    input.accept = ACCEPTED_EXTENSIONS.join(',');
    byId('open-files').addEventListener('click', () => input.click());
    // A folder's files (every file under it), for a batch.
    const folder = byId<HTMLInputElement>('folder-input');
    byId('open-folder').addEventListener('click', () => folder.click());
    for (const picker of [input, folder]) {
      picker.addEventListener('change', () => {
        const files = [...(picker.files ?? [])];
        picker.value = '';
        if (files.length > 0) onFiles(files);
      });
    }
  }

  setStatus(text: string): void {
    this.status.textContent = text;
  }
}
