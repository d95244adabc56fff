#!/usr/bin/env python3
"""rviz on the table it is launched for: rviz/table.rviz with its current view set to the saved
view named "<table> table" (each bundled table has one, framing it), then rviz itself. table.launch
runs it as its rviz node; arguments after the config (roslaunch's __name:= and __log:=) go to rviz.
With --robot PARAM, a robot's model (a URDF in the parameter PARAM, such as robot.launch's cue
robot) is shown too.

    rviz_table.py TABLE CONFIG [--robot PARAM] [rviz arguments...]
"""
import copy
import os
import sys
import tempfile

import yaml


def robot_display(description):
    """An rviz RobotModel display of the URDF in the parameter `description`."""
    return {"Alpha": 1, "Class": "rviz/RobotModel", "Collision Enabled": False, "Enabled": True,
            "Name": f"Robot ({description})", "Robot Description": description, "TF Prefix": "",
            "Update Interval": 0, "Value": True, "Visual Enabled": True}


def config_for(table, config_path, robot=None):
    """The configuration's text with the current view framing `table` (unchanged if it has no view of
    that name), and the robot whose URDF is in the parameter `robot` shown, if given."""
    with open(config_path) as f:
        config = yaml.safe_load(f)
    if robot:
        config["Visualization Manager"]["Displays"].append(robot_display(robot))
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
    rest = sys.argv[3:]
    robot = None
    if len(rest) >= 2 and rest[0] == "--robot":
        robot, rest = rest[1], rest[2:]
    directory = os.path.join(os.environ.get("ROS_HOME", os.path.expanduser("~/.ros")), "cue_sim")
    os.makedirs(directory, exist_ok=True)
    path = os.path.join(directory, f"table_{table}.rviz")
    # Written whole, then renamed: two launches at once never read half a file.
    with tempfile.NamedTemporaryFile("w", suffix=".rviz", dir=directory, delete=False) as out:
        out.write(config_for(table, config_path, robot))
    os.replace(out.name, path)
    os.execvp("rviz", ["rviz", "-d", path] + rest)


if __name__ == "__main__":
    main()
