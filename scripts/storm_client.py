#!/usr/bin/python3
# A storm of mixed requests on one table_node, good and hostile, from several threads at once:
# strikes (and NaN, too fast, unknown balls), cues in frames tf does not know, predictions with
# samples, batches up to a size, whole tables (and balls at 1e308 m/s), single balls placed and
# removed, racks with jitter, pause and step, reconfigure (and a NaN real-time factor), games
# started (unknown rules, odd players, hostile positions) and ended, cue balls placed in hand
# (NaN, off the table) and calls (unknown balls and pockets, push-outs out of turn).
#   storm_client.py SECONDS [THREADS] [MAX_BATCH]
# Prints progress every 10 s to stderr and a summary line to stdout; exits 1 if a call failed
# outright (the node did not answer).
#
# A connection that roscpp closes before the request reaches the node is tried again, up to
# ATTEMPTS times, and counted as "dropped". Debian's roscpp (ros_comm 1.15) polls for POLLRDHUP
# (ros_comm#1704) but its guard against events of a socket just closed covers only
# ERR|HUP|NVAL: when a connection closes and the next one accepted takes its file descriptor in
# the same poll round, the old one's half-close closes the new one (seen in the node's roscpp
# debug log: "Socket 13 closed with (ERR|HUP|NVAL) events 8196" 70 us after set_state's
# connection on socket 13 was accepted; ros_comm#1976 reports calls lost to the same POLLRDHUP
# handling). About 1 call in 1500 under this storm; a call dropped ATTEMPTS times in a row is a
# failure.
import math
import random
import sys
import threading
import time

import rospy
from dynamic_reconfigure.msg import Config, DoubleParameter
from dynamic_reconfigure.srv import Reconfigure
from geometry_msgs.msg import Point, PoseStamped
from std_srvs.srv import SetBool, Trigger

from cue_sim.msg import BallState, Shot
from cue_sim.srv import (CallShot, PlaceBall, PlaceCueBall, Predict, PredictBatch, Rack, RemoveBall, SetState,
                         StartGame, Step, Strike, StrikeCue)

NAN = float("nan")
ATTEMPTS = 3
DROPPED = "unable to receive data from sender"


def shot(rng, bad=False):
    s = Shot(ball_id=0, speed=rng.uniform(0.2, 8.0), phi=rng.uniform(-math.pi, math.pi),
             theta=rng.uniform(0, 0.3), a=rng.uniform(-0.3, 0.3), b=rng.uniform(-0.3, 0.3))
    if bad:
        choice = rng.randrange(3)
        if choice == 0:
            s.speed = NAN
        elif choice == 1:
            s.speed = 1e308
        else:
            s.ball_id = 99
    return s


def ball(rng, ball_id, hostile=False):
    b = BallState(id=ball_id)
    b.position.x = rng.uniform(-0.9, 0.9)
    b.position.y = rng.uniform(-0.45, 0.45)
    if hostile:
        b.velocity.x = rng.choice([1e308, NAN, -1e300])
    elif rng.random() < 0.3:
        b.velocity.x = rng.uniform(-1, 1)
    return b


class Storm:
    def __init__(self, seconds, max_batch):
        self.until = time.time() + seconds
        self.max_batch = max_batch
        self.lock = threading.Lock()
        self.calls = self.refused = self.failed = self.dropped = 0
        ns = "/table/"
        self.services = {
            "strike": rospy.ServiceProxy(ns + "strike", Strike),
            "strike_cue": rospy.ServiceProxy(ns + "strike_cue", StrikeCue),
            "predict": rospy.ServiceProxy(ns + "predict", Predict),
            "predict_batch": rospy.ServiceProxy(ns + "predict_batch", PredictBatch),
            "set_state": rospy.ServiceProxy(ns + "set_state", SetState),
            "place_ball": rospy.ServiceProxy(ns + "place_ball", PlaceBall),
            "remove_ball": rospy.ServiceProxy(ns + "remove_ball", RemoveBall),
            "rack": rospy.ServiceProxy(ns + "rack", Rack),
            "reset": rospy.ServiceProxy(ns + "reset", Trigger),
            "pause": rospy.ServiceProxy(ns + "pause", SetBool),
            "step": rospy.ServiceProxy(ns + "step", Step),
            "reconfigure": rospy.ServiceProxy(ns + "set_parameters", Reconfigure),
            "start_game": rospy.ServiceProxy(ns + "start_game", StartGame),
            "end_game": rospy.ServiceProxy(ns + "end_game", Trigger),
            "place_cue_ball": rospy.ServiceProxy(ns + "place_cue_ball", PlaceCueBall),
            "call_shot": rospy.ServiceProxy(ns + "call_shot", CallShot),
        }

    KINDS = ["strike", "strike", "cue", "predict", "batch", "set_state", "place", "remove", "rack", "reset",
             "pause", "reconfigure", "game", "place_cue", "call"]

    def request(self, rng, kind):
        s = self.services
        if kind == "strike":
            return s["strike"](**vars_of(shot(rng, bad=rng.random() < 0.3))).success
        if kind == "cue":
            pose = PoseStamped()
            pose.header.frame_id = rng.choice(["no_such_frame", "table"])
            pose.pose.position = Point(rng.uniform(-1, 1), rng.uniform(-0.5, 0.5), 0.03)
            pose.pose.orientation.w = 1.0
            return s["strike_cue"](cue=pose, speed=rng.uniform(0.5, 5)).success
        if kind == "predict":
            period = rng.choice([0.0, 0.01, 0.001, 1e-9])
            return s["predict"](shot=shot(rng), balls=[], sample_period=period, noise=rng.random() < 0.5,
                                seed=rng.randrange(1000)).prediction.success
        if kind == "batch":
            n = rng.choice([1, 10, 100, self.max_batch, 10 ** 6])
            period = rng.choice([0.0, 0.0, 0.05])
            if n == 10 ** 6:  # refused before any work: only its size goes over the wire
                n = self.max_batch * 20
            return s["predict_batch"](shots=[shot(rng) for _ in range(n)], balls=[], sample_period=period,
                                      noise=False, seed=0).success
        if kind == "set_state":
            hostile = rng.random() < 0.3
            balls = [ball(rng, i, hostile and i == 0) for i in rng.sample(range(16), rng.randrange(1, 6))]
            return s["set_state"](balls=balls).success
        if kind == "place":
            return s["place_ball"](ball=ball(rng, rng.randrange(17), rng.random() < 0.2)).success
        if kind == "remove":
            return s["remove_ball"](ball_id=rng.randrange(17)).success
        if kind == "rack":
            return s["rack"](layout=rng.choice(["eight", "nine", "ten", "empty", "eleven"]), ids=[], positions=[],
                             jitter=rng.choice([0.0, 5e-6, 1.0]), seed=rng.randrange(100)).success
        if kind == "reset":
            return s["reset"]().success
        if kind == "game":
            if rng.random() < 0.4:
                return s["end_game"]().success
            balls = [] if rng.random() < 0.7 else [ball(rng, i, rng.random() < 0.3) for i in rng.sample(range(16), 4)]
            return s["start_game"](rules=rng.choice(["eight_ball", "nine_ball", "ten_ball", "straight_pool"]),
                                   players=rng.choice([[], ["a", "b"], ["a"], ["", "b"]]),
                                   first_player=rng.choice([0, 1, 7]), seed=rng.randrange(100), balls=balls).success
        if kind == "place_cue":
            where = Point(rng.choice([rng.uniform(-1, 1), NAN, 1e308]), rng.uniform(-0.5, 0.5), 0.0)
            return s["place_cue_ball"](position=where).success
        if kind == "call":
            return s["call_shot"](ball=rng.randrange(-2, 17), pocket=rng.choice(["", "pocket_foot_ypos", "nowhere"]),
                                  push_out=rng.random() < 0.2).success
        if kind == "pause":
            s["pause"](data=True)
            ok = s["step"](duration=rng.choice([0.1, 0.5, NAN, 100.0])).success
            s["pause"](data=False)
            return ok
        config = Config()
        config.doubles = [DoubleParameter(name="mu_roll", value=rng.uniform(0.005, 0.015)),
                          DoubleParameter(name="real_time_factor", value=rng.choice([1.0, 1.0, NAN]))]
        s["reconfigure"](config=config)
        return True

    def worker(self, seed):
        rng = random.Random(seed)
        while time.time() < self.until and not rospy.is_shutdown():
            kind = rng.choice(self.KINDS)
            state = rng.getstate()
            for attempt in range(1, ATTEMPTS + 1):
                rng.setstate(state)  # the same request again
                try:
                    ok = self.request(rng, kind)
                    with self.lock:
                        self.calls += 1
                        self.refused += not ok
                    break
                except (rospy.ServiceException, rospy.ROSException) as e:
                    dropped = DROPPED in str(e) and attempt < ATTEMPTS
                    with self.lock:
                        self.dropped += dropped
                        self.calls += not dropped
                        self.failed += not dropped
                    print("storm: a %s request %s: %s" % (kind, "dropped, sent again" if dropped else "failed", e),
                          file=sys.stderr)
                    if not dropped:
                        break


def vars_of(s):
    return {"ball_id": s.ball_id, "speed": s.speed, "phi": s.phi, "theta": s.theta, "a": s.a, "b": s.b}


def main():
    seconds = float(sys.argv[1])
    threads = int(sys.argv[2]) if len(sys.argv) > 2 else 4
    max_batch = int(sys.argv[3]) if len(sys.argv) > 3 else 1000
    rospy.init_node("storm_client", anonymous=True, disable_signals=True)
    for name in ["strike", "predict_batch", "set_parameters"]:
        rospy.wait_for_service("/table/" + name, timeout=30)
    storm = Storm(seconds, max_batch)
    workers = [threading.Thread(target=storm.worker, args=(k,), daemon=True) for k in range(threads)]
    for w in workers:
        w.start()
    start = last = time.time()
    while any(w.is_alive() for w in workers):
        time.sleep(0.5)
        if time.time() - last >= 10.0:  # progress every 10 s, also while the last calls finish
            last = time.time()
            with storm.lock:
                print("storm: %4.0f s of %.0f, %d calls, %d refused, %d failed, %d dropped by roscpp and sent again" %
                      (last - start, seconds, storm.calls, storm.refused, storm.failed, storm.dropped), file=sys.stderr)
    print("%d calls, %d refused, %d failed, %d dropped by roscpp and sent again" %
          (storm.calls, storm.refused, storm.failed, storm.dropped))
    sys.exit(1 if storm.failed else 0)


if __name__ == "__main__":
    main()
