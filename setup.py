# The Python package cue_sim for catkin (catkin_python_setup): python/cue_sim. Its compiled part,
# cue_sim._core, is built by CMake beside the generated messages.
from setuptools import setup

from catkin_pkg.python_setup import generate_distutils_setup

setup(**generate_distutils_setup(packages=["cue_sim", "cue_sim.envs"], package_dir={"": "python"}))
