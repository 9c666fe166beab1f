// A whole game (`cueball game play --html`): the game document
//   {"game": {"kind", "players": [a, b], "winner": 0 | 1 | null, "end_reason",
//             "shots": [{"player", "caption", "scores": [p0, p1],
//                        "foul": null | name, "result": <result JSON>}
//                       or {"player", "caption", "scores", "decision": name,
//                           "result": <the table as it stands> (optional)}],
//             each with an optional "reasoning": {"summary", "considered":
//             [{"what", "estimate"?, "next_estimate"?}]} (the agent's)}}
// read and checked (loadGame), and the shot list beside the table: a click
// on a row, the keys [ and ] or the prev/next buttons load that shot into
// the viewer, and the agent's reasoning for it (the options it weighed and
// their estimates) is shown under the caption.

/** True when the embedded document is a game, not one result. */
export function isGame(doc) {
  return Boolean(doc && typeof doc === 'object' && 'game' in doc);
}

function fail(path, what) {
  throw new Error(`${path}: ${what}`);
}

function checkProbability(value, path) {
  if (value === undefined) return null;
  if (typeof value !== 'number' || !(value >= 0 && value <= 1)) fail(path, 'expected a probability in [0, 1]');
  return value;
}

/** An entry's "reasoning", checked: {summary, considered: [{what, estimate, next}]} or null. */
export function loadReasoning(value, path) {
  if (value === undefined || value === null) return null;
  if (typeof value !== 'object') fail(path, 'expected an object');
  const summary = value.summary === undefined ? '' : value.summary;
  if (typeof summary !== 'string') fail(`${path}.summary`, 'expected a string');
  const list = value.considered === undefined ? [] : value.considered;
  if (!Array.isArray(list)) fail(`${path}.considered`, 'expected an array');
  const considered = list.map((c, i) => {
    const at = `${path}.considered[${i}]`;
    if (!c || typeof c !== 'object' || typeof c.what !== 'string') fail(`${at}.what`, 'expected a string');
    return {
      what: c.what,
      estimate: checkProbability(c.estimate, `${at}.estimate`),
      next: checkProbability(c.next_estimate, `${at}.next_estimate`),
    };
  });
  return { summary, considered };
}

/** One line of a weighed option: "direct 3 ...: P 0.82, next 0.75". */
export function consideredLine(c) {
  const parts = [];
  if (c.estimate !== null) parts.push(`P ${c.estimate.toFixed(3)}`);
  if (c.next !== null) parts.push(`next ${c.next.toFixed(3)}`);
  return parts.length ? `${c.what}: ${parts.join(', ')}` : c.what;
}

function checkScores(value, path) {
  if (!Array.isArray(value) || value.length !== 2 || !value.every((v) => typeof v === 'number')) {
    fail(path, 'expected two numbers');
  }
  return value;
}

/**
 * Checks a game document and returns its entries, each with `result` (the
 * result to load: a shot's own; for a decision its own snapshot, or the last
 * shot before it at its end) and `atEnd` (show the result's last instant).
 */
export function loadGame(doc) {
  const game = doc && doc.game;
  if (!game || typeof game !== 'object') fail('game', 'expected an object');
  if (!Array.isArray(game.players) || game.players.length !== 2) fail('game.players', 'expected two names');
  if (!Array.isArray(game.shots)) fail('game.shots', 'expected an array');
  if (!(game.winner === null || game.winner === undefined || game.winner === 0 || game.winner === 1)) {
    fail('game.winner', 'expected 0, 1 or null');
  }
  let lastShot = null;
  const entries = game.shots.map((shot, index) => {
    const path = `game.shots[${index}]`;
    if (!shot || typeof shot !== 'object') fail(path, 'expected an object');
    if (shot.player !== 0 && shot.player !== 1) fail(`${path}.player`, 'expected 0 or 1');
    if (typeof shot.caption !== 'string') fail(`${path}.caption`, 'expected a string');
    const scores = checkScores(shot.scores, `${path}.scores`);
    const decision = typeof shot.decision === 'string' ? shot.decision : null;
    const hasResult = shot.result && typeof shot.result === 'object';
    if (!decision && !hasResult) fail(`${path}.result`, 'expected a result (or a "decision")');
    let result = hasResult ? shot.result : null;
    let atEnd = Boolean(decision);
    if (!decision) lastShot = shot.result;
    else if (!result) result = lastShot;
    return {
      index,
      player: shot.player,
      caption: shot.caption,
      scores,
      foul: typeof shot.foul === 'string' ? shot.foul : null,
      decision,
      result,
      atEnd,
      reasoning: loadReasoning(shot.reasoning, `${path}.reasoning`),
    };
  });
  return {
    kind: String(game.kind ?? ''),
    players: game.players.map(String),
    winner: game.winner ?? null,
    endReason: typeof game.end_reason === 'string' ? game.end_reason : '',
    entries,
  };
}

/** "nine_ball" -> "nine ball". */
export function kindLabel(kind) {
  return kind.replaceAll('_', ' ');
}

/** The line under the list: who won and why, or how the game ended. */
export function gameOutcome(game) {
  const who = game.winner === null ? null : `player ${game.winner} (${game.players[game.winner]}) wins`;
  if (who && game.endReason) return `${who}: ${game.endReason}`;
  if (who) return who;
  return game.endReason ? `no winner: ${game.endReason}` : 'no result yet';
}

/**
 * The shot list and its controls, beside the viewer.
 * @param {Record<string, HTMLElement>} el elements of template.html
 * @param {ReturnType<typeof loadGame>} game
 * @param {(entry: object) => void} show loads an entry into the viewer
 */
export class GameList {
  constructor(el, game, show) {
    this.el = el;
    this.game = game;
    this.show = show;
    this.current = -1;
    this.rows = [];

    el.gamePanel.hidden = false;
    document.getElementById('app').classList.add('has-game');
    el.gameTitle.textContent = `${kindLabel(game.kind)}: ${game.players
      .map((p, i) => `player ${i} (${p})`)
      .join(' v ')}`;
    const rows = document.createDocumentFragment();
    for (const entry of game.entries) {
      const row = document.createElement('li');
      row.className = `shot${entry.decision ? ' decision' : ''}${entry.foul ? ' foul' : ''} p${entry.player}`;
      const button = document.createElement('button');
      button.type = 'button';
      button.dataset.testid = `shot-${entry.index}`;
      const number = document.createElement('span');
      number.className = 'shot-number';
      number.textContent = String(entry.index + 1);
      const caption = document.createElement('span');
      caption.className = 'shot-caption';
      caption.textContent = entry.caption;
      const scores = document.createElement('span');
      scores.className = 'shot-scores';
      scores.textContent = `${entry.scores[0]}–${entry.scores[1]}`;
      button.title = entry.caption;
      button.append(number, caption, scores);
      button.addEventListener('click', () => this.select(entry.index));
      row.append(button);
      rows.append(row);
      this.rows.push(row);
    }
    el.shotList.append(rows);
    el.gameResult.textContent = gameOutcome(game);
    el.prevShot.addEventListener('click', () => this.step(-1));
    el.nextShot.addEventListener('click', () => this.step(1));
    document.addEventListener('keydown', (e) => {
      if (e.altKey || e.ctrlKey || e.metaKey) return;
      const tag = e.target && e.target.tagName;
      if (tag === 'SELECT' || tag === 'INPUT' || tag === 'TEXTAREA') return;
      if (e.key === '[') this.step(-1);
      else if (e.key === ']') this.step(1);
      else return;
      e.preventDefault();
    });
    if (game.entries.length === 0) el.shotCaption.textContent = 'no shots';
  }

  /** The agent's reasoning under the caption: its summary, then the options weighed, the chosen first. */
  showReasoning(reasoning) {
    const box = this.el.shotReasoning;
    if (!box) return;
    box.replaceChildren();
    box.hidden = !reasoning;
    if (!reasoning) return;
    const summary = document.createElement('div');
    summary.className = 'reasoning-summary';
    summary.textContent = reasoning.summary;
    box.append(summary);
    if (reasoning.considered.length === 0) return;
    const list = document.createElement('ol');
    list.className = 'reasoning-considered';
    for (const c of reasoning.considered) {
      const item = document.createElement('li');
      item.textContent = consideredLine(c);
      list.append(item);
    }
    box.append(list);
  }

  step(delta) {
    const k = this.current + delta;
    if (k >= 0 && k < this.game.entries.length) this.select(k);
  }

  select(index) {
    const entry = this.game.entries[index];
    if (!entry) return;
    if (this.current >= 0) this.rows[this.current].classList.remove('current');
    this.current = index;
    const row = this.rows[index];
    row.classList.add('current');
    row.scrollIntoView({ block: 'nearest' });
    this.el.shotCaption.textContent = entry.caption;
    this.showReasoning(entry.reasoning);
    this.el.prevShot.disabled = index === 0;
    this.el.nextShot.disabled = index === this.game.entries.length - 1;
    this.show(entry);
  }
}
