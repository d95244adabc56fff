"""rviz opens on the table it is launched for: scripts/rviz_table.py makes the saved view of that
table the current one."""
import os
import sys

import yaml

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import rviz_table  # noqa: E402

CONFIG = os.path.join(ROOT, "rviz", "table.rviz")


def views(text):
    return yaml.safe_load(text)["Visualization Manager"]["Views"]


def test_each_bundled_table_opens_on_its_own_framing():
    saved = {v["Name"]: v for v in views(open(CONFIG).read())["Saved"]}
    distances = set()
    for table in ("7ft", "9ft", "carom", "snooker"):
        current = views(rviz_table.config_for(table, CONFIG))["Current"]
        expected = dict(saved[f"{table} table"], Name="Current View")
        assert current == expected, table
        distances.add(current["Distance"])
    assert len(distances) == 4, "each table has a framing of its own"


def test_an_unknown_table_keeps_the_configurations_view(capsys):
    original = views(open(CONFIG).read())["Current"]
    assert views(rviz_table.config_for("bagatelle", CONFIG))["Current"] == original
    assert "no saved view named 'bagatelle table'" in capsys.readouterr().err
