"""A shot drawn from above with matplotlib: the table, every ball's path, where the balls started
and stopped, and the events (collisions, cushions, pockets) where they happened.

    shot = cue_sim.simulate(engine, start, speed=8.0, phi=0.002)
    cue_sim.draw_shot(engine, start, shot, "break.png")

Paths are the exact trajectories, sampled finely between events and exact at every event (the
balls' positions at an event come from simulating to that event's time), so a path bends where
the ball did.
"""
from __future__ import annotations

from typing import Dict, Optional, Tuple

import numpy as np

from matplotlib.figure import Figure
from matplotlib.patheffects import Normal, Stroke

from cue_sim.api import EVENT_KINDS, Engine, Shot, State, _core, ball_colour, is_numbered, is_striped, simulate

#: Points a path gets between the strike and rest (the engine's sample period is clamped to
#: [1 ms, 10 s] and 10000 samples, so long shots get fewer).
PATH_POINTS = 4000
#: Events whose positions are computed exactly (each a simulation to its time); past this the
#: paths rely on the samples alone.
MAX_EXACT_EVENTS = 2000
#: The drawn depth of a cushion's rubber behind its nose line, and of the rail behind it [m].
RUBBER = 0.03
RAIL = 0.1

CLOTH = (0.05, 0.5, 0.22)
CUSHION = (0.02, 0.36, 0.15)
RAIL_WOOD = (0.36, 0.2, 0.09)
EVENT_KINDS_BY_NAME = {name: kind for kind, name in EVENT_KINDS.items()}


def _ball_index(state: State) -> Dict[int, int]:
    return {int(ball): i for i, ball in enumerate(state.ids)}


#: How long before a pocketed event a ball's position is taken for it [s]: once in, a ball's
#: position is its pocket's centre; 1 ns earlier it is on the capture circle to within nanometres.
BEFORE_POCKET = 1e-9


def _positions_at(engine: Engine, start: State, shot: Shot, times: np.ndarray) -> Dict[float, np.ndarray]:
    """Every ball on the table's (x, y) at each time, exactly (the shot run again up to it); NaN
    for balls already pocketed, and a ball pocketed at that very time where it went in."""
    pocketed = EVENT_KINDS_BY_NAME["pocketed"]
    index = _ball_index(start)
    out = {}
    for t in times:
        at = simulate(engine, start, until=float(t), **shot.strike).final
        xy = np.where((at.motion == 4)[:, None], np.nan, at.positions[:, :2])
        going_in = shot.events[(shot.events["time"] == t) & (shot.events["kind"] == pocketed)]["ball"]
        if len(going_in):
            before = simulate(engine, start, until=max(float(t) - BEFORE_POCKET, 0.0), **shot.strike).final
            for ball in going_in:
                xy[index[int(ball)]] = before.positions[index[int(ball)], :2]
        out[float(t)] = xy
    return out


def paths(engine: Engine, start: State, shot: Shot):
    """The balls along `shot` (what cue_sim.simulate gave for `start` on `engine`): times (T,) [s],
    positions (T, balls, 2) [m] in start's ball order (NaN once pocketed), sampled finely and exact
    at every event; and the positions at each event's time {time: (balls, 2)}, a ball pocketed at
    that time where it crossed the capture circle."""
    end = shot.time_to_rest if shot.until is None else min(shot.until, shot.time_to_rest)
    end = max(end, 1e-3)
    period = min(10.0, max(1e-3, end / PATH_POINTS, end / 9999))
    sampled = simulate(engine, start, until=shot.until, sample_period=period, **shot.strike).samples
    times = list(sampled.times)
    positions = list(np.where((sampled.motion == 4)[..., None], np.nan, sampled.positions[..., :2]))
    event_times = np.unique(shot.events["time"])[:MAX_EXACT_EVENTS]
    exact = _positions_at(engine, start, shot, event_times)
    final = shot.final.positions[:, :2].copy()
    final[shot.final.motion == 4] = np.nan
    for t, at in exact.items():
        times.append(t)
        positions.append(at)
    times.append(end)
    positions.append(final)
    order = np.argsort(times, kind="stable")
    return np.asarray(times)[order], np.asarray(positions)[order], exact


def _draw_table(ax, engine: Engine) -> None:
    from matplotlib.patches import Circle, Polygon, Rectangle

    g = engine.geometry
    cx, cy = g.cloth_centre
    half = np.array([g.cloth_length / 2, g.cloth_width / 2])
    outer = half + RUBBER + RAIL
    ax.add_patch(Rectangle((cx - outer[0], cy - outer[1]), 2 * outer[0], 2 * outer[1], color=RAIL_WOOD, zorder=0))
    bed = half + RUBBER
    ax.add_patch(Rectangle((cx - bed[0], cy - bed[1]), 2 * bed[0], 2 * bed[1], color=CUSHION, zorder=1))
    ax.add_patch(Rectangle((cx - half[0], cy - half[1]), 2 * half[0], 2 * half[1], color=CLOTH, zorder=1))
    clip = Rectangle((cx - bed[0], cy - bed[1]), 2 * bed[0], 2 * bed[1], transform=ax.transData)
    for x, y, r in g.pockets.values():  # the capture circle, where it lies on the table
        pocket = Circle((x, y), r, color="black", zorder=2)
        ax.add_patch(pocket)
        pocket.set_clip_path(clip)
    for _, a, b in g.cushions:
        a, b = np.asarray(a), np.asarray(b)
        direction = (b - a) / np.linalg.norm(b - a)
        back = -np.array([-direction[1], direction[0]]) * RUBBER  # away from the play (on the left)
        ax.add_patch(Polygon([a, b, b + back, a + back], closed=True, color=CUSHION, zorder=3))
    for _, centre, r in g.jaws:
        if r > 0:
            ax.add_patch(Circle(centre, r, color=CUSHION, zorder=3))
    if g.pockets:  # the head string, where a pool break is played from
        ax.plot([g.cloth_centre[0] - g.cloth_length / 4] * 2, [cy - half[1], cy + half[1]], color="white",
                alpha=0.25, lw=0.8, zorder=2)


def _draw_ball(ax, xy, ball: int, radius: float, final: bool, ball_set: str) -> None:
    from matplotlib.patches import Circle

    colour = ball_colour(ball, ball_set=ball_set)
    if not final:  # where it started: an outline
        ax.add_patch(Circle(xy, radius, fill=False, edgecolor=colour, lw=1.0, ls="--", zorder=6))
        return
    striped = is_striped(ball, ball_set=ball_set)
    ax.add_patch(Circle(xy, radius, facecolor=colour, edgecolor="black", lw=0.6, zorder=7))
    if striped:  # from above, a white cap in a coloured ring
        ax.add_patch(Circle(xy, 0.55 * radius, facecolor=ball_colour(0), lw=0, zorder=8))
    if is_numbered(ball, ball_set=ball_set):
        ax.text(xy[0], xy[1], str(ball), ha="center", va="center", fontsize=5.5, zorder=9,
                color=_core.number_colour(ball))


def _draw_events(ax, shot: Shot, exact: Dict[float, np.ndarray], index: Dict[int, int], radius: float) -> None:
    styles = {"ball_ball": ("x", "white", "ball-ball"), "ball_cushion": ("^", "orange", "cushion"),
              "ball_jaw": ("^", "red", "jaw"), "pocketed": ("o", "yellow", "pocketed"),
              "ball_slate": ("v", "cyan", "lands"), "off_table": ("X", "red", "leaves the table")}
    seen = set()
    for event in shot.events:
        kind = EVENT_KINDS.get(int(event["kind"]))
        at = exact.get(float(event["time"]))
        if kind not in styles or at is None or int(event["ball"]) not in index:
            continue
        xy = at[index[int(event["ball"])]]
        if kind == "ball_ball" and int(event["other"]) in index:
            xy = (xy + at[index[int(event["other"])]]) / 2  # the contact point
        marker, colour, label = styles[kind]
        ax.plot(*xy, marker=marker, ms=4 if marker != "o" else 6, mfc="none" if marker == "o" else colour,
                mec=colour, mew=1.0, ls="none", zorder=10, label=None if label in seen else label)
        seen.add(label)


def draw_shot(engine: Engine, start: State, shot: Shot, path: Optional[str] = None, title: Optional[str] = None,
              ax=None, dpi: int = 150, size: Tuple[float, float] = (9.0, 5.2)):
    """Draws `shot` (what cue_sim.simulate gave for `start` on `engine`) from above: the table, each
    ball's path in its colour, its start (dashed outline) and where it stopped, and the events
    (ball-ball contacts, cushion and jaw hits, pockets) where they happened.

    path: a file to save to (PNG, or any format matplotlib knows by its extension); None to only
    return the figure. title: above the table (default: the strike). ax: a matplotlib Axes to draw
    into (pyplot's or a notebook's, say) instead of a new figure of its own. Returns the Figure.
    """
    if not shot.strike:
        raise ValueError("shot has no strike: pass a Shot that cue_sim.simulate returned")
    radius = engine.params["ball_radius"]
    index = _ball_index(start)
    times, positions, exact = paths(engine, start, shot)
    if ax is None:  # a figure of its own, outside pyplot: no display needed, nothing global
        figure = Figure(figsize=size)
        ax = figure.subplots()
    else:
        figure = ax.figure
    _draw_table(ax, engine)
    ball_set = engine.ball_set  # the table's own balls: pool's, carom's or snooker's
    for ball, i in index.items():
        track = positions[:, i]
        if np.nanmax(np.abs(track - start.positions[i, :2]), initial=0.0) > 1e-6:
            ax.plot(track[:, 0], track[:, 1], color=ball_colour(ball, ball_set=ball_set), lw=1.1, zorder=5,
                    solid_capstyle="round",
                    path_effects=[Stroke(linewidth=2.0, foreground=(0, 0, 0, 0.45)), Normal()])  # seen on any cloth
        _draw_ball(ax, start.positions[i, :2], ball, radius, final=False, ball_set=ball_set)
        if shot.final.motion[i] != 4:
            _draw_ball(ax, shot.final.positions[i, :2], ball, radius, final=True, ball_set=ball_set)
    _draw_events(ax, shot, exact, index, radius)
    s = shot.strike
    ax.set_title(title if title is not None else
                 f"ball {s['ball']}: {s['speed']:.4g} m/s, phi {s['phi']:.4g} rad, theta {s['theta']:.4g}, "
                 f"a {s['a']:.4g}, b {s['b']:.4g}; {len(shot.events)} events, "
                 f"{int((shot.final.motion == 4).sum())} pocketed, {shot.time_to_rest:.2f} s", fontsize=9)
    ax.set_aspect("equal")
    ax.set_xlabel("x [m] (table frame)")
    ax.set_ylabel("y [m]")
    if ax.get_legend_handles_labels()[0]:
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.1), ncol=4, fontsize=7, facecolor=CLOTH,
                  labelcolor="white")
    g = engine.geometry
    margin = RUBBER + RAIL
    ax.set_xlim(g.cloth_centre[0] - g.cloth_length / 2 - margin, g.cloth_centre[0] + g.cloth_length / 2 + margin)
    ax.set_ylim(g.cloth_centre[1] - g.cloth_width / 2 - margin, g.cloth_centre[1] + g.cloth_width / 2 + margin)
    figure.tight_layout()
    if path is not None:
        figure.savefig(path, dpi=dpi)
    return figure
