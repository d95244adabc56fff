#!/usr/bin/env python3
"""The folder arrows run one way (doc/architecture.md, "Layers"): every #include of the package's
own headers goes from a file to one of its own layer or a lower one, and the ROS-free parts include
nothing of ROS. Prints each include that goes the wrong way and exits non-zero if there is one.

    scripts/check_layers.py [ROOT] [--junit FILE]    (FILE: the result as a JUnit file, for catkin)
"""
import pathlib
import re
import sys
from xml.sax.saxutils import escape, quoteattr

# The physics core, lowest first: what a folder holds may use what the folders before it hold.
PHYSICS_LAYERS = [
    ("models and table", ["models", "table"]),
    ("engine", ["engine"]),
    ("supports", ["supports"]),
    ("contacts", ["contacts"]),
    ("search", ["search"]),
    ("shots", ["shots"]),
]
# The public headers of include/cue_sim/physics/ that belong above the models and the table (the
# rest are the vocabulary of the models and the table: balls, events, coefficients, motion).
PHYSICS_PUBLIC = {
    "engine.hpp": "engine",
    "simulation.hpp": "search",
    "scan.hpp": "search",
    "polynomial.hpp": "search",
    "batch.hpp": "shots",
    "cue_aim.hpp": "shots",
    "cue_sweep.hpp": "shots",
    "execution_noise.hpp": "shots",
    "thread_pool.hpp": "shots",
}
# The package around the core, lowest first; the adapters (node, python, tools, examples) may use
# everything and are used by nothing.
PACKAGE_LAYERS = [
    ("physics", ["physics"]),
    ("game", ["game"]),
    ("table_description", ["table_description"]),
    ("scene", ["scene"]),
    ("evaluation", ["evaluation"]),
    ("session", ["session"]),
    ("camera", ["camera"]),
    ("learning", ["learning"]),
    ("calibration", ["calibration"]),
    ("adapters", ["node", "python", "tools", "examples"]),
]
# Headers of ROS that the ROS-free layers must not include.
ROS_INCLUDE = re.compile(r"^(ros|tf2|tf2_ros|sensor_msgs|geometry_msgs|visualization_msgs|std_msgs|nodelet|"
                         r"image_transport|camera_info_manager|dynamic_reconfigure|rosbag|cue_sim/[A-Z])")
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^">]+)[">]', re.M)


def rank(layers, name):
    for index, (_, folders) in enumerate(layers):
        if name in folders:
            return index
    return None


def physics_rank(path):
    """The layer of a physics file or header, from its path relative to src/ or include/cue_sim/."""
    parts = path.split("/")
    if parts[0] != "physics":
        return None
    if len(parts) == 2:  # a public header: include/cue_sim/physics/X
        return rank(PHYSICS_LAYERS, PHYSICS_PUBLIC.get(parts[1], "models"))
    return rank(PHYSICS_LAYERS, parts[1])


def package_rank(path):
    return rank(PACKAGE_LAYERS, path.split("/")[0])


def target_of(include):
    """The included header relative to src/ or include/cue_sim/, or None if not the package's."""
    if include.startswith("cue_sim/") and include[len("cue_sim/"):][:1].islower():
        return include[len("cue_sim/"):]
    first = include.split("/")[0]
    if first in {folders[0] for _, folders in PACKAGE_LAYERS} | {"node", "python", "tools", "examples"}:
        return include
    return None


def write_junit(path, wrong):
    failure = f"<failure message={quoteattr(f'{len(wrong)} includes go the wrong way')}>" \
              f"{escape(chr(10).join(wrong))}</failure>" if wrong else ""
    pathlib.Path(path).parent.mkdir(parents=True, exist_ok=True)
    pathlib.Path(path).write_text(
        f'<?xml version="1.0" encoding="UTF-8"?>\n<testsuite name="check_layers" tests="1" failures="{int(bool(wrong))}" '
        f'errors="0">\n  <testcase classname="layers" name="includes_go_one_way">{failure}</testcase>\n</testsuite>\n')


def main():
    args = sys.argv[1:]
    junit = None
    if "--junit" in args:
        at = args.index("--junit")
        junit = args[at + 1]
        del args[at:at + 2]
    root = pathlib.Path(args[0] if args else pathlib.Path(__file__).resolve().parent.parent)
    files = []
    for base in (root / "src", root / "include" / "cue_sim"):
        files += [(base, f) for f in sorted(base.rglob("*")) if f.suffix in {".hpp", ".cpp", ".def", ".h"}]
    wrong = []
    for base, path in files:
        here = path.relative_to(base).as_posix()
        here_package = package_rank(here)
        here_physics = physics_rank(here)
        for include in INCLUDE.findall(path.read_text()):
            there = target_of(include)
            if there is None:
                if here_package is not None and here_package < rank(PACKAGE_LAYERS, "node") and \
                        ROS_INCLUDE.match(include):
                    wrong.append(f"{path.relative_to(root)}: includes {include}: no ROS below the adapters")
                continue
            there_package = package_rank(there)
            if here_package is not None and there_package is not None and there_package > here_package:
                wrong.append(f"{path.relative_to(root)}: includes {include}: "
                             f"{PACKAGE_LAYERS[here_package][0]} may not use {PACKAGE_LAYERS[there_package][0]}")
            there_physics = physics_rank(there)
            if here_physics is not None and there_physics is not None and there_physics > here_physics:
                wrong.append(f"{path.relative_to(root)}: includes {include}: the physics core's "
                             f"{PHYSICS_LAYERS[here_physics][0]} may not use its {PHYSICS_LAYERS[there_physics][0]}")
    for line in wrong:
        print(line)
    order = " -> ".join(name for name, _ in PHYSICS_LAYERS)
    print(f"check_layers: {len(files)} files; physics core {order}; "
          f"{'all includes go one way' if not wrong else f'{len(wrong)} includes go the wrong way'}")
    if junit:
        write_junit(junit, wrong)
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main())
