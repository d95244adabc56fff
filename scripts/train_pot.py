#!/usr/bin/env python3
"""A baseline that learns: a policy for the *pot* task trained from scratch with NumPy alone
(doc/learning.md, "A baseline that learns").

The policy reads the state observation, and the ghost-ball geometry it implies for each ball and
pocket (the cut's cosine and the two distances, computed from the observation and the table's
pockets: features a player sees at a glance), and chooses a relative action: which ball into which
pocket (one categorical choice among the pairs), the cut's offset from the ghost-ball aim and the
speed (a Gaussian each), through one hidden layer. It is trained by REINFORCE with a batch-mean baseline (Williams,
"Simple statistical gradient-following algorithms for connectionist reinforcement learning",
Machine Learning 8, 1992) and Adam (Kingma and Ba, ICLR 2015) on the vector environment, with
the tournaments' execution noise on. Every few updates the greedy policy's pot rate is measured on
fresh tables, beside a uniformly random relative action's and a uniformly random absolute one's.

    /usr/bin/python3 scripts/train_pot.py [--shots N] [--seconds S] [--figure FILE] [--seed K] [--require-learning]
"""
import argparse
import sys
import time

import numpy as np

from cue_sim.envs import TableVectorEnv

HIDDEN = 64
BATCH = 2048
LEARNING_RATE = 3e-3
ENTROPY = 1e-3  # a little, so that the pocket choice does not settle before it has been learned
BALL_CHOICES = 2  # the pot task's default: one or two object balls
POCKETS = 6
SPEED_CENTRE, SPEED_SCALE = 2.0, 1.0  # [m/s]: the speed is centre + scale * z
OFFSET_SCALE = 0.05  # [rad]: the cut's offset is scale * z


class Geometry:
    """The ghost-ball geometry of each (ball, pocket) pair from a batch of state observations."""

    def __init__(self, engine):
        cx, cy, length, width = engine._engine.cloth
        self.half = np.array([length / 2, width / 2])
        self.centre = np.array([cx, cy])
        # Where the relative action aims: the middle of each pocket's mouth (the cloth's edge
        # nearest its capture circle's centre), in the table frame.
        self.pockets = np.array([np.clip([x - cx, y - cy], -self.half, self.half) for _, x, y, _ in
                                 engine._engine.pockets]) + self.centre
        self.radius = engine.params["ball_radius"]

    def pairs(self, obs):
        """(B, PAIRS, PAIR_FEATURES) for the first two object balls on the table (the relative
        action's choices, in id order) and each pocket: the cut's cosine, the object ball's distance
        to the pocket and the cue ball's to the ghost ball [m]; and (B, PAIRS), whether the ball is
        there."""
        balls = obs[:, :48].reshape(len(obs), 16, 3)
        xy = balls[:, :, :2] * self.half + self.centre
        on = balls[:, 1:, 2] > 0
        rows = np.arange(len(obs))
        order = np.argsort(~on, axis=1, kind="stable")[:, :BALL_CHOICES] + 1
        out = np.zeros((len(obs), BALL_CHOICES, POCKETS, PAIR_FEATURES))
        present = np.zeros((len(obs), BALL_CHOICES, POCKETS), dtype=bool)
        for k in range(BALL_CHOICES):
            obj = xy[rows, order[:, k]]
            present[:, k] = on[rows, order[:, k] - 1][:, None]
            to_pocket = self.pockets[None] - obj[:, None]
            d_pocket = np.linalg.norm(to_pocket, axis=2)
            ghost = obj[:, None] - 2 * self.radius * to_pocket / d_pocket[..., None]
            to_ghost = ghost - xy[:, 0][:, None]
            d_ghost = np.linalg.norm(to_ghost, axis=2) + 1e-9
            out[:, k] = np.stack([(to_ghost * to_pocket).sum(2) / (d_ghost * d_pocket), d_pocket, d_ghost], axis=2)
        return out.reshape(len(obs), PAIRS, PAIR_FEATURES), present.reshape(len(obs), PAIRS)


PAIRS = BALL_CHOICES * POCKETS
PAIR_FEATURES = 3
PAIR_HIDDEN = 32


class Policy:
    """Which pair: a small network shared by every (ball, pocket) pair scores it from its own
    geometry (a pair's logit; pairs of an absent ball are left out). How: one hidden layer (tanh)
    on the observation gives the Gaussian means of the offset and the speed (in units of their
    scales), with a learned log-deviation each."""

    def __init__(self, inputs, rng):
        def layer(n_in, n_out, gain=1.0):
            return rng.normal(0, gain / np.sqrt(n_in), (n_in, n_out)), np.zeros(n_out)
        self.params = {}
        self.params["w1"], self.params["b1"] = layer(inputs, HIDDEN)
        self.params["wm"], self.params["bm"] = layer(HIDDEN, 2, 0.01)
        self.params["log_std"] = np.log(np.array([1.0, 1.0]))
        self.params["w3"], self.params["b3"] = layer(PAIR_FEATURES, PAIR_HIDDEN)
        self.params["w4"], self.params["b4"] = layer(PAIR_HIDDEN, 1, 0.01)
        self.moments = {k: (np.zeros_like(v), np.zeros_like(v)) for k, v in self.params.items()}
        self.updates = 0

    def forward(self, obs, pairs, present):
        p = self.params
        h = np.tanh(obs @ p["w1"] + p["b1"])
        h2 = np.tanh(pairs @ p["w3"] + p["b3"])
        logits = np.where(present, (h2 @ p["w4"])[..., 0] + p["b4"], -1e9)
        return h, h2, logits, h @ p["wm"] + p["bm"]

    def act(self, obs, pairs, present, rng, greedy=False):
        """Actions for a batch of observations, and what the update needs to know of them."""
        h, h2, logits, mean = self.forward(obs, pairs, present)
        pp = softmax(logits)
        if greedy:
            pair, z = pp.argmax(1), mean
        else:
            pair = sample(pp, rng)
            z = mean + np.exp(self.params["log_std"]) * rng.standard_normal(mean.shape)
        return to_action(pair // POCKETS, pair % POCKETS, z), (obs, pairs, h, h2, pp, mean, pair, z)

    def update(self, memo, advantage):
        """One step of gradient ascent on mean(advantage * log pi) + ENTROPY * entropy."""
        obs, pairs, h, h2, pp, mean, pair, z = memo
        p = self.params
        n = len(advantage)
        a = advantage[:, None] / n
        d_logits = (one_hot(pair, PAIRS) - pp) * a - ENTROPY * pp * (np.log(pp + 1e-12) + entropy(pp)[:, None]) / n
        var = np.exp(2 * p["log_std"])
        d_mean = (z - mean) / var * a
        grads = {"log_std": (((z - mean) ** 2 / var - 1) * a).sum(0) + ENTROPY,
                 "wm": h.T @ d_mean, "bm": d_mean.sum(0),
                 "w4": np.einsum("bph,bp->h", h2, d_logits)[:, None], "b4": np.array([d_logits.sum()])}
        d_pre2 = d_logits[..., None] * p["w4"][:, 0] * (1 - h2 ** 2)
        grads["w3"], grads["b3"] = np.einsum("bpf,bph->fh", pairs, d_pre2), d_pre2.sum((0, 1))
        d_pre = (d_mean @ p["wm"].T) * (1 - h ** 2)
        grads["w1"], grads["b1"] = obs.T @ d_pre, d_pre.sum(0)
        self.updates += 1
        for k, g in grads.items():  # Adam, ascending
            m, v = self.moments[k]
            m[...] = 0.9 * m + 0.1 * g
            v[...] = 0.999 * v + 0.001 * g * g
            m_hat, v_hat = m / (1 - 0.9 ** self.updates), v / (1 - 0.999 ** self.updates)
            p[k] += LEARNING_RATE * m_hat / (np.sqrt(v_hat) + 1e-8)
        p["log_std"] = np.clip(p["log_std"], np.log(0.05), np.log(2.0))


def softmax(logits):
    e = np.exp(logits - logits.max(1, keepdims=True))
    return e / e.sum(1, keepdims=True)


def entropy(p):
    return -(p * np.log(p + 1e-12)).sum(1)


def sample(p, rng):
    return (p.cumsum(1) > rng.random((len(p), 1))).argmax(1)


def one_hot(k, n):
    out = np.zeros((len(k), n))
    out[np.arange(len(k)), k] = 1
    return out


def to_action(ball, pocket, z):
    """The relative action (ball, pocket, cut_offset, speed) inside the action's box."""
    return np.stack([(ball + 0.5) / BALL_CHOICES, (pocket + 0.5) / POCKETS,
                     np.clip(OFFSET_SCALE * z[:, 0], -0.2, 0.2),
                     np.clip(SPEED_CENTRE + SPEED_SCALE * z[:, 1], 0.05, 12.0)], axis=1)


def pot_rate(envs, choose, batches=4):
    """The share of one-shot episodes that pot a ball without scratching."""
    pots = shots = 0
    obs, _ = envs.reset(seed=10_000_000)
    for _ in range(batches):
        obs, reward, terminated, truncated, info = envs.step(choose(obs))
        pots += int((reward > 0).sum())
        shots += len(reward)
        obs, _ = envs.reset()
    return pots / shots


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--shots", type=int, default=3_000_000, help="training shots (default 3,000,000)")
    parser.add_argument("--seconds", type=float, default=0, help="stop after this long instead (0: no limit)")
    parser.add_argument("--figure", default="", help="write the learning curve here (PNG)")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--require-learning", action="store_true",
                        help="exit 1 unless the trained policy pots more often than random relative actions")
    args = parser.parse_args()
    rng = np.random.default_rng(args.seed)
    train = TableVectorEnv(BATCH, task="pot", action="relative")
    test = TableVectorEnv(BATCH, task="pot", action="relative")
    test_absolute = TableVectorEnv(BATCH, task="pot", action="absolute")
    import cue_sim
    geometry = Geometry(cue_sim.Engine("7ft"))
    policy = Policy(train.single_observation_space.shape[0], rng)

    def act(obs, greedy):
        return policy.act(obs, *geometry.pairs(obs), rng, greedy=greedy)
    low, high = test_absolute.single_action_space.low, test_absolute.single_action_space.high
    random_relative = pot_rate(test, lambda o: to_action(rng.integers(0, BALL_CHOICES, len(o)),
                                                         rng.integers(0, POCKETS, len(o)),
                                                         rng.uniform(-4, 4, (len(o), 2))))
    random_absolute = pot_rate(test_absolute, lambda o: low + rng.random((len(o), 2)) * (high - low))
    print(f"random relative actions pot {100 * random_relative:.1f} %, random absolute ones "
          f"{100 * random_absolute:.1f} % (noise on)", flush=True)
    greedy = lambda o: act(o, True)[0]  # noqa: E731
    curve = [(0, pot_rate(test, greedy))]
    begin = time.perf_counter()
    obs, _ = train.reset(seed=args.seed)
    shots = 0
    while shots < args.shots and not (args.seconds and time.perf_counter() - begin > args.seconds):
        action, memo = act(obs, False)
        _, reward, _, _, _ = train.step(action)
        obs, _ = train.reset()  # every episode is one shot: the next batch's tables
        shots += BATCH
        advantage = (reward - reward.mean()) / (reward.std() + 1e-8)
        policy.update(memo, advantage)
        if policy.updates % 50 == 0:
            curve.append((shots, pot_rate(test, greedy)))
            print(f"{shots:>10,} shots  {time.perf_counter() - begin:7.1f} s  greedy pot rate "
                  f"{100 * curve[-1][1]:5.1f} %  (training batch {100 * (reward > 0).mean():5.1f} %)", flush=True)
    final = pot_rate(test, greedy, batches=10)
    print(f"after {shots:,} shots in {time.perf_counter() - begin:.0f} s: the greedy policy pots {100 * final:.1f} %"
          f" (random: {100 * random_relative:.1f} % relative, {100 * random_absolute:.1f} % absolute)")
    if args.figure:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6.4, 3.6), dpi=100)
        ax.plot([s / 1e6 for s, _ in curve], [100 * r for _, r in curve], label="greedy policy (REINFORCE, NumPy)")
        ax.axhline(100 * random_relative, color="grey", linestyle="--", label="random relative action")
        ax.axhline(100 * random_absolute, color="grey", linestyle=":", label="random absolute action")
        ax.set_xlabel("training shots [millions]")
        ax.set_ylabel("pot rate [%]")
        ax.set_title("pot, 1-2 balls, tournament execution noise on")
        ax.set_ylim(0, 100)
        ax.legend(loc="upper left")
        fig.tight_layout()
        fig.savefig(args.figure)
        print("learning curve:", args.figure)
    return 1 if args.require_learning and not final > random_relative else 0


if __name__ == "__main__":
    sys.exit(main())
