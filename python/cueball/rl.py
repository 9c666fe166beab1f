"""Reinforcement learning on real games: cueball.rl.

Three environments over the engine's games (cueball.games) and its native
learning environment (include/cueball/rl/environment.hpp):

- ``CueballEnv``: one learner against an opponent (or self-play), the
  Gymnasium ``Env`` API: ``reset(seed=None, options=None) -> (obs, info)``,
  ``step(action) -> (obs, reward, terminated, truncated, info)``,
  ``observation_space``, ``action_space``, ``render()``.
- ``TwoPlayerEnv``: two learners, the PettingZoo AEC API (``agents``,
  ``agent_selection``, ``observe``, ``last``, ``step``, ``rewards``,
  ``terminations``, ``truncations``, ``infos``).
- ``VectorEnv``: N tables stepped together in C++ threads with the GIL
  released, the Gymnasium vector API (``num_envs``,
  ``single_action_space``, ``single_observation_space``, auto-reset).

Gymnasium and PettingZoo are not required: without them the spaces are this
module's own ``Box``, ``Discrete`` and ``Dict`` (``shape``, ``dtype``,
``low``/``high`` or ``n``, ``sample()``, ``contains()``, ``seed()``); when
``gymnasium`` imports, ``CueballEnv`` is a ``gymnasium.Env`` and the spaces
are Gymnasium's. python/README.md ("Reinforcement learning") documents the
action and observation layouts, the options and the rewards.
"""

from __future__ import annotations

import os
from typing import Any, Callable, Mapping, Sequence, Union

import numpy as np
from numpy.typing import NDArray

from . import _cueball

_native: Any = getattr(_cueball, "_rl")

try:  # Gymnasium's Env and spaces when the package is there
    import gymnasium as _gym  # type: ignore
    import gymnasium.spaces as _gym_spaces  # type: ignore
except ImportError:  # pragma: no cover - depends on the machine
    _gym = None
    _gym_spaces = None

GAMES = ("nine_ball", "eight_ball", "ten_ball", "snooker", "three_cushion")
OPPONENTS = ("planner", "safety_planner", "ghost_ball", "random", "carom_search", "strongest")
REWARD_TERMS = ("win", "points", "pots", "fouls", "illegal")
# The weight a term named alone gets (reward="pots" or reward=["win", "fouls"]).
DEFAULT_WEIGHTS = {"win": 1.0, "points": 1.0, "pots": 1.0, "fouls": -1.0, "illegal": -1.0}
DECISIONS = ("shoot", "play", "pass", "rerack_and_break", "rerack_opponent_breaks", "respot_eight", "rerack", "restore")

MIN_SPEED: float = _native.min_speed
MAX_CUT_OFFSET_DEG: float = _native.max_cut_offset_deg
MAX_ELEVATION_DEG: float = _native.max_elevation_deg

Action = Union[Mapping[str, Any], Sequence[float], NDArray[Any]]
Opponent = Union[str, None, Callable[[NDArray[np.float32], dict[str, Any]], Any]]


# ------------------------------------------------------------------ spaces (Gymnasium's shapes, no dependency)


class Box:
    """A box of floats: ``shape``, ``dtype``, ``low``, ``high`` (as gymnasium.spaces.Box)."""

    def __init__(self, low: Any, high: Any, shape: tuple[int, ...], dtype: Any = np.float32, seed: int | None = None):
        self.shape = tuple(shape)
        self.dtype = np.dtype(dtype)
        self.low = np.broadcast_to(np.asarray(low, dtype=self.dtype), self.shape).copy()
        self.high = np.broadcast_to(np.asarray(high, dtype=self.dtype), self.shape).copy()
        self.np_random = np.random.default_rng(seed)

    def seed(self, seed: int | None = None) -> list[int | None]:
        self.np_random = np.random.default_rng(seed)
        return [seed]

    def sample(self) -> NDArray[Any]:
        low = np.where(np.isfinite(self.low), self.low, -1.0)
        high = np.where(np.isfinite(self.high), self.high, 1.0)
        return np.asarray(self.np_random.uniform(low, high), dtype=self.dtype)

    def contains(self, x: Any) -> bool:
        a = np.asarray(x)
        return bool(a.shape == self.shape and np.all(a >= self.low) and np.all(a <= self.high))

    def __contains__(self, x: Any) -> bool:
        return self.contains(x)

    def __repr__(self) -> str:
        return f"Box({self.shape}, {self.dtype})"


class Discrete:
    """The integers 0 .. n-1 (as gymnasium.spaces.Discrete); ``sample(mask)`` takes an int8 mask."""

    def __init__(self, n: int, seed: int | None = None):
        self.n = int(n)
        self.shape: tuple[int, ...] = ()
        self.dtype = np.dtype(np.int64)
        self.np_random = np.random.default_rng(seed)

    def seed(self, seed: int | None = None) -> list[int | None]:
        self.np_random = np.random.default_rng(seed)
        return [seed]

    def sample(self, mask: Any = None) -> int:
        if mask is not None:
            allowed = np.flatnonzero(np.asarray(mask))
            if allowed.size:
                return int(self.np_random.choice(allowed))
        return int(self.np_random.integers(self.n))

    def contains(self, x: Any) -> bool:
        try:
            v = int(x)
        except (TypeError, ValueError):
            return False
        return v == x and 0 <= v < self.n

    def __contains__(self, x: Any) -> bool:
        return self.contains(x)

    def __repr__(self) -> str:
        return f"Discrete({self.n})"


class Dict:
    """Named sub-spaces (as gymnasium.spaces.Dict)."""

    def __init__(self, spaces: Mapping[str, Any], seed: int | None = None):
        self.spaces = dict(spaces)
        self.shape = None
        self.dtype = None
        if seed is not None:
            self.seed(seed)

    def seed(self, seed: int | None = None) -> list[int | None]:
        for i, space in enumerate(self.spaces.values()):
            space.seed(None if seed is None else seed + i)
        return [seed]

    def sample(self, mask: Mapping[str, Any] | None = None) -> dict[str, Any]:
        out: dict[str, Any] = {}
        for k, space in self.spaces.items():
            m = None if mask is None else mask.get(k)
            out[k] = space.sample(m) if isinstance(space, Discrete) and m is not None else space.sample()
        return out

    def contains(self, x: Any) -> bool:
        return isinstance(x, Mapping) and set(x) == set(self.spaces) and all(
            self.spaces[k].contains(x[k]) for k in self.spaces)

    def __contains__(self, x: Any) -> bool:
        return self.contains(x)

    def __getitem__(self, key: str) -> Any:
        return self.spaces[key]

    def __repr__(self) -> str:
        return "Dict(" + ", ".join(f"{k}: {v!r}" for k, v in self.spaces.items()) + ")"


def _box(low: Any, high: Any, shape: tuple[int, ...], seed: int | None = None) -> Any:
    if _gym_spaces is not None:
        return _gym_spaces.Box(low=np.broadcast_to(np.asarray(low, np.float32), shape),
                               high=np.broadcast_to(np.asarray(high, np.float32), shape), dtype=np.float32, seed=seed)
    return Box(low, high, shape, np.float32, seed)


def _discrete(n: int, seed: int | None = None) -> Any:
    return _gym_spaces.Discrete(n, seed=seed) if _gym_spaces is not None else Discrete(n, seed)


def _dict(spaces: Mapping[str, Any], seed: int | None = None) -> Any:
    return _gym_spaces.Dict(dict(spaces), seed=seed) if _gym_spaces is not None else Dict(spaces, seed)


# ------------------------------------------------------------------ options


def _reward_weights(reward: Any) -> dict[str, float]:
    """reward=: a term's name, a list of names (DEFAULT_WEIGHTS) or a dict name -> weight."""
    if isinstance(reward, str):
        reward = [reward]
    if isinstance(reward, Mapping):
        items = [(str(k), float(v)) for k, v in reward.items()]
    elif isinstance(reward, (list, tuple)):
        items = [(str(k), DEFAULT_WEIGHTS.get(str(k), 0.0)) for k in reward]
    else:
        raise _cueball.InvalidArgument(f"reward = {reward!r} is not a term, a list of terms or a dict of weights; "
                                       f"terms: {', '.join(REWARD_TERMS)}")
    for k, _ in items:
        if k not in REWARD_TERMS:
            raise _cueball.InvalidArgument(f"reward term {k!r} is not known; allowed: {', '.join(REWARD_TERMS)}")
    return dict(items)


def _noise(noise: Any) -> tuple[Any, tuple[float, float]]:
    """noise=: None, 'none', 'tournament', a dict of sigmas, or {'base': ..., 'scale': [lo, hi]} (drawn per episode)."""
    if isinstance(noise, Mapping) and "scale" in noise:
        scale: Any = noise["scale"]
        lo, hi = (float(scale), float(scale)) if isinstance(scale, (int, float)) else (float(scale[0]), float(scale[1]))
        base = noise.get("base", "tournament")
        return (None if base is None else base), (lo, hi)
    return noise, (1.0, 1.0)


class _Options:
    """The environments' options, parsed once (names as the constructors take them)."""

    def __init__(self, game: str, opponent: Opponent, noise: Any, reward: Any, max_shots: int, action: str,
                 break_shot: str, seat: int | None, max_speed: float, simulations: int | None,
                 opponent_seconds: float | None = None):
        if game not in GAMES:
            raise _cueball.InvalidArgument(f"game = {game!r} is not known; allowed: {', '.join(GAMES)}")
        self.game = game
        self.callable_opponent = opponent if callable(opponent) else None
        if opponent is not None and not callable(opponent) and opponent not in OPPONENTS:
            raise _cueball.InvalidArgument(f"opponent = {opponent!r} is not known; allowed: "
                                           f"{', '.join(OPPONENTS)}, a callable or None (self-play)")
        self.opponent = opponent if isinstance(opponent, str) else None
        self.noise, self.noise_scale = _noise(noise)
        self.reward = _reward_weights(reward)
        self.max_shots = int(max_shots)
        self.action = action
        self.break_shot = break_shot
        self.seat = -1 if seat is None else int(seat)
        self.max_speed = float(max_speed)
        self.simulations = None if simulations is None else int(simulations)
        self.seconds = None if opponent_seconds is None else float(opponent_seconds)
        if self.seconds is not None:
            if not 0.0 <= self.seconds <= 3600.0:
                raise _cueball.InvalidArgument(f"opponent_seconds = {opponent_seconds!r} is out of range [0, 3600] "
                                               "(s a decision; None: no time budget)")
            if self.opponent is None:
                raise _cueball.InvalidArgument(f"opponent_seconds = {opponent_seconds!r} needs a built-in opponent "
                                               f"({', '.join(OPPONENTS)}); a callable or self-play takes none")

    def native_args(self, opponent: str | None) -> tuple[Any, ...]:
        return (self.game, opponent, self.simulations, self.seconds, self.noise, self.noise_scale, self.reward, self.action,
                self.break_shot, self.seat, self.max_shots, self.max_speed)


def _action_parts(action: Action) -> tuple[list[float], list[float], int, int, int, int]:
    """An action dict (or a bare strike of 5 numbers) as the native step's arguments; missing parts are 0."""
    if isinstance(action, Mapping):
        strike = np.asarray(action.get("strike", np.zeros(5)), dtype=np.float64).reshape(-1)
        place = np.asarray(action.get("place", np.zeros(2)), dtype=np.float64).reshape(-1)
        ints = [int(action.get(k, 0)) for k in ("ball", "pocket", "decision", "push_out")]
    else:
        strike = np.asarray(action, dtype=np.float64).reshape(-1)
        place = np.zeros(2)
        ints = [0, 0, 0, 0]
    if strike.shape != (5,):
        raise _cueball.InvalidArgument(f"action['strike'] must hold 5 numbers, not {strike.shape}")
    if place.shape != (2,):
        raise _cueball.InvalidArgument(f"action['place'] must hold 2 numbers, not {place.shape}")
    return [float(v) for v in strike], [float(v) for v in place], ints[0], ints[1], ints[2], ints[3]


def observation_names(game: str = "nine_ball") -> list[str]:
    """The name of every entry of a discipline's observation ("ball3.x", ..., "noise.aim")."""
    return list(_native.observation_names(game))


def _observation_bounds(game: str) -> tuple[NDArray[np.float32], NDArray[np.float32]]:
    names = observation_names(game)
    low = np.zeros(len(names), np.float32)
    high = np.ones(len(names), np.float32)
    for i, name in enumerate(names):
        if name.endswith((".x", ".y", ".value")) or name == "group":
            low[i] = -1.0
        elif name in ("score", "opponent_score"):
            low[i], high[i] = -np.inf, np.inf
        elif name.startswith("noise."):
            high[i] = 100.0
    return low, high


def _spaces(game: str, pockets: int) -> tuple[Any, Any]:
    low, high = _observation_bounds(game)
    observation = _box(low, high, low.shape)
    action = _dict({
        "strike": _box(-1.0, 1.0, (5,)),
        "place": _box(-1.0, 1.0, (2,)),
        "ball": _discrete(int(_native.ball_count(game))),
        "pocket": _discrete(max(1, pockets)),
        "decision": _discrete(int(_native.decision_choices)),
        "push_out": _discrete(2),
    })
    return observation, action


def _viewer_page(game_json: str) -> str:
    return str(_cueball.viewer_page(game_json))


_EnvBase: Any = _gym.Env if _gym is not None else object


# ------------------------------------------------------------------ one learner


class CueballEnv(_EnvBase):  # type: ignore[misc]
    """One learner plays a whole game against ``opponent`` (python/README.md, "Reinforcement learning").

    Options: ``game`` (GAMES), ``opponent`` ('ghost_ball' by default, 'planner', 'safety_planner',
    'random', 'carom_search', 'strongest' (the strongest agent, issue 27), a callable ``f(observation, info) -> action`` playing the other seat with
    the same action space, or None for self-play: every step is the action of the player to
    act, the observation that player's), ``noise`` (None, 'tournament', a dict of sigmas in the
    scenario's units, or ``{'base': ..., 'scale': [lo, hi]}`` drawn per episode), ``reward``
    (a term, a list of terms or a dict of weights over REWARD_TERMS), ``max_shots``, ``action``
    ('raw' or 'target'), ``break_shot`` ('recommended': the engine breaks for whoever breaks;
    'agent'), ``seat`` (0 breaks, 1, or None drawn per episode), ``max_speed`` (m/s of
    strike[0] = 1), ``simulations`` (the opponent's engine runs a decision; None: 300 for a
    kind's name, the strongest agent's own budget for 'strongest'), ``opponent_seconds`` (a
    built-in opponent's wall-clock budget a decision, AgentOptions::seconds: it plans in rounds up
    to ``simulations`` while they fit; None: no budget. Its decisions then depend on the machine's
    speed, so an episode is reproducible from its seed only without it),
    ``render_mode`` (None or 'html': render() returns the episode's viewer page).
    """

    metadata = {"render_modes": ["html"], "render_fps": 1}

    def __init__(self, game: str = "nine_ball", opponent: Opponent = "ghost_ball", noise: Any = None,
                 reward: Any = "win", max_shots: int = 200, action: str = "raw", break_shot: str = "recommended",
                 seat: int | None = 0, max_speed: float = 8.0, simulations: int | None = None,
                 render_mode: str | None = None, opponent_seconds: float | None = None):
        if render_mode not in (None, "html"):
            raise _cueball.InvalidArgument(f"render_mode = {render_mode!r} is not known; allowed: None, 'html'")
        self.options = _Options(game, opponent, noise, reward, max_shots, action, break_shot, seat, max_speed,
                                simulations, opponent_seconds)
        self.render_mode = render_mode
        self._table = _native.Table(*self.options.native_args(self.options.opponent), render_mode == "html")
        self.observation_space, self.action_space = _spaces(game, 6 if game != "three_cushion" else 0)
        self._seat = 0
        self._noise: dict[str, float] = {}
        self._last_info: dict[str, Any] = {}

    # The learner's seat; the observation is from its point of view.
    def _learner(self) -> int:
        return int(self._table.status[3])

    def _callable_to_act(self) -> bool:
        over, _, to_shoot, _ = self._table.status
        return self.options.callable_opponent is not None and not over and to_shoot != self._seat

    def _play_callable(self, reward: float, infos: list[dict[str, Any]]) -> float:
        opponent = self.options.callable_opponent
        assert opponent is not None
        while self._callable_to_act():
            seat = int(self._table.status[2])
            obs = self._table.observe(seat)
            action = opponent(obs, {"action_mask": self._table.masks(), "player": seat})
            _, _, _, _, info = self._table.step(*_action_parts(action))
            reward += float(info["rewards"][self._seat])
            infos.append(info)
        return reward

    def _info(self, step_info: dict[str, Any] | None = None) -> dict[str, Any]:
        info: dict[str, Any] = {} if step_info is None else dict(step_info)
        info["action_mask"] = self._table.masks()
        info["noise"] = self._noise
        info["to_shoot"] = int(self._table.status[2])
        info["seat"] = self._seat
        return info

    def _observation(self) -> NDArray[np.float32]:
        return np.asarray(self._table.observe(self._seat), dtype=np.float32)

    def reset(self, *, seed: int | None = None, options: Mapping[str, Any] | None = None
              ) -> tuple[NDArray[np.float32], dict[str, Any]]:
        """A new game (seeded: episode 0 of that seed; else the next episode); plays the opponent up to the learner's turn.

        options={'state': s} starts from the cueball.games.GameState s instead (a drill, a saved position).
        """
        if _gym is not None:
            super().reset(seed=seed)  # gymnasium.Env seeds its np_random
        if seed is not None:
            for i, space in enumerate((self.observation_space, self.action_space)):
                space.seed(seed + i)
        start = None if options is None else options.get("state")
        if start is not None:  # a given position (a cueball.games.GameState of this game)
            if seed is not None:
                self._table.reset(seed)  # the table's seeds restart from `seed`
            self._table.reset_from(start)
        else:
            self._table.reset(seed)
        self._noise = self._table.noise
        if self.options.callable_opponent is not None:
            self._seat = int(self.options.seat) if self.options.seat >= 0 else int(self._table.game_seed % 2)
            self._play_callable(0.0, [])
        else:
            self._seat = self._learner()
        self._last_info = self._info()
        return self._observation(), self._last_info

    def step(self, action: Action) -> tuple[NDArray[np.float32], float, bool, bool, dict[str, Any]]:
        """One action of the learner, then the opponent's replies up to the learner's next turn."""
        if self._table.status[0]:
            raise _cueball.InvalidArgument("step: the episode is over; call reset()")
        if self.options.callable_opponent is None:
            self._seat = self._learner()
        _, _, terminated, truncated, info = self._table.step(*_action_parts(action))
        reward = float(info["rewards"][self._seat])
        replies: list[dict[str, Any]] = []
        if self.options.callable_opponent is not None:
            reward = self._play_callable(reward, replies)
        elif self.options.opponent is None:
            self._seat = self._learner()
        over, truncated, _, _ = self._table.status
        info = self._info(info)
        if replies:
            info["replies"] = replies
        self._last_info = info
        return self._observation(), reward, bool(over and not truncated), bool(over and truncated), info

    @property
    def state(self) -> Any:
        """The game's state (a cueball.games.GameState, a copy)."""
        return self._table.state

    def action_masks(self) -> dict[str, NDArray[np.bool_]]:
        """The masks of the discrete parts (ball, pocket, decision, push_out) for the player to act."""
        return dict(self._table.masks())

    def mirror(self, observation: NDArray[np.float32], action: Action) -> tuple[NDArray[np.float32], dict[str, Any]]:
        """The mirror image about the long string of an observation and an action (data augmentation)."""
        strike, place, ball, pocket, decision, push_out = self._table.mirror_action(*_action_parts(action))
        return (np.asarray(self._table.mirror_observation(np.asarray(observation, np.float32))),
                {"strike": np.asarray(strike), "place": np.asarray(place), "ball": ball, "pocket": pocket,
                 "decision": decision, "push_out": push_out})

    def render(self) -> str | None:
        """render_mode 'html': the episode so far as a self-contained viewer page (a str of HTML)."""
        if self.render_mode != "html":
            return None
        names = ("learner", str(self.options.opponent or "self"))
        players = [names[0], names[1]] if self._seat == 0 else [names[1], names[0]]
        return _viewer_page(self._table.viewer_json(players))

    def close(self) -> None:
        pass


# ------------------------------------------------------------------ two learners


class TwoPlayerEnv:
    """Two learners in the PettingZoo AEC manner: the player to act is ``agent_selection``.

    Turns do not alternate on every shot: a player who pots keeps the table; decisions
    (push-out replies, re-racks, restore) are actions too (the ``decision`` part). Options as
    CueballEnv's, without ``opponent`` and ``seat``.
    """

    metadata = {"render_modes": ["html"], "name": "cueball_v0", "is_parallelizable": False}

    def __init__(self, game: str = "nine_ball", noise: Any = None, reward: Any = "win", max_shots: int = 200,
                 action: str = "raw", break_shot: str = "recommended", max_speed: float = 8.0,
                 render_mode: str | None = None):
        self.options = _Options(game, None, noise, reward, max_shots, action, break_shot, 0, max_speed, 1)
        self.render_mode = render_mode
        self._table = _native.Table(*self.options.native_args(None), render_mode == "html")
        self.possible_agents = ["player_0", "player_1"]
        self.agents: list[str] = []
        self._observation_space, self._action_space = _spaces(game, 6 if game != "three_cushion" else 0)
        self.rewards: dict[str, float] = {}
        self._cumulative_rewards: dict[str, float] = {}
        self.terminations: dict[str, bool] = {}
        self.truncations: dict[str, bool] = {}
        self.infos: dict[str, dict[str, Any]] = {}
        self.agent_selection = "player_0"

    def observation_space(self, agent: str) -> Any:
        return self._observation_space

    def action_space(self, agent: str) -> Any:
        return self._action_space

    def _player(self, agent: str) -> int:
        return self.possible_agents.index(agent)

    def _select(self) -> None:
        live = [a for a in self.agents if not (self.terminations[a] or self.truncations[a])]
        to_shoot = self.possible_agents[int(self._table.status[2])]
        self.agent_selection = to_shoot if to_shoot in live or not self.agents else (
            to_shoot if to_shoot in self.agents else self.agents[0])

    def reset(self, seed: int | None = None, options: Mapping[str, Any] | None = None) -> None:
        """A new game; options={'state': s} starts from the cueball.games.GameState s instead."""
        start = None if options is None else options.get("state")
        if start is not None:
            if seed is not None:
                self._table.reset(seed)
            self._table.reset_from(start)
        else:
            self._table.reset(seed)
        self.agents = list(self.possible_agents)
        self.rewards = {a: 0.0 for a in self.agents}
        self._cumulative_rewards = {a: 0.0 for a in self.agents}
        self.terminations = {a: False for a in self.agents}
        self.truncations = {a: False for a in self.agents}
        self.infos = {a: {"action_mask": self._table.masks()} for a in self.agents}
        self._select()

    def observe(self, agent: str) -> NDArray[np.float32]:
        return np.asarray(self._table.observe(self._player(agent)), dtype=np.float32)

    def last(self, observe: bool = True) -> tuple[NDArray[np.float32] | None, float, bool, bool, dict[str, Any]]:
        a = self.agent_selection
        return (self.observe(a) if observe else None, self._cumulative_rewards[a], self.terminations[a],
                self.truncations[a], self.infos[a])

    def step(self, action: Action | None) -> None:
        a = self.agent_selection
        if self.terminations[a] or self.truncations[a]:
            # The dead step: the agent leaves (PettingZoo's convention; action must be None).
            self.agents.remove(a)
            del self.rewards[a], self._cumulative_rewards[a], self.terminations[a], self.truncations[a], self.infos[a]
            if self.agents:
                self.agent_selection = self.agents[0]
            return
        if action is None:
            raise _cueball.InvalidArgument("action: None is only for an agent whose game has ended")
        self._cumulative_rewards[a] = 0.0
        _, _, terminated, truncated, info = self._table.step(*_action_parts(action))
        for i, agent in enumerate(self.possible_agents):
            self.rewards[agent] = float(info["rewards"][i])
            self._cumulative_rewards[agent] += self.rewards[agent]
            self.terminations[agent] = bool(terminated)
            self.truncations[agent] = bool(truncated)
            self.infos[agent] = {"action_mask": self._table.masks(), "rulings": info["rulings"],
                                 "illegal": info["illegal"] if agent == a else None}
        self._select()

    @property
    def state(self) -> Any:
        return self._table.state

    def render(self) -> str | None:
        if self.render_mode != "html":
            return None
        return _viewer_page(self._table.viewer_json(["player_0", "player_1"]))

    def close(self) -> None:
        pass


# ------------------------------------------------------------------ many tables


def _batched(space: Any, n: int) -> Any:
    if isinstance(space, Box) or (_gym_spaces is not None and isinstance(space, _gym_spaces.Box)):
        return _box(np.broadcast_to(space.low, (n, *space.shape)), np.broadcast_to(space.high, (n, *space.shape)),
                    (n, *space.shape))
    return None


class VectorEnv:
    """N tables stepped at once in C++ threads (the GIL released), as Gymnasium's vector envs.

    ``step(actions)`` takes a dict of arrays with a leading dimension N (``strike`` (N, 5),
    ``place`` (N, 2), ``ball``, ``pocket``, ``decision``, ``push_out`` (N,); missing parts
    are 0) and returns ``(obs (N, D), rewards (N,), terminated (N,), truncated (N,), infos)``.
    A table whose game ends is reset at once: its row of ``obs`` is the new episode's first
    observation and ``infos['final_observation']`` holds the last one (rows where
    ``infos['_final_observation']``). Table i is seeded ``seed + i``; results do not depend on
    ``threads``. Opponents are the built-in agents or None (self-play); a callable is not
    supported here (use CueballEnv). ``opponent_seconds`` as CueballEnv's.
    """

    def __init__(self, num_envs: int, game: str = "nine_ball", opponent: str | None = "ghost_ball",
                 noise: Any = None, reward: Any = "win", max_shots: int = 200, action: str = "raw",
                 break_shot: str = "recommended", seat: int | None = 0, max_speed: float = 8.0,
                 simulations: int | None = None, threads: int | None = None, seed: int = 0,
                 opponent_seconds: float | None = None):
        if callable(opponent):
            raise _cueball.InvalidArgument("opponent: a callable opponent is not supported by VectorEnv; use CueballEnv")
        self.options = _Options(game, opponent, noise, reward, max_shots, action, break_shot, seat, max_speed,
                                simulations, opponent_seconds)
        self.num_envs = int(num_envs)
        self.threads = int(threads if threads is not None else (os.cpu_count() or 1))
        self._tables = _native.VectorTables(*self.options.native_args(self.options.opponent), self.num_envs,
                                            self.threads, int(seed))
        pockets = int(self._tables.pockets)
        self.single_observation_space, self.single_action_space = _spaces(game, pockets)
        self.observation_space = _batched(self.single_observation_space, self.num_envs)
        self.action_space = self.single_action_space  # sample per table with sample_actions()
        self._rng = np.random.default_rng(seed)

    def reset(self, *, seed: int | None = None, options: Mapping[str, Any] | None = None
              ) -> tuple[NDArray[np.float32], dict[str, Any]]:
        if seed is not None:
            self._rng = np.random.default_rng(seed)
        obs = self._tables.reset(seed)
        return obs, {"action_mask": self._tables.masks()}

    def sample_actions(self, masks: Mapping[str, Any] | None = None) -> dict[str, NDArray[Any]]:
        """Random actions for every table, the discrete parts drawn within `masks` (a step's infos['action_mask'])."""
        n = self.num_envs
        out: dict[str, NDArray[Any]] = {
            "strike": self._rng.uniform(-1.0, 1.0, (n, 5)),
            "place": self._rng.uniform(-1.0, 1.0, (n, 2)),
        }
        for key in ("ball", "pocket", "decision", "push_out"):
            m = None if masks is None else np.asarray(masks[key])
            size = int(self.single_action_space[key].n)
            if m is None:
                out[key] = self._rng.integers(0, size, n)
            else:
                weights = m.astype(np.float64) + 1e-12
                cumulative = np.cumsum(weights, axis=1)
                u = self._rng.uniform(0.0, 1.0, n) * cumulative[:, -1]
                out[key] = (cumulative < u[:, None]).sum(axis=1).astype(np.int64)
        return out

    def step(self, actions: Mapping[str, Any]) -> tuple[NDArray[np.float32], NDArray[np.float64],
                                                        NDArray[np.bool_], NDArray[np.bool_], dict[str, Any]]:
        n = self.num_envs
        strike = np.asarray(actions.get("strike", np.zeros((n, 5))), dtype=np.float64)
        place = np.asarray(actions.get("place", np.zeros((n, 2))), dtype=np.float64)
        ints = [np.asarray(actions.get(k, np.zeros(n, np.int64)), dtype=np.int64)
                for k in ("ball", "pocket", "decision", "push_out")]
        obs, reward, terminated, truncated, illegal, player, final = self._tables.step(strike, place, *ints)
        done = terminated | truncated
        infos = {"illegal": illegal, "player": player, "final_observation": final, "_final_observation": done,
                 "action_mask": self._tables.masks()}
        return obs, reward, terminated, truncated, infos

    def close(self) -> None:
        pass
