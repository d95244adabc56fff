#!/usr/bin/env python3
"""rviz on the table it is launched for: rviz/table.rviz with its current view set to the saved
view named "<table> table" (each bundled table has one, framing it), then rviz itself. table.launch
runs it as its rviz node; arguments after the config (roslaunch's __name:= and __log:=) go to rviz.

    rviz_table.py TABLE CONFIG [rviz arguments...]
"""
import copy
import os
import sys
import tempfile

import yaml


def config_for(table, config_path):
    """The configuration's text with the current view framing `table` (unchanged if it has no view of that name)."""
    with open(config_path) as f:
        config = yaml.safe_load(f)
    views = config["Visualization Manager"]["Views"]
    for saved in views.get("Saved", []):
        if saved.get("Name") == f"{table} table":
            current = copy.deepcopy(saved)
            current["Name"] = "Current View"
            views["Current"] = current
            break
    else:
        print(f"rviz_table: no saved view named '{table} table' in {config_path}: the configuration's own view",
              file=sys.stderr)
    return yaml.safe_dump(config, default_flow_style=False, sort_keys=False)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    table, config_path = sys.argv[1], sys.argv[2]
    directory = os.path.join(os.environ.get("ROS_HOME", os.path.expanduser("~/.ros")), "cue_sim")
    os.makedirs(directory, exist_ok=True)
    path = os.path.join(directory, f"table_{table}.rviz")
    # Written whole, then renamed: two launches at once never read half a file.
    with tempfile.NamedTemporaryFile("w", suffix=".rviz", dir=directory, delete=False) as out:
        out.write(config_for(table, config_path))
    os.replace(out.name, path)
    os.execvp("rviz", ["rviz", "-d", path] + sys.argv[3:])


if __name__ == "__main__":
    main()
