#!/usr/bin/env python3
"""Public robots, unchanged, through sim_node as their stock Gazebo launches
run them: the table of issue 58's "done when".

  bench/public_robots.py ROBOTS_DIR [NAME ...] [--seconds S]

ROBOTS_DIR holds each robot's description expanded from its xacro into
ROBOTS_DIR/urdf/FILE.urdf (README: "Your own robot: URDF and xacro") and the
packages they name (meshes, the stock controller YAML), found through
ROS_PACKAGE_PATH=ROBOTS_DIR. The ROBOTS table below says which file, YAML,
spawn flags and command topic each robot's own launch files use
(turtlebot3_gazebo, husky_gazebo, jackal_gazebo, rosbot_gazebo, ur_gazebo).

For each robot, in a master and a node of its own, a world of the ground and
a wall whose face is WALL m ahead of the robot's start, it
  - loads the YAML where the stock launch loads it (rosparam) and spawns the
    robot with the real spawn_body script and the stock launch's flags;
  - holds still at zero command for S s: the base's drift (truth,
    ~body_states), an arm's joints' drift;
  - reads every sensor its Gazebo markup declares, while still: its rate
    (message stamps, sim time) against the markup's, and its values against
    the truth within the markup's own noise (4 sigma, plus its bias): a
    lidar's and a range sensor's forward ray against the wall, a depth
    image's centre pixel, an IMU's |a| = g and |w| = 0, a GPS fix against
    the base's position on hector's tangent plane;
  - drives a base backward, then forward, S s each at the table's speed, and
    compares the truth's speed along the base's heading over each window's
    second half with the command (the issue's 5 %); moves each of an arm's
    joints by 0.4 rad (the shoulder and elbow up) along a trajectory of S s
    on its stock trajectory controller, and compares the joints' speeds over
    the middle half with 0.4/S and where they end 1 s later with the goal;
    steers a steered base (angular z the steering angle) backward for S s at
    the table's angle and compares the truth's yaw rate with v tan(angle) / L.
Prints one JSON line per robot and a Markdown table at the end. A bench, not a
test: nothing here fails the build.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
WALL = 0.8  # m from the robot's start to the wall's face, along +x (a sonar's 0.9 m reaches it)
G = 9.81

# name: the stock launch's file, model name, YAML (loaded at the root, as the
# launches load it), spawn flags, and what drives it.
ROBOTS = {
    "turtlebot3_burger": dict(urdf="burger.urdf", model="turtlebot3_burger", cmd="/cmd_vel", speed=0.2),
    "turtlebot3_waffle": dict(urdf="waffle.urdf", model="turtlebot3_waffle", cmd="/cmd_vel", speed=0.2),
    "turtlebot3_waffle_pi": dict(urdf="waffle_pi.urdf", model="turtlebot3_waffle_pi", cmd="/cmd_vel", speed=0.2),
    "husky": dict(urdf="husky.urdf", model="husky", yaml="husky/husky_control/config/control.yaml",
                  flags=["-robot_namespace", "/"], cmd="/husky_velocity_controller/cmd_vel", speed=0.5),
    "jackal": dict(urdf="jackal.urdf", model="jackal", yaml="jackal/jackal_control/config/control.yaml",
                   flags=["-z", "1.0"], cmd="/jackal_velocity_controller/cmd_vel", speed=0.5),
    "rosbot": dict(urdf="rosbot.urdf", model="rosbot", cmd="/cmd_vel", speed=0.3),
    "kobuki": dict(urdf="kobuki.urdf", model="mobile_base", flags=["-unpause"],
                   cmd="/mobile_base/commands/velocity", speed=0.3),
    "mir_100": dict(urdf="mir.urdf", model="mir",
                    yaml=["mir_robot/mir_description/config/joint_state_controller.yaml",
                          "mir_robot/mir_description/config/diffdrive_controller.yaml"],
                    args={"prefix": ""}, cmd="/mobile_base_controller/cmd_vel", speed=0.5),
    "ridgeback": dict(urdf="ridgeback.urdf", model="ridgeback", yaml="ridgeback/ridgeback_control/config/control.yaml",
                      cmd="/cmd_vel", speed=0.5),
    "hunter2": dict(urdf="hunter2.urdf", model="hunter2_base",
                    yaml=["ugv_gazebo_sim/hunter/hunter2_control/config/ctrl_ackermann_steering_controller.yaml",
                          "ugv_gazebo_sim/hunter/hunter2_control/config/ctrl_gains.yaml",
                          "ugv_gazebo_sim/hunter/hunter2_control/config/ctrl_joint_state_publisher.yaml",
                          "ugv_gazebo_sim/hunter/hunter2_control/config/ctrl_steer_bot_hardware_gazebo.yaml"],
                    flags=["-z", "1.5"], cmd="/ackermann_steering_controller/cmd_vel", speed=0.5,
                    steer=0.3, wheelbase=0.65),  # its controller's wheel_separation_h
    "ur5": dict(urdf="ur5.urdf", model="robot", yaml="universal_robot/ur_gazebo/config/ur5_controllers.yaml",
                flags=["-z", "0.1"], arm="/eff_joint_traj_controller/command"),
    "ur10": dict(urdf="ur10.urdf", model="robot", yaml="universal_robot/ur_gazebo/config/ur10_controllers.yaml",
                 flags=["-z", "0.1"], arm="/eff_joint_traj_controller/command"),
    "ur3e": dict(urdf="ur3e.urdf", model="robot", yaml="universal_robot/ur_gazebo/config/ur3e_controllers.yaml",
                 flags=["-z", "0.1"], arm="/eff_joint_traj_controller/command"),
}


# ---- the markup: what each sensor declares ---------------------------------

def floats(text, default=None):
    return [float(v) for v in text.split()] if text is not None else default


def rpy_matrix(r, p, y):
    cr, sr, cp, sp, cy, sy = math.cos(r), math.sin(r), math.cos(p), math.sin(p), math.cos(y), math.sin(y)
    return [[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
            [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
            [-sp, cp * sr, cp * cr]]


def compose(a, b):
    """(R, t) of frame b given in frame a, composed: a * b."""
    ra, ta = a
    rb, tb = b
    r = [[sum(ra[i][k] * rb[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
    t = [ta[i] + sum(ra[i][k] * tb[k] for k in range(3)) for i in range(3)]
    return r, t


def link_pose(root, link):
    """The pose of `link` in the URDF's root link, joints at 0."""
    parent_of = {j.find("child").get("link"): j for j in root.findall("joint")}
    pose = ([[1, 0, 0], [0, 1, 0], [0, 0, 1]], [0.0, 0.0, 0.0])
    while link in parent_of:
        joint = parent_of[link]
        origin = joint.find("origin")
        xyz = floats(origin.get("xyz") if origin is not None else None, [0, 0, 0])
        rpy = floats(origin.get("rpy") if origin is not None else None, [0, 0, 0])
        pose = compose((rpy_matrix(*rpy), xyz), pose)
        link = joint.find("parent").get("link")
    return pose


def text(element, path, default=None):
    found = element.find(path) if element is not None else None
    return found.text.strip() if found is not None and found.text else default


def noise_sigma(element, path="noise/stddev"):
    return float(text(element, path, "0") or 0)


def declared_sensors(urdf_text):
    """Each sensor the markup declares: kind, topic (relative to the robot's
    namespace, or absolute), declared rate (Hz), link, pose in the root link,
    its noise; and the plugins nothing reads as a sensor are left out."""
    root = ET.fromstring(urdf_text)
    out = []
    for gz in root.findall("gazebo"):
        ref = gz.get("reference")
        for sensor in gz.findall("sensor"):
            kind = sensor.get("type")
            rate = float(text(sensor, "update_rate", "0"))
            pose = floats(text(sensor, "pose"), [0] * 6)
            mount = compose(link_pose(root, ref), (rpy_matrix(*pose[3:]), pose[:3]))
            for plugin in sensor.findall("plugin"):
                lib = plugin.get("filename", "")
                entry = dict(link=ref, rate=rate, mount=mount, plugin=lib)
                if kind in ("ray", "gpu_ray") and "laser" in lib:
                    entry.update(kind="scan", topic=text(plugin, "topicName", "scan"),
                                 sigma=noise_sigma(sensor, "ray/noise/stddev"),
                                 range=(float(text(sensor, "ray/range/min", "0")),
                                        float(text(sensor, "ray/range/max", "inf"))))
                elif kind == "ray" and "velodyne" in lib:
                    entry.update(kind="cloud", topic=text(plugin, "topicName", "points"))
                elif kind == "ray" and "range" in lib:
                    entry.update(kind="range", topic=text(plugin, "topicName", "range"),
                                 sigma=float(text(plugin, "gaussianNoise", "0")),
                                 half_fov=(float(text(sensor, "ray/scan/horizontal/max_angle", "0")) -
                                           float(text(sensor, "ray/scan/horizontal/min_angle", "0"))) / 2,
                                 range=(float(text(sensor, "ray/range/min", "0")),
                                        float(text(sensor, "ray/range/max", "inf"))))
                elif kind == "imu":
                    entry.update(kind="imu", topic=text(plugin, "topicName", "imu"),
                                 sigma=float(text(plugin, "gaussianNoise", "0")), bias=0.0)
                elif kind == "depth":
                    cam = text(plugin, "cameraName", "camera")
                    entry.update(kind="depth", topic=cam + "/" + text(plugin, "depthImageTopicName", "depth/image_raw"))
                    out.append(dict(entry, kind="image", topic=cam + "/" + text(plugin, "imageTopicName", "rgb/image_raw")))
                elif kind == "camera":
                    cam = text(plugin, "cameraName", "camera")
                    entry.update(kind="image", topic=cam + "/" + text(plugin, "imageTopicName", "image_raw"))
                else:
                    continue
                out.append(entry)
        for plugin in gz.findall("plugin"):
            lib = plugin.get("filename", "")
            rate = float(text(plugin, "updateRate", text(plugin, "updateRateHZ", "0")))
            body = text(plugin, "bodyName", text(plugin, "frameName"))
            entry = dict(link=body, rate=rate, plugin=lib)
            if lib == "libgazebo_ros_imu.so":
                accel = plugin.find("imu/noise/accel")
                rate_noise = plugin.find("imu/noise/rate")
                sigma = float(text(plugin, "gaussianNoise", "0"))
                entry.update(kind="imu", topic=text(plugin, "topicName", "imu"),
                             sigma=max(sigma, noise_sigma(accel, "stddev")),
                             bias=abs(float(text(accel, "bias_mean", "0"))),
                             gyro_sigma=max(sigma, noise_sigma(rate_noise, "stddev")),
                             gyro_bias=abs(float(text(rate_noise, "bias_mean", "0"))))
            elif lib == "libhector_gazebo_ros_imu.so":
                entry.update(kind="imu", topic=text(plugin, "topicName", "imu"),
                             sigma=max(floats(text(plugin, "accelGaussianNoise"), [0])),
                             bias=max(abs(v) for v in floats(text(plugin, "accelOffset"), [0]))
                             + max(floats(text(plugin, "accelDrift"), [0])) * 4,
                             gyro_sigma=max(floats(text(plugin, "rateGaussianNoise"), [0])),
                             gyro_bias=max(abs(v) for v in floats(text(plugin, "rateOffset"), [0]))
                             + max(floats(text(plugin, "rateDrift"), [0])) * 4)
            elif lib == "libhector_gazebo_ros_gps.so":
                entry.update(kind="gps", topic=text(plugin, "topicName", "fix"),
                             sigma=max(floats(text(plugin, "gaussianNoise"), [0])),
                             bias=max(floats(text(plugin, "drift"), [0])) * 4
                             + max(abs(v) for v in floats(text(plugin, "offset"), [0])),
                             lat=float(text(plugin, "referenceLatitude", "49.9")),
                             lon=float(text(plugin, "referenceLongitude", "8.9")),
                             heading=float(text(plugin, "referenceHeading", "0")))
                if rate == 0:
                    entry["rate"] = 4.0  # hector's default
            elif lib == "libgazebo_ros_p3d.so":
                entry.update(kind="odom", topic=text(plugin, "topicName", "odom"))
            elif lib in ("libgazebo_ros_planar_move.so", "libgazebo_ros_force_based_move.so",
                         "libridgeback_ros_force_based_move.so"):
                entry.update(kind="odom", topic=text(plugin, "odometryTopic", "odom"),
                             rate=float(text(plugin, "odometryRate", "20")), drive=True)
            elif lib == "libgazebo_ros_kobuki.so":  # its odometry and the IMU sensor it names, each step
                every = float(text(plugin, "update_rate", "0")) or 1000.0
                out.append(dict(entry, kind="odom", topic="odom", rate=every, drive=True, mount=None))
                imu = next(s for g in root.findall("gazebo") for s in g.findall("sensor")
                           if s.get("type") == "imu" and s.get("name") == text(plugin, "imu_name"))
                entry = dict(link=None, rate=every, plugin=lib, kind="imu", topic="mobile_base/sensors/imu_data",
                             sigma=noise_sigma(imu, "imu/noise/accel/stddev"), bias=0.0,
                             gyro_sigma=noise_sigma(imu, "imu/noise/rate/stddev"), gyro_bias=0.0)
            elif lib in ("libgazebo_ros_diff_drive.so", "libgazebo_ros_skid_steer_drive.so"):
                entry.update(kind="odom", topic=text(plugin, "odometryTopic", "odom"), drive=True)
                if rate == 0:
                    entry["rate"] = 100.0
            else:
                continue
            entry.setdefault("mount", link_pose(root, body) if body else None)
            out.append(entry)
    return out


# ---- one robot, in a master and a node of its own ----------------------------

def world_yaml(path):
    with open(path, "w") as f:
        f.write("rate: 1000.0\nrealtime_factor: 1.0\npublish_rate: 100.0\nbodies: []\n"
                "scene:\n  - {type: plane, normal: [0, 0, 1]}\n"
                "  - {type: box, size: [0.2, 6.0, 1.5], position: [%g, 0.0, 0.75]}\n" % (WALL + 0.1))


def run_one(name, robots_dir, seconds, port):
    """Runs in its own process: rospy inits once per process."""
    global WALL
    spec = ROBOTS[name]
    if "arm" in spec:
        WALL = 3.0  # beyond a UR10's reach (1.3 m): an arm stretched along x would lean on it
    env = dict(os.environ, ROS_MASTER_URI="http://localhost:%d" % port, ROS_HOSTNAME="localhost",
               ROS_PACKAGE_PATH=robots_dir + ":" + os.environ.get("ROS_PACKAGE_PATH", ""))
    os.environ.update(env)
    procs = []
    log = tempfile.NamedTemporaryFile("w+", prefix="public_robot_%s_" % name, suffix=".log", delete=False)
    try:
        procs.append(subprocess.Popen(["roscore", "-p", str(port)], stdout=subprocess.DEVNULL,
                                      stderr=subprocess.DEVNULL, env=env))
        import rosgraph
        master = rosgraph.Master("/public_robots")
        for _ in range(100):
            try:
                master.getPid()
                break
            except Exception:
                time.sleep(0.2)
        cfg = os.path.join(tempfile.gettempdir(), "public_robots_world_%d.yaml" % port)
        world_yaml(cfg)
        import rosparam
        for params, ns in rosparam.load_file(cfg, default_namespace="/sim_node"):
            rosparam.upload_params(ns, params)
        master.setParam("/use_sim_time", True)
        urdf_path = os.path.join(robots_dir, "urdf", spec["urdf"])
        with open(urdf_path) as f:
            urdf = f.read()
        master.setParam("/robot_description", urdf)
        files = spec.get("yaml", [])
        for yaml_file in [files] if isinstance(files, str) else files:
            # The launch's <rosparam subst_value="true">: its $(arg NAME)s as the launch gives them.
            with open(os.path.join(robots_dir, yaml_file)) as f:
                text = f.read()
            for arg, value in spec.get("args", {}).items():
                text = text.replace("$(arg %s)" % arg, value)
            for params, ns in rosparam.load_str(text, yaml_file, default_namespace="/"):
                rosparam.upload_params(ns, params)
        procs.append(subprocess.Popen(["rosrun", "rigid_body_sim", "sim_node", "__name:=sim_node"], stdout=log,
                                      stderr=subprocess.STDOUT, env=env))
        spawn = subprocess.run(["rosrun", "rigid_body_sim", "spawn_body", "-urdf", "-param", "robot_description",
                                "-model", spec["model"]] + spec.get("flags", []),
                               capture_output=True, text=True, env=env, timeout=120)
        result = dict(robot=name, spawned=spawn.returncode == 0)
        if spawn.returncode != 0:
            result["error"] = (spawn.stderr.strip().splitlines() or ["?"])[-1][:400]
            return result
        result["answer"] = spawn.stdout.strip()[-2000:]
        result.update(measure(spec, urdf, seconds))
        return result
    finally:
        for p in reversed(procs):
            p.terminate()
            try:
                p.wait(10)
            except subprocess.TimeoutExpired:
                p.kill()
        log.close()


def yaw_of(q):
    return math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))


def measure(spec, urdf, seconds):
    import rospy
    from geometry_msgs.msg import Twist
    from nav_msgs.msg import Odometry
    from sensor_msgs.msg import Image, Imu, JointState, LaserScan, NavSatFix, PointCloud2, Range
    from trajectory_msgs.msg import JointTrajectory, JointTrajectoryPoint
    from rigid_body_sim.msg import BodyStates

    rospy.init_node("public_robots", anonymous=True)
    states = []
    rospy.Subscriber("/sim_node/body_states", BodyStates, lambda m: states.append(m), queue_size=100)
    joints = []
    rospy.Subscriber("/joint_states", JointState, lambda m: joints.append(m), queue_size=100)
    types = dict(scan=LaserScan, range=Range, imu=Imu, depth=Image, image=Image, cloud=PointCloud2,
                 gps=NavSatFix, odom=Odometry)
    sensors = declared_sensors(urdf)
    for s in sensors:
        s["resolved"] = s["topic"] if s["topic"].startswith("/") else "/" + s["topic"]
        s["got"] = []
        rospy.Subscriber(s["resolved"], types[s["kind"]], lambda m, s=s: s["got"].append(m), queue_size=200)
    out = {}

    def wait_sim(dt):
        end = rospy.get_time() + dt
        while not rospy.is_shutdown() and rospy.get_time() < end:
            time.sleep(0.01)

    def base(m):
        return m.poses[0], m.twists[0]

    while rospy.get_time() == 0 or not states:
        time.sleep(0.05)
    wait_sim(2.0)  # settle on the ground (Jackal is dropped from 1 m)
    # --- still, at zero command
    t0, wall0 = rospy.get_time(), time.time()
    for s in sensors:
        s["got"].clear()
    states.clear()
    joints.clear()
    wait_sim(seconds)
    t1 = rospy.get_time()
    out["realtime_factor"] = (t1 - t0) / (time.time() - wall0)  # the world asks for 1.0
    first, last = base(states[0])[0], base(states[-1])[0]
    out["still_drift_m"] = math.dist((first.position.x, first.position.y), (last.position.x, last.position.y))
    out["still_turn_rad"] = abs(yaw_of(last.orientation) - yaw_of(first.orientation))
    if joints:
        drift = [abs(a - b) for a, b in zip(joints[0].position, joints[-1].position)]
        out["still_joint_drift_rad"] = max(drift)
        out["still_joint_drifting"] = joints[0].name[drift.index(max(drift))]
        out["joint_states_hz"] = len(joints) / (t1 - t0)
    pose = base(states[-1])[0]
    out["sensors"] = [check_sensor(s, pose, t0, t1) for s in sensors]
    # --- driven
    if "cmd" in spec:
        pub = rospy.Publisher(spec["cmd"], Twist, queue_size=1)
        deadline = time.time() + 10
        while pub.get_num_connections() == 0 and time.time() < deadline:
            time.sleep(0.05)

        def hold(linear, angular=0.0):
            """Commands (linear x, angular z) for `seconds`: the states of its second half."""
            cmd = Twist()
            cmd.linear.x, cmd.angular.z = linear, angular
            start = rospy.get_time()
            states.clear()
            while rospy.get_time() < start + seconds:
                pub.publish(cmd)
                wait_sim(0.05)
            return [m for m in states if m.header.stamp.to_sec() > start + seconds / 2]

        for sign, label in ((-1, "backward"), (1, "forward")):
            window = hold(sign * spec["speed"])
            speeds = []
            for m in window:
                p, v = base(m)
                yaw = yaw_of(p.orientation)
                # twist in the base's own frame (body_states' default): its x is the heading
                speeds.append(v.linear.x if m.twist_frames[0] != "world" else
                              v.linear.x * math.cos(yaw) + v.linear.y * math.sin(yaw))
            mean = sum(speeds) / len(speeds) if speeds else float("nan")
            out[label + "_speed"] = mean
            out[label + "_error"] = abs(mean - sign * spec["speed"]) / spec["speed"]
            out[label + "_turn_rad"] = abs(yaw_of(base(window[-1])[0].orientation) -
                                           yaw_of(base(window[0])[0].orientation)) if window else float("nan")
        if "steer" in spec:  # a steered base, backward (away from the wall): angular z is the steering angle
            window = hold(-spec["speed"], spec["steer"])
            rates = [base(m)[1].angular.z for m in window]
            expected = -spec["speed"] * math.tan(spec["steer"]) / spec["wheelbase"]
            out["turn_yaw_rate"] = sum(rates) / len(rates) if rates else float("nan")
            out["turn_expected"] = expected
            out["turn_error"] = abs(out["turn_yaw_rate"] - expected) / abs(expected)
        stop = Twist()
        for _ in range(5):
            pub.publish(stop)
            wait_sim(0.05)
    if "arm" in spec and joints:
        # Each joint 0.4 rad along a line of `seconds` (a trajectory of one
        # point, positions only: ros_controllers' linear segment), each away
        # from the ground the arm stands on: the shoulder and elbow lift.
        pub = rospy.Publisher(spec["arm"], JointTrajectory, queue_size=1)
        deadline = time.time() + 10
        while pub.get_num_connections() == 0 and time.time() < deadline:
            time.sleep(0.05)
        now = joints[-1]
        goal = JointTrajectory()
        goal.joint_names = list(now.name)
        point = JointTrajectoryPoint()
        lift = ("shoulder_lift", "elbow")
        point.positions = [q + (-0.4 if n.startswith(lift) else 0.4) for n, q in zip(now.name, now.position)]
        point.time_from_start = rospy.Duration(seconds)
        goal.points = [point]
        start = rospy.get_time()
        joints.clear()
        pub.publish(goal)
        wait_sim(seconds + 1.0)
        middle = [m for m in joints if start + seconds / 4 <= m.header.stamp.to_sec() <= start + 3 * seconds / 4]
        if len(middle) > 1:
            span = (middle[-1].header.stamp - middle[0].header.stamp).to_sec()
            speeds = [abs(b - a) / span for a, b in zip(middle[0].position, middle[-1].position)]
            out["arm_speed_error"] = max(abs(v - 0.4 / seconds) for v in speeds) / (0.4 / seconds)
            out["arm_speeds"] = dict(zip(middle[0].name, speeds))
        end = joints[-1]
        out["arm_goal_error_rad"] = max(abs(a - b) for a, b in zip(end.position, point.positions))
        out["arm_goal_errors"] = {n: a - b for n, a, b in zip(end.name, end.position, point.positions)}
    return out


def check_sensor(s, pose, t0, t1):
    got = [m for m in s["got"] if t0 <= m.header.stamp.to_sec() <= t1]
    entry = dict(kind=s["kind"], topic=s["resolved"], plugin=s["plugin"], declared_hz=s["rate"],
                 hz=len(got) / (t1 - t0))
    if not got:
        return entry
    mount = s.get("mount")
    world = None
    if mount is not None:
        yaw = yaw_of(pose.orientation)
        base = (rpy_matrix(0, 0, yaw), [pose.position.x, pose.position.y, pose.position.z])
        world = compose(base, mount)
    if s["kind"] in ("scan", "range") and world is not None:
        # The ray along world +x (a lidar's beam at minus the sensor's yaw; a
        # range sensor's axis, if it looks ahead) against the wall's face.
        r, t = world
        yaw = math.atan2(r[1][0], r[0][0])
        lo, hi = s["range"]
        if s["kind"] == "scan":
            m = got[-1]
            i = int(round((-yaw - m.angle_min) / m.angle_increment)) if m.angle_increment else 0
            if not 0 <= i < len(m.ranges):
                i = int(round((-yaw + 2 * math.pi - m.angle_min) / m.angle_increment))
            readings = [g.ranges[i] for g in got if 0 <= i < len(g.ranges)]
            expected = WALL - t[0]
        else:
            # the least ray of its cone: the one nearest the wall's normal
            readings = [g.range for g in got]
            off = max(0.0, abs(yaw) - s["half_fov"])
            expected = (WALL - t[0]) / math.cos(off) if abs(yaw) < math.pi / 3 else float("inf")
        mean = sum(readings) / len(readings) if readings else float("nan")
        entry.update(expected_m=expected if expected <= hi else float("inf"), mean_m=mean)
        tolerance = 4 * s["sigma"] + 0.01
        entry["ok"] = (abs(mean - expected) <= tolerance) if expected <= hi else (mean >= hi - tolerance)
    elif s["kind"] == "imu":
        a = [math.sqrt(m.linear_acceleration.x ** 2 + m.linear_acceleration.y ** 2 + m.linear_acceleration.z ** 2)
             for m in got]
        w = [math.sqrt(m.angular_velocity.x ** 2 + m.angular_velocity.y ** 2 + m.angular_velocity.z ** 2)
             for m in got]
        entry.update(accel=sum(a) / len(a), rate=sum(w) / len(w))
        entry["ok"] = (abs(entry["accel"] - G) <= 4 * s["sigma"] * math.sqrt(3) + s["bias"] * math.sqrt(3) + 0.02
                       and entry["rate"] <= 4 * s.get("gyro_sigma", s["sigma"]) * math.sqrt(3)
                       + s.get("gyro_bias", 0) * math.sqrt(3) + 0.002)
    elif s["kind"] == "gps" and world is not None:
        # hector's tangent plane: north over the meridian radius, east over N cos(lat)
        a, f = 6378137.0, 1 / 298.257223563
        e2 = f * (2 - f)
        lat0 = math.radians(s["lat"])
        n = a / math.sqrt(1 - e2 * math.sin(lat0) ** 2)
        m_r = n * (1 - e2) / (1 - e2 * math.sin(lat0) ** 2)
        h = math.radians(s["heading"])
        x, y = world[1][0], world[1][1]
        north = x * math.cos(h) + y * math.sin(h)  # hector: x north at heading 0
        east = x * math.sin(h) - y * math.cos(h)
        lat = [(g.latitude - s["lat"]) * math.pi / 180 * m_r for g in got]
        lon = [(g.longitude - s["lon"]) * math.pi / 180 * n * math.cos(lat0) for g in got]
        entry.update(north_m=sum(lat) / len(lat), east_m=sum(lon) / len(lon), truth_north_m=north,
                     truth_east_m=east)
        tol = 4 * s["sigma"] + s["bias"] + 0.01
        entry["ok"] = abs(entry["north_m"] - north) <= tol and abs(entry["east_m"] - east) <= tol
    elif s["kind"] == "depth" and world is not None:
        m = got[-1]
        import struct
        row, col = m.height // 2, m.width // 2
        if m.encoding == "32FC1":
            (d,) = struct.unpack_from(("<" if not m.is_bigendian else ">") + "f", bytes(m.data),
                                      row * m.step + col * 4)
        else:
            (d,) = struct.unpack_from("<H", bytes(m.data), row * m.step + col * 2)
            d /= 1000.0
        r, t = world
        expected = (WALL - t[0]) / r[0][0] if r[0][0] > 0.5 else float("inf")
        entry.update(expected_m=expected, centre_m=d, ok=abs(d - expected) <= 0.01)
    elif s["kind"] == "odom":
        entry["ok"] = True  # its values against the truth: the drive windows
    if "ok" in entry or s["kind"] in ("cloud", "image"):
        entry.setdefault("ok", True)
    if s["rate"] > 0:
        entry["rate_ok"] = abs(entry["hz"] - min(s["rate"], 1000.0)) <= 0.05 * min(s["rate"], 1000.0) + 0.5
    return entry


def table(results):
    rows = ["| robot | loads | real time | still (mm, mrad) | backward | forward | sensors at rate and within noise | "
            "not published |", "| --- | --- | --- | --- | --- | --- | --- | --- |"]
    for r in results:
        if not r.get("spawned"):
            rows.append("| %s | refused: %s | | | | | | |" % (r["robot"], r.get("error", "")))
            continue
        still = "%.1f, %.1f" % (1000 * r["still_drift_m"], 1000 * r["still_turn_rad"])
        if "still_joint_drift_rad" in r and "backward_speed" not in r:
            still = "joints %.1f mrad" % (1000 * r["still_joint_drift_rad"])
        drive = []
        for label in ("backward", "forward"):
            if label + "_speed" in r:
                drive.append("%.3f m/s (%.1f %%)" % (r[label + "_speed"], 100 * r[label + "_error"]))
                if label == "forward" and "turn_yaw_rate" in r:  # steered: v tan(d) / L
                    drive[-1] += "; steered: %.4f rad/s (%.1f %%)" % (r["turn_yaw_rate"], 100 * r["turn_error"])
            elif label == "forward" and "arm_goal_error_rad" in r:
                drive.append("joint speeds off by %.1f %%, goal off by %.1f mrad" % (
                    100 * r.get("arm_speed_error", float("nan")), 1000 * r["arm_goal_error_rad"]))
            else:
                drive.append("")
        good = [s for s in r["sensors"] if s["hz"] > 0 and s.get("ok") and s.get("rate_ok", True)]
        bad = [s for s in r["sensors"] if s["hz"] > 0 and not (s.get("ok") and s.get("rate_ok", True))]
        silent = [s for s in r["sensors"] if s["hz"] == 0]
        sensors = ", ".join("%s %.1f Hz" % (s["topic"], s["hz"]) for s in good)
        if bad:
            sensors += "; off: " + ", ".join("%s %.1f/%.1f Hz %s" % (
                s["topic"], s["hz"], s["declared_hz"],
                {k: round(v, 4) for k, v in s.items() if isinstance(v, float) and k not in ("hz", "declared_hz")})
                for s in bad)
        rows.append("| %s | yes | %.2f | %s | %s | %s | %s | %s |" % (
            r["robot"], r["realtime_factor"], still, drive[0], drive[1], sensors,
            ", ".join(s["topic"] for s in silent)))
    return "\n".join(rows)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("robots_dir")
    p.add_argument("names", nargs="*", default=list(ROBOTS))
    p.add_argument("--seconds", type=float, default=4.0)
    p.add_argument("--one", help=argparse.SUPPRESS)
    p.add_argument("--port", type=int, default=11521)
    args = p.parse_args()
    robots_dir = os.path.abspath(args.robots_dir)
    if args.one:
        print(json.dumps(run_one(args.one, robots_dir, args.seconds, args.port)))
        return
    results = []
    for i, name in enumerate(args.names):
        done = subprocess.run([sys.executable, os.path.abspath(__file__), robots_dir, "--one", name,
                               "--seconds", str(args.seconds), "--port", str(args.port + i)],
                              capture_output=True, text=True)
        line = done.stdout.strip().splitlines()[-1] if done.stdout.strip() else ""
        try:
            result = json.loads(line)
        except ValueError:
            result = dict(robot=name, spawned=False, error=(done.stderr.strip().splitlines() or ["?"])[-1][:300])
        print(json.dumps(result), flush=True)
        results.append(result)
    print(table(results))


if __name__ == "__main__":
    main()
