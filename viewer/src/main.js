// Entry point: reads the result embedded by `cueball view` / `simulate --html`
// (the JSON in <script id="cueball-result">), starts the viewer and exposes a
// small read-only hook for tests: window.cueballViewer.

import { Viewer } from './app.js';
import { loadResult } from './model.js';

function elements() {
  const get = (id) => document.getElementById(id);
  return {
    stage: get('stage'),
    canvas: get('table'),
    hudTable: get('hud-table'),
    hudTime: get('hud-time'),
    message: get('message'),
    ballSelect: get('ball-select'),
    readout: get('ball-readout'),
    plot: get('plot'),
    showTransitions: get('show-transitions'),
    eventList: get('event-list'),
    play: get('play'),
    previous: get('prev-event'),
    next: get('next-event'),
    speed: get('speed'),
    scrubber: get('scrubber'),
    timeline: get('timeline'),
    timelineLegend: get('timeline-legend'),
    timeText: get('time-text'),
    trails: get('trails'),
  };
}

function start(el, result) {
  const model = loadResult(result);
  const viewer = new Viewer(el, model);
  window.cueballViewer = Object.freeze({
    ready: true,
    time: () => viewer.player.time,
    duration: () => model.duration,
    seek: (t) => viewer.player.seek(t), // keeps playing if it was
    play: () => viewer.player.play(),
    pause: () => viewer.player.pause(),
    ballPixel: (id) => viewer.ballPixel(id),
    ghostPixel: () => viewer.ghostPixel(),
  });
}

function showMessage(el, text) {
  el.message.hidden = false;
  el.message.textContent = text;
}

// The template itself (no result filled in): offer to open a result file,
// read locally (no network).
function offerFile(el) {
  showMessage(
    el,
    'No shot in this page. Make one with "cueball view RESULT.json -o shot.html", or open a result JSON here: ',
  );
  const input = document.createElement('input');
  input.type = 'file';
  input.accept = '.json,application/json';
  input.dataset.testid = 'open-result';
  input.addEventListener('change', async () => {
    const file = input.files && input.files[0];
    if (!file) return;
    try {
      const result = JSON.parse(await file.text());
      el.message.hidden = true;
      start(el, result);
    } catch (err) {
      showMessage(el, `Cannot show ${file.name}: ${err.message}`);
    }
  });
  el.message.append(input);
}

function main() {
  const el = elements();
  const text = document.getElementById('cueball-result').textContent.trim();
  if (!text.startsWith('{')) {
    offerFile(el);
    return;
  }
  let result;
  try {
    result = JSON.parse(text);
  } catch (err) {
    showMessage(el, `The embedded result is not valid JSON: ${err.message}`);
    return;
  }
  try {
    start(el, result);
  } catch (err) {
    showMessage(el, `Cannot show this result: ${err.message}`);
    throw err;
  }
}

main();
