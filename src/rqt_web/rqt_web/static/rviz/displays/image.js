// Image: a panel under the view per display, the image on a canvas of its size, shown 320 px
// wide (rviz scales it to its panel, keeping the aspect ratio).
import {imagePanel, setStatus} from '../panel.js';
import {enabled, state} from '../state.js';
import {streamLoop} from '../streams.js';

export function add() {
  for (const d of enabled('/Image')) {
    const canvas = rqt.el('canvas', {class: 'rviz-image', 'data-name': d.name, width: 1, height: 1,
      style: 'width:320px;height:auto;image-rendering:pixelated;background:#000'});
    imagePanel.append(rqt.el('figure', {style: 'margin:4px'}, rqt.el('figcaption', {text: `${d.name} ${d.topic || ''}`}), canvas));
    const ctx = canvas.getContext('2d');
    const info = {received: 0, drawn: 0, width: 0, height: 0, encoding: null, seq: 0};
    state.images[d.name] = info;
    streamLoop('image', d, (meta, body) => {
      if (canvas.width !== meta.width || canvas.height !== meta.height) {
        canvas.width = meta.width;
        canvas.height = meta.height;
      }
      if (meta.width && meta.height) {
        ctx.putImageData(new ImageData(new Uint8ClampedArray(body), meta.width, meta.height), 0, 0);
      }
      Object.assign(info, {drawn: info.drawn + 1, width: meta.width, height: meta.height,
        encoding: meta.encoding, seq: meta.seq});
      setStatus(d.name, 'OK');
    }, info);
  }
}
