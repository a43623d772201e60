"""The soak's driver (bench/soak.sh): seeded random valid requests to the
pushed box until SIM_SECONDS of sim time, the node's RSS sampled along the
way, and the resting box's state compared bit for bit over the run."""
import random
import struct
import sys
import time

import rospy
from geometry_msgs.msg import Vector3, WrenchStamped
from rigid_body_sim.srv import ApplyImpulse, ApplyWrench, ClearWrenches, GetState, SetState

pid, sim_seconds = int(sys.argv[1]), float(sys.argv[2])
rospy.init_node("soak", anonymous=True)
for name in ("get_state", "apply_wrench", "apply_impulse", "set_state", "clear_wrenches"):
    rospy.wait_for_service("/sim_node/" + name, timeout=60)
get = rospy.ServiceProxy("/sim_node/get_state", GetState, persistent=True)
wrench = rospy.ServiceProxy("/sim_node/apply_wrench", ApplyWrench, persistent=True)
impulse = rospy.ServiceProxy("/sim_node/apply_impulse", ApplyImpulse, persistent=True)
set_state = rospy.ServiceProxy("/sim_node/set_state", SetState, persistent=True)
clear = rospy.ServiceProxy("/sim_node/clear_wrenches", ClearWrenches, persistent=True)
topic = rospy.Publisher("/sim_node/pushed/wrench", WrenchStamped, queue_size=10)


def rss_mb():
    with open(f"/proc/{pid}/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024.0
    return float("nan")


def bits(state):
    p, o, v, w = state.pose.position, state.pose.orientation, state.twist.linear, state.twist.angular
    return struct.pack("13d", p.x, p.y, p.z, o.x, o.y, o.z, o.w, v.x, v.y, v.z, w.x, w.y, w.z)


def sim_time():
    return get(body="pushed", frame="world").state.stamp.to_sec()


rng = random.Random(13)
vec = lambda s: Vector3(rng.uniform(-s, s), rng.uniform(-s, s), rng.uniform(-s, s))
start_stamp = sim_time()
# The resting box settles (and sleeps) in its first seconds: compare from 60 s on.
while sim_time() - start_stamp < 60.0:
    time.sleep(0.05)
rest0 = bits(get(body="resting", frame="world").state)
samples, requests, wall0 = [], 0, time.time()
while True:
    t = sim_time() - start_stamp
    if t >= sim_seconds:
        break
    if not samples or t - samples[-1][0] >= sim_seconds / 20:
        samples.append((t, rss_mb()))
    kind = rng.randrange(6)
    if kind == 0:
        wrench(body="pushed", frame=rng.choice(["world", "pushed/base_link"]), force=vec(50), torque=vec(5),
               duration=rospy.Duration(rng.uniform(0.001, 0.5)))
    elif kind == 1:
        impulse(body="pushed", frame="world", linear=vec(2), angular=vec(0.1))
    elif kind == 2:
        s = get(body="pushed", frame="world").state
        s.pose.position.x, s.pose.position.y, s.pose.position.z = rng.uniform(-2, 2), rng.uniform(-2, 2), 0.5
        s.twist.linear, s.twist.angular = vec(1), vec(1)
        set_state(body="pushed", state=s)
    elif kind == 3:
        m = WrenchStamped()
        m.header.frame_id = "world"
        m.wrench.force, m.wrench.torque = vec(20), vec(2)
        topic.publish(m)
    elif kind == 4:
        clear(body="pushed")
    else:
        get(body="resting", frame="world")
    requests += 1
samples.append((sim_time() - start_stamp, rss_mb()))
rest1 = bits(get(body="resting", frame="world").state)
wall = time.time() - wall0
print(f"soak: {sim_seconds:.0f} s of sim time in {wall:.0f} s wall, {requests} requests")
print("soak: RSS (MB) at sim time (s): " + ", ".join(f"{t:.0f}: {r:.1f}" for t, r in samples))
print(f"soak: RSS first {samples[0][1]:.1f} MB, last {samples[-1][1]:.1f} MB, max {max(r for _, r in samples):.1f} MB")
print(f"soak: resting box bit-identical from 60 s to the end: {'yes' if rest0 == rest1 else 'NO'}")
sys.exit(0 if rest0 == rest1 else 1)
