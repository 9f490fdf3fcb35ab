"""shadelab from Python: the lecture's lighting, shading and materials, rendered on the CPU.

    import shadelab
    scene = shadelab.load_scene("scenes/lecture/09-spot-cutoff.json")
    scene.set("lights[0].spot.cutoff", 30)       # the same key paths as `shadelab render --set`
    image = shadelab.render(scene, size=(320, 240), shading="phong")
    image.shape                                  # (240, 320, 4), uint8, top row first
    image                                        # in Jupyter: shows itself (_repr_png_)
    shadelab.explain(scene, 160, 120)            # the lighting equation's terms at a pixel
    shadelab.sweep(scene, {"lights[0].spot.cutoff": [10, 20, 30]})
    shadelab.materials()                         # the material presets

Scenes are the command's JSON scenes (docs/scene-format.md). Errors in them raise SceneError,
whose `diagnostics` name the file, line, column and key path of each problem. Renders run with
the GIL released, so threads render side by side.
"""
import json
import os

import numpy as np

from . import _shadelab

__all__ = ["Diagnostic", "Image", "Scene", "SceneError", "explain", "load_scene", "materials", "render", "sweep"]


class Diagnostic(tuple):
    """One problem in a scene: (file, line, column, key_path, message); line and column are
    1-based, 0 when unknown."""

    __slots__ = ()

    def __new__(cls, file, line, column, key_path, message):
        return super().__new__(cls, (file, line, column, key_path, message))

    file = property(lambda self: self[0])
    line = property(lambda self: self[1])
    column = property(lambda self: self[2])
    key_path = property(lambda self: self[3])
    message = property(lambda self: self[4])


class SceneError(ValueError):
    """A scene that the reader refuses: str(error) is every problem, one a line, as the command
    prints them; `diagnostics` is the list of Diagnostic."""

    def __init__(self, text, items=()):
        super().__init__(text)
        self.diagnostics = [Diagnostic(*d) for d in items]


_shadelab._set_error_type(SceneError)


class Image(np.ndarray):
    """A rendered picture: an H x W x 4 numpy array of uint8 (RGBA, top row first) over the
    renderer's own pixels, which Jupyter shows as a PNG."""

    def __array_wrap__(self, result, context=None, *args):
        # What is computed from a picture (sums, comparisons, means) is plain numbers.
        result = np.asarray(result)
        return result if result.ndim else result[()]

    def _repr_png_(self):
        # Only whole pictures show as PNG; slices and computed arrays show as numbers.
        if self.ndim != 3 or self.shape[2] != 4 or self.dtype != np.uint8:
            return None
        return self.png()

    def png(self):
        """The picture as PNG bytes."""
        return _shadelab.png(np.ascontiguousarray(self, dtype=np.uint8))

    def save(self, path):
        """Writes the picture as a PNG file."""
        with open(path, "wb") as f:
            f.write(self.png())


def _image(array):
    return array.view(Image)


class Scene:
    """A scene read and validated by shadelab's scene reader. set() changes it through the same
    overrides as the command's --set; a change the reader refuses raises SceneError and leaves
    the scene as it was."""

    def __init__(self, native):
        self._native = native

    def set(self, key, value):
        """Sets the value at a key path ("lights[0].spot.cutoff", "objects[1].material.shininess",
        "image.width") to a JSON value (numbers, strings, lists, dicts); returns the scene."""
        self._native.set(key, json.dumps(value))
        return self

    width = property(lambda self: self._native.width, doc="The image's width in pixels.")
    height = property(lambda self: self._native.height, doc="The image's height in pixels.")
    samples = property(lambda self: self._native.samples, doc="Samples per pixel (1, 4, 9, ...).")
    overrides = property(lambda self: list(self._native.overrides), doc="The changes made by set(), as --set texts.")
    objects = property(lambda self: list(self._native.object_names), doc="The objects' names, in order.")
    light_count = property(lambda self: self._native.light_count, doc="How many lights the scene has.")

    def render(self, **options):
        """The scene rendered: shadelab.render(self, **options)."""
        return render(self, **options)

    def _repr_png_(self):
        return render(self)._repr_png_()

    def __repr__(self):
        return "<shadelab.Scene %s: %dx%d, %d objects, %d lights%s>" % (
            self._native.filename, self.width, self.height, len(self.objects), self.light_count,
            "".join(", " + o for o in self.overrides))


def load_scene(source, base_dir=None):
    """A Scene from a scene file's path, or from a dict (or JSON text) in the scene format;
    relative mesh and texture paths start at the file's folder, or at `base_dir` (by default
    the current folder) for a dict."""
    if isinstance(source, dict):
        return Scene(_shadelab.Scene(json.dumps(source), "<dict>", os.fspath(base_dir or ".")))
    if isinstance(source, str) and source.lstrip().startswith("{"):
        return Scene(_shadelab.Scene(source, "<text>", os.fspath(base_dir or ".")))
    return Scene(_shadelab.scene_from_file(os.fspath(source)))


def _scene(scene):
    return scene if isinstance(scene, Scene) else load_scene(scene)


def render(scene, size=None, shading=None, samples=None, reference=False):
    """Renders a scene (a Scene, a path or a dict) into an Image. size=(width, height) and
    samples override the scene's; shading ("flat", "gouraud", "phong") overrides every object's;
    reference=True draws with the reference rasterizer instead of the fast one."""
    s = _scene(scene)
    if size is not None:
        size = (int(size[0]), int(size[1]))
    return _image(_shadelab.render(s._native, size, shading, samples, reference))


def explain(scene, x, y):
    """The lighting equation at pixel (x, y) (0, 0 the top-left) of the rendered scene, as a dict:
    the object, its shading, the eye-space position and normal, and each term (emission, global
    ambient, every light's attenuation, spot factor, ambient, diffuse and specular) with their
    sum before and after clamping. None where the pixel shows the background."""
    return _shadelab.explain(_scene(scene)._native, int(x), int(y))


def sweep(scene, vary, shading=None, samples=None, columns=0, title="", labels=()):
    """A contact sheet: the scene rendered once per value of one or two keys, each picture
    labelled, as `shadelab sweep` makes it. vary maps a key path (or "shading") to its values:
    {"lights[0].spot.cutoff": [10, 20, 30]}, or a list of (key, values) pairs to fix the order.
    Strings are bare words, as on the command line ("phong", "brass"). labels replace the
    pictures' "key = value" labels, in order; columns sets the sheet's width in pictures."""
    pairs = list(vary.items()) if isinstance(vary, dict) else list(vary)
    encoded = [(key, [v if isinstance(v, str) else json.dumps(v) for v in values]) for key, values in pairs]
    cells = 1
    for _, values in encoded:
        cells *= len(values)
    if labels and len(labels) != cells:
        raise ValueError("labels: expected %d, one for each picture, got %d" % (cells, len(labels)))
    return _image(_shadelab.sweep(_scene(scene)._native, encoded, shading, samples, int(columns), title,
                                  [str(label) for label in labels]))


def materials():
    """The material presets (the lecture's, then the classic OpenGL table): a list of dicts with
    name, description, ambient, diffuse, specular, emission (RGBA) and shininess."""
    return _shadelab.materials()
