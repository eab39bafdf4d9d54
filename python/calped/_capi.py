# SPDX-License-Identifier: BSD-2-Clause
"""ctypes declarations of the C API (calped/calped_c.h) and the loading of libcalped_c.

The structs here mirror the header field for field; calped_config carries its own size
(struct_size), which the library checks, so a mismatch is an error, not a misread.
"""
import ctypes
import ctypes.util
import os

from . import _build


class Error(ctypes.Structure):
    _fields_ = [("code", ctypes.c_int), ("message", ctypes.c_char * 256)]


class Config(ctypes.Structure):
    _fields_ = [
        ("struct_size", ctypes.c_uint32),
        ("max_width", ctypes.c_int),
        ("max_height", ctypes.c_int),
        ("resize", ctypes.c_double),
        ("resize_at", ctypes.c_int),
        ("max_candidates", ctypes.c_int),
        ("cascade_threshold", ctypes.c_float),
        ("nms", ctypes.c_int),
        ("method", ctypes.c_int),
        ("min_person_height", ctypes.c_double),
        ("max_person_height", ctypes.c_double),
        ("sparse_dense", ctypes.c_int),
        ("dense_region_persistence", ctypes.c_int),
        ("max_dense_regions", ctypes.c_int),
        ("score_ratio", ctypes.c_int),
        ("box_voting", ctypes.c_int),
        ("levels", ctypes.c_int),
        ("placed_level_reach", ctypes.c_int),
        ("static_rejection", ctypes.c_int),
        ("static_difference", ctypes.c_int),
        ("static_min_foreground", ctypes.c_float),
        ("static_warmup_frames", ctypes.c_int),
        ("threads", ctypes.c_int),
    ]


class Image(ctypes.Structure):
    _fields_ = [
        ("planes", ctypes.c_void_p * 3),
        ("strides", ctypes.c_int * 3),
        ("width", ctypes.c_int),
        ("height", ctypes.c_int),
        ("format", ctypes.c_int),
        ("yuv", ctypes.c_int),
    ]


class Detection(ctypes.Structure):
    _fields_ = [(name, ctypes.c_float) for name in
                ("x", "y", "w", "h", "score", "ground_x", "ground_y", "world_height")]


class Stats(ctypes.Structure):
    _fields_ = [
        ("levels", ctypes.c_int),
        ("computed_levels", ctypes.c_int),
        ("windows", ctypes.c_uint64),
        ("candidates", ctypes.c_uint64),
        ("dropped_windows", ctypes.c_uint64),
        ("sparse_windows", ctypes.c_uint64),
        ("dense_windows", ctypes.c_uint64),
        ("dense_regions", ctypes.c_int),
        ("dropped_regions", ctypes.c_uint64),
        ("static_rejected", ctypes.c_int),
        ("static_skipped", ctypes.c_uint64),
        ("ms_resize", ctypes.c_double),
        ("ms_channels", ctypes.c_double),
        ("ms_approx", ctypes.c_double),
        ("ms_classify", ctypes.c_double),
        ("ms_candidates", ctypes.c_double),
        ("ms_nms", ctypes.c_double),
        ("ms_total", ctypes.c_double),
    ]


def _candidates():
    """Where libcalped_c may be, most specific first."""
    explicit = os.environ.get("CALPED_LIBRARY")
    if explicit:
        return [explicit]
    here = os.path.dirname(os.path.abspath(__file__))
    # The installed layout: the library at the same place relative to the package as
    # Meson put it, whatever the DESTDIR or wherever the prefix was moved.
    relative = os.path.relpath(_build.LIBDIR, _build.PACKAGE_DIR)
    found = [os.path.normpath(os.path.join(here, relative, _build.LIBRARY)),
             os.path.join(_build.LIBDIR, _build.LIBRARY)]
    system = ctypes.util.find_library("calped_c")
    if system:
        found.append(system)
    return found


def _load():
    tried = []
    for path in _candidates():
        if os.sep in path and not os.path.exists(path):
            tried.append(path + " (absent)")
            continue
        try:
            return ctypes.CDLL(path), path
        except OSError as e:
            tried.append("%s (%s)" % (path, e))
    raise ImportError("calped: cannot load the C API library %s; tried: %s (set CALPED_LIBRARY to its path)"
                      % (_build.LIBRARY, "; ".join(tried)))


lib, library_path = _load()

_P = ctypes.POINTER
_status = ctypes.c_int
_handle = ctypes.c_void_p


def _declare(name, restype, *argtypes):
    f = getattr(lib, name)
    f.restype = restype
    f.argtypes = list(argtypes)


_declare("calped_status_name", ctypes.c_char_p, ctypes.c_int)
_declare("calped_version", ctypes.c_char_p)
_declare("calped_model_load_file", _status, ctypes.c_char_p, _P(_handle), _P(Error))
_declare("calped_model_load_memory", _status, ctypes.c_void_p, ctypes.c_size_t, _P(_handle), _P(Error))
_declare("calped_model_name", ctypes.c_char_p, _handle)
_declare("calped_model_free", None, _handle)
_declare("calped_camera_load_file", _status, ctypes.c_char_p, _P(_handle), _P(Error))
_declare("calped_camera_load_memory", _status, ctypes.c_void_p, ctypes.c_size_t, ctypes.c_char_p,
         _P(_handle), _P(Error))
_declare("calped_camera_image_size", None, _handle, _P(ctypes.c_int), _P(ctypes.c_int))
_declare("calped_camera_free", None, _handle)
_declare("calped_config_defaults", None, _P(Config))
_declare("calped_config_validate", _status, _P(Config), _handle, _P(Error))
_declare("calped_detector_create", _status, _handle, _handle, _P(Config), _P(_handle), _P(Error))
_declare("calped_detector_free", None, _handle)
_declare("calped_detect", _status, _handle, _P(Image), _P(_P(Detection)), _P(ctypes.c_int), _P(Error))
_declare("calped_detector_stats", _status, _handle, _P(Stats), _P(Error))
_declare("calped_detector_method", ctypes.c_int, _handle)
