"""Stubs of cueball.games, the extension's submodule `games` (python/src/games.cpp)."""

from typing import Any

from ._cueball import Result, Scenario

_Region = None | str | dict[str, Any]

class GameConfig:
    @property
    def kind(self) -> str: ...
    table: str
    max_shots: int
    fouls_to_lose: int
    nine_on_break_wins: bool
    push_out: bool
    reds: int
    miss_rule: bool
    race_to: int
    @property
    def noise(self) -> dict[str, float]: ...
    @noise.setter
    def noise(self, noise: str | dict[str, float] | None) -> None: ...
    def to_dict(self) -> dict[str, Any]: ...
    @staticmethod
    def from_dict(d: dict[str, Any]) -> GameConfig:
        """A config from its dict (every key but 'kind' optional); validated."""

def default_config(kind: str) -> GameConfig:
    """The config a game is played with unless changed: its table and the variants' defaults."""

class GameState:
    @property
    def kind(self) -> str: ...
    @property
    def config(self) -> GameConfig: ...
    @property
    def table(self) -> Scenario: ...
    @property
    def balls(self) -> dict[int, tuple[float, float]]: ...
    @property
    def phase(self) -> str: ...
    @property
    def to_shoot(self) -> int: ...
    @property
    def breaker(self) -> int: ...
    @property
    def ball_in_hand(self) -> _Region: ...
    @property
    def cue_must_leave_kitchen(self) -> bool: ...
    @property
    def scores(self) -> tuple[int, int]: ...
    @property
    def fouls_in_a_row(self) -> tuple[int, int]: ...
    @property
    def on(self) -> list[int]: ...
    @property
    def groups(self) -> tuple[str, str]: ...
    @property
    def decisions(self) -> list[str]: ...
    @property
    def push_out_available(self) -> bool: ...
    @property
    def free_ball(self) -> bool: ...
    @property
    def shots(self) -> int: ...
    @property
    def over(self) -> bool: ...
    @property
    def winner(self) -> int | None: ...
    @property
    def truncated(self) -> bool: ...
    @property
    def end_reason(self) -> str: ...
    @property
    def cue_ball(self) -> int: ...
    def to_json(self, indent: int = 1) -> str: ...
    def to_dict(self) -> dict[str, Any]: ...
    @staticmethod
    def from_json(text: str) -> GameState:
        """Reads and checks a state file's JSON text."""
    def copy(self) -> GameState: ...

def new_game(config: GameConfig | str, seed: int = 0) -> GameState:
    """A game ready to break: config is a GameConfig or a game's name."""

class Action:
    def __init__(
        self,
        speed: float = 3.0,
        aim_deg: float | None = None,
        target: int | None = None,
        elevation_deg: float = 0.0,
        side: float = 0.0,
        height: float = 0.0,
        place: tuple[float, float] | None = None,
        call: tuple[int, int] | None = None,
        push_out: bool = False,
        nominate: int | None = None,
        decision: str | None = None,
    ) -> None: ...
    @property
    def decision(self) -> str | None: ...
    @property
    def speed(self) -> float: ...
    @property
    def aim_deg(self) -> float: ...
    @property
    def target(self) -> int | None: ...
    @property
    def elevation_deg(self) -> float: ...
    @property
    def side(self) -> float: ...
    @property
    def height(self) -> float: ...
    @property
    def place(self) -> tuple[float, float] | None: ...
    @property
    def called_ball(self) -> int | None: ...
    @property
    def called_pocket(self) -> int | None: ...
    @property
    def push_out(self) -> bool: ...
    @property
    def nominate(self) -> int | None: ...
    def to_json(self, indent: int = -1) -> str: ...
    def to_dict(self) -> dict[str, Any]: ...
    @staticmethod
    def from_json(text: str) -> Action:
        """An action from its JSON."""

def legal_actions(state: GameState) -> dict[str, Any]:
    """What the player to act may do."""

class GameStep:
    @property
    def action(self) -> Action: ...
    @property
    def ruling(self) -> dict[str, Any]: ...
    @property
    def facts(self) -> dict[str, Any] | None: ...
    @property
    def next(self) -> GameState: ...
    @property
    def shot(self) -> Scenario | None: ...
    @property
    def result(self) -> Result | None: ...
    def to_json(self, indent: int = 1) -> str: ...

def play(state: GameState, action: Action, seed: int = 0) -> GameStep:
    """Plays the action; step.next is the state after it."""

def choose_action(
    state: GameState,
    agent: str = "random",
    seed: int = 0,
    simulations: int | None = None,
    noise: str | dict[str, float] | None = None,
    seconds: float | None = None,
) -> Action:
    """The agent's action for the player to act (always legal); seconds: a wall-clock budget a decision."""

class GameRecord:
    @property
    def players(self) -> tuple[str, str]: ...
    @property
    def seed(self) -> int: ...
    @property
    def start(self) -> GameState: ...
    @property
    def steps(self) -> list[dict[str, Any]]:
        """[{action, seed, ruling, state, reasoning}]: reasoning the agent's {summary, considered} or None."""
    @property
    def end(self) -> GameState: ...
    def tally(self) -> dict[str, tuple[int, int]]: ...
    def replay(self) -> dict[str, Any] | None: ...

def play_game(
    config: GameConfig | str,
    players: tuple[str, str] | list[str] = ("random", "random"),
    seed: int = 0,
    simulations: int | None = None,
    noise: str | dict[str, float] | None = None,
    seconds: float | None = None,
) -> GameRecord:
    """Plays one game between two agents and records it."""

def records_to_json(records: list[GameRecord], indent: int = -1) -> str:
    """The record file's JSON text."""

def records_from_json(text: str) -> list[GameRecord]:
    """The games of a record file's JSON text."""
