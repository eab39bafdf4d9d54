#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""All cameras' people on one ground plan (docs/deploying.md).

Subscribes to calped/+/detections (or any topic filter) with paho-mqtt, keeps each
camera's latest message, turns its detections into the Python binding's own detection
records (calped.DETECTION_DTYPE: box, score, ground_x, ground_y, world_height) and redraws
a text plan of the ground, metres on both axes, every camera's people as its letter.

    ground_plan.py [--broker HOST[:PORT]] [--topic FILTER] [--area X0,Y0,X1,Y1] [--every S]
    mosquitto_sub -t 'calped/+/detections' -v | ground_plan.py --stdin [--once]

--stdin reads `mosquitto_sub -v` lines (topic, a space, the JSON) or bare JSON messages
instead of subscribing; --once draws one plan at the end of the input and exits.
"""
import argparse
import json
import math
import sys
import threading
import time

import numpy as np

import calped


def detections(message):
    """One message's detections as calped.DETECTION_DTYPE records; the world fields are NaN
    where the camera has no calibration, as the binding gives them."""
    people = message.get("detections", [])
    out = np.zeros(len(people), dtype=calped.DETECTION_DTYPE)
    for i, d in enumerate(people):
        out[i]["box"] = (d["x"], d["y"], d["w"], d["h"])
        out[i]["score"] = d["score"]
        for field in ("ground_x", "ground_y", "world_height"):
            out[i][field] = d.get(field, math.nan)
    return out


class Plan:
    """The latest frame of every camera, safe to update from paho's network thread."""

    def __init__(self):
        self.lock = threading.Lock()
        self.latest = {}  # camera -> (frame, time, detections)

    def add(self, payload):
        try:
            message = json.loads(payload)
            camera, frame = str(message["camera"]), int(message["frame"])
            dets = detections(message)
        except (ValueError, KeyError, TypeError) as e:
            print("ground_plan: skipping a message that is not a calped frame record (%s)" % e, file=sys.stderr)
            return
        with self.lock:
            old = self.latest.get(camera)
            if old is None or frame > old[0]:  # QoS 1 may repeat a message: keep the newest
                self.latest[camera] = (frame, message.get("time"), dets)

    def snapshot(self):
        with self.lock:
            return dict(self.latest)


def draw(latest, area, columns=72, rows=24):
    x0, y0, x1, y1 = area
    grid = [[" "] * columns for _ in range(rows)]
    letters = {}
    lines = []
    for k, camera in enumerate(sorted(latest)):
        letter = chr(ord("A") + k % 26)
        letters[camera] = letter
        frame, t, dets = latest[camera]
        placed = dets[np.isfinite(dets["ground_x"]) & np.isfinite(dets["ground_y"])]
        for d in placed:
            c = int((d["ground_x"] - x0) / (x1 - x0) * (columns - 1) + 0.5)
            r = int((y1 - d["ground_y"]) / (y1 - y0) * (rows - 1) + 0.5)  # y up
            if 0 <= c < columns and 0 <= r < rows:
                grid[r][c] = letter if grid[r][c] in (" ", letter) else "*"
        heights = ", ".join("%.2f m" % h for h in placed["world_height"])
        lines.append("%s %s: frame %d, %d people (%d on the plan%s)" % (
            letter, camera, frame, len(dets), len(placed), ": " + heights if heights else ""))
    border = "+" + "-" * columns + "+"
    out = ["ground plan x %.1f..%.1f m, y %.1f..%.1f m (* = more than one camera)" % (x0, x1, y0, y1), border]
    out += ["|" + "".join(row) + "|" for row in grid]
    out += [border] + lines
    return "\n".join(out)


def parse_area(text):
    parts = [float(p) for p in text.split(",")]
    if len(parts) != 4 or parts[0] >= parts[2] or parts[1] >= parts[3]:
        raise argparse.ArgumentTypeError("--area wants X0,Y0,X1,Y1 with X0 < X1 and Y0 < Y1")
    return parts


def read_stdin(plan):
    for line in sys.stdin:
        line = line.strip()
        if not line:
            continue
        # mosquitto_sub -v: "TOPIC {json}"; a topic has no spaces, a message starts with {
        payload = line if line.startswith("{") else line.split(" ", 1)[-1]
        plan.add(payload)


def subscribe(plan, broker, topic):
    import paho.mqtt.client as mqtt  # Debian python3-paho-mqtt (1.6)
    host, _, port = broker.partition(":")
    client = mqtt.Client()
    client.on_connect = lambda c, userdata, flags, rc: c.subscribe(topic, qos=1)
    client.on_message = lambda c, userdata, msg: plan.add(msg.payload)
    client.connect(host, int(port or 1883), keepalive=30)
    client.loop_start()  # reconnects by itself
    return client


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--broker", default="127.0.0.1:1883")
    ap.add_argument("--topic", default="calped/+/detections")
    ap.add_argument("--area", type=parse_area, default=[-15.0, -15.0, 15.0, 15.0],
                    help="the plan's extent in metres: X0,Y0,X1,Y1 (default -15,-15,15,15)")
    ap.add_argument("--every", type=float, default=1.0, help="seconds between plans (default 1)")
    ap.add_argument("--stdin", action="store_true", help="read mosquitto_sub -v lines from standard input")
    ap.add_argument("--once", action="store_true", help="with --stdin: one plan at the end of the input")
    args = ap.parse_args()
    plan = Plan()
    if args.stdin and args.once:
        read_stdin(plan)
        print(draw(plan.snapshot(), args.area))
        return 0
    if args.stdin:
        threading.Thread(target=read_stdin, args=(plan,), daemon=True).start()
    else:
        subscribe(plan, args.broker, args.topic)
    try:
        while True:
            time.sleep(args.every)
            print("\033[H\033[2J" + draw(plan.snapshot(), args.area), flush=True)
    except KeyboardInterrupt:
        return 0


if __name__ == "__main__":
    sys.exit(main())
