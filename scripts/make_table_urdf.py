#!/usr/bin/env python3
"""Writes urdf/table_7ft.urdf, table_9ft.urdf, table_carom.urdf and table_snooker.urdf.

The link naming convention the simulator reads (doc/tools.md, "Describing a table in URDF"):
  table          root link: the table frame, origin at the cloth's centre, cloth top at z = 0
  cloth          collision box: the playing surface is its footprint; its top at z = 0
  cushion_<name> collision box; the rubber nose is the top edge of the box face at local +y,
                 running along local x; play lies towards local +y
  pocket_<name>  collision cylinder: a ball whose centre enters the circle drops
  jaw_<name>     collision cylinder: a circular cushion (pocket jaw); a straight cushion
                 ends where its jaw begins
  rails_<name>   collision box: the wooden rail; a ball flying over a cushion lands on the
                 rails' top, and beyond their outer edges it falls off the table
  balls          collision sphere and inertial mass: the balls the table is played with
                 (optional; without it, the pool ball of physics_params.def)
Other links (legs, a snooker table's markings) are visual only. All joints are fixed.
Run it again after changing a dimension here; the files are committed.
"""
import math
import os

CUSHION_WIDTH = 0.05  # [m] nose to rail
NOSE_HEIGHT = 0.036576  # [m] 0.64 x 2R
RAIL_WIDTH = 0.10  # [m] wood beyond the cushion
RAIL_BELOW = 0.005  # [m] how far the rail reaches below the cloth's top
JAW_RADIUS = 0.01  # [m] the rounded end of a cushion at a pocket (pool tables)
CAPTURE_RADIUS = 0.15  # [m] pocket capture circles

# The balls each table is played with: (radius [m], mass [kg], the set's name).
POOL_BALL = (0.028575, 0.170097, "pool")  # WPA: 2 1/4 in, 5 1/2 to 6 oz (physics_params.def's default)
CAROM_BALL = (0.03075, 0.210, "carom")  # UMB: 61 to 61.5 mm, 205 to 220 g
SNOOKER_BALL = (0.02625, 0.142, "snooker")  # WPBSA: 52.5 mm (+/- 0.05 mm); no mass in the rules, 142 g a match set's
# A snooker table's pockets. The WPBSA's templates are not public. The mouths, between the
# cushions' noses where their rounded knuckles begin, are those of one public project
# (polymorvic/deep-peep-snooker: corner 89 mm, middle 83 mm); pooltool's generic snooker table
# also has its middle pockets the narrower. The knuckles' radii are this simulator's choice: the
# narrowest gap a ball passes is then 25 mm (corner) and 10.5 mm (middle) wider than the ball.
SNOOKER_CORNER_MOUTH, SNOOKER_MIDDLE_MOUTH = 0.089, 0.083  # [m]
SNOOKER_CORNER_JAW, SNOOKER_MIDDLE_JAW = 0.02, 0.01  # [m]


def capture_centre(jaw1, jaw2, outward):
    """Centre of the capture circle through both jaw centres, outward of their chord."""
    half = math.dist(jaw1, jaw2) / 2
    mid = ((jaw1[0] + jaw2[0]) / 2, (jaw1[1] + jaw2[1]) / 2)
    norm = math.hypot(*outward)
    depth = math.sqrt(CAPTURE_RADIUS**2 - half**2)
    return (mid[0] + depth * outward[0] / norm, mid[1] + depth * outward[1] / norm)


def fmt(*values):
    return " ".join(f"{v:.9f}" for v in values)


def link(name, collision=None, visual=None):
    out = [f'  <link name="{name}">']
    for tag, item in (("visual", visual), ("collision", collision)):
        if item is None:
            continue
        geometry, xyz, material = item
        out.append(f"    <{tag}>")
        out.append(f'      <origin xyz="{fmt(*xyz)}" rpy="0 0 0"/>')
        out.append(f"      <geometry>{geometry}</geometry>")
        if tag == "visual" and material:
            out.append(f'      <material name="{material}"/>')
        out.append(f"    </{tag}>")
    out.append("  </link>")
    return out


def joint(child, xyz, yaw=0.0):
    return [
        f'  <joint name="table_to_{child}" type="fixed">',
        '    <parent link="table"/>',
        f'    <child link="{child}"/>',
        f'    <origin xyz="{fmt(*xyz)}" rpy="0 0 {yaw:.12f}"/>',
        "  </joint>",
    ]


def box(x, y, z):
    return f'<box size="{fmt(x, y, z)}"/>'


def cylinder(r, length):
    return f'<cylinder radius="{r:.9f}" length="{length:.9f}"/>'


def sphere(r):
    return f'<sphere radius="{r:.9f}"/>'


def balls_link(radius, mass, ball_set):
    """The balls the table is played with: their radius as a sphere (the collision named for the
    set, for pictures), their mass as an inertial."""
    inertia = 0.4 * mass * radius**2
    return [
        '  <link name="balls">',
        "    <inertial>",
        f'      <mass value="{mass:.9f}"/>',
        f'      <inertia ixx="{inertia:.12e}" ixy="0" ixz="0" iyy="{inertia:.12e}" iyz="0" izz="{inertia:.12e}"/>',
        "    </inertial>",
        f'    <collision name="{ball_set}">',
        f"      <geometry>{sphere(radius)}</geometry>",
        "    </collision>",
        "  </link>",
    ] + joint("balls", (0, 0, radius))


def snooker_markings(length, width):
    """The baulk line, the D and the six spots (WPBSA Official Rules, Section 1), drawn as thin
    visual links a hair above the cloth; on a table of another size, in proportion."""
    along, across = length / 3.569, width / 1.778
    hx = length / 2
    baulk_x = -hx + 0.737 * along
    d_radius = 0.292 * across
    line = 0.003  # [m] the chalk line's width
    lift = 0.0005
    lines = link("marking_baulk_line", None, (box(line, width, 0.001), (0, 0, 0), "chalk"))
    lines += joint("marking_baulk_line", (baulk_x, 0, lift - 0.0005))
    pieces = 24
    for i in range(pieces):
        a0, a1 = math.pi / 2 + math.pi * i / pieces, math.pi / 2 + math.pi * (i + 1) / pieces
        mid = (a0 + a1) / 2
        chord = 2 * d_radius * math.sin((a1 - a0) / 2)
        name = f"marking_d_{i:02d}"
        lines += link(name, None, (box(line, chord + line, 0.001), (0, 0, 0), "chalk"))
        lines += joint(name, (baulk_x + d_radius * math.cos(mid), d_radius * math.sin(mid), lift - 0.0005), mid)
    spots = {
        "yellow": (baulk_x, -d_radius),
        "green": (baulk_x, d_radius),
        "brown": (baulk_x, 0),
        "blue": (0, 0),
        "pink": (hx / 2, 0),
        "black": (hx - 0.324 * along, 0),
    }
    for colour, (x, y) in spots.items():
        name = f"marking_spot_{colour}"
        lines += link(name, None, (cylinder(0.004, 0.001), (0, 0, 0), "chalk"))
        lines += joint(name, (x, y, lift))
    return lines


def segments_pool(hx, hy, d, s):
    return [
        ("cushion_yneg_head", (-hx + d, -hy), (-s, -hy)),
        ("cushion_yneg_foot", (s, -hy), (hx - d, -hy)),
        ("cushion_foot", (hx, -hy + d), (hx, hy - d)),
        ("cushion_ypos_foot", (hx - d, hy), (s, hy)),
        ("cushion_ypos_head", (-s, hy), (-hx + d, hy)),
        ("cushion_head", (-hx, hy - d), (-hx, -hy + d)),
    ]


def segments_carom(hx, hy):
    return [
        ("cushion_yneg", (-hx, -hy), (hx, -hy)),
        ("cushion_foot", (hx, -hy), (hx, hy)),
        ("cushion_ypos", (hx, hy), (-hx, hy)),
        ("cushion_head", (-hx, hy), (-hx, -hy)),
    ]


def table(name, length, width, balls, corner_mouth=None, side_mouth=None, corner_jaw=JAW_RADIUS, side_jaw=JAW_RADIUS,
          markings=False):
    hx, hy = length / 2, width / 2
    lines = [
        '<?xml version="1.0"?>',
        f"<!-- Generated by scripts/make_table_urdf.py: a {name} table, cloth {length} x {width} m. -->",
        f'<robot name="cue_sim_table_{name}">',
        '  <material name="cloth"><color rgba="0.05 0.45 0.2 1"/></material>',
        '  <material name="cushion"><color rgba="0.03 0.33 0.15 1"/></material>',
        '  <material name="wood"><color rgba="0.4 0.22 0.08 1"/></material>',
        '  <material name="pocket"><color rgba="0.02 0.02 0.02 1"/></material>',
        '  <material name="chalk"><color rgba="0.85 0.88 0.85 1"/></material>',
        '  <link name="table"/>',
    ]
    lines += balls_link(*balls)
    # The cloth's visual sits 2 mm lower than its collision box so rviz markers drawn on the
    # physics surface never fight it for the same pixels.
    lines += link("cloth", (box(length, width, 0.02), (0, 0, -0.01), None),
                  (box(length + 2 * CUSHION_WIDTH, width + 2 * CUSHION_WIDTH, 0.02), (0, 0, -0.012), "cloth"))
    lines += joint("cloth", (0, 0, 0))
    if corner_mouth is None:
        segments = segments_carom(hx, hy)
    else:
        d, s = corner_mouth / math.sqrt(2), side_mouth / 2
        segments = segments_pool(hx, hy, d, s)
    for seg_name, start, end in segments:
        dx, dy = end[0] - start[0], end[1] - start[1]
        seg_len = math.hypot(dx, dy)
        mid = ((start[0] + end[0]) / 2, (start[1] + end[1]) / 2, 0.0)
        shape = box(seg_len, CUSHION_WIDTH, NOSE_HEIGHT)
        offset = (0, -CUSHION_WIDTH / 2, NOSE_HEIGHT / 2)
        lines += link(seg_name, (shape, offset, None), (shape, offset, "cushion"))
        lines += joint(seg_name, mid, math.atan2(dy, dx))
    if corner_mouth is not None:
        # Jaws tangent to each cushion where it ends, and a capture circle through each pocket's
        # two jaw centres, centred outwards (TableModel::pool() builds the same).
        jaws, pockets, pocket_jaws, jaw_radii = [], [], [], []
        for sy, side in ((-1, "yneg"), (1, "ypos")):
            for sx, end in ((-1, "head"), (1, "foot")):
                long_jaw = (sx * (hx - d), sy * (hy + corner_jaw))
                end_jaw = (sx * (hx + corner_jaw), sy * (hy - d))
                jaws += [(f"jaw_{end}_{side}_long", long_jaw), (f"jaw_{end}_{side}_end", end_jaw)]
                pockets.append((f"pocket_{end}_{side}", capture_centre(long_jaw, end_jaw, (sx, sy))))
                pocket_jaws.append((long_jaw, end_jaw))
                jaw_radii += [corner_jaw, corner_jaw]
            head_jaw, foot_jaw = (-s, sy * (hy + side_jaw)), (s, sy * (hy + side_jaw))
            jaws += [(f"jaw_side_{side}_head", head_jaw), (f"jaw_side_{side}_foot", foot_jaw)]
            pockets.append((f"pocket_side_{side}", capture_centre(head_jaw, foot_jaw, (0, sy))))
            pocket_jaws.append((head_jaw, foot_jaw))
            jaw_radii += [side_jaw, side_jaw]
        for (j_name, centre), jaw_radius in zip(jaws, jaw_radii):
            shape = cylinder(jaw_radius, NOSE_HEIGHT)
            lines += link(j_name, (shape, (0, 0, NOSE_HEIGHT / 2), None), (shape, (0, 0, NOSE_HEIGHT / 2), "cushion"))
            lines += joint(j_name, (centre[0], centre[1], 0))
        for (p_name, centre), (jaw1, jaw2) in zip(pockets, pocket_jaws):
            # Drawn: a hole the size of the mouth between the jaws; the capture circle itself is
            # the collision geometry.
            mid = ((jaw1[0] + jaw2[0]) / 2 - centre[0], (jaw1[1] + jaw2[1]) / 2 - centre[1], -0.0035)
            hole = cylinder(math.dist(jaw1, jaw2) / 2, 0.003)
            lines += link(p_name, (cylinder(CAPTURE_RADIUS, 0.1), (0, 0, -0.05), None), (hole, mid, "pocket"))
            lines += joint(p_name, (centre[0], centre[1], 0))
    # Wooden rails outside the cushions, their top flush with the cushions' nose.
    outer = CUSHION_WIDTH + RAIL_WIDTH / 2
    rails = [
        ("rails_yneg", (0, -hy - outer), (length + 2 * (CUSHION_WIDTH + RAIL_WIDTH), RAIL_WIDTH)),
        ("rails_ypos", (0, hy + outer), (length + 2 * (CUSHION_WIDTH + RAIL_WIDTH), RAIL_WIDTH)),
        ("rails_head", (-hx - outer, 0), (RAIL_WIDTH, width + 2 * CUSHION_WIDTH)),
        ("rails_foot", (hx + outer, 0), (RAIL_WIDTH, width + 2 * CUSHION_WIDTH)),
    ]
    for r_name, centre, (sx, sy) in rails:
        rail = (box(sx, sy, NOSE_HEIGHT + RAIL_BELOW), (0, 0, (NOSE_HEIGHT - RAIL_BELOW) / 2), "wood")
        lines += link(r_name, rail, rail)
        lines += joint(r_name, (centre[0], centre[1], 0))
    if markings:
        lines += snooker_markings(length, width)
    lines.append("</robot>")
    return "\n".join(lines) + "\n"


def main():
    here = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "urdf")
    # Pocket mouths from ../shared/PHYSICS.md (7-ft table), also used for the 9-ft table.
    files = {
        "table_7ft.urdf": table("7ft", 1.9812, 0.9906, POOL_BALL, 0.118, 0.137),
        "table_9ft.urdf": table("9ft", 2.54, 1.27, POOL_BALL, 0.118, 0.137),
        "table_carom.urdf": table("carom", 2.84, 1.42, CAROM_BALL),
        "table_snooker.urdf": table("snooker", 3.569, 1.778, SNOOKER_BALL, SNOOKER_CORNER_MOUTH, SNOOKER_MIDDLE_MOUTH,
                                    SNOOKER_CORNER_JAW, SNOOKER_MIDDLE_JAW, markings=True),
    }
    for file_name, text in files.items():
        with open(os.path.join(here, file_name), "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()
