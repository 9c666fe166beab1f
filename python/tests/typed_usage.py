"""The module's API as a typed program: checked by `mypy --strict` against
python/cueball/_cueball.pyi (ctest python_stubs) and run by test_stubs.py, so the
stubs and the module cannot drift apart unnoticed."""

import math
import pathlib

import numpy as np
from numpy.typing import NDArray

import cueball
import cueball.dask
from cueball import games

CUT_SHOT = pathlib.Path(__file__).resolve().parents[2] / "docs" / "example-cut-shot.json"


def final_positions(result: cueball.Result) -> NDArray[np.float64]:
    return result.balls["position"]


def main() -> None:
    p: cueball.Parameters = cueball.pool_parameters()
    radius: float = p.ball.radius
    state = cueball.BallState(position=np.array([0.5, 0.5]), velocity=(1.5, np.float32(0.0)))
    later: cueball.BallState = cueball.evolve(state, np.float64(1.0), p)
    x, y = later.position
    t, kind = cueball.next_transition(state, p)
    assert isinstance(kind, str) and t > 0.0 and x > 0.5 and y == 0.5 and radius > 0.0
    shot: cueball.StraightShot = cueball.straight_shot(1.5, params=p)
    plan: cueball.ShotPlan = cueball.plan_natural_roll_shot(x2=1.0)
    ball = cueball.strike_ball(cueball.CueStrike(2.0, side_offset=0.01), params=p)
    impact = cueball.cushion_impact(1.0, math.radians(45), sidespin=np.int64(3))
    reference = cueball.cushion_impact(1.0, math.radians(45), exact_tolerance=1e-11, rolling_table=False)
    assert reference.solver_steps > 0
    assert shot.v1 > 0.0 and plan.v0 > 0.0 and ball.angular_velocity[2] > 0.0 and impact.rebound_speed > 0.0

    result = cueball.simulate(CUT_SHOT, sample_rate=30.0)
    types: NDArray[np.int8] = result.events["type"]
    names = [cueball.EVENT_TYPES[int(code)] for code in types]
    states: cueball.StateArrays = result.state_at(np.linspace(0.0, result.end_time, 11))
    phases: NDArray[np.int8] = states["phase"]
    sampled = result.sample(10.0)
    first: cueball.SegmentArrays = result.segments[0]
    as_dict: dict[str, object] = result.to_dict()
    text: str = result.to_json(indent=-1)
    assert names[0] == "cue_strike" and phases.shape == (3, 11) and sampled["position"].ndim == 3
    assert first["time"][0] == 0.0 and "events" in as_dict and text.startswith("{")
    assert final_positions(result).shape == (3, 2)
    odds = cueball.simulate_batch({"table": "pool_9ft", "rack": {"type": "nine_ball"},
                                   "cue": {"ball": 0, "target": 1, "speed": np.float32(7.0)}},
                                  shots=np.int64(4), seed=1, noise="tournament")
    assert odds["shots"] == 4
    many: cueball.ManyOutcomes = cueball.simulate_many(None, np.array([[3.0, 0.0, 0.0, 0.0, 0.0]]), threads=1)
    pocketed: NDArray[np.bool_] = many["pocketed"]
    assert pocketed.shape == (1, 10) and many["first_contact"][0] == 1
    on_table = np.ones((1, 10), dtype=np.bool_)
    on_table[0, 9] = False
    sparse = cueball.simulate_many(None, np.array([[3.0, 0.0, 0.0, 0.0, 0.0]]), present=on_table,
                                   noise={"aim_deg": 0.1}, seed=np.uint64(2))
    assert not sparse["present"][0, 9] and sparse["pocket"][0, 9] == -1
    bounds: list[tuple[int, int]] = cueball.dask.chunk_bounds(10, 4)
    assert bounds == [(0, 4), (4, 8), (8, 10)]
    try:
        cueball.simulate(sample_rate=-1.0)
    except cueball.InvalidArgument as e:
        field: str = e.field
        assert field == "sample_rate"
    seconds: float = cueball._time_run_scenario(None, 1)
    assert seconds > 0.0
    objects()


def objects() -> None:
    table: cueball.Table = cueball.Table.preset("pool_9ft")
    normal: tuple[float, float] = table.cushions[0].inward_normal
    names: list[str] = [c.name for c in table.cushions] + [p.name for p in table.pockets]
    assert abs(normal[0] ** 2 + normal[1] ** 2 - 1.0) < 1e-12 and "bottom-left" in names
    assert table.ball_on_table(np.array([1.0, 0.6])) and not table.inside_playing_area((5.0, 5.0))
    spec: cueball.TableSpec = cueball.preset_table_spec("pool_9ft")
    spec.length = 2.24
    small = cueball.build_table(spec)
    assert small.length == 2.24 and cueball.Table.from_json(small.to_json()) == small
    rack: list[cueball.PlacedBall] = cueball.rack_nine_ball(table, cueball.RackOptions(gap_sigma=0.001, seed=1))
    spots: cueball.SnookerSpots = cueball.snooker_spots(cueball.snooker_table_12ft())
    assert len(rack) == 10 and spots.blue[0] > 0.0 and cueball.foot_spot(table)[0] > cueball.head_string_x(table)
    scenario = cueball.Scenario(table, rack, cueball.ShotStrike(np.float32(7.0), target=1),
                                settings=cueball.SimulationSettings(max_events=50000))
    result = cueball.simulate(scenario)
    replay: cueball.Scenario = result.scenario
    cue: cueball.ShotStrike | None = replay.cue
    assert cue is not None and cue.target == 1 and cueball.simulate(replay).to_json() == result.to_json()
    assert cueball.Scenario.from_json(scenario.to_json()) == scenario and scenario.parameters.ball.radius > 0.0
    strike = cueball.CueStrike.from_units(3.0, aim_deg=10.0, side=0.2, radius=scenario.parameters.ball.radius)
    units: dict[str, float] = strike.in_units(radius=scenario.parameters.ball.radius)
    assert abs(units["side"] - 0.2) < 1e-12
    a = cueball.BallState((0.0, 0.0), (1.0, 0.0))
    b = cueball.BallState((2 * cueball.pool_parameters().ball.radius, 0.0))
    after: cueball.BallCollisionResult = cueball.resolve_ball_collision(a, b, contact=cueball.ball_collision_frictionless(1.0))
    assert after.b.velocity == (1.0, 0.0) and cueball.balls_approaching(a, b)
    data = cueball.CushionFitData([cueball.HeadOnRebound(v, 0.9 * v) for v in (0.5, 1.0, 1.5)])
    fit: cueball.CushionFit = cueball.fit_cushion(data, options=cueball.CushionFitOptions(grid_step=0.1))
    assert fit.poorly_separated and 0.0 < fit.restitution <= 1.0

    game: games.GameState = games.new_game(games.default_config("nine_ball"), seed=1)
    legal: dict[str, object] = games.legal_actions(game)
    played: games.GameStep = games.play(game, games.Action(speed=8.0, target=1, place=(0.5, 0.6)), seed=2)
    foul: object = played.ruling["foul"]
    after_break: games.GameState = games.GameState.from_json(played.next.to_json())
    assert legal["shoot"] and after_break == played.next and game.shots == 0 and foul in (None, *[str(foul)])
    record: games.GameRecord = games.play_game("nine_ball", ("random", "random"), seed=3)
    records: list[games.GameRecord] = games.records_from_json(games.records_to_json([record]))
    assert records[0].replay() is None and record.end.over


if __name__ == "__main__":
    main()
