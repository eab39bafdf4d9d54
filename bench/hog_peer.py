#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""A peer side by side: OpenCV's HOG people detector against calped on the same frames.

Runs cv2.HOGDescriptor with the default people SVM (Dalal & Triggs, one thread) over the
first N frames, writes its detections as calped's CSV and scores them, together with
calped's own detections on the same frames, with `calped-eval --score-only`: one matcher
for both (docs/evaluation.md). Prints time per frame and accuracy side by side, as ratios.

Box correction. The default detector's 64x128 window holds a person about 96 pixels tall
with about 16 pixels of margin on every side (Dalal & Triggs, CVPR 2005, section 3: "our
64x128 detection window includes about 16 pixels of margin around the person on all four
sides"). Ground truth boxes are tight, so each window (x, y, w, h) is shrunk to its central
person box (x + w/4, y + h/8, w/2, 3h/4). The uncorrected windows are scored as "hog-raw"
to show what the correction is worth.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import time

import cv2


def list_frames(folder, limit):
    names = sorted(n for n in os.listdir(folder)
                   if n.lower().endswith((".png", ".jpg", ".jpeg", ".ppm", ".pgm")))
    if not names:
        sys.exit(f"hog_peer: no images in {folder}")
    if limit > 0:
        names = names[:limit]
    return [os.path.join(folder, n) for n in names]


def run_hog(frames, resize, stride, scale):
    """Returns per-frame lists of (x, y, w, h, score) windows in input pixels, and ms/frame."""
    cv2.setNumThreads(1)  # one core, as calped
    hog = cv2.HOGDescriptor()
    hog.setSVMDetector(cv2.HOGDescriptor_getDefaultPeopleDetector())
    windows, times = [], []
    last = time.monotonic()
    for i, path in enumerate(frames):
        image = cv2.imread(path, cv2.IMREAD_COLOR)
        if image is None:
            sys.exit(f"hog_peer: cannot decode {path}")
        # Timed like calped's FrameStats::msTotal: the resize and the detection, not decoding.
        t0 = time.perf_counter()
        if resize != 1.0:
            image = cv2.resize(image, None, fx=resize, fy=resize, interpolation=cv2.INTER_LINEAR)
        rects, weights = hog.detectMultiScale(image, winStride=(stride, stride), padding=(8, 8),
                                              scale=scale)
        times.append((time.perf_counter() - t0) * 1000.0)
        frame = []
        for (x, y, w, h), s in zip(rects, list(weights.ravel()) if len(rects) else []):
            frame.append((x / resize, y / resize, w / resize, h / resize, float(s)))
        windows.append(frame)
        if time.monotonic() - last > 5:
            last = time.monotonic()
            print(f"hog_peer: {i + 1}/{len(frames)} frames, {statistics.mean(times):.0f} ms/frame",
                  file=sys.stderr, flush=True)
    return windows, times


def person_box(x, y, w, h):
    """The person inside a HOG window: 16 of 64 pixels off each side, 16 of 128 off top and bottom."""
    return x + w / 4.0, y + h / 8.0, w / 2.0, h * 0.75


def write_csv(path, windows, correct):
    with open(path, "w") as f:
        f.write("frame,x,y,w,h,score\n")
        for k, frame in enumerate(windows, start=1):
            for x, y, w, h, s in frame:
                if correct:
                    x, y, w, h = person_box(x, y, w, h)
                f.write(f"{k},{x:.9g},{y:.9g},{w:.9g},{h:.9g},{s:.9g}\n")


def run(cmd):
    print("hog_peer: " + " ".join(cmd), file=sys.stderr, flush=True)
    done = subprocess.run(cmd, stdout=subprocess.PIPE, text=True)
    if done.returncode != 0:
        sys.exit(f"hog_peer: {cmd[0]} failed with exit status {done.returncode}")
    return done.stdout


def fmt(v, digits):
    return "n/a" if v is None else f"{v:.{digits}f}"


def ratio(a, b):
    return None if a is None or b in (None, 0) else a / b


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--frames", required=True, help="folder of frames (sorted by name)")
    ap.add_argument("--gt", required=True, help="ground truth (CVML XML or MOTChallenge)")
    ap.add_argument("--model", required=True, help="calped model blob")
    ap.add_argument("--eval", required=True, help="the calped-eval executable")
    ap.add_argument("--resize", type=float, default=2.0,
                    help="input resize for both detectors (default 2.0)")
    ap.add_argument("--max-frames", type=int, default=100,
                    help="first N frames (default 100; 0 = all: HOG takes about 1 s a frame at resize 2)")
    ap.add_argument("--win-stride", type=int, default=8, help="HOG window stride (default 8)")
    ap.add_argument("--scale", type=float, default=1.05, help="HOG pyramid scale step (default 1.05)")
    ap.add_argument("--out", default="out/peer", help="output folder (default out/peer)")
    args = ap.parse_args()

    frames = list_frames(args.frames, args.max_frames)
    n = len(frames)
    os.makedirs(args.out, exist_ok=True)
    tag = f"r{args.resize:.1f}" if abs(args.resize * 10 - round(args.resize * 10)) < 1e-9 else f"r{args.resize:g}"

    print(f"hog_peer: OpenCV {cv2.__version__} HOG people detector on {n} frames, resize {args.resize:g}",
          file=sys.stderr, flush=True)
    windows, hog_ms = run_hog(frames, args.resize, args.win_stride, args.scale)
    hog_csv = os.path.join(args.out, f"hog_{tag}.csv")
    raw_csv = os.path.join(args.out, f"hog-raw_{tag}.csv")
    write_csv(hog_csv, windows, correct=True)
    write_csv(raw_csv, windows, correct=False)

    # calped on the same frames, then every detection file through the same matcher.
    calped_json = os.path.join(args.out, "calped.json")
    dets = os.path.join(args.out, "dets")
    run([args.eval, "--frames", args.frames, "--max-frames", str(n), "--gt", args.gt,
         "--model", args.model, "--methods", "generic", "--resizes", f"{args.resize:g}",
         "--resize-at", "frame",
         "--json", calped_json, "--dets", dets, "--quiet"])
    ours_csv = os.path.join(dets, f"generic_{tag}.csv")
    scored_json = os.path.join(args.out, "scored.json")
    table = run([args.eval, "--score-only", ",".join([ours_csv, hog_csv, raw_csv]),
                 "--frames", args.frames, "--max-frames", str(n), "--gt", args.gt,
                 "--json", scored_json, "--plots", os.path.join(args.out, "plots"), "--quiet"])

    with open(calped_json) as f:
        ours_run = json.load(f)[0]
    with open(scored_json) as f:
        scored = {r["method"]: r for r in json.load(f)}
    ours, hog, raw = scored["generic"], scored["hog"], scored["hog-raw"]
    ours_ms = ours_run["ms_per_frame"]
    hog_mean = statistics.mean(hog_ms)

    rows = [
        ("calped generic (ACF, fixed point)", ours_ms, ours),
        ("OpenCV HOG, person box (corrected)", hog_mean, hog),
        ("OpenCV HOG, raw 64x128 windows", hog_mean, raw),
    ]
    out = []
    out.append(f"Peer comparison on {n} frames of {args.frames}, resize {args.resize:g} for both, "
               f"one thread each (OpenCV {cv2.__version__}, HOG winStride {args.win_stride}, "
               f"scale {args.scale:g}, default people SVM).\n")
    out.append("| detector | ms/frame | TPR | FPPF | TPR (any) | LAMR |")
    out.append("|---|---:|---:|---:|---:|---:|")
    for name, ms, r in rows:
        out.append(f"| {name} | {ms:.1f} | {fmt(r['tpr'], 3)} | {fmt(r['fppf'], 2)} | "
                   f"{fmt(r['tpr_any'], 3)} | {fmt(r['log_avg_miss_rate'], 3)} |")
    out.append("")
    out.append("| HOG / calped | time per frame | TPR | FPPF | LAMR |")
    out.append("|---|---:|---:|---:|---:|")
    out.append(f"| ratio | {fmt(ratio(hog_mean, ours_ms), 2)} | {fmt(ratio(hog['tpr'], ours['tpr']), 2)} | "
               f"{fmt(ratio(hog['fppf'], ours['fppf']), 2)} | "
               f"{fmt(ratio(hog['log_avg_miss_rate'], ours['log_avg_miss_rate']), 2)} |")
    out.append("")
    out.append("calped's time is the detector's own FrameStats::msTotal; HOG's is cv2.resize plus "
               "detectMultiScale, both without image decoding. Scored by calped-eval --score-only:")
    out.append("")
    out.append(table.rstrip())
    text = "\n".join(out) + "\n"
    print(text)
    with open(os.path.join(args.out, "peer.md"), "w") as f:
        f.write(text)
    with open(os.path.join(args.out, "peer.json"), "w") as f:
        json.dump({"frames": n, "resize": args.resize, "opencv": cv2.__version__,
                   "calped": {"ms_per_frame": ours_ms, **{k: ours[k] for k in
                              ("tpr", "tpr_any", "fppf", "log_avg_miss_rate")}},
                   "hog": {"ms_per_frame": hog_mean, "ms_per_frame_median": statistics.median(hog_ms),
                           **{k: hog[k] for k in ("tpr", "tpr_any", "fppf", "log_avg_miss_rate")}},
                   "hog_raw": {k: raw[k] for k in ("tpr", "tpr_any", "fppf", "log_avg_miss_rate")},
                   "time_ratio_hog_over_calped": ratio(hog_mean, ours_ms)}, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
