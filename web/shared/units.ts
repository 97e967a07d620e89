// Length units: the choices a scan offers (the core detects them; the panel can override).
import type { Units } from './results';

export const UNITS: readonly Units[] = ['metres', 'centimetres', 'millimetres'];
