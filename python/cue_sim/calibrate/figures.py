"""A fit drawn: each shot's observed positions against the fitted simulation's paths on the table,
and the residuals against time (matplotlib, no display needed)."""
from __future__ import annotations

from typing import Optional, Sequence

import numpy as np

from cue_sim.calibrate.fit import Calibration
from cue_sim.calibrate.tracks import Track


def draw_fit(result: Calibration, tracks: Sequence[Track], path: Optional[str] = None, shots: int = 4,
             dpi: int = 130):
    """The first `shots` shots, one row each: the table from above with every observed position (dots)
    and the fitted paths (lines) in the balls' colours, and beside it each ball's residual [mm] against
    time since the fitted strike (outliers, beyond 5 noises, as crosses). Saved to `path` if given;
    returns the Figure."""
    from matplotlib.figure import Figure

    from cue_sim.api import ball_colour
    from cue_sim.drawing import _draw_table
    engine = result.engine()
    count = min(shots, len(tracks))
    figure = Figure(figsize=(13, 3.4 * count))
    axes = figure.subplots(count, 2, squeeze=False, gridspec_kw={"width_ratios": [1.7, 1]})
    for row, (track, report, predicted) in enumerate(zip(tracks[:count], result.shots, result.predicted)):
        table, residual = axes[row]
        _draw_table(table, engine)
        t = track.times - report.unknowns["t0"]
        for j, ball in enumerate(track.ball_ids):
            colour = ball_colour(int(ball))
            seen = np.all(np.isfinite(track.positions[:, j]), axis=1)
            table.plot(predicted[:, j, 0], predicted[:, j, 1], color=colour, lw=1.2, zorder=6)
            table.scatter(track.positions[seen, j, 0], track.positions[seen, j, 1], s=4, color=colour,
                          edgecolors="black", linewidths=0.2, zorder=7)
            miss = 1e3 * np.linalg.norm(track.positions[seen, j] - predicted[seen, j], axis=1)
            outlier = miss > 5e3 * result.noise
            ink = colour if sum(colour) < 2.7 else (0.55, 0.55, 0.55)  # the cue ball's white, seen on white
            residual.plot(t[seen][~outlier], miss[~outlier], ".", ms=3, color=ink, mec="black", mew=0.3,
                          label=f"ball {ball}")
            residual.plot(t[seen][outlier], np.full(outlier.sum(), 5e3 * result.noise), "x", ms=4, color=ink)
        table.set_aspect("equal")
        table.set_title(f"{report.name}: observed (dots), fitted (lines); RMS {1e3 * report.rms:.2f} mm, "
                        f"{report.outliers} outliers", fontsize=8)
        table.set_xticks([])
        table.set_yticks([])
        residual.set_xlabel("time since the fitted strike [s]", fontsize=8)
        residual.set_ylabel("|observed - fitted| [mm]", fontsize=8)
        residual.axhline(1e3 * result.noise * np.sqrt(2), color="grey", lw=0.8, ls="--")
        residual.set_ylim(0, 5.5e3 * result.noise)
        residual.legend(fontsize=7, loc="upper right")
    figure.suptitle(", ".join(f"{n} {result.values[n]:.4g} +- {result.standard_errors[n]:.2g}" for n in result.fitted),
                    fontsize=9)
    figure.tight_layout()
    if path is not None:
        figure.savefig(path, dpi=dpi)
    return figure
