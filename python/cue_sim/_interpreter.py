"""The compiled engine, and a plain answer when this Python cannot load it.

cue_sim._core is built for one interpreter (the build's PYTHON_EXECUTABLE, on Debian /usr/bin/python3
with Debian's NumPy); a python3 that comes first on PATH (pyenv, a virtualenv) may lack NumPy or be
another version. Then the import says which interpreter to use instead of failing deep inside.
"""
import sys


def _built_for():
    try:
        from cue_sim import _built_for as built  # written next to _core by the build
        return built.EXECUTABLE, built.VERSION
    except ImportError:
        return "the Python it was built with", "?"


def wrong_interpreter(error):
    """An ImportError saying which interpreter cue_sim was built for, and which one this is."""
    executable, version = _built_for()
    here = f"{sys.version_info.major}.{sys.version_info.minor}"
    return ImportError(f"cue_sim was built for {executable} (Python {version}, with its NumPy); this is "
                       f"{sys.executable} (Python {here}), which cannot load it ({error}): run {executable} instead")


def _point_at_data():
    """Installed from a wheel (pip install .), the tables' URDF files and the configuration are
    in cue_sim/data: the library looks there first (a user's own setting is kept)."""
    import os
    data = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data")
    if os.path.isdir(data):
        os.environ.setdefault("CUE_SIM_URDF_DIR", os.path.join(data, "urdf"))
        os.environ.setdefault("CUE_SIM_CONFIG_DIR", os.path.join(data, "config"))


def core():
    """cue_sim._core, loaded (with NumPy, which it needs)."""
    _point_at_data()
    try:
        import numpy  # noqa: F401
        from cue_sim import _core
    except ImportError as error:
        raise wrong_interpreter(error) from error
    return _core
