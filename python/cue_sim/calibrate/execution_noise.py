"""A robot's execution noise from its repeatability test: the same commanded strike played many
times, each observed, the strike each one actually was fitted to its track, and the spread of
those about the command taken as the noise model's standard deviations (speed, phi, theta, a, b:
the node's ~noise/*, cue_sim.physics.ExecutionNoise; Archibald, Altman and Shoham, IJCAI 2009).

Each shot's strike is fitted with the physics held (fit the physics first, from other shots:
cue_sim.calibrate.calibrate), by the same least squares and robust loss as the physics. The
tracks resolve each field only so far (a shot's fitted strike has its own standard error), so the
spread of the fitted strikes is the noise and that error together: the error's mean square is
taken off the spread's (what is left is the noise's variance), and a field whose spread the
error explains is reported as not determined. A mean offset from the command is the robot's bias,
not its noise (the node's noise has zero mean): it is reported beside it. A field commanded at
its limit (a level cue, theta = 0) is folded there by the cue as the node folds it (a strike
below the cloth is a level one), so its noise is half-normal: its deviation is sqrt(2 E[d^2]).
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Sequence

import numpy as np

from cue_sim.calibrate.fit import DEFAULT_NOISE, STAGES, _Problem, _stages
from cue_sim.calibrate.uncertainty import shot_block
from cue_sim.calibrate.tracks import CUE_FIELDS, Track

#: The noise model's fields, in the node's order (~noise/speed ... ~noise/b).
NOISE_FIELDS = CUE_FIELDS
#: Each field's unit in the node's ~noise/* (a and b are metres there, units of R in a strike).
NOISE_UNITS = {"speed": "m/s", "phi": "rad", "theta": "rad", "a": "m", "b": "m"}
#: A deviation is not determined when the tracks' own error on a shot's field is more than this
#: share of the spread seen: what is left for the noise is then mostly the error's estimate.
ERROR_SHARE = 0.7


@dataclass
class NoiseFit:
    """Fitted standard deviations (the node's units) with standard errors, the robot's bias per
    field, what the tracks resolve of one shot's field (the RMS of its standard error), each
    shot's fitted strike, and warnings."""
    deviations: Dict[str, float]
    standard_errors: Dict[str, float]
    bias: Dict[str, float]
    bias_errors: Dict[str, float]
    resolution: Dict[str, float]
    executed: List[Dict[str, float]]
    commanded: Dict[str, float]
    warnings: List[str]
    seconds: float
    shots: int = 0
    determined: Dict[str, bool] = field(default_factory=dict)

    def summary(self) -> str:
        lines = [f"execution noise from {self.shots} strikes of the same command "
                 f"({', '.join(f'{k} {v:.4g}' for k, v in self.commanded.items())}), {self.seconds:.1f} s:"]
        for name in NOISE_FIELDS:
            if not math.isfinite(self.resolution[name]):
                lines.append(f"  {name:<6} not fitted (held at the command)")
                continue
            lines.append(f"  {name:<6} deviation {self.deviations[name]:.3g} +- {self.standard_errors[name]:.2g} "
                         f"[{NOISE_UNITS[name]}]; bias {self.bias[name]:+.3g} +- {self.bias_errors[name]:.2g}; "
                         f"one shot resolves it to {self.resolution[name]:.2g}")
        lines += [f"  warning: {w}" for w in self.warnings]
        return "\n".join(lines)

    def to_yaml(self) -> str:
        """The node's ~noise/* parameters (rosparam load into the table's namespace); a field the
        data does not determine keeps the node's default and says so."""
        lines = [f"# cue_sim.calibrate: execution noise fitted to {self.shots} strikes of one command.",
                 "noise:", "  enabled: true"]
        for name in NOISE_FIELDS:
            if self.determined.get(name):
                lines.append(f"  {name}: {self.deviations[name]!r}  # [{NOISE_UNITS[name]}] +- "
                             f"{self.standard_errors[name]:.3g}")
            elif not math.isfinite(self.resolution[name]):
                lines.append(f"  # {name}: not fitted (held at the command); the node's default stands")
            else:
                lines.append(f"  # {name}: not determined by the data (one shot resolves it to "
                             f"{self.resolution[name]:.3g} {NOISE_UNITS[name]}); the node's default stands")
        return "\n".join(lines) + "\n"


def _in_node_units(name: str, value: float, radius: float) -> float:
    return value * radius if name in ("a", "b") else value


def fit_execution_noise(tracks: Sequence[Track], commanded: Optional[Dict[str, float]] = None, table: str = "7ft",
                        ball_ball_model: Optional[str] = None, cushion_model: Optional[str] = None,
                        params: Optional[Dict[str, float]] = None, noise: float = DEFAULT_NOISE, threads: int = 0,
                        max_evaluations: int = 300, progress=None) -> NoiseFit:
    """The execution noise of `tracks`, each a strike of the same `commanded` shot (speed, phi,
    theta, a, b; else each track's own `commanded`), on the physics given (the module's text).
    `progress(stage, evaluations, cost)` is called as the solver goes, as calibrate() calls it."""
    from cue_sim.api import Engine
    tracks = list(tracks)
    if len(tracks) < 3:
        raise ValueError(f"tracks: at least 3 strikes of the same command for a spread, got {len(tracks)}")
    if commanded is not None:
        missing = [f for f in NOISE_FIELDS if f not in commanded]
        if missing:
            raise ValueError(f"commanded: the whole strike is needed, {', '.join(missing)} missing")
        for track in tracks:
            track.commanded = {"ball": track.struck_ball, **{f: float(commanded[f]) for f in NOISE_FIELDS}}
    elif any(t.commanded is None for t in tracks):
        raise ValueError("commanded: not given, and a track has no commanded strike of its own")
    command = {f: tracks[0].commanded[f] for f in NOISE_FIELDS}
    for track in tracks:
        if any(abs(track.commanded[f] - command[f]) > 1e-9 for f in NOISE_FIELDS):
            raise ValueError(f"{track.label}commanded a different strike ({track.commanded}) from the first "
                             f"({command}): a repeatability test repeats one command")
        # A level cue's elevation is held level: its noise is folded at 0 and what it does (a masse
        # curve, second order in theta) is below what tracks resolve, so fitting it only lends the
        # other fields its freedom.
        track.strike = {"ball": track.struck_ball, **({"theta": 0.0} if command["theta"] <= 0 else {})}
    base = Engine(table, ball_ball_model, cushion_model, **(params or {}))
    models = {"ball_ball": base.models["ball_ball"], "cushion": base.models["cushion"]}
    radius = base.params["ball_radius"]
    begin = time.perf_counter()
    problem = _Problem(tracks, table, models, base.params, [], noise, threads, unknowns="strike")
    x, result = _stages(problem, problem.x0, range(len(STAGES)), max_evaluations, progress)
    executed, errors = [], []
    offset, row = 0, 0
    for track, names, (k, _) in zip(tracks, problem.shot_names, problem.rows):
        values = {name: float(x[offset + n]) for n, name in enumerate(names)}
        executed.append({f: values.get(f, track.strike.get(f, math.nan)) for f in NOISE_FIELDS})
        cov = shot_block(result.jac, result.cost, problem.size, slice(row, row + 2 * len(k)),
                         range(offset, offset + len(names)))
        errors.append({f: float(np.sqrt(abs(cov[names.index(f), names.index(f)]))) if f in names else math.inf
                       for f in NOISE_FIELDS})
        offset += len(names)
        row += 2 * len(k)
    return _spread(executed, errors, command, radius, len(tracks), time.perf_counter() - begin)


def _spread(executed, errors, command, radius: float, shots: int, seconds: float) -> NoiseFit:
    """The deviations, biases and warnings from each shot's fitted strike and its standard error."""
    deviations, standard_errors, bias, bias_errors, resolution, determined = {}, {}, {}, {}, {}, {}
    warnings = []
    n = len(executed)
    for name in NOISE_FIELDS:
        d = np.array([_in_node_units(name, e[name] - command[name], radius) for e in executed])
        se = np.array([_in_node_units(name, e[name], radius) for e in errors])
        resolution[name] = float(np.sqrt(np.mean(se ** 2))) if np.all(np.isfinite(se)) else math.inf
        at_limit = name == "theta" and command[name] <= 0.0
        if not np.all(np.isfinite(se)):  # held, not fitted
            deviations[name], standard_errors[name], bias[name], bias_errors[name] = (math.nan,) * 4
            resolution[name], determined[name] = math.inf, False
            warnings.append(f"{name}: not fitted: the command is a level cue, whose elevation's noise is folded at 0 "
                            "and bends a path too little for tracks to see; command an elevated cue to measure it")
            continue
        if at_limit:  # half-normal: E[d^2] = sigma^2 / 2, the error's square adds to it
            spread2 = 2 * float(np.mean(d ** 2))
            variance = max(spread2 - resolution[name] ** 2, 0.0)
            bias[name], bias_errors[name] = 0.0, 0.0
            # d = max(0, n): E[d^2] = sigma^2 / 2, E[d^4] = 3 sigma^4 / 2, so Var(d^2) = 5 sigma^4 / 4
            # and the spread (twice the mean of d^2) has the standard error sqrt(5) sigma^2 / sqrt(n).
            spread_error = math.sqrt(5.0) * spread2 / math.sqrt(n)
        else:
            spread2 = float(np.var(d, ddof=1))
            variance = max(spread2 - resolution[name] ** 2, 0.0)
            bias[name] = float(np.mean(d))
            bias_errors[name] = float(math.sqrt(spread2 / n))
            spread_error = spread2 * math.sqrt(2.0 / (n - 1))  # the sample variance's, for Gaussian d
        deviations[name] = math.sqrt(variance)
        # d sigma = d variance / (2 sigma); at sigma = 0, the square root of the variance's error
        standard_errors[name] = (spread_error / (2 * deviations[name]) if deviations[name] > 0
                                 else math.sqrt(spread_error))
        determined[name] = bool(np.isfinite(resolution[name]) and resolution[name] < ERROR_SHARE * math.sqrt(spread2))
        if not determined[name]:
            warnings.append(f"{name}: not determined: one shot's tracks resolve it to {resolution[name]:.2g} "
                            f"{NOISE_UNITS[name]}, about the whole spread seen ({math.sqrt(spread2):.2g})")
        elif abs(bias[name]) > 3 * bias_errors[name] and not at_limit:
            warnings.append(f"{name}: the strikes are biased by {bias[name]:+.3g} {NOISE_UNITS[name]} "
                            f"(+- {bias_errors[name]:.2g}) from the command: a calibration of the robot's aim, not noise")
    return NoiseFit(deviations, standard_errors, bias, bias_errors, resolution, executed, dict(command), warnings,
                    seconds, n, determined)
