"""The Python module against the library it wraps: scenes, overrides and their errors, renders
as numpy arrays, explanations, sweeps and materials (run by ctest with build/python on the
path, from the source folder)."""
import json
import pathlib
import struct
import threading
import time
import zlib

import numpy as np
import pytest

import shadelab

LECTURE = pathlib.Path("scenes/lecture")

BALL = {
    "image": {"width": 120, "height": 90, "background": [0, 0, 0]},
    "camera": {"eye": [0, 0, 6], "target": [0, 0, 0], "fovy": 30},
    "lights": [{"position": [2, 2, 3, 1], "diffuse": [1, 0.9, 0.7], "specular": [1, 1, 1]}],
    "objects": [{"name": "ball", "shape": {"type": "sphere", "radius": 1.3, "slices": 48, "stacks": 24},
                 "material": {"diffuse": [0.7, 0.6, 0.5], "specular": [0.8, 0.8, 0.8], "shininess": 20},
                 "shading": "phong"}],
}


def png_size(data):
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    width, height = struct.unpack(">II", data[16:24])
    return width, height


def test_scenes_load_from_files_dicts_and_text():
    s = shadelab.load_scene(LECTURE / "10-spot-cutoff.json")
    assert (s.width, s.height) == (400, 400)
    assert s.light_count == 1
    d = shadelab.load_scene(BALL)
    assert (d.width, d.height) == (120, 90) and d.objects == ["ball"]
    t = shadelab.load_scene(json.dumps(BALL))
    assert t.objects == ["ball"]


def test_set_uses_the_command_line_key_paths():
    s = shadelab.load_scene(BALL)
    assert s.set("image.width", 64) is s
    s.set("lights[0].diffuse", [0, 1, 0]).set("lights[0].specular", [0, 0, 0]).set("objects[0].shading", "flat")
    assert s.width == 64
    assert s.overrides == ["image.width=64", "lights[0].diffuse=[0, 1, 0]", "lights[0].specular=[0, 0, 0]",
                           'objects[0].shading="flat"']
    image = shadelab.render(s)
    assert image.shape == (90, 64, 4)
    assert image[..., 0].max() < 20 < 100 < image[..., 1].max()  # a green light (and the global ambient)


def test_a_refused_change_raises_and_leaves_the_scene_as_it_was():
    s = shadelab.load_scene(BALL)
    with pytest.raises(shadelab.SceneError) as e:
        s.set("lights[0].spot.cutof", 30)
    d = e.value.diagnostics[0]
    assert d.key_path == "lights[0].spot" and "did you mean \"cutoff\"" in d.message
    assert "cutof" in str(e.value)
    with pytest.raises(shadelab.SceneError) as e:
        s.set("objects[0].material.shininess", -5)
    assert e.value.diagnostics[0].key_path == "objects[0].material.shininess"
    assert s.overrides == []
    assert shadelab.render(s).shape == (90, 120, 4)


def test_errors_in_a_file_name_its_line_and_column(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text('{\n  "image": {"width": 32, "height": 32},\n  "camera": {"eye": [0, 0, 5]},\n'
                   '  "objects": [{"shape": {"type": "sphere"}, "material": {"shininess": "high"}}]\n}\n')
    with pytest.raises(shadelab.SceneError) as e:
        shadelab.load_scene(bad)
    d = e.value.diagnostics[0]
    assert d.file == str(bad) and d.line == 4 and d.column > 0
    assert d.key_path == "objects[0].material.shininess"
    assert str(bad) + ":4:" in str(e.value)
    with pytest.raises(shadelab.SceneError):
        shadelab.load_scene(tmp_path / "missing.json")
    with pytest.raises(shadelab.SceneError):
        shadelab.load_scene('{"image": ')


def test_a_render_is_a_numpy_array_over_the_renderers_pixels():
    image = shadelab.render(BALL, size=(80, 60))
    assert isinstance(image, np.ndarray) and isinstance(image, shadelab.Image)
    assert type(image.max()) is np.uint8 and type(image > 0) is np.ndarray  # computed: plain numbers
    assert image.shape == (60, 80, 4) and image.dtype == np.uint8
    assert not image.flags.owndata  # no copy: the array is a view of the library's buffer
    assert (image[..., 3] == 255).all()
    assert image[30, 40, :3].sum() > 150 and image[2, 2, :3].sum() == 0  # the ball, the background
    # The same picture as the reference rasterizer's, within the fast pipeline's 1/255.
    ref = shadelab.render(BALL, size=(80, 60), reference=True)
    assert np.abs(image.astype(int) - ref.astype(int)).max() <= 1


def test_render_options_override_the_scenes():
    flat = shadelab.render(BALL, shading="flat")
    phong = shadelab.render(BALL, shading="phong")
    assert (flat != phong).any()
    smooth = shadelab.render(BALL, samples=4)
    assert smooth.shape == (90, 120, 4)
    with pytest.raises(ValueError):
        shadelab.render(BALL, shading="wireframe")
    with pytest.raises(shadelab.SceneError) as e:
        shadelab.render(BALL, samples=3)  # samples are square numbers
    assert e.value.diagnostics[0].key_path == "image.samples"
    with pytest.raises(shadelab.SceneError):
        shadelab.render(BALL, size=(0, 10))


def test_an_image_shows_itself_as_png_and_saves(tmp_path):
    image = shadelab.render(BALL)
    assert png_size(image._repr_png_()) == (120, 90)
    assert image[..., :3]._repr_png_() is None  # a slice is not a picture
    image.save(tmp_path / "ball.png")
    assert png_size((tmp_path / "ball.png").read_bytes()) == (120, 90)


def test_renders_release_the_gil():
    big = shadelab.load_scene(BALL).set("image.width", 900).set("image.height", 700)
    big.set("objects[0].shape.slices", 400).set("objects[0].shape.stacks", 200)
    done = threading.Event()
    worker = threading.Thread(target=lambda: (shadelab.render(big, samples=4), done.set()))
    spins = 0
    worker.start()
    while not done.is_set():
        spins += 1  # runs only while the render does not hold the GIL
        time.sleep(0)
    worker.join()
    assert spins > 100


def test_explain_gives_the_lighting_equations_terms():
    s = shadelab.load_scene(BALL)
    e = shadelab.explain(s, 60, 45)
    assert e["object"] == "ball" and e["shading"] == "phong" and e["lit"]
    total = np.array(e["emission"]) + np.array(e["global_ambient"])
    for light in e["lights"]:
        total += np.array(light["ambient"]) + np.array(light["diffuse"]) + np.array(light["specular"])
    assert np.allclose(total, e["unclamped"], atol=1e-5)
    assert np.allclose(np.minimum(total, 1.0), e["result"][:3], atol=1e-5)
    # On a Phong object the explained colour is the rendered pixel.
    pixel = shadelab.render(s)[45, 60, :3] / 255.0
    assert np.abs(pixel - np.array(e["result"][:3])).max() <= 1.0 / 255 + 1e-6
    assert shadelab.explain(s, 1, 1) is None  # the background


def test_sweep_makes_the_commands_contact_sheet():
    spot = shadelab.load_scene(LECTURE / "10-spot-cutoff.json").set("image.width", 100).set("image.height", 100)
    sheet = shadelab.sweep(spot, {"lights[0].spot.cutoff": [10, 30, 60]}, title="cutoff")
    assert sheet.ndim == 3 and sheet.shape[2] == 4 and sheet.shape[1] > 3 * 100
    two = shadelab.sweep(spot, [("lights[0].spot.cutoff", [10, 60]), ("shading", ["flat", "phong"])])
    assert two.shape[0] > 2 * 100  # two rows
    labelled = shadelab.sweep(spot, {"lights[0].spot.cutoff": [10, 60]}, labels=["narrow", "wide"])
    assert labelled.shape == shadelab.sweep(spot, {"lights[0].spot.cutoff": [10, 60]}).shape
    with pytest.raises(ValueError):
        shadelab.sweep(spot, {"lights[0].spot.cutoff": [10, 60]}, labels=["one"])
    with pytest.raises(shadelab.SceneError) as e:
        shadelab.sweep(spot, {"lights[0].spot.cutof": [10]})
    assert e.value.diagnostics[0].file == "--vary"


def test_materials_are_the_presets():
    presets = shadelab.materials()
    names = [m["name"] for m in presets]
    assert "brass" in names and len(names) == len(set(names))
    brass = presets[names.index("brass")]
    assert len(brass["diffuse"]) == 4 and brass["shininess"] > 0 and brass["description"]
