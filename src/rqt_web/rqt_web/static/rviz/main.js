// The RViz page's entry: the panel at once, then the 3D view (start.js), whose modules need
// three.js. Imported dynamically so that a missing browser library or a failed start shows
// in the page's note instead of leaving it blank.
import {note} from './panel.js';

import('./start.js').then(({start}) => start())
  .catch((error) => { note.textContent = `RViz could not start: ${error.message || error}`; });
