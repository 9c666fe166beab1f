// Entry point: reads the result embedded by `cueball view` / `simulate --html`
// (the JSON in <script id="cueball-result">), or a whole game's document
// (`cueball game play --html`: src/game.js), starts the viewer and exposes a
// small read-only hook for tests: window.cueballViewer.

import { Viewer } from './app.js';
import { GameList, isGame, loadGame } from './game.js';
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
    gamePanel: get('game-panel'),
    gameTitle: get('game-title'),
    prevShot: get('prev-shot'),
    nextShot: get('next-shot'),
    shotCaption: get('shot-caption'),
    shotReasoning: get('shot-reasoning'),
    shotList: get('shot-list'),
    gameResult: get('game-result'),
  };
}

// The viewer now shown (a game page replaces it shot by shot).
let viewer = null;
let gameList = null;

function show(el, result, atEnd = false) {
  const model = loadResult(result);
  if (viewer) viewer.destroy();
  viewer = new Viewer(el, model);
  if (atEnd) viewer.player.seek(model.duration);
}

function exposeHook() {
  window.cueballViewer = Object.freeze({
    ready: true,
    time: () => (viewer ? viewer.player.time : 0),
    duration: () => (viewer ? viewer.model.duration : 0),
    seek: (t) => viewer && viewer.player.seek(t), // keeps playing if it was
    play: () => viewer && viewer.player.play(),
    pause: () => viewer && viewer.player.pause(),
    ballPixel: (id) => (viewer ? viewer.ballPixel(id) : null),
    ghostPixel: () => (viewer ? viewer.ghostPixel() : null),
    /** A game page: the index of the shot shown (null on a one-shot page). */
    shot: () => (gameList ? gameList.current : null),
  });
}

function start(el, doc) {
  if (isGame(doc)) {
    const game = loadGame(doc);
    gameList = new GameList(el, game, (entry) => {
      if (entry.result) {
        el.message.hidden = true;
        show(el, entry.result, entry.atEnd);
      } else {
        // a decision before any shot: nothing on the table to show yet
        if (viewer) viewer.destroy();
        viewer = null;
        showMessage(el, entry.caption);
      }
    });
    if (game.entries.length === 0) {
      showMessage(el, 'This game has no shots.');
      return;
    }
    gameList.select(0);
  } else {
    show(el, doc);
  }
  exposeHook();
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
    showMessage(el, `Cannot show this ${isGame(result) ? 'game' : 'result'}: ${err.message}`);
    throw err;
  }
}

main();
