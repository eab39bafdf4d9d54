# SPDX-License-Identifier: BSD-2-Clause
"""calped: the pedestrian detector (Dollar's ACF, and the calibrated method) from Python.

    import calped, numpy as np
    model = calped.Model("AcfInriaDetector.cpm")
    camera = calped.Camera("View_001.xml")
    detector = calped.Detector(model, 768, 576, camera=camera, resize=2.0)
    found = detector.detect(rgb)          # rgb: a 576x768x3 uint8 array
    for d in found[found["score"] > 30]:
        x, y, w, h = d["box"]
        print(x, y, w, h, d["score"], d["ground_x"], d["ground_y"], d["world_height"])

A ctypes binding over the C API (libcalped_c, docs/c-api.md); docs/python.md has the
details. Thread safety: one Detector per thread; Models and Cameras may be shared. ctypes
releases the GIL while the detector runs, so detectors on several threads run in parallel.
"""
import ctypes
import enum
import os

import numpy as np

from . import _build
from . import _capi

__all__ = [
    "Camera", "Detector", "Model", "DETECTION_DTYPE", "ErrorCode", "Error", "InvalidArgumentError",
    "ImageError", "ModelError", "FileError", "ParseError", "default_settings", "__version__",
]

__version__ = _capi.lib.calped_version().decode()


class ErrorCode(enum.IntEnum):
    """The C API's calped_status (the C++ calped::ErrorCode), docs/errors.md."""
    OK = 0
    INVALID_ARGUMENT = 1
    UNSUPPORTED_PIXEL_FORMAT = 2
    IMAGE_EMPTY = 3
    IMAGE_TOO_LARGE = 4
    IMAGE_TOO_SMALL = 5
    MODEL_TRUNCATED = 6
    MODEL_BAD_MAGIC = 7
    MODEL_BAD_VERSION = 8
    MODEL_CHECKSUM = 9
    MODEL_INVALID = 10
    MODEL_UNSUPPORTED = 11
    OUT_OF_MEMORY = 12
    IO = 13
    PARSE = 14
    CAMERA_NOT_FOUND = 15
    CAMERA = 16
    CAMERA_LOST = 17
    TIMEOUT = 18
    END_OF_STREAM = 19
    INTERNAL = 100


class Error(Exception):
    """A calped failure: `code` (an ErrorCode), `name` (the library's name of the code, e.g.
    "ModelChecksum") and `message` (the library's one-line message, which is str(error))."""

    def __init__(self, code, message):
        super().__init__(message)
        try:
            self.code = ErrorCode(code)
        except ValueError:
            self.code = code
        self.name = _capi.lib.calped_status_name(int(code)).decode()
        self.message = message


class InvalidArgumentError(Error, ValueError):
    """A setting, argument or array that calped refuses (also a ValueError)."""


class ImageError(Error):
    """The frame: unsupported format, empty, too large or too small."""


class ModelError(Error):
    """A model blob that is truncated, corrupt, invalid or unsupported."""


class FileError(Error):
    """A file that cannot be read (IoError)."""


class ParseError(Error):
    """A malformed calibration file (the message names the file and line)."""


def _error_class(code):
    if code == ErrorCode.INVALID_ARGUMENT:
        return InvalidArgumentError
    if ErrorCode.UNSUPPORTED_PIXEL_FORMAT <= code <= ErrorCode.IMAGE_TOO_SMALL:
        return ImageError
    if ErrorCode.MODEL_TRUNCATED <= code <= ErrorCode.MODEL_UNSUPPORTED:
        return ModelError
    if code == ErrorCode.IO:
        return FileError
    if code == ErrorCode.PARSE:
        return ParseError
    return Error


def _check(status, err):
    if status != 0:
        raise _error_class(status)(status, err.message.decode("utf-8", "replace"))


def _invalid(message):
    return InvalidArgumentError(ErrorCode.INVALID_ARGUMENT, "InvalidArgument: " + message)


class _Handle:
    """Owns one C handle, freed by close(), by `with`, or when collected."""
    _free = None

    def __init__(self):
        self._h = None

    def close(self):
        if self._h is not None:
            type(self)._free(self._h)
            self._h = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __del__(self):
        try:
            self.close()
        except Exception:  # interpreter shutdown: the library may be gone already
            pass

    def _load(self, fn, *args):
        h = ctypes.c_void_p()
        err = _capi.Error()
        _check(fn(*args, ctypes.byref(h), ctypes.byref(err)), err)
        self._h = h

    @classmethod
    def _loaded(cls, fn, *args):
        """An instance whose handle fn(*args, &handle, &err) makes (the from_* constructors)."""
        obj = cls.__new__(cls)
        _Handle.__init__(obj)
        obj._load(fn, *args)
        return obj


def _path(path):
    return os.fsencode(os.fspath(path))


class Model(_Handle):
    """A classifier model blob (calped-convert makes one from the toolbox's .mat file)."""
    _free = _capi.lib.calped_model_free

    def __init__(self, path):
        super().__init__()
        self._load(_capi.lib.calped_model_load_file, _path(path))

    @classmethod
    def from_bytes(cls, data):
        """The model from a bytes-like object (copied)."""
        data = bytes(data)
        return cls._loaded(_capi.lib.calped_model_load_memory, data, len(data))

    @property
    def name(self):
        return _capi.lib.calped_model_name(self._h).decode()


class Camera(_Handle):
    """A camera calibration: Tsai XML (PETS 2009), Town Centre .ci, projection text, OpenCV YAML."""
    _free = _capi.lib.calped_camera_free

    def __init__(self, path):
        super().__init__()
        self._load(_capi.lib.calped_camera_load_file, _path(path))

    @classmethod
    def from_bytes(cls, data, name="calibration"):
        """The calibration from a bytes-like object (or str); `name` is what messages call it."""
        data = data.encode() if isinstance(data, str) else bytes(data)
        return cls._loaded(_capi.lib.calped_camera_load_memory, data, len(data), name.encode())

    @property
    def image_size(self):
        """(width, height) the calibration states, (0, 0) when it states none."""
        w, h = ctypes.c_int(), ctypes.c_int()
        _capi.lib.calped_camera_image_size(self._h, ctypes.byref(w), ctypes.byref(h))
        return w.value, h.value


# One detection, the C calped_detection's layout: box is (x, y, w, h) in input pixels.
DETECTION_DTYPE = np.dtype([("box", "<f4", (4,)), ("score", "<f4"), ("ground_x", "<f4"),
                            ("ground_y", "<f4"), ("world_height", "<f4")])
assert DETECTION_DTYPE.itemsize == ctypes.sizeof(_capi.Detection)

_ENUMS = {
    "method": {"auto": 0, "generic": 1, "calibrated": 2},
    "resize_at": {"pyramid": 0, "frame": 1},
    "levels": {"placed": 0, "toolbox": 1},
}
_BOOLS = {"nms", "sparse_dense", "score_ratio", "box_voting", "static_rejection"}
# Every calped_config field but the struct's size and the frame size (Detector's width, height).
_SETTINGS = [name for name, _ in _capi.Config._fields_ if name not in ("struct_size", "max_width", "max_height")]


def _setting_value(name, raw):
    if name in _BOOLS:
        return bool(raw)
    if name in _ENUMS:
        return next(k for k, v in _ENUMS[name].items() if v == raw)
    return raw


def default_settings():
    """The detector's settings and their defaults (the C++ DetectorConfig's) as a dict."""
    cfg = _capi.Config()
    _capi.lib.calped_config_defaults(ctypes.byref(cfg))
    return {name: _setting_value(name, getattr(cfg, name)) for name in _SETTINGS}


_FORMATS = {
    "rgb": 0, "bgr": 1, "gray": 2, "grey": 2, "nv12": 3, "yuv420": 4, "i420": 4, "yuyv": 5,
    "bayer_rggb": 6, "bayer_grbg": 7, "bayer_gbrg": 8, "bayer_bggr": 9,
}
_YUV = {"bt601-limited": 0, "bt601-full": 1, "bt709-limited": 2, "bt709-full": 3}
_PLANAR = {3: "nv12", 4: "yuv420"}


def _lookup(table, value, what):
    try:
        return table[value]
    except (KeyError, TypeError):
        raise _invalid("%s %r is not one of %s" % (what, value, ", ".join(sorted(table)))) from None


def _image(array, fmt, width, height, yuv):
    """The calped_image for a numpy array, and the array it points into (kept alive)."""
    if not isinstance(array, np.ndarray):
        raise _invalid("detect() takes a numpy array, not %s" % type(array).__name__)
    if array.dtype != np.uint8:
        raise _invalid("detect() reads uint8 pixels; the array's dtype is %s" % array.dtype)
    if fmt is None:
        fmt = "rgb" if array.ndim == 3 else "gray"
    code = _lookup(_FORMATS, fmt, "format")
    im = _capi.Image()
    im.format = code
    im.yuv = _lookup(_YUV, yuv, "yuv")
    if code in _PLANAR:
        if width is None or height is None:
            raise _invalid("format %r needs width and height (the array is the planes, flat)" % fmt)
        width, height = int(width), int(height)
        cw, ch = (width + 1) // 2, (height + 1) // 2
        need = width * height + 2 * cw * ch
        if array.ndim != 1 or array.size != need:
            raise _invalid("a %dx%d %s frame is a flat array of %d bytes (width*height + 2*ceil(w/2)*ceil(h/2)); "
                           "got shape %s" % (width, height, _PLANAR[code], need, array.shape))
        array = np.ascontiguousarray(array)
        base = array.ctypes.data
        im.planes[0] = base
        im.planes[1] = base + width * height
        if code == 4:
            im.planes[2] = base + width * height + cw * ch
        im.width, im.height = width, height
        return im, array
    channels = {0: 3, 1: 3, 5: 2}.get(code, 1)
    shape = "HxWx%d" % channels if channels > 1 else "HxW"
    if (channels == 1 and array.ndim != 2) or (channels > 1 and (array.ndim != 3 or array.shape[2] != channels)):
        raise _invalid("format %r takes an %s uint8 array; got shape %s" % (fmt, shape, array.shape))
    if (width is not None and int(width) != array.shape[1]) or (height is not None and int(height) != array.shape[0]):
        raise _invalid("width x height %sx%s do not match the %s array's shape %s" % (width, height, shape, array.shape))
    # Rows may be strided (a crop of a larger frame); pixels within a row must be packed.
    inner = array.strides[1:] == ((channels, 1) if channels > 1 else (1,))
    if not inner or array.strides[0] < 0:
        array = np.ascontiguousarray(array)
    im.planes[0] = array.ctypes.data
    im.strides[0] = array.strides[0]
    im.height, im.width = array.shape[0], array.shape[1]
    return im, array


class Detector(_Handle):
    """A detector for frames up to width x height pixels (exactly that size with a camera).

    Settings are the C API's calped_config fields (docs/python.md), by keyword, defaults
    from the library (default_settings()): method ("auto", "generic", "calibrated"),
    resize, resize_at ("pyramid", "frame"), levels ("placed", "toolbox"),
    min_person_height, max_person_height, static_rejection, nms, box_voting,
    max_candidates, cascade_threshold, threads, ... Invalid settings raise InvalidArgumentError
    naming the setting. The model and camera may be closed afterwards (they are copied).
    """
    _free = _capi.lib.calped_detector_free

    def __init__(self, model, width, height, camera=None, **settings):
        super().__init__()
        cfg = _capi.Config()
        _capi.lib.calped_config_defaults(ctypes.byref(cfg))
        cfg.max_width, cfg.max_height = int(width), int(height)
        for name, value in settings.items():
            if name not in _SETTINGS:
                raise TypeError("Detector() got an unknown setting %r (settings: %s)" % (name, ", ".join(_SETTINGS)))
            if name in _ENUMS:
                value = _lookup(_ENUMS[name], value, name)
            elif name in _BOOLS:
                value = int(bool(value))
            setattr(cfg, name, value)
        if not isinstance(model, Model) or model._h is None:
            raise _invalid("Detector() needs an open calped.Model")
        if camera is not None and (not isinstance(camera, Camera) or camera._h is None):
            raise _invalid("camera must be an open calped.Camera or None")
        self._load(_capi.lib.calped_detector_create, model._h, camera._h if camera is not None else None,
                   ctypes.byref(cfg))
        self._err = _capi.Error()
        self._dets = ctypes.POINTER(_capi.Detection)()
        self._count = ctypes.c_int()

    def detect(self, image, format=None, width=None, height=None, yuv="bt601-limited"):
        """Detections on one frame, as a numpy structured array of DETECTION_DTYPE (a copy).

        image: HxWx3 uint8 (format "rgb", the default for 3 dimensions, or "bgr"); HxW uint8
        (grey, the default for 2 dimensions, or "bayer_rggb", "bayer_grbg", "bayer_gbrg",
        "bayer_bggr"); HxWx2 uint8 "yuyv"; or "nv12" / "yuv420" as a flat uint8 array of
        width*height*3/2 bytes with width and height given. yuv: the YUV formats' encoding,
        "bt601-limited" (default), "bt601-full", "bt709-limited", "bt709-full".
        """
        if self._h is None:
            raise _invalid("detect() on a closed Detector")
        im, keep = _image(image, format, width, height, yuv)
        _check(_capi.lib.calped_detect(self._h, ctypes.byref(im), ctypes.byref(self._dets),
                                       ctypes.byref(self._count), ctypes.byref(self._err)), self._err)
        del keep
        n = self._count.value
        if n == 0:
            return np.zeros(0, dtype=DETECTION_DTYPE)
        raw = ctypes.string_at(self._dets, n * DETECTION_DTYPE.itemsize)
        return np.frombuffer(raw, dtype=DETECTION_DTYPE).copy()

    @property
    def stats(self):
        """The last frame's statistics (windows, candidates, levels, ms_total, ...) as a dict."""
        s = _capi.Stats()
        err = _capi.Error()
        _check(_capi.lib.calped_detector_stats(self._h, ctypes.byref(s), ctypes.byref(err)), err)
        return {name: getattr(s, name) for name, _ in _capi.Stats._fields_}

    @property
    def method(self):
        """The method that runs: "generic" or "calibrated" ("auto" resolved by the camera)."""
        return _setting_value("method", _capi.lib.calped_detector_method(self._h))


if _build.VERSION != __version__:  # a package and a library from different builds
    import warnings
    warnings.warn("calped %s package loaded libcalped_c %s from %s" % (_build.VERSION, __version__,
                                                                      _capi.library_path))
