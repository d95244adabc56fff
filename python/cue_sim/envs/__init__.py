"""Learning environments on the exact table, with Gymnasium's API (Gymnasium is not needed).

    from cue_sim.envs import TableEnv
    env = TableEnv("pot", balls=2)               # pot one of 1-2 object balls, one shot
    obs, info = env.reset(seed=0)
    obs, reward, terminated, truncated, info = env.step([0.3, 2.0])   # phi [rad], speed [m/s]

TableVectorEnv steps N tables in one call on every core. When gymnasium is importable the tasks
are registered: gymnasium.make("cue_sim/Pot-v0"), make_vec(..., vectorization_mode="vector_entry_point").
doc/learning.md describes each task's observation, action, reward and end.
"""
from cue_sim.envs.spaces import Box, Dict, Discrete
from cue_sim.envs.table_env import DEFAULT_OPTIONS, TableEnv
from cue_sim.envs.vector_env import TableVectorEnv


def task_names():
    """The tasks TableEnv takes: pot, position, break and a game per ruleset (cue_sim.rules())."""
    from cue_sim.envs.table_env import _core
    return list(_core.task_names())


def _env_id(task):
    """cue_sim/Pot-v0 for pot, cue_sim/TenBall-v0 for ten_ball."""
    return "cue_sim/" + "".join(word.capitalize() for word in task.split("_")) + "-v0"


#: Registered ids and their tasks: one per task, the games' from the referee's registry.
TASK_IDS = {_env_id(task): task for task in task_names()}


def _register():
    try:
        import gymnasium
    except ImportError:
        return
    for env_id, task in TASK_IDS.items():
        if env_id not in gymnasium.registry:
            gymnasium.register(id=env_id, entry_point="cue_sim.envs:TableEnv", kwargs={"task": task},
                               vector_entry_point="cue_sim.envs:TableVectorEnv")


_register()

__all__ = ["TableEnv", "TableVectorEnv", "Box", "Dict", "Discrete", "DEFAULT_OPTIONS", "TASK_IDS", "task_names"]
