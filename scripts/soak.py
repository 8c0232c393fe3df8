"""Soak test of segmentation_node; run through scripts/soak (which builds and sources the workspace).

One process of its own for the node (its VmRSS is the node's memory), a master on a free port,
simulated time from a looping `rosbag play --clock`, tf map -> camera published here (so it can
be dropped), 4 threads calling ~segment with the scene's cloud, and a schedule of abuse:

  warm-up   every abuse below once, so one-off allocations are in the baseline; then VmRSS
            "start" = median of 21 samples (--memory-samples), 1 s apart, while the node is busy
  during    tf stops for 10 s; empty and all-NaN clouds (topic and service); a 5M-point cloud
            (topic and service: rejected by ~max_input_points); for 10 s the OctoMap in frame
            "odom" (moved into "map" through tf; the map comes from here, not from the bag);
            the bag player killed and restarted (time jumps back; the loop itself jumps back
            at every pass too)
  end       VmRSS "end" the same way, once at least --clouds clouds were segmented from the
            topic (counted on ~objects: service results are stamped 0, topic ones with the
            bag's stamps)

Fails when the node dies, a service call does not return within --call-timeout, a call gets a
status other than the expected one, or VmRSS grew by --max-growth or more.

Each VmRSS figure comes with where the resident memory is (from /proc/PID/smaps): the main
malloc heap, glibc's per-thread arenas (how many, and their resident total), other anonymous
mappings (large mmap'd blocks, thread stacks) and file-backed pages. Growth in the arenas while
the heap in use stays flat (heaptrack) is allocator retention, not a leak.

SYMSEG_SOAK_NODE_PREFIX, when set, is put in front of the node's command (split like a shell
would), e.g. SYMSEG_SOAK_NODE_PREFIX="heaptrack -o /tmp/node" or "valgrind --tool=massif": the
memory figures are then those of the node process itself, found below the wrapper.
"""
import argparse
import os
import random
import re
import shlex
import shutil
import signal
import socket
import statistics
import subprocess
import sys
import tempfile
import threading
import time

SUCCESS, NO_CLOUD, NO_OCCUPANCY, INVALID_INPUT, TIMEOUT, TRANSFORM_FAILED, SEGMENTATION_FAILED = range(7)
STATUS_NAMES = ["SUCCESS", "NO_CLOUD", "NO_OCCUPANCY", "INVALID_INPUT", "TIMEOUT", "TRANSFORM_FAILED",
                "SEGMENTATION_FAILED"]


def parse_args():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--workspace", required=True)
    parser.add_argument("--source", required=True)
    parser.add_argument("--clouds", type=int, default=1000, help="clouds to segment from the topic (default 1000)")
    parser.add_argument("--rate", type=float, default=2.0, help="bag playback rate (default 2)")
    parser.add_argument("--threads", type=int, default=4, help="threads calling ~segment (default 4)")
    parser.add_argument("--call-pause", type=float, default=0.5, help="pause between one thread's calls (s)")
    parser.add_argument("--call-timeout", type=float, default=120.0, help="a call taking longer has hung (s)")
    parser.add_argument("--memory-samples", type=int, default=21,
                        help="VmRSS samples, 1 s apart, whose median is the start / end figure (default 21)")
    parser.add_argument("--max-growth", type=float, default=0.05, help="allowed VmRSS growth (default 0.05)")
    parser.add_argument("--time-limit", type=float, default=3600.0, help="give up after this many s")
    parser.add_argument("--big-points", type=int, default=5000000, help="points of the big cloud")
    parser.add_argument("--keep", help="keep the run's files (bag, logs) in this directory")
    return parser.parse_args()


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def vm_rss_kb(pid):
    with open("/proc/%d/status" % pid) as status:
        for line in status:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    raise RuntimeError("no VmRSS for pid %d" % pid)


ARENA_HEAP_SIZE = 64 << 20  # glibc's HEAP_MAX_SIZE on 64-bit: each non-main arena heap reserves this much


def memory_breakdown_kb(pid):
    """Resident kB by kind of mapping, from /proc/PID/smaps: the main malloc heap, the heaps of
    glibc's other arenas (64 MB-aligned anonymous reservations, rw part plus ---p rest), other
    anonymous mappings, file-backed mappings."""
    mappings = []  # [start, end, perms, path, rss_kb]
    header = re.compile(r"^([0-9a-f]+)-([0-9a-f]+) (\S+) \S+ \S+ \S+\s*(.*)$")
    with open("/proc/%d/smaps" % pid) as smaps:
        for line in smaps:
            match = header.match(line)
            if match:
                mappings.append([int(match.group(1), 16), int(match.group(2), 16), match.group(3),
                                 match.group(4).strip(), 0])
            elif line.startswith("Rss:"):
                mappings[-1][4] = int(line.split()[1])
    kinds = {"heap": 0, "arenas": 0, "anonymous": 0, "files": 0}
    arena_count = 0
    for index, (start, end, perms, path, rss) in enumerate(mappings):
        if path == "[heap]":
            kinds["heap"] += rss
        elif path and not path.startswith("["):
            kinds["files"] += rss
        elif path:
            kinds["anonymous"] += rss  # [stack], [vvar], ...
        else:
            reserved_end = end
            if index + 1 < len(mappings) and mappings[index + 1][0] == end and mappings[index + 1][2] == "---p":
                reserved_end = mappings[index + 1][1]
            if start % ARENA_HEAP_SIZE == 0 and reserved_end - start == ARENA_HEAP_SIZE and perms == "rw-p":
                kinds["arenas"] += rss
                arena_count += 1
            else:
                kinds["anonymous"] += rss
    kinds["arena_count"] = arena_count
    return kinds


def describe_breakdown(kinds):
    return "main heap %.1f MB, %d arena heaps %.1f MB, other anonymous %.1f MB, files %.1f MB" % (
        kinds["heap"] / 1024.0, kinds["arena_count"], kinds["arenas"] / 1024.0, kinds["anonymous"] / 1024.0,
        kinds["files"] / 1024.0)


def node_process(pid):
    """The node's own pid: `pid` itself, or with a wrapper in front (heaptrack runs it as a child),
    the descendant running segmentation_node."""
    pending = [pid]
    while pending:
        current = pending.pop(0)
        try:
            with open("/proc/%d/cmdline" % current, "rb") as cmdline:
                program = cmdline.read().split(b"\0")[0]
        except OSError:
            continue
        if os.path.basename(program) == b"segmentation_node":
            return current
        try:
            with open("/proc/%d/task/%d/children" % (current, current)) as children:
                pending.extend(int(child) for child in children.read().split())
        except OSError:
            pass
    return pid


class Failure(Exception):
    pass


class Soak:
    def __init__(self, args, directory):
        self.args = args
        self.dir = directory
        self.tools = os.path.join(args.workspace, "devel", "lib", "symmetry_segmentation")
        self.processes = {}
        self.lock = threading.Lock()
        self.stop = threading.Event()
        self.tf_enabled = threading.Event()
        self.tf_enabled.set()
        self.processed = 0          # ~objects messages for topic clouds
        self.calls = 0
        self.statuses = {}
        self.in_flight = {}         # thread index -> (start wall time, kind)
        self.problems = []
        self.events = []

    # --- processes -----------------------------------------------------------------------
    def start(self, name, command, **kwargs):
        log = open(os.path.join(self.dir, name + ".log"), "w")
        # stdin from /dev/null: rosbag play reads keys from stdin (a space pauses it).
        self.processes[name] = subprocess.Popen(command, stdin=subprocess.DEVNULL, stdout=log, stderr=subprocess.STDOUT,
                                                start_new_session=True, **kwargs)
        return self.processes[name]

    def kill(self, name, timeout=15.0):
        process = self.processes.pop(name, None)
        if process is None or process.poll() is not None:
            return
        os.killpg(process.pid, signal.SIGINT)
        try:
            process.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            process.wait()

    def node_alive(self):
        node = self.processes.get("node")
        return node is not None and node.poll() is None

    def log(self, text):
        print("[%7.1f s] %s" % (time.monotonic() - self.t0, text), flush=True)

    # --- inputs --------------------------------------------------------------------------
    def make_bag(self):
        scene = os.path.join(self.dir, "scene")
        subprocess.run([os.path.join(self.tools, "make_scene"), "--kind", "isolated", "--seed", "3", "--views", "2",
                        "--output", scene], check=True, stdout=subprocess.DEVNULL)
        self.bag = os.path.join(self.dir, "soak.bag")
        # Topics as the node names them; the bag's static tf names a frame the node does not use,
        # so the only map -> camera is the one published (and dropped) here.
        subprocess.run([os.path.join(self.tools, "scene_to_bag"), scene, "--output", self.bag, "--clouds", "50",
                        "--rate", "10", "--voxel", "0.01", "--camera-frame", "recorded_camera",
                        "--cloud-topic", "/segmentation/input", "--octomap-topic", "/recorded_octomap"],
                       check=True, stdout=subprocess.DEVNULL)
        # scene_to_bag writes bz2 chunks of one cloud each: the player decompresses one per message,
        # falls behind real time on a busy machine and its clock then steps back and forth.
        subprocess.run(["rosbag", "decompress", "--force", self.bag], check=True, stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL)

    def read_bag(self):
        import rosbag
        with rosbag.Bag(self.bag) as bag:
            for topic, message, _ in bag.read_messages(topics=["/segmentation/input", "/tf_static"]):
                if topic == "/segmentation/input" and not hasattr(self, "cloud"):
                    self.cloud = message
                elif topic == "/tf_static":
                    self.camera = message.transforms[0]
                    # Debian packages no Python tf2_msgs: the bag's own class serves.
                    self.TFMessage = type(message)
        self.log("bag: %d-point cloud, camera at (%.2f, %.2f, %.2f)" % (
            self.cloud.width * self.cloud.height, self.camera.transform.translation.x,
            self.camera.transform.translation.y, self.camera.transform.translation.z))

    def clouds(self):
        from sensor_msgs.msg import PointCloud2, PointField
        import numpy as np

        def xyz_cloud(points):
            message = PointCloud2()
            message.header.frame_id = "map"
            message.height = 1
            message.width = len(points)
            message.fields = [PointField(name, 4 * i, PointField.FLOAT32, 1) for i, name in enumerate("xyz")]
            message.point_step = 12
            message.row_step = 12 * len(points)
            message.is_dense = False
            message.data = np.asarray(points, dtype=np.float32).tobytes()
            return message

        self.empty_cloud = xyz_cloud(np.zeros((0, 3)))
        self.nan_cloud = xyz_cloud(np.full((1000, 3), np.nan))
        rng = np.random.default_rng(1)
        self.big_cloud = xyz_cloud(rng.uniform(-1.0, 1.0, (self.args.big_points, 3)))
        self.scene_cloud = self.cloud
        self.scene_cloud.header.stamp.secs = 0  # service results are told apart by stamp 0
        self.scene_cloud.header.stamp.nsecs = 0
        self.scene_cloud.header.frame_id = "map"
        # A region of interest: the middle of the scene's extent.
        offsets = {field.name: field.offset for field in self.cloud.fields}
        raw = np.frombuffer(self.cloud.data, dtype=np.uint8).reshape(-1, self.cloud.point_step)
        xyz = np.stack([raw[:, offsets[c]:offsets[c] + 4].copy().view(np.float32)[:, 0] for c in "xyz"], axis=1)
        xyz = xyz[np.isfinite(xyz).all(axis=1)]
        low, high = xyz.min(axis=0), xyz.max(axis=0)
        self.roi = (low + 0.25 * (high - low), high - 0.25 * (high - low) + [0, 0, 1.0])

    def recorded_map(self, frame):
        """The bag's map, in `frame` (tf map -> odom is the identity). The bag's own map goes to a
        topic the node does not read: the map the node has is always the one sent from here."""
        import rosbag
        with rosbag.Bag(self.bag) as bag:
            for _, message, _ in bag.read_messages(topics=["/recorded_octomap"]):
                message.header.frame_id = frame
                return message
        raise Failure("no OctoMap in the bag")

    # --- ROS side ------------------------------------------------------------------------
    def ros_setup(self):
        import rospy
        from geometry_msgs.msg import TransformStamped
        from sensor_msgs.msg import PointCloud2
        from symmetry_segmentation.msg import SegmentedObjectArray
        rospy.init_node("soak", anonymous=True, disable_signals=True)
        self.rospy = rospy
        self.cloud_pub = rospy.Publisher("/segmentation/input", PointCloud2, queue_size=1)
        self.tf_pub = rospy.Publisher("/tf", self.TFMessage, queue_size=10)
        self.static_pub = rospy.Publisher("/tf_static", self.TFMessage, queue_size=1, latch=True)

        def on_objects(message):
            if message.header.stamp.to_sec() > 0:
                with self.lock:
                    self.processed += 1
        self.objects_sub = rospy.Subscriber("/segmentation/objects", SegmentedObjectArray, on_objects, queue_size=10)
        self.TransformStamped = TransformStamped

    def tf_loop(self):
        # map -> camera at 20 Hz (wall), stamped with simulated time; paused while tf is dropped.
        last = None
        while not self.stop.is_set():
            now = self.rospy.Time.now()
            # Not the same stamp twice (tf2 warns about it): the clock stands while the player restarts.
            if self.tf_enabled.is_set() and not now.is_zero() and now != last:
                last = now
                transform = self.TransformStamped()
                transform.header.stamp = now
                transform.header.frame_id = "map"
                transform.child_frame_id = "camera"
                transform.transform = self.camera.transform
                self.tf_pub.publish(self.TFMessage([transform]))
            time.sleep(0.05)

    def call_loop(self, index):
        import rospy
        from symmetry_segmentation.srv import SegmentCloud, SegmentCloudRequest
        proxy = rospy.ServiceProxy("/segmentation/segment", SegmentCloud)
        rng = random.Random(index)
        while not self.stop.is_set():
            request = SegmentCloudRequest()
            request.cloud = self.scene_cloud
            request.timeout = 1.0
            kind = "scene"
            if rng.random() < 0.1:
                request.use_roi = True
                request.roi_min.x, request.roi_min.y, request.roi_min.z = map(float, self.roi[0])
                request.roi_max.x, request.roi_max.y, request.roi_max.z = map(float, self.roi[1])
                kind = "scene+roi"
            # Without tf (dropped, or cleared after a time jump) the sensor frame is unknown.
            self.call(index, proxy, request, kind, {SUCCESS, TRANSFORM_FAILED})
            time.sleep(self.args.call_pause)

    def call(self, index, proxy, request, kind, expected):
        with self.lock:
            self.in_flight[index] = (time.monotonic(), kind)
        try:
            response = proxy(request)
        except Exception as error:  # the node died or the call failed at the transport level
            with self.lock:
                self.problems.append("call %s failed: %s" % (kind, error))
            return None
        finally:
            with self.lock:
                self.in_flight.pop(index, None)
        with self.lock:
            self.calls += 1
            key = (kind, STATUS_NAMES[response.status])
            self.statuses[key] = self.statuses.get(key, 0) + 1
            if response.status not in expected:
                self.problems.append("call %s: unexpected status %s: %s" % (kind, STATUS_NAMES[response.status],
                                                                           response.message))
        return response

    # --- abuse ---------------------------------------------------------------------------
    def abuse_bad_clouds(self):
        import rospy
        from symmetry_segmentation.srv import SegmentCloud, SegmentCloudRequest
        proxy = rospy.ServiceProxy("/segmentation/segment", SegmentCloud)
        for _ in range(5):
            self.cloud_pub.publish(self.empty_cloud)
            time.sleep(0.1)
            self.cloud_pub.publish(self.nan_cloud)
            time.sleep(0.1)
        for cloud, kind, needle in ((self.empty_cloud, "empty", "empty"), (self.nan_cloud, "all-NaN", "finite")):
            request = SegmentCloudRequest(cloud=cloud)
            response = self.call(100, proxy, request, kind, {INVALID_INPUT})
            if response is not None and needle not in response.message:
                self.problems.append("%s cloud: message '%s' lacks '%s'" % (kind, response.message, needle))
        self.event("empty and all-NaN clouds on the topic and the service")

    def abuse_big_cloud(self):
        import rospy
        from symmetry_segmentation.srv import SegmentCloud, SegmentCloudRequest
        proxy = rospy.ServiceProxy("/segmentation/segment", SegmentCloud)
        self.cloud_pub.publish(self.big_cloud)
        response = self.call(101, proxy, SegmentCloudRequest(cloud=self.big_cloud), "5M points", {INVALID_INPUT})
        if response is not None and "max_input_points" not in response.message:
            self.problems.append("big cloud: message '%s' does not name the limit" % response.message)
        self.event("%d-point cloud on the topic and the service: %s" % (
            self.args.big_points, response.message if response else "no response"))

    def abuse_odom_map(self):
        import rospy
        from symmetry_segmentation.srv import SegmentCloud, SegmentCloudRequest
        odom = self.TransformStamped()
        odom.header.stamp = rospy.Time(0)
        odom.header.frame_id = "map"
        odom.child_frame_id = "odom"
        odom.transform.rotation.w = 1.0
        self.static_pub.publish(self.TFMessage([odom]))
        self.map_pub.publish(self.recorded_map("odom"))
        time.sleep(1.0)
        proxy = rospy.ServiceProxy("/segmentation/segment", SegmentCloud)
        response = self.call(102, proxy, SegmentCloudRequest(cloud=self.scene_cloud, timeout=2.0), "odom map",
                             {SUCCESS, TRANSFORM_FAILED})
        self.event("OctoMap in frame 'odom' for 10 s: %s" % (response.message if response else "no response"))
        self.wait_wall(10.0)
        self.map_pub.publish(self.recorded_map("map"))

    def octomap_publisher(self):
        # The node's OctoMap type is octomap_msgs/Octomap, which Debian does not package: the bag's
        # message class (rosbag builds it from the stored definition) serves as the type.
        import rosbag
        import rospy
        with rosbag.Bag(self.bag) as bag:
            for _, message, _ in bag.read_messages(topics=["/recorded_octomap"]):
                return rospy.Publisher("/segmentation/octomap", type(message), queue_size=1, latch=True)
        raise Failure("no OctoMap in the bag")

    def drop_tf(self, seconds):
        self.tf_enabled.clear()
        self.event("tf stopped for %.0f s" % seconds)
        self.wait_wall(seconds)
        self.tf_enabled.set()

    def restart_bag(self):
        self.kill("player")
        self.wait_wall(2.0)
        self.start_player()
        self.event("bag player killed and restarted (time jumps back)")

    def start_player(self):
        self.start("player", ["rosbag", "play", "--clock", "--loop", "--quiet", "-r", str(self.args.rate), self.bag])

    def event(self, text):
        with self.lock:
            processed = self.processed
        self.events.append((processed, text))
        self.log("%s (processed %d)" % (text, processed))

    # --- checks --------------------------------------------------------------------------
    def check(self):
        if not self.node_alive():
            raise Failure("the node died (exit code %s)" % self.processes["node"].poll())
        now = time.monotonic()
        with self.lock:
            for index, (start, kind) in self.in_flight.items():
                if now - start > self.args.call_timeout:
                    raise Failure("a %s call has not returned for %.0f s" % (kind, now - start))
            if self.problems:
                raise Failure(self.problems[0])
        if now - self.t0 > self.args.time_limit:
            raise Failure("time limit of %.0f s reached with %d clouds processed" % (self.args.time_limit,
                                                                                    self.processed))

    def wait_wall(self, seconds):
        end = time.monotonic() + seconds
        while time.monotonic() < end:
            self.check()
            time.sleep(0.2)

    def wait_processed(self, count):
        while True:
            with self.lock:
                processed, calls = self.processed, self.calls
            if processed >= count:
                return
            if time.monotonic() - getattr(self, "last_progress", 0.0) > 60.0:
                self.last_progress = time.monotonic()
                self.log("progress: %d clouds processed, %d service calls, VmRSS %.1f MB" % (
                    processed, calls, vm_rss_kb(self.node_pid()) / 1024.0))
            self.wait_wall(1.0)

    def node_pid(self):
        if not hasattr(self, "node_own_pid") or not os.path.exists("/proc/%d" % self.node_own_pid):
            self.node_own_pid = node_process(self.processes["node"].pid)
        return self.node_own_pid

    def memory(self, label):
        # The median of many samples: resident memory follows the segmentations in flight (up and
        # down by ~10 MB within a second here), and 5 samples could not tell that from growth.
        samples = []
        for _ in range(self.args.memory_samples):
            samples.append(vm_rss_kb(self.node_pid()))
            self.wait_wall(1.0)
        value = statistics.median(samples)
        self.log("VmRSS %s: %.1f MB (samples %s kB)" % (label, value / 1024.0, " ".join(map(str, samples))))
        self.log("  where: %s" % describe_breakdown(memory_breakdown_kb(self.node_pid())))
        return value

    # --- the run -------------------------------------------------------------------------
    def run(self):
        self.t0 = time.monotonic()
        self.make_bag()
        self.read_bag()
        self.clouds()
        port = free_port()
        os.environ["ROS_MASTER_URI"] = "http://127.0.0.1:%d" % port
        os.environ["ROS_HOME"] = self.dir
        os.environ["ROS_LOG_DIR"] = os.path.join(self.dir, "ros_log")
        self.start("master", ["rosmaster", "--core", "-p", str(port)])
        time.sleep(2.0)
        subprocess.run(["rosparam", "set", "/use_sim_time", "true"], check=True)
        subprocess.run(["rosparam", "load", os.path.join(self.args.source, "config", "default.yaml"), "/segmentation"],
                       check=True)
        for name, value in (("mode", "continuous"), ("fixed_frame", "map"), ("sensor_frame", "camera")):
            subprocess.run(["rosparam", "set", "/segmentation/" + name, value], check=True)
        prefix = shlex.split(os.environ.get("SYMSEG_SOAK_NODE_PREFIX", ""))
        self.start("node", prefix + [os.path.join(self.tools, "segmentation_node"), "__name:=segmentation"])
        self.ros_setup()
        self.map_pub = self.octomap_publisher()  # latched, like octomap_server
        self.map_pub.publish(self.recorded_map("map"))
        threading.Thread(target=self.tf_loop, daemon=True).start()
        self.start_player()
        self.log("node pid %d, master port %d, bag played at %gx in a loop%s" % (
            self.processes["node"].pid, port, self.args.rate, " (prefix: %s)" % " ".join(prefix) if prefix else ""))
        deadline = time.monotonic() + 120
        while self.processed < 5:
            if time.monotonic() > deadline:
                raise Failure("nothing segmented within 120 s of starting")
            self.wait_wall(0.5)
        callers = [threading.Thread(target=self.call_loop, args=(i,), daemon=True) for i in range(self.args.threads)]
        for caller in callers:
            caller.start()
        self.log("%d threads calling ~segment" % len(callers))

        # Warm-up: every path once.
        self.wait_processed(30)
        self.abuse_bad_clouds()
        self.abuse_big_cloud()
        self.abuse_odom_map()
        self.drop_tf(5)
        self.restart_bag()
        self.wait_processed(self.processed + 30)
        start_rss = self.memory("start (after warm-up)")
        warm = self.processed

        total = self.args.clouds
        schedule = [
            (0.15, lambda: self.drop_tf(10)),
            (0.25, self.abuse_bad_clouds),
            (0.35, self.abuse_big_cloud),
            (0.45, self.abuse_odom_map),
            (0.55, self.restart_bag),
            (0.65, lambda: self.drop_tf(10)),
            (0.75, self.abuse_big_cloud),
            (0.80, self.abuse_bad_clouds),
            (0.85, self.restart_bag),
        ]
        for fraction, action in schedule:
            self.wait_processed(max(warm, int(fraction * total)))
            action()
        self.wait_processed(total)
        end_rss = self.memory("end")
        self.stop.set()
        for caller in callers:
            caller.join(timeout=self.args.call_timeout)
            if caller.is_alive():
                raise Failure("a calling thread did not finish")
        self.check()
        growth = (end_rss - start_rss) / start_rss
        return start_rss, end_rss, growth, warm

    def summary(self):
        lines = []
        for (kind, status), count in sorted(self.statuses.items()):
            lines.append("  %-10s %-20s %d" % (kind, status, count))
        return "\n".join(lines)

    def shutdown(self):
        self.stop.set()
        # A profiler in front of the node (SYMSEG_SOAK_NODE_PREFIX) writes its data after the node exits.
        profiled = bool(os.environ.get("SYMSEG_SOAK_NODE_PREFIX"))
        for name in ("player", "node", "master"):
            self.kill(name, timeout=600.0 if profiled and name == "node" else 15.0)


def main():
    args = parse_args()
    directory = args.keep or tempfile.mkdtemp(prefix="symseg_soak_")
    os.makedirs(directory, exist_ok=True)
    soak = Soak(args, directory)
    outcome = "FAIL"
    reason = ""
    figures = ""
    try:
        start_rss, end_rss, growth, warm = soak.run()
        figures = "VmRSS start %.1f MB, end %.1f MB (%+.1f %%)" % (start_rss / 1024, end_rss / 1024, 100 * growth)
        if growth >= args.max_growth:
            reason = "memory grew by %.1f %% (limit %.1f %%)" % (100 * growth, 100 * args.max_growth)
        else:
            outcome = "PASS"
    except Failure as failure:
        reason = str(failure)
    except KeyboardInterrupt:
        reason = "interrupted"
    finally:
        alive = soak.node_alive()
        soak.shutdown()
    log = os.path.join(directory, "node.log")
    if os.path.exists(log):
        with open(log) as text:
            lines = text.readlines()
        jumps = sum("moved backwards" in line for line in lines)
        print("node log %s: %d lines, %d time jumps handled, %d 'ignoring cloud' warnings, %d errors" % (
            log, len(lines), jumps, sum("ignoring cloud" in line for line in lines),
            sum("[ERROR]" in line for line in lines)))
        if outcome != "PASS":
            print("".join(lines[-30:]))
    print("events (clouds processed when it happened):")
    for processed, text in soak.events:
        print("  %5d  %s" % (processed, text))
    print("service calls by kind and status:")
    print(soak.summary())
    if not args.keep:
        shutil.rmtree(directory, ignore_errors=True)
    print("soak %s: %d clouds processed from the topic, %d service calls, node %s, %s%s" % (
        outcome, soak.processed, soak.calls, "alive to the end" if alive else "NOT alive at the end",
        figures or "no memory figures", "" if outcome == "PASS" else ": " + reason))
    return 0 if outcome == "PASS" else 1


if __name__ == "__main__":
    sys.exit(main())
