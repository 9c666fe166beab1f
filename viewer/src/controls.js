// Playback controls: play/pause, speed, scrubber, previous/next event, and
// the keyboard (space: play/pause; arrows: previous/next key event).

import { formatTime } from './format.js';

export const SPEEDS = [0.05, 0.1, 0.25, 0.5, 1, 2];

/**
 * @param {Record<string, HTMLElement>} el the control elements (see template.html)
 * @param {import('./player.js').Player} player
 * @param {{previous:(t:number)=>number|null, next:(t:number)=>number|null}} events times of key events
 * @param {AbortSignal} [signal] removes the listeners when aborted
 */
export function bindControls(el, player, events, signal = undefined) {
  el.play.addEventListener('click', () => player.toggle(), { signal });

  for (const s of SPEEDS) {
    const option = document.createElement('option');
    option.value = String(s);
    option.textContent = `${s}×`;
    option.selected = s === player.speed;
    el.speed.append(option);
  }
  el.speed.addEventListener('change', () => player.setSpeed(Number(el.speed.value)), { signal });

  el.scrubber.max = String(player.duration);
  el.scrubber.step = 'any';
  el.scrubber.addEventListener('input', () => {
    player.pause();
    player.seek(Number(el.scrubber.value));
  }, { signal });

  const jump = (t) => {
    if (t === null) return;
    player.pause();
    player.seek(t);
  };
  el.previous.addEventListener('click', () => jump(events.previous(player.time)), { signal });
  el.next.addEventListener('click', () => jump(events.next(player.time)), { signal });

  document.addEventListener('keydown', (e) => {
    if (e.altKey || e.ctrlKey || e.metaKey) return;
    const tag = e.target && e.target.tagName;
    if (tag === 'SELECT' || tag === 'INPUT' || tag === 'TEXTAREA') return;
    if (tag === 'BUTTON' && e.key === ' ') return; // the focused button acts on space itself
    if (e.key === ' ') {
      player.toggle();
    } else if (e.key === 'ArrowLeft') {
      jump(events.previous(player.time));
    } else if (e.key === 'ArrowRight') {
      jump(events.next(player.time));
    } else {
      return;
    }
    e.preventDefault();
  }, { signal });
}

/** Shows the player's state in the controls. */
export function showPlayerState(el, t, playing, duration) {
  el.play.setAttribute('aria-label', playing ? 'Pause' : 'Play');
  el.play.title = playing ? 'Pause (space)' : 'Play (space)';
  el.play.dataset.state = playing ? 'playing' : 'paused';
  el.scrubber.value = String(t);
  el.timeText.textContent = `${formatTime(t)} / ${formatTime(duration)}`;
}
