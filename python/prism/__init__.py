"""Prism, the recursive ray tracer, from Python (docs/python.md).

    import prism
    scene = prism.load("scenes/table.sc")
    img = prism.render(scene, depth=5, width=640, height=480)  # linear radiance
    rgb8 = prism.expose(img)                                   # 8-bit, 128 / avgmax
    prism.write("table.tif", img)

A thin layer over the C++ extension _prism, which binds the library's public
API (core/api/prism.h). Errors: prism.SceneError (a ValueError) for a scene
that cannot be read, ValueError for a value out of range, IndexError for a
light that does not exist, KeyboardInterrupt when Ctrl-C stops a render.
"""

import json as _json
import os as _os

import numpy as _np

from . import _prism
from ._prism import Scene, SceneError

SceneError.__module__ = __name__
Scene.__module__ = __name__

__all__ = ["Image", "Scene", "SceneError", "expose", "load", "parse", "ray_tree",
           "ray_tree_text", "render", "write"]


class Image(_np.ndarray):
    """A render's linear radiance: float32, shape (height, width, 3), rows from
    the top, before exposure.

    Beside the pixels it carries what the pixels alone cannot give back:
      avgmax        the mean of max(r, g, b) over pass 1's pixel centres, which
                    the automatic exposure divides by (expose, write);
      stats         the render's statistics, a dict with the keys of
                    `prism render --stats-json` (docs/statistics.md);
      supersampled  a bool array (height, width): the pixels pass 2 supersampled.

    Views and slices keep these; arithmetic (img * 2, img + other) gives a
    plain numpy.ndarray, whose exposure must be given (expose(a, avgmax=...)).
    """

    def __array_finalize__(self, obj):
        self.avgmax = getattr(obj, "avgmax", None)
        self.stats = getattr(obj, "stats", None)
        self.supersampled = getattr(obj, "supersampled", None)

    def __array_wrap__(self, out, context=None):
        # A ufunc's result is new radiance: not this render's any more.
        out = out.view(_np.ndarray)
        return out[()] if out.ndim == 0 else out


def load(path):
    """The scene in a .sc, .nff or .obj file (by its extension)."""
    return _prism.load(_os.fspath(path))


def parse(text, name="<string>"):
    """A scene from .sc text; `name` is the file name its messages show, and
    its includes are resolved against name's folder."""
    return _prism.parse(text, name)


def _size(width, height):
    return (0 if width is None else width, 0 if height is None else height)


def render(scene, *, depth=5, width=None, height=None, thresh=0.1, antialias=True,
           jitter=False, bailout=0.0, threads=0, progress=None):
    """Renders `scene` to an Image of linear radiance, the picture of
    `prism render` with the same settings, bit for bit.

    width, height  pixels, both or neither (default: the scene's resolution)
    depth          maximum ray depth, >= 1
    thresh         antialiasing threshold in [0, 1], a fraction of avgmax
    antialias      False: pass 1 only, one ray per pixel centre
    jitter         jitter pass 2's sub-samples within their cells
    bailout        >= 0; 0 traces exactly
    threads        0: every core this process may run on
    progress       called as progress(pass_, fraction) on the calling thread
                   after tiles finish; an exception it raises stops the render

    The GIL is released while rendering; Ctrl-C stops the render within a
    tile and raises KeyboardInterrupt.
    """
    w, h = _size(width, height)
    radiance, supersampled, avgmax, stats = _prism.render(
        scene, width=w, height=h, depth=depth, thresh=thresh, antialias=antialias,
        jitter=jitter, bailout=bailout, threads=threads, progress=progress)
    image = radiance.view(Image)
    image.avgmax = avgmax
    image.stats = _json.loads(stats)
    image.supersampled = supersampled.view(_np.bool_)
    return image


def _avgmax(image, avgmax):
    if avgmax is not None:
        return float(avgmax)
    if getattr(image, "avgmax", None) is None:
        raise ValueError("this array is not a render's Image: give its exposure as "
                         "avgmax= (e.g. the render's img.avgmax)")
    return image.avgmax


def expose(image, *, srgb=False, avgmax=None):
    """The 8-bit picture, uint8 (height, width, 3): each channel
    min(255, round(radiance * 128 / avgmax)), or its sRGB encoding with `srgb`.
    avgmax defaults to the render's own (image.avgmax); a plain array needs it."""
    return _prism.expose(image, avgmax=_avgmax(image, avgmax), srgb=srgb)


def write(path, image, *, srgb=False, float_radiance=False, avgmax=None):
    """Writes the picture as the extension says (.tif, .png, .exr, ...),
    atomically: 8-bit exposed as expose() does, or the float radiance for
    .exr, .hdr or with float_radiance. Raises RuntimeError naming the file if
    it cannot be written."""
    _prism.write(_os.fspath(path), image, avgmax=_avgmax(image, avgmax), srgb=srgb,
                 float_radiance=float_radiance)


def _tree(scene, x, y, depth, width, height, bailout):
    w, h = _size(width, height)
    return _prism.ray_tree(scene, x, y, width=w, height=h, depth=depth, bailout=bailout)


def ray_tree(scene, x, y, *, depth=5, width=None, height=None, bailout=0.0):
    """The ray tree of the centre ray of pixel (x, y) (from the top left) of
    a width x height picture, as nested dicts (docs/python.md#a-pixels-ray-tree):
    every hit, each term of the shading formula per light, and the
    secondary rays under "children"."""
    return _tree(scene, x, y, depth, width, height, bailout)[0]


def ray_tree_text(scene, x, y, *, depth=5, width=None, height=None, bailout=0.0):
    """The same ray tree as `prism render --pixel X Y` prints it."""
    return _tree(scene, x, y, depth, width, height, bailout)[1]
