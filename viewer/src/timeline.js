// Event timeline: markers along the time axis under the scrubber, and a list
// of events beside the table. Clicking either seeks to the event.

import { formatTime, describeEvent, EVENT_LABELS } from './format.js';
import { TRANSITION_EVENTS } from './model.js';

/** Event types shown prominently (contacts and the cue strike). */
const KEY_EVENTS = new Set(['cue_strike', 'ball_ball', 'ball_cushion', 'ball_jaw', 'ball_pocket']);

export class Timeline {
  /**
   * @param {{track:HTMLElement, list:HTMLElement, legend:HTMLElement}} elements
   * @param {(event:object) => void} onPick called when an event is clicked
   */
  constructor(elements, model, names, onPick) {
    this.model = model;
    this.track = elements.track;
    this.list = elements.list;
    this.rows = [];
    this.current = -1;
    this.time = 0;
    this.transitionsShown = false;
    const duration = model.duration > 0 ? model.duration : 1;

    const markers = document.createDocumentFragment();
    const rows = document.createDocumentFragment();
    for (const event of model.events) {
      const transition = TRANSITION_EVENTS.has(event.type);
      const what = describeEvent(event, model, names);
      const text = `${formatTime(event.time)} · ${EVENT_LABELS[event.type] || event.type} · ${what}`;

      const marker = document.createElement('button');
      marker.type = 'button';
      marker.className = `marker ev-${event.type}${transition ? ' transition' : ''}`;
      marker.style.left = `${(100 * event.time) / duration}%`;
      marker.title = text;
      marker.tabIndex = -1; // the list is the keyboard route
      marker.dataset.testid = `event-marker-${event.index}`;
      marker.dataset.time = String(event.time);
      marker.addEventListener('click', () => onPick(event));
      markers.append(marker);

      const row = document.createElement('li');
      row.className = `event ev-${event.type}${transition ? ' transition' : ''}`;
      const button = document.createElement('button');
      button.type = 'button';
      button.dataset.testid = `event-${event.index}`;
      button.dataset.time = String(event.time);
      const time = document.createElement('span');
      time.className = 'event-time';
      time.textContent = formatTime(event.time);
      const label = document.createElement('span');
      label.className = 'event-what';
      label.textContent = what;
      button.title = text;
      button.append(time, label);
      button.addEventListener('click', () => onPick(event));
      row.append(button);
      rows.append(row);
      this.rows.push(row);
    }
    // key events above the faint transitions
    this.track.append(...[...markers.children].sort((a, b) => keyOrder(a) - keyOrder(b)));
    this.list.append(rows);
    elements.legend.append(...legendItems());
  }

  /** Lists the motion transitions (slide to roll...) too, or only the key events. */
  showTransitions(on) {
    this.transitionsShown = on;
    this.list.classList.toggle('show-transitions', on);
    this.update(this.time, true);
  }

  /** Marks the last listed event at or before t as current and keeps it in view. */
  update(t, force = false) {
    this.time = t;
    const events = this.model.events;
    let k = -1;
    for (let i = 0; i < events.length && events[i].time <= t; ++i) {
      if (this.transitionsShown || !TRANSITION_EVENTS.has(events[i].type)) k = i;
    }
    if (k === this.current && !force) return;
    if (this.current >= 0) this.rows[this.current].classList.remove('current');
    this.current = k;
    if (k < 0) return;
    const row = this.rows[k];
    row.classList.add('current');
    // scroll the list only (not the page) to show the row if it is hidden;
    // the list is positioned, so offsetTop is relative to it
    if (row.offsetParent === null) return;
    const list = this.list;
    const top = row.offsetTop;
    if (top < list.scrollTop || top + row.offsetHeight > list.scrollTop + list.clientHeight) {
      list.scrollTop = Math.max(0, top - list.clientHeight / 3);
    }
  }
}

function keyOrder(marker) {
  return marker.classList.contains('transition') ? 0 : 1;
}

function legendItems() {
  return [...KEY_EVENTS].map((type) => {
    const item = document.createElement('span');
    item.className = `legend-item ev-${type}`;
    item.textContent = EVENT_LABELS[type];
    return item;
  });
}
