# SPDX-License-Identifier: BSD-2-Clause
"""The MQTT publisher against a real mosquitto broker on 127.0.0.1 (docs/mqtt.md): the
message schema, a clear error for a broker that is not there, and the fault test: three
cameras publish at once, the broker is stopped and started again mid-stream, and the
subscriber must receive every message the publishers did not report as dropped, in order
per camera. Every case skips, saying why, where mosquitto, the programs, the model or the
PETS frames are missing; every process runs under a timeout."""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from broker import Broker, free_port  # noqa: E402

SOURCE = os.environ.get("CALPED_SOURCE_DIR", ".")
BUILD = os.environ.get("CALPED_BUILD_DIR", "build")
SHARED = os.environ.get("CALPED_SHARED_DIR", os.path.join(SOURCE, "..", "shared"))
FRAMES = os.path.join(SOURCE, "data", "pets", "frames")
CALIB = os.path.join(SHARED, "data", "pets2009-s2l1", "View_001.xml")
SANITIZED = os.environ.get("CALPED_SANITIZED") == "1"
SUMMARY = re.compile(r"mqtt (\S+): frames (\d+), sent (\d+), acknowledged (\d+), dropped (\d+) "
                     r"\(queue full\), unacknowledged (\d+), reconnects (\d+)")


def program(name):
    path = os.environ.get(name.upper().replace("-", "_"))
    if not path or not os.path.exists(path):
        pytest.skip("%s is not built here" % name)
    return path


def need_mqtt():
    if os.environ.get("CALPED_MQTT_BUILT") != "1":
        pytest.skip("calped was built without MQTT (libmosquitto-dev, meson -Dmqtt)")
    missing = [p for p in ("mosquitto_sub", "mosquitto_pub") if not shutil.which(p)]
    if not Broker.program():
        missing.insert(0, "mosquitto")
    if missing:
        pytest.skip("no %s (Debian: apt-get install mosquitto mosquitto-clients)" % ", ".join(missing))


def frames_needed(count):
    if not os.path.isdir(FRAMES) or len([f for f in os.listdir(FRAMES) if f.endswith(".png")]) < count:
        pytest.skip("needs %d PETS frames in data/pets/frames (scripts/fetch-pets.sh %d)" % (count, count))


def model():
    """The INRIA model blob the C++ tests use (tests/common/test_data.cpp), converted from
    ../shared once per build."""
    blob = os.path.join(BUILD, "tests", "inria-test.cpm")
    if os.path.exists(blob):
        return blob
    mat = os.path.join(SHARED, "models", "dollar-toolbox", "AcfInriaDetector.mat")
    convert = os.environ.get("CALPED_CONVERT")
    if not os.path.exists(mat) or not convert or not os.path.exists(convert):
        pytest.skip("needs ../shared's AcfInriaDetector.mat and calped-convert")
    tmp = "%s.%d" % (blob, os.getpid())
    subprocess.run([convert, mat, tmp], check=True, stdout=subprocess.DEVNULL, timeout=120)
    os.replace(tmp, blob)  # atomic: other tests may convert at the same time
    return blob


@pytest.fixture
def folder():
    path = tempfile.mkdtemp(prefix="calped-mqtt-")
    yield path
    shutil.rmtree(path, ignore_errors=True)


@pytest.fixture
def broker(folder):
    need_mqtt()
    b = Broker(folder)
    b.start()
    yield b
    b.stop()


class Subscriber:
    """mosquitto_sub with a persistent session (-c, a fixed id, QoS 1): after a broker
    restart it reconnects and gets what the broker queued for it meanwhile."""

    def __init__(self, broker, folder, topic="calped/+/detections"):
        self.path = os.path.join(folder, "received.txt")
        self.out = open(self.path, "wb")
        self.proc = subprocess.Popen(
            ["mosquitto_sub", "-h", "127.0.0.1", "-p", str(broker.port), "-t", topic, "-q", "1",
             "-c", "-i", "calped-test-%d" % broker.port, "-v"], stdout=self.out, stderr=subprocess.PIPE)
        # Ready once a probe published after it started comes through.
        deadline = time.monotonic() + 20
        while "calped/probe/detections" not in self.topics():
            subprocess.run(["mosquitto_pub", "-h", "127.0.0.1", "-p", str(broker.port), "-q", "1",
                            "-t", "calped/probe/detections", "-m", "{}"], timeout=10, check=True)
            if time.monotonic() > deadline:
                raise RuntimeError("the subscriber did not receive its probe within 20 s")
            time.sleep(0.2)

    def lines(self):
        with open(self.path, "rb") as f:
            return [line.decode("utf-8") for line in f.read().split(b"\n") if line]

    def topics(self):
        return [line.split(" ", 1)[0] for line in self.lines()]

    def messages(self):
        out = []
        for line in self.lines():
            topic, payload = line.split(" ", 1)
            if topic != "calped/probe/detections":
                out.append((topic, json.loads(payload)))
        return out

    def stop(self):
        self.proc.terminate()
        self.proc.wait(timeout=10)
        self.out.close()


def counts(stderr):
    found = SUMMARY.findall(stderr)
    assert len(found) == 1, "expected one mqtt summary line on stderr:\n" + stderr
    url, *numbers = found[0]
    names = ("frames", "sent", "acknowledged", "dropped", "unacknowledged", "reconnects")
    return dict(zip(names, map(int, numbers)), url=url)


def test_detect_publishes_one_message_per_frame_with_the_schema(broker, folder):
    detect = program("calped-detect")
    frames_needed(3)
    if not os.path.exists(CALIB):
        pytest.skip("needs ../shared's PETS calibration View_001.xml")
    sub = Subscriber(broker, folder)
    r = subprocess.run([detect, "--model", model(), "--calib", CALIB, "--resize", "2", "--max-frames", "3",
                        "--mqtt", broker.url("calped/pets1/detections"), "--camera-id", "pets1", FRAMES],
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    c = counts(r.stderr)
    assert (c["frames"], c["sent"], c["acknowledged"], c["dropped"], c["unacknowledged"]) == (3, 3, 3, 0, 0)
    deadline = time.monotonic() + 20
    while len(sub.messages()) < 3 and time.monotonic() < deadline:
        time.sleep(0.1)
    sub.stop()
    messages = sub.messages()
    assert [m["frame"] for _, m in messages] == [1, 2, 3]
    now = time.time()
    for topic, m in messages:
        assert topic == "calped/pets1/detections"
        assert m["camera"] == "pets1"
        assert m["method"] == "calibrated"
        assert now - 600 < m["time"] <= now + 1  # unix seconds, UTC
        assert (m["width"], m["height"]) == (768, 576)
        assert m["file"].endswith(".png")
    people = [d for _, m in messages for d in m["detections"]]
    assert people, "PETS frames 1-3 show people"
    for d in people:
        assert set(d) == {"x", "y", "w", "h", "score", "ground_x", "ground_y", "world_height"}
        assert 1.0 < d["world_height"] < 2.5


def test_unreachable_broker_is_a_clear_error_at_start(folder):
    need_mqtt()
    detect = program("calped-detect")
    frames_needed(1)
    port = free_port()  # nobody listens there
    start = time.monotonic()
    r = subprocess.run([detect, "--model", model(), "--max-frames", "1",
                        "--mqtt", "mqtt://127.0.0.1:%d/calped/x/detections" % port, FRAMES],
                       capture_output=True, text=True, timeout=60)
    assert r.returncode == 1
    assert time.monotonic() - start < 15
    assert r.stderr.startswith("calped-detect: ")
    assert "127.0.0.1:%d" % port in r.stderr
    assert len(r.stderr.strip().splitlines()) == 1, r.stderr


@pytest.mark.parametrize("url, why", [
    ("http://127.0.0.1:1883/t", "only the mqtt:// scheme"),
    ("127.0.0.1:1883/t", "no mqtt:// scheme"),
    ("mqtt://127.0.0.1:1883", "no topic"),
    ("mqtt://127.0.0.1:1883/", "no topic"),
    ("mqtt://127.0.0.1:0/t", "port"),
    ("mqtt://127.0.0.1:65536/t", "port"),
    ("mqtt://127.0.0.1:x/t", "port"),
    ("mqtt://:1883/t", "no host"),
    ("mqtt://user:pw@host/t", "user names"),
    ("mqtt://host/calped/+/detections", "wildcard"),
    ("mqtt://host/calped/#", "wildcard"),
    ("mqtt://host/t?x=1", "queries"),
])
def test_bad_urls_are_usage_errors(url, why):
    detect = program("calped-detect")
    r = subprocess.run([detect, "--model", "m.cpm", "--mqtt", url, "x.png"], capture_output=True,
                       text=True, timeout=60)
    assert r.returncode == 2, r.stderr
    assert r.stderr.startswith("calped-detect: --mqtt: bad MQTT URL '%s'" % url), r.stderr
    assert why in r.stderr


def test_camera_id_without_mqtt_is_a_usage_error():
    detect = program("calped-detect")
    r = subprocess.run([detect, "--model", "m.cpm", "--camera-id", "c1", "x.png"], capture_output=True,
                       text=True, timeout=60)
    assert r.returncode == 2 and "need --mqtt" in r.stderr, r.stderr


# The fault test. Cameras 2 and 3 have the default queue and must lose nothing; camera 1
# holds one unacknowledged message only, so while the broker is away it drops (and counts)
# every further frame.
CAMERAS = {"cam1": 1, "cam2": 1000, "cam3": 1000}
FRAMES_PER_CAMERA = 40


def test_three_cameras_survive_a_broker_restart(broker, folder):
    play = program("calped-play")
    frames_needed(FRAMES_PER_CAMERA)
    blob = model()
    sub = Subscriber(broker, folder)
    fps = 2 if SANITIZED else 8
    publishers = {}
    for cam, queue in CAMERAS.items():
        err = open(os.path.join(folder, cam + ".err"), "w+")
        publishers[cam] = (subprocess.Popen(
            [play, "--model", blob, "--input", FRAMES, "--fps", str(fps), "--frames", str(FRAMES_PER_CAMERA),
             "--stats-every", "3600", "--mqtt", broker.url("calped/%s/detections" % cam), "--camera-id", cam,
             "--mqtt-queue", str(queue)], stdout=subprocess.DEVNULL, stderr=err), err)
    try:
        # Mid-stream: every camera has had some messages through.
        deadline = time.monotonic() + 120
        while min(sum(t == "calped/%s/detections" % c for t in sub.topics()) for c in CAMERAS) < 4:
            assert time.monotonic() < deadline, "the cameras' first messages did not arrive within 120 s"
            assert all(p.poll() is None for p, _ in publishers.values()), "a publisher ended early"
            time.sleep(0.05)
        broker.restart(pause=1.5)
        results = {}
        for cam, (proc, err) in publishers.items():
            proc.wait(timeout=600)
            err.seek(0)
            text = err.read()
            assert proc.returncode == 0, text
            results[cam] = counts(text)
    finally:
        for proc, _ in publishers.values():
            if proc.poll() is None:
                proc.kill()
                proc.wait()
    # Everything the broker acknowledged reaches the subscriber (its session was saved).
    expected = sum(c["acknowledged"] for c in results.values())
    deadline = time.monotonic() + 30
    while len({(t, m["frame"]) for t, m in sub.messages()}) < expected and time.monotonic() < deadline:
        time.sleep(0.1)
    sub.stop()

    received = {cam: [] for cam in CAMERAS}
    for topic, m in sub.messages():
        assert topic == "calped/%s/detections" % m["camera"]
        received[m["camera"]].append(m["frame"])
    report = []
    for cam, c in results.items():
        frames = received[cam]
        unique = list(dict.fromkeys(frames))  # QoS 1 is at least once: duplicates are allowed
        report.append("%s: frames %d, sent %d, acknowledged %d, dropped %d, received %d (%d duplicates), "
                      "reconnects %d" % (cam, c["frames"], c["sent"], c["acknowledged"], c["dropped"],
                                         len(unique), len(frames) - len(unique), c["reconnects"]))
        assert c["frames"] == FRAMES_PER_CAMERA
        assert c["sent"] + c["dropped"] == c["frames"]
        assert c["unacknowledged"] == 0 and c["acknowledged"] == c["sent"]
        assert c["reconnects"] >= 1, "the broker restart was not seen"
        assert unique == sorted(unique), "%s: out of order: %s" % (cam, unique)
        assert set(unique) <= set(range(1, FRAMES_PER_CAMERA + 1))
        assert len(unique) == c["frames"] - c["dropped"], "%s: a message neither received nor counted as dropped" % cam
        if CAMERAS[cam] >= FRAMES_PER_CAMERA:
            assert c["dropped"] == 0
    assert results["cam1"]["dropped"] > 0, "camera 1's one-message queue never filled while the broker was away"
    print("broker restarts %d\n%s" % (broker.restarts, "\n".join(report)))


def binding_env(folder):
    """A PYTHONPATH with the binding's sources and this build's _build.py, and the library
    of this build: the binding as ground_plan.py imports it, without installing."""
    if SANITIZED:
        pytest.skip("sanitizer build: ctypes would need libasan preloaded (tests/python skips too)")
    built = os.path.join(BUILD, "python", "_build.py")
    library = [f for f in os.listdir(os.path.join(BUILD, "capi")) if f.startswith("libcalped_c.so.")] \
        if os.path.isdir(os.path.join(BUILD, "capi")) else []
    if not os.path.exists(built) or not library:
        pytest.skip("the Python binding and libcalped_c are not built here")
    try:
        import numpy  # noqa: F401
    except ImportError:
        pytest.skip("no numpy (Debian: apt-get install python3-numpy)")
    package = os.path.join(folder, "py", "calped")
    os.makedirs(package)
    for name in ("__init__.py", "_capi.py"):
        shutil.copy(os.path.join(SOURCE, "python", "calped", name), package)
    shutil.copy(built, package)
    return dict(os.environ, PYTHONPATH=os.path.join(folder, "py"),
                CALPED_LIBRARY=os.path.abspath(os.path.join(BUILD, "capi", sorted(library)[0])))


def test_ground_plan_example_draws_real_messages(broker, folder):
    """examples/fleet/ground_plan.py over messages two calped-detect cameras published."""
    detect = program("calped-detect")
    frames_needed(2)
    if not os.path.exists(CALIB):
        pytest.skip("needs ../shared's PETS calibration View_001.xml")
    env = binding_env(folder)
    sub = Subscriber(broker, folder)
    for cam in ("north", "south"):
        r = subprocess.run([detect, "--model", model(), "--calib", CALIB, "--resize", "2", "--max-frames", "2",
                            "--mqtt", broker.url("calped/%s/detections" % cam), "--camera-id", cam, FRAMES],
                           capture_output=True, text=True, timeout=300)
        assert r.returncode == 0, r.stderr
    deadline = time.monotonic() + 20
    while len(sub.messages()) < 4 and time.monotonic() < deadline:
        time.sleep(0.1)
    sub.stop()
    with open(sub.path, "rb") as f:
        lines = f.read()
    plan = subprocess.run([sys.executable, os.path.join(SOURCE, "examples", "fleet", "ground_plan.py"),
                           "--stdin", "--once"], input=lines, capture_output=True, env=env, timeout=60)
    assert plan.returncode == 0, plan.stderr.decode()
    text = plan.stdout.decode()
    last = {m["camera"]: m for _, m in sub.messages()}
    for letter, cam in (("A", "north"), ("B", "south")):
        people = last[cam]["detections"]
        assert "%s %s: frame 2, %d people" % (letter, cam, len(people)) in text, text
    rows = [line for line in text.splitlines() if line.startswith("|")]
    assert any("A" in row or "*" in row for row in rows), text


def gst_launch():
    if os.environ.get("CALPED_GSTCALPED") != "1":
        pytest.skip("the GStreamer element is not built here (libgstreamer1.0-dev)")
    if SANITIZED:
        pytest.skip("an instrumented plugin cannot load into gst-launch-1.0 (sanitizer build)")
    path = shutil.which("gst-launch-1.0")
    if not path:
        pytest.skip("no gst-launch-1.0 (Debian: gstreamer1.0-tools)")
    return path


def element_pipeline(launch, frames, properties):
    return [launch, "-q", "multifilesrc", "location=%s/%%06d.png" % FRAMES, "index=1",
            "stop-index=%d" % frames, "caps=image/png,framerate=10/1", "!", "pngdec", "!",
            "videoconvert", "!", "calped", "model=" + model()] + properties + ["!", "fakesink"]


def test_gstreamer_element_publishes_each_frame_with_calibration_auto(broker, folder):
    launch = gst_launch()
    frames_needed(4)
    sub = Subscriber(broker, folder)
    r = subprocess.run(element_pipeline(launch, 4, [
        "calibration=auto", "resize=2", "mqtt=" + broker.url("calped/gst1/detections"), "camera-id=gst1"]),
        capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    deadline = time.monotonic() + 20
    while len(sub.messages()) < 4 and time.monotonic() < deadline:
        time.sleep(0.1)
    sub.stop()
    messages = sub.messages()
    assert [m["frame"] for _, m in messages] == [1, 2, 3, 4]
    for topic, m in messages:
        assert topic == "calped/gst1/detections"
        assert m["camera"] == "gst1"
        # Four frames are too few people to estimate the camera: the generic method, no estimate.
        assert (m["method"], m["camera_estimate"]) == ("generic", 0)
        assert (m["width"], m["height"]) == (768, 576)
    assert any(m["detections"] for _, m in messages), "PETS frames 1-4 show people"


def test_gstreamer_element_refuses_an_unreachable_broker_at_start(folder):
    need_mqtt()
    launch = gst_launch()
    frames_needed(1)
    port = free_port()
    r = subprocess.run(element_pipeline(launch, 1, ["mqtt=mqtt://127.0.0.1:%d/calped/x/detections" % port]),
                       capture_output=True, text=True, timeout=120)
    assert r.returncode != 0
    assert "cannot connect to the MQTT broker 127.0.0.1:%d" % port in r.stdout + r.stderr
