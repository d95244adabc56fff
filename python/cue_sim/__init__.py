"""cue_sim: an exact, event-based pool table, from Python without ROS.

    import cue_sim
    engine = cue_sim.Engine("7ft")
    start = engine.rack("eight")
    shot = cue_sim.simulate(engine, start, speed=8.0, phi=0.002)
    shot.events            # a NumPy structured array: time, kind, ball, other, obstacle
    shot.final.positions   # (16, 3) [m]

In a catkin workspace the generated messages live here too (cue_sim.msg, cue_sim.srv); importing
them does not load the engine, which loads on first use of the names below.
"""

from pkgutil import extend_path

# The package spans directories: this one (the API) and the build's (the compiled cue_sim._core and,
# in a catkin build, the generated messages). catkin's devel space joins them when it is imported
# first; when this directory comes first on sys.path (as in a Dask worker started from such a
# process), join them here.
__path__ = extend_path(__path__, __name__)
del extend_path

_API = ("Engine", "State", "Shot", "Samples", "Batch", "TableGeometry", "simulate", "batch", "tables", "models",
        "parameters", "ball_colour", "is_striped", "is_numbered", "EVENT_KINDS", "MOTION")
_GAMES = ("Game", "Ruling", "rules")
_DRAWING = ("draw_shot",)
__all__ = list(_API + _GAMES + _DRAWING)


def __getattr__(name):
    if name in _API:
        from cue_sim import api
        return getattr(api, name)
    if name in _GAMES:
        from cue_sim import games
        return getattr(games, name)
    if name in _DRAWING:
        from cue_sim import drawing  # matplotlib loads only here
        return getattr(drawing, name)
    raise AttributeError(f"module 'cue_sim' has no attribute '{name}'")


def __dir__():
    return sorted(list(globals()) + __all__)
