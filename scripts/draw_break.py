#!/usr/bin/python3
"""Draws a break with cue_sim.draw_shot (the README's picture from Python, doc/python_break.png).

By default the best of a million breaks that scripts/search_breaks.py found (seed 1): it pots 9
object balls. Any other strike of the cue ball on the same rack:

    python3 scripts/draw_break.py [--speed 8 --phi 0.002 --theta 0 --a 0 --b 0] [--out file.png]
"""
import argparse
import os

import cue_sim

# search_breaks.py's best (seed 1, shot 296894), as it prints it: a break is chaotic, and these
# figures rounded to four places pot 3 balls instead.
BEST_OF_A_MILLION = dict(speed=9.881480091086635, phi=0.04572913020908084, theta=0.17733293967983288,
                         a=0.24093296969038508, b=-0.2778915560798462)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    for name, value in BEST_OF_A_MILLION.items():
        parser.add_argument("--" + name, type=float, default=value)
    parser.add_argument("--seed", type=int, default=1, help="the rack's jitter seed, as search_breaks.py's")
    parser.add_argument("--out", default=os.path.join(os.path.dirname(__file__), "..", "doc", "python_break.png"))
    args = parser.parse_args()
    engine = cue_sim.Engine("7ft")
    start = engine.rack("eight", gap=1e-4, jitter=5e-5, seed=args.seed)
    strike = {name: getattr(args, name) for name in BEST_OF_A_MILLION}
    shot = cue_sim.simulate(engine, start, **strike)
    cue_sim.draw_shot(engine, start, shot, args.out)
    potted = int((shot.final.motion[1:] == 4).sum())
    print(f"draw_break: {len(shot.events)} events, {potted} object balls potted, "
          f"cue ball {'potted' if shot.final.motion[0] == 4 else 'up'}; wrote {os.path.normpath(args.out)}")


if __name__ == "__main__":
    main()
