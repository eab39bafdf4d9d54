# SPDX-License-Identifier: BSD-2-Clause
"""The installed Python binding (run by run_pytest.py after `meson install --destdir`):
error messages, every input layout, wrong arrays refused, and a PETS frame whose
detections equal the C++ API's (printed by the C++ helper capi_reference)."""
import os
import subprocess

import numpy as np
import pytest

import calped

HELPER = os.environ.get("CALPED_TEST_HELPER", "")
SHARED = os.environ.get("CALPED_SHARED_DIR", "../shared")
CALIB = os.path.join(SHARED, "data", "pets2009-s2l1", "View_001.xml")


def helper(*args, check=True):
    r = subprocess.run([HELPER, *map(str, args)], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if r.returncode == 77:
        pytest.skip(r.stderr.strip())
    if check:
        assert r.returncode == 0, r.stderr
    return r.stdout


def read_ppm(path):
    data = open(path, "rb").read()
    magic, w, h, maxval = data.split(maxsplit=4)[:4]
    assert magic == b"P6" and maxval == b"255"
    w, h = int(w), int(h)
    return np.frombuffer(data[len(data) - w * h * 3:], dtype=np.uint8).reshape(h, w, 3)


@pytest.fixture(scope="module")
def synthetic_blob(tmp_path_factory):
    path = tmp_path_factory.mktemp("model") / "synthetic.cpm"
    helper("synthetic-model", path)
    return path


@pytest.fixture(scope="module")
def synthetic(synthetic_blob):
    return calped.Model(synthetic_blob)


@pytest.fixture(scope="module")
def pets(tmp_path_factory):
    """(model path, frame path, RGB array) of PETS frame 1; skipped when not there."""
    model = helper("model").strip()
    if not os.path.exists(CALIB):
        pytest.skip("no calibration %s (../shared missing)" % CALIB)
    ppm = tmp_path_factory.mktemp("pets") / "000001.ppm"
    helper("frame", 1, ppm)
    return model, ppm, read_ppm(ppm)


def assert_same(a, b):
    """Bit for bit (NaN equal to NaN, unlike == on structured arrays)."""
    assert a.dtype == b.dtype and a.shape == b.shape and a.tobytes() == b.tobytes()


def random_rgb(h=240, w=320, seed=1):
    return np.random.default_rng(seed).integers(0, 256, size=(h, w, 3), dtype=np.uint8)


def test_installed_package_and_version():
    destdir = os.environ["CALPED_TEST_DESTDIR"]
    assert os.path.abspath(calped.__file__).startswith(destdir + os.sep)
    assert os.path.abspath(calped._capi.library_path).startswith(destdir + os.sep)
    assert calped.__version__ == os.environ["CALPED_TEST_VERSION"]


def test_error_codes_are_the_library_codes():
    names = {code: calped.Error(code, "").name for code in calped.ErrorCode}
    assert names[calped.ErrorCode.MODEL_CHECKSUM] == "ModelChecksum"
    assert names[calped.ErrorCode.INVALID_ARGUMENT] == "InvalidArgument"
    assert names[calped.ErrorCode.INTERNAL] == "Internal"
    assert "Unknown" not in names.values() and len(set(names.values())) == len(names)


def test_missing_model_file(tmp_path):
    path = tmp_path / "no-such-model.cpm"
    with pytest.raises(calped.FileError) as e:
        calped.Model(path)
    assert e.value.code == calped.ErrorCode.IO and isinstance(e.value, calped.Error)
    assert str(path) in str(e.value) and str(e.value).startswith("IoError: ")


def test_corrupt_model_bytes(synthetic_blob):
    with pytest.raises(calped.ModelError) as e:
        calped.Model.from_bytes(b"this is not a calped model")
    assert e.value.code == calped.ErrorCode.MODEL_BAD_MAGIC and "CALPEDM" in e.value.message
    blob = bytearray(open(synthetic_blob, "rb").read())
    blob[-1] ^= 0x55
    with pytest.raises(calped.ModelError) as e:
        calped.Model.from_bytes(blob)
    assert e.value.code == calped.ErrorCode.MODEL_CHECKSUM and "CRC-32" in str(e.value)
    assert calped.Model.from_bytes(open(synthetic_blob, "rb").read()).name != ""


def test_camera_errors(tmp_path):
    with pytest.raises(calped.FileError) as e:
        calped.Camera(tmp_path / "missing.xml")
    assert "missing.xml" in str(e.value)
    with pytest.raises(calped.ParseError) as e:
        calped.Camera.from_bytes('<Camera name="x">\n<Geometry width=', name="broken.xml")
    assert e.value.code == calped.ErrorCode.PARSE and "broken.xml:2" in str(e.value)


def test_bad_settings_are_named(synthetic):
    with pytest.raises(calped.InvalidArgumentError) as e:
        calped.Detector(synthetic, 640, 480, max_candidates=0)
    assert "maxCandidates 0" in str(e.value) and isinstance(e.value, ValueError)
    with pytest.raises(calped.InvalidArgumentError, match="needs a camera"):
        calped.Detector(synthetic, 640, 480, method="calibrated")
    with pytest.raises(calped.InvalidArgumentError, match="method 'fastest' is not one of"):
        calped.Detector(synthetic, 640, 480, method="fastest")
    with pytest.raises(calped.InvalidArgumentError, match="staticRejection.difference"):
        calped.Detector(synthetic, 640, 480, static_rejection=True, static_difference=300)
    with pytest.raises(calped.InvalidArgumentError, match="threads 0 is outside 1..64"):
        calped.Detector(synthetic, 640, 480, threads=0)
    with pytest.raises(TypeError, match="unknown setting 'speed'"):
        calped.Detector(synthetic, 640, 480, speed=2)


def test_default_settings():
    d = calped.default_settings()
    assert d["method"] == "auto" and d["resize"] == 1.0 and d["resize_at"] == "pyramid"
    assert d["levels"] == "placed" and d["nms"] is True and d["static_rejection"] is False
    assert d["min_person_height"] == 1.4 and d["max_person_height"] == 2.2 and np.isnan(d["cascade_threshold"])


def test_mismatched_frame_size(synthetic):
    det = calped.Detector(synthetic, 640, 480)
    with pytest.raises(calped.ImageError) as e:
        det.detect(random_rgb(600, 800))
    assert e.value.code == calped.ErrorCode.IMAGE_TOO_LARGE and "800x600" in str(e.value)
    with pytest.raises(calped.ImageError, match="smaller than the model"):
        det.detect(random_rgb(60, 30))


def test_wrong_arrays_are_refused(synthetic):
    det = calped.Detector(synthetic, 640, 480)
    rgb = random_rgb()
    with pytest.raises(calped.InvalidArgumentError, match="uint8 pixels; the array's dtype is float32"):
        det.detect(rgb.astype(np.float32))
    with pytest.raises(calped.InvalidArgumentError, match=r"HxWx3 uint8 array; got shape \(240, 320, 4\)"):
        det.detect(np.zeros((240, 320, 4), np.uint8))
    with pytest.raises(calped.InvalidArgumentError, match="takes a numpy array, not list"):
        det.detect([[0, 0], [0, 0]])
    with pytest.raises(calped.InvalidArgumentError, match="needs width and height"):
        det.detect(np.zeros(320 * 240 * 3 // 2, np.uint8), format="nv12")
    with pytest.raises(calped.InvalidArgumentError, match="flat array of 115200 bytes"):
        det.detect(np.zeros(1000, np.uint8), format="nv12", width=320, height=240)
    with pytest.raises(calped.InvalidArgumentError, match="format 'rgba' is not one of"):
        det.detect(rgb, format="rgba")
    with pytest.raises(calped.InvalidArgumentError, match="do not match"):
        det.detect(rgb, width=100)


def nv12_of(rgb):
    """A BT.601 limited-range NV12 frame of an RGB one (any fair encoder will do here)."""
    f = rgb.astype(np.float64)
    y = 16 + 0.257 * f[..., 0] + 0.504 * f[..., 1] + 0.098 * f[..., 2]
    u = 128 - 0.148 * f[..., 0] - 0.291 * f[..., 1] + 0.439 * f[..., 2]
    v = 128 + 0.439 * f[..., 0] - 0.368 * f[..., 1] - 0.071 * f[..., 2]
    h, w = y.shape
    sub = lambda c: c.reshape(h // 2, 2, w // 2, 2).mean(axis=(1, 3))
    uv = np.stack([sub(u), sub(v)], axis=-1)
    planes = [np.clip(np.rint(p), 0, 255).astype(np.uint8).ravel() for p in (y, uv)]
    return np.concatenate(planes), (y, sub(u), sub(v))


def test_every_layout(synthetic):
    det = calped.Detector(synthetic, 640, 480)
    rgb = random_rgb()
    h, w = rgb.shape[:2]
    base = det.detect(rgb)
    assert base.dtype == calped.DETECTION_DTYPE
    assert_same(det.detect(np.ascontiguousarray(rgb[..., ::-1]), format="bgr"), base)
    # A crop whose rows are strided is read in place and equals the packed copy.
    big = random_rgb(300, 400, seed=2)
    crop = big[20:260, 30:350]
    assert_same(det.detect(crop), det.detect(np.ascontiguousarray(crop)))
    grey = rgb[..., 1].copy()
    assert det.detect(grey).dtype == calped.DETECTION_DTYPE
    assert det.detect(grey, format="bayer_rggb").dtype == calped.DETECTION_DTYPE
    nv12, (y, u, v) = nv12_of(rgb)
    assert det.detect(nv12, format="nv12", width=w, height=h).dtype == calped.DETECTION_DTYPE
    i420 = np.concatenate([np.clip(np.rint(p), 0, 255).astype(np.uint8).ravel() for p in (y, u, v)])
    assert det.detect(i420, format="yuv420", width=w, height=h, yuv="bt601-limited").dtype == calped.DETECTION_DTYPE
    yuyv = np.zeros((h, w, 2), np.uint8)
    yuyv[..., 0] = y.clip(0, 255).astype(np.uint8)
    assert det.detect(yuyv, format="yuyv").dtype == calped.DETECTION_DTYPE
    s = det.stats
    assert s["windows"] > 0 and s["ms_total"] > 0 and det.method == "generic"


def test_threads_give_the_same_detections(synthetic):
    one = calped.Detector(synthetic, 640, 480)
    three = calped.Detector(synthetic, 640, 480, threads=3)
    for seed in (1, 2, 3):
        rgb = random_rgb(seed=seed)
        assert_same(three.detect(rgb), one.detect(rgb))
    assert three.stats["windows"] == one.stats["windows"] > 0


def reference(model, ppm, *args):
    """The C++ API's detections as float32 rows of the C struct's eight fields."""
    text = helper("detect", model, ppm, *args)
    rows = [[float(v) for v in line.split()] for line in text.splitlines()]
    return np.array(rows, dtype=np.float32).reshape(-1, 8)


def as_rows(found):
    return np.column_stack([found["box"], found["score"], found["ground_x"], found["ground_y"],
                            found["world_height"]]).astype(np.float32)


def test_pets_frame_equals_cpp(pets):
    model_path, ppm, rgb = pets
    model, camera = calped.Model(model_path), calped.Camera(CALIB)
    assert camera.image_size == (rgb.shape[1], rgb.shape[0])
    det = calped.Detector(model, rgb.shape[1], rgb.shape[0], camera=camera, method="calibrated", resize=2.0)
    model.close()
    camera.close()  # the detector holds copies
    assert det.method == "calibrated"
    with pytest.raises(calped.InvalidArgumentError, match="768x576 frames, got 640x480"):
        det.detect(rgb[:480, :640])
    found = det.detect(rgb)
    want = reference(model_path, ppm, "--camera", CALIB, "--resize", 2, "--method", "calibrated")
    assert len(found) > 0
    np.testing.assert_array_equal(as_rows(found), want)  # bit for bit, NaN where NaN
    assert np.all(np.isfinite(found["world_height"]))
    assert_same(det.detect(np.ascontiguousarray(rgb[..., ::-1]), format="bgr"), found)
    nv12, _ = nv12_of(rgb)
    assert len(det.detect(nv12, format="nv12", width=rgb.shape[1], height=rgb.shape[0])) > 0

    generic = calped.Detector(calped.Model(model_path), rgb.shape[1], rgb.shape[0], method="generic")
    found = generic.detect(rgb)
    np.testing.assert_array_equal(as_rows(found), reference(model_path, ppm, "--method", "generic"))
    assert np.all(np.isnan(found["world_height"]))
